#![no_main]
//! Fuzz target `model`: see `axcheck_fuzz::model`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::model(data));
