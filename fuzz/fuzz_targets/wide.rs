#![no_main]
//! Fuzz target `wide`: see `axcheck_fuzz::wide`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::wide(data));
