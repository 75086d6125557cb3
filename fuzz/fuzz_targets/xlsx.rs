#![no_main]
//! Fuzz target `xlsx`: see `axcheck_fuzz::xlsx`. calamine's panics on damaged books are
//! contained by the reader (`axcheck_campaign::panics`); the quiet hook lets them be, and any
//! other panic still aborts the fuzzer.
use libfuzzer_sys::fuzz_target;

fuzz_target!(init: axcheck_campaign::panics::install_quiet_hook(), |data: &[u8]| axcheck_fuzz::xlsx(data));
