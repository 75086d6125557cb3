#![no_main]
//! Fuzz target `spec`: see `axcheck_fuzz::spec`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::spec(data));
