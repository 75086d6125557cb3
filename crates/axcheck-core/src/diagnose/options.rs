//! The level of the tests and the options of a diagnosis: read by every layer of the
//! diagnosis, they need nothing of it.

use crate::evaluate::StandardId;

/// Level of each effect's test: eight tests at 0.1 % leave data the base model explains
/// without a finding in at least 99.2 % of tests.
pub const ALPHA: f64 = 0.001;

/// The share of tests in which an effect of the size a plan is said to confirm is found
/// (`detectable`).
pub const POWER: f64 = 0.80;

/// Options of a diagnosis.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Declared lead-screw or encoder pitch (mm or deg): tested as a prior candidate
    /// period, and named in the advice when the plan cannot resolve it.
    pub pitch: Option<f64>,
    /// Where a thermal growth of the axis holds still (mm or deg; the lead screw's fixed
    /// bearing, or the scale's fixing point), when known: a drift and a growth about
    /// another origin fit the same readings, and only a declared origin tells them apart
    /// (without it the origin is fitted, within a quarter of the travel beyond its ends).
    pub thermal_origin: Option<f64>,
    /// Monte-Carlo tests simulated from the fitted base model for the model checks.
    pub simulations: usize,
    /// Seed of the simulations and the cross-validation folds.
    pub seed: u64,
    /// Standard of the "as measured / effect removed" parameters.
    pub standard: StandardId,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            pitch: None,
            thermal_origin: None,
            simulations: 200,
            seed: 0,
            standard: StandardId::Iso230_2,
        }
    }
}
