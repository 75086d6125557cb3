//! Replays the committed fuzz corpus (`fuzz/corpus/<target>/*`) through the same functions
//! the cargo-fuzz targets call, so `cargo test` checks every seed and every regression input
//! without cargo-fuzz or a nightly compiler.

#[path = "../../fuzz/src/lib.rs"]
mod targets;

use std::path::PathBuf;

fn replay(target: &str, run: fn(&[u8])) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz/corpus")
        .join(target);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no corpus in {}", dir.display());
    for file in &files {
        let bytes = std::fs::read(file).unwrap();
        let outcome = std::panic::catch_unwind(|| run(&bytes));
        assert!(outcome.is_ok(), "{target}: {} panics", file.display());
    }
}

#[test]
fn csv_corpus() {
    replay("csv", targets::csv);
}

#[test]
fn ecmc_app_corpus() {
    replay("ecmc_app", targets::ecmc_app);
}

#[test]
fn keyvalue_corpus() {
    replay("keyvalue", targets::keyvalue);
}

#[test]
fn renishaw_corpus() {
    replay("renishaw", targets::renishaw);
}

#[test]
fn evaluate_corpus() {
    replay("evaluate", targets::evaluate);
}

#[test]
fn campaign_corpus() {
    replay("campaign", targets::campaign);
}

#[test]
fn spec_corpus() {
    replay("spec", targets::spec);
}

#[test]
fn controllers_corpus() {
    replay("controllers", targets::controllers);
}

#[test]
fn model_corpus() {
    replay("model", targets::model);
}

#[test]
fn wide_corpus() {
    replay("wide", targets::wide);
}

#[test]
fn xlsx_corpus() {
    replay("xlsx", targets::xlsx);
}

/// The `history` target (`fuzz/fuzz_targets/history.rs`, built with polars, so not in
/// `fuzz/src/lib.rs`): the seeds read whole, every corpus file without a panic.
#[test]
fn history_corpus() {
    let seed = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("fuzz/corpus/history/plant-2-annual-inspection_2022-11-20.parquet");
    let rows = axcheck::history::read_bytes(&std::fs::read(&seed).unwrap(), &seed).unwrap();
    assert_eq!(rows.len(), 201);
    // Footers whose list lengths made polars reserve 13 and 20 GB and abort: refused first.
    for (name, claim) in [
        (
            "footer-list-length-20GB",
            "a list claims 317064368 elements",
        ),
        (
            "footer-list-length-13GB",
            "a list claims 212307468 elements",
        ),
    ] {
        let path = seed.with_file_name(name);
        let e = axcheck::history::read_bytes(&std::fs::read(&path).unwrap(), &path)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("its footer is damaged at byte") && e.contains(claim),
            "{e}"
        );
    }
    replay("history", |bytes| {
        let _ = axcheck::history::read_bytes(bytes, std::path::Path::new("fuzz.parquet"));
    });
}
