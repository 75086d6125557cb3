//! The extended model fitted on all (non-outlier) readings with the kept terms, as the
//! effects read it ([`Fitted`]; it is fitted and written out as a simulation file in
//! `extended.rs`, above the effects).

use super::maths::periodogram::Peak;
use super::model::PlanGuess;
use super::model_terms::Predictor;

/// The extended model's terms as the simulator has them.
pub(crate) struct Fitted {
    pub pred: Predictor,
    pub guess: PlanGuess,
    /// Hours per time unit (1, or the guessed plan's duration of a run).
    pub(crate) hours_per_unit: f64,
    /// Drift δ per time unit at the thermal origin.
    pub(crate) drift_rate: f64,
    /// Thermal growth γ, deviation per position unit per time unit.
    pub growth: f64,
    /// Where the thermal growth is zero.
    pub origin: f64,
    /// Run offsets, centred (empty without the term).
    pub run_offsets: Vec<f64>,
    /// Reversal value per target, and its mean.
    pub reversal: Vec<f64>,
    pub(crate) reversal_mean: f64,
    /// The shape of the reversal term (a line without it).
    pub(crate) reversal_shape: super::shape::Shape,
    /// The periodic term, when kept.
    pub periodic: Option<Peak>,
    /// Rows the fit used.
    pub(crate) train: Vec<bool>,
    /// The outliers the tests found: (row of `prep`, deleted residual).
    pub outliers: Vec<(usize, f64)>,
    /// The scatter σ at the first and last target, when the scatter test ran.
    pub(crate) scatter_ends: Option<(f64, f64)>,
    /// The scatter σ at each target in the shape of the kept term, when it is not a line.
    pub(crate) scatter_knots: Option<Vec<f64>>,
    /// Whether the warm-up's level changes along the axis (its growth term was found).
    pub(crate) warm_growth: bool,
}
