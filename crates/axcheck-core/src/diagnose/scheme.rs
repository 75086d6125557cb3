//! The held-out schemes a term's gain is measured under, and the gain itself: read by
//! the selection of terms ([`super::select`]) and by the shaped terms
//! ([`super::shaped`]).

use super::validate::Score;
use serde::Serialize;

/// The held-out scheme that can show a term's gain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scheme {
    /// k-fold over readings (10 folds stratified by target and direction), RMS of the
    /// held-out readings: terms that change the readings (time, reversal, outliers).
    KFoldRms,
    /// The same folds, mean negative log predictive density per reading: a scatter term
    /// changes no prediction, only how sure it is.
    KFoldDensity,
    /// Leave-one-target-out on the target means, RMS: a periodic error costs between
    /// the targets, which a free mean per target hides from the readings.
    LeaveTargetsOut,
}

impl Scheme {
    /// The measure of a score this scheme compares (RMS or log density).
    pub(crate) fn measure(self, s: &Score) -> f64 {
        match self {
            Scheme::KFoldDensity => s.nlpd,
            _ => s.rms,
        }
    }

    /// The scheme in words, for the text and the report.
    pub fn describe(self) -> &'static str {
        match self {
            Scheme::KFoldRms => "k-fold over readings, RMS",
            Scheme::KFoldDensity => "k-fold over readings, log density",
            Scheme::LeaveTargetsOut => "leave-targets-out (h-block), RMS of the target means",
        }
    }
}

/// The gain of the scheme's measure from `without` to `with`, %.
pub(crate) fn gain_pct(scheme: Scheme, without: f64, with: f64) -> f64 {
    match scheme {
        Scheme::KFoldDensity => ((without - with).exp() - 1.0) * 100.0,
        _ => (without - with) / without * 100.0,
    }
}
