#![no_main]
//! Fuzz target `controllers`: see `axcheck_fuzz::controllers`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::controllers(data));
