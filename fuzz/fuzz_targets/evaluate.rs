#![no_main]
//! Fuzz target `evaluate`: see `axcheck_fuzz::evaluate`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::evaluate(data));
