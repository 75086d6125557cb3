#![no_main]
//! Fuzz target `ecmc_app`: see `axcheck_fuzz::ecmc_app`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::ecmc_app(data));
