//! A row of the history: one parameter of one axis test of one inspection (long form, so
//! any engine can filter and pivot it).

use chrono::NaiveDate;
use serde::Serialize;

/// The version of the history's schema, stored in every row (`schema_version`).
pub const SCHEMA_VERSION: u32 = 1;

/// One parameter of one axis test of one campaign run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Record {
    pub schema_version: u32,
    /// Campaign name and date: the run's identity.
    pub campaign: String,
    pub date: NaiveDate,
    pub machine: String,
    pub serial: Option<String>,
    pub axis: String,
    /// Test number within the axis (1 for a single file).
    pub test: u32,
    /// `linear` or `rotary`.
    pub kind: String,
    /// Standard key (`iso230-2`, …).
    pub standard: String,
    /// The test's verdict (`pass`, `fail`, …).
    pub verdict: String,
    /// Parameter key as in `eval --json`.
    pub parameter: String,
    /// Deviation unit: `um` or `arcsec`.
    pub unit: String,
    pub value: f64,
    /// The limit that applied, if any.
    pub limit: Option<f64>,
    /// Expanded uncertainty U of the parameter, if evaluated.
    pub uncertainty: Option<f64>,
    /// The diagnosis' effects, space-separated (`drift periodic`), or `none`.
    pub effects: String,
}
