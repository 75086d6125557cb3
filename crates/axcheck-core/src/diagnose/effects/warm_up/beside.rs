//! The linear time terms beside a warm-up found: a thermal growth (against the pure
//! scatter) and a drift (against the drift's reference), each tested with τ profiled again
//! with and without it; at a declared thermal origin the drift is the trend there, tested
//! against the growth held still at the origin.

use super::profiled;
use crate::diagnose::maths::stats::f_upper;
use crate::diagnose::prep::Prep;
use crate::diagnose::time_fit::{CoefTest, DriftTest, Terms, TimeFit};

/// Drift and thermal growth beside a warm-up, and the fit of the warm-up with the linear
/// terms found.
pub(crate) struct Beside {
    pub thermal: Option<CoefTest>,
    pub drift: Option<DriftTest>,
    pub kept: Option<TimeFit>,
}

/// A linear term beside a warm-up: the fall of the residual sum of squares when it joins,
/// τ profiled again with and without it (a τ chosen with the term's help would flatter
/// it), as a t test of the term's coefficient `estimate`.
fn beside_test(
    without: &TimeFit,
    with: &TimeFit,
    estimate: f64,
    reference: (f64, f64),
) -> CoefTest {
    let (ms, df) = reference;
    let f = (without.rss - with.rss).max(0.0) / ms;
    let t = f.sqrt() * estimate.signum();
    CoefTest {
        estimate,
        se: if f > 0.0 {
            estimate.abs() / f.sqrt()
        } else {
            f64::INFINITY
        },
        t,
        p: f_upper(f, 1.0, df),
        df,
    }
}

/// Thermal growth (against the pure scatter `pure`) and drift (against `drift_ref`, as
/// [`crate::diagnose::time::drift_reference`] gives it) beside a warm-up found, and the warm-up's
/// fit with the linear terms found: thermal growth with a drift beside it, the drift with
/// the thermal growth when found.
pub(crate) fn linear_tests(
    prep: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    pure: (f64, f64),
    drift_ref: (f64, f64, &'static str),
    alpha: f64,
) -> Beside {
    let prof_about = |thermal: bool, drift: bool, thermal_about: Option<f64>| {
        let terms = Terms {
            thermal,
            drift,
            thermal_about,
            ..Terms::default()
        };
        profiled(prep, values, active, scale, terms)
    };
    let prof = |thermal: bool, drift: bool| prof_about(thermal, drift, None);
    let (Some(drift_only), Some(both)) = (prof(false, true), prof(true, true)) else {
        return Beside {
            thermal: None,
            drift: None,
            kept: None,
        };
    };
    let thermal = both
        .thermal_col
        .filter(|&c| both.ls.kept[c])
        .map(|_| beside_test(&drift_only, &both, both.gamma, pure));
    let thermal_found = thermal.as_ref().is_some_and(|t| t.p < alpha);
    let (ms, df, against) = drift_ref;
    // At a declared origin: β + γ (origin − P̄) from the fit with both linear terms, as
    // `drift::test` has it without a warm-up, tested as the others here are, by the fall
    // of the sum of squares from the growth held still at the origin, τ profiled again
    // (with the drift's help τ bends the curve so that the trend at the origin looks
    // larger than the readings make it).
    let declared = (prep.thermal_origin).and_then(|o| {
        let (estimate, _) = both.drift_at(prep, o)?;
        let held = prof_about(true, false, Some(o))?;
        Some(DriftTest {
            test: beside_test(&held, &both, estimate, (ms, df)),
            origin: Some(o),
            against,
        })
    });
    let with_drift = if thermal_found { both } else { drift_only };
    let without = prof(thermal_found, false);
    let drift = declared.or_else(|| {
        without.as_ref().and_then(|w| {
            let c = with_drift.drift_col.filter(|&c| with_drift.ls.kept[c])?;
            Some(DriftTest {
                test: beside_test(w, &with_drift, with_drift.ls.coef[c], (ms, df)),
                origin: None,
                against,
            })
        })
    });
    let drift_found = drift.as_ref().is_some_and(|d| d.test.p < alpha);
    Beside {
        thermal,
        drift,
        kept: if drift_found {
            Some(with_drift)
        } else {
            without
        },
    }
}
