//! Inspection trends: one parameter of one axis over its inspections, the slope per year
//! (robust to one odd inspection), and the date it will reach its limit. Pure: the series
//! come from the history store (the `history` module, a higher layer), the results go to
//! JSON, CSV and charts.

pub mod fit;
pub mod sen;

pub use fit::{HorizonError, Trend, TrendOptions, fit};

use chrono::NaiveDate;
use serde::Serialize;

/// One inspection's value of the parameter.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Inspection {
    pub date: NaiveDate,
    /// Deviation unit (µm or arcsec), as evaluated.
    pub value: f64,
}

/// One parameter of one axis (machine id and axis name; a new serial number starts a new
/// series) over its inspections, in date order.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Series {
    pub machine: String,
    /// The machine's serial number, when the campaign gives it.
    pub serial: Option<String>,
    pub axis: String,
    /// Parameter key as in `eval --json` (`E`, `R_up`, …).
    pub parameter: String,
    /// Deviation unit: `um` or `arcsec`.
    pub unit: String,
    /// The limit at the latest inspection, when one applied.
    pub limit: Option<f64>,
    pub points: Vec<Inspection>,
}
