#![no_main]
//! Fuzz target `xlsx`: see `axcheck_fuzz::xlsx`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::xlsx(data));
