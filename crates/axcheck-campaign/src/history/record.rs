//! A row of the history: one parameter of one axis test of one inspection (long form, so
//! any engine can filter and pivot it).

use chrono::NaiveDate;
use std::sync::Arc;

/// A text column's value. Shared: a history repeats each machine, axis, parameter and unit
/// on thousands of rows, and a reader keeps one copy of each per file (a row takes about
/// a third of the memory of owned strings).
pub type SharedText = Arc<str>;

/// The version of the history's schema, stored in every row (`schema_version`).
pub const SCHEMA_VERSION: u32 = 1;

/// One parameter of one axis test of one campaign run.
#[derive(Debug, Clone, PartialEq)]
pub struct Record {
    pub schema_version: u32,
    /// Campaign name and date: the run's identity.
    pub campaign: SharedText,
    pub date: NaiveDate,
    pub machine: SharedText,
    pub serial: Option<SharedText>,
    pub axis: SharedText,
    /// Test number within the axis (1 for a single file).
    pub test: u32,
    /// `linear` or `rotary`.
    pub kind: SharedText,
    /// Standard key (`iso230-2`, …).
    pub standard: SharedText,
    /// The test's verdict (`pass`, `fail`, …).
    pub verdict: SharedText,
    /// Parameter key as in `eval --json`.
    pub parameter: SharedText,
    /// Deviation unit: `um` or `arcsec`.
    pub unit: SharedText,
    pub value: f64,
    /// The limit that applied, if any.
    pub limit: Option<f64>,
    /// Expanded uncertainty U of the parameter, if evaluated.
    pub uncertainty: Option<f64>,
    /// The diagnosis' effects, space-separated (`drift periodic`), or `none`.
    pub effects: SharedText,
}
