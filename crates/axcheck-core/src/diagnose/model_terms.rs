//! The terms of a reading model and what a model fitted to training rows predicts
//! ([`Predictor`]): the data the effects switch and read. Fitting one (folds, the
//! per-fold tests of the terms) is `validate.rs`, above the effects.

use super::prep::Prep;
use super::shape::Shape;
use super::time_fit::TimeFit;

/// The terms of a model.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct ModelTerms {
    pub drift: bool,
    pub warm: bool,
    /// The warm-up's time constant when it is given (an unrelated curve's, fitted on all
    /// the readings); None: profiled on each fold's training readings.
    pub(crate) warm_tau: Option<f64>,
    pub thermal: bool,
    pub runs: bool,
    pub reversal: bool,
    /// The reversal's shape along the axis, with `reversal`.
    pub(crate) reversal_shape: Shape,
    pub outliers: bool,
    pub scatter: bool,
    /// The scatter's shape along the axis (log σ² a line, a curve or one per target),
    /// with `scatter`.
    pub(crate) scatter_shape: Shape,
}

/// A model fitted to training rows: its time model and what it has at the targets.
pub(crate) struct Predictor {
    pub time: TimeFit,
    pub lines: Lines,
}

/// What a model has at each target and cell beside its time model.
pub(crate) struct Lines {
    /// Bidirectional mean per target.
    pub mean: Vec<f64>,
    /// Reversal value per target as the model has it.
    pub reversal: Vec<f64>,
    /// Scatter σ per cell.
    pub sigma: Vec<f64>,
    /// Training readings per cell.
    pub count: Vec<usize>,
}

impl Predictor {
    /// The predicted reading of row `k`.
    pub(crate) fn predict(&self, prep: &Prep, k: usize) -> f64 {
        self.lines.predict(prep, &self.time, k)
    }
}

impl Lines {
    /// The predicted reading of row `k` with the time model `time`.
    pub(crate) fn predict(&self, prep: &Prep, time: &TimeFit, k: usize) -> f64 {
        let r = &prep.rows[k];
        self.mean[r.i] + r.sign * self.reversal[r.i] / 2.0 + time.effect(prep, k)
    }

    /// Predictive variance of a new reading in the cell of row `k`.
    pub(crate) fn variance(&self, prep: &Prep, k: usize) -> f64 {
        let c = prep.cell(&prep.rows[k]);
        let s = self.sigma[c];
        s * s * (1.0 + 1.0 / self.count[c].max(1) as f64)
    }
}
