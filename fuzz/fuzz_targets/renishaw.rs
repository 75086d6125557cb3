#![no_main]
//! Fuzz target `renishaw`: see `axcheck_fuzz::renishaw`.
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| axcheck_fuzz::renishaw(data));
