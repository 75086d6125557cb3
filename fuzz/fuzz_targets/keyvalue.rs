#![no_main]
//! Fuzz target `keyvalue`: see `axcheck_fuzz::keyvalue`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::keyvalue(data));
