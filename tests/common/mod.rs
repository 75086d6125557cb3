//! Helpers shared by the integration tests.
#![allow(dead_code)]

use axcheck::measurement::{self, AxisData};
use std::path::PathBuf;

pub fn data_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

pub fn load(name: &str) -> AxisData {
    measurement::read_file(&data_path(name)).unwrap_or_else(|e| panic!("{e}"))
}

pub fn assert_close(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        (got - want).abs() <= tol,
        "{what}: got {got}, want {want} ± {tol}"
    );
}
