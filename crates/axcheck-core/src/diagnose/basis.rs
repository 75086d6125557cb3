//! What every effect's test and finding reads of one measurement: the prepared readings,
//! the rows that are not outliers, the scatter of the full time model and the per-target
//! reversal values and bidirectional means of the readings corrected for the time
//! effects. Built by the analysis (`analysis.rs`, above the effects), which also keeps
//! each effect's own test.

use super::finding::Units;
use super::prep::Prep;
use crate::measurement::AxisData;

/// The shared part of the analysis of one measurement.
pub(crate) struct Basis<'a> {
    pub data: &'a AxisData,
    pub(crate) prep: Prep,
    pub units: Units,
    /// The readings, one per row of `prep`.
    pub x: Vec<f64>,
    /// Rows that are not outliers.
    pub active: Vec<bool>,
    /// Scatter σ of the full time model (NaN when unknown: n = 1).
    pub sigma: f64,
    /// Reversal value Bi per target of the readings corrected for the time effects.
    pub b: Vec<f64>,
    /// Bidirectional mean X̄i per target of the same readings.
    pub means: Vec<f64>,
}

impl Basis<'_> {
    /// Length of the measured travel (first to last target).
    pub fn length(&self) -> f64 {
        self.prep.length()
    }
}
