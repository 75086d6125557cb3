#![no_main]
//! Fuzz target `campaign`: see `axcheck_fuzz::campaign`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::campaign(data));
