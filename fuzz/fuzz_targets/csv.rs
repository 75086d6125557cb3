#![no_main]
//! Fuzz target `csv`: see `axcheck_fuzz::csv`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::csv(data));
