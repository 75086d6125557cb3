#![no_main]
//! Fuzz target `history`: bytes read as a history file (Parquet, through polars, whose
//! panics on damaged files `axcheck_campaign::panics` contains). What it can still find: an abort,
//! an allocation without bound (`-rss_limit_mb`), a hang, or a panic outside the reader.
//! Built with the `history` feature, which brings in polars:
//! `cargo fuzz run history --features history`.
use libfuzzer_sys::fuzz_target;
use std::path::Path;

// The quiet hook lets contained panics be; any other panic still aborts the fuzzer.
fuzz_target!(init: axcheck_campaign::panics::install_quiet_hook(), |data: &[u8]| {
    let path = Path::new("fuzz.parquet");
    if let Ok(records) = axcheck::history::read_bytes(data, path) {
        // Rows that read are regrouped and fitted, as `trend` does.
        let options = axcheck_core::trend::fit::TrendOptions { horizon_years: 2.0 };
        for series in axcheck::history::series(&records) {
            let _ = axcheck_core::trend::fit::fit(&series, &options);
        }
    }
});
