//! Effects in time: drift, warm-up, thermal growth and run offsets.
//!
//! Every fit has a fixed effect per cell (target, direction), so only what changes
//! *between the approaches of one cell* identifies a time effect; the systematic
//! deviation, the reversal and any periodic error are absorbed by the cell effects.
//! Terms (Hemingray et al. 1971, §5.4 and conclusion 1; ISO 230-2 clause 3.3):
//!
//! * drift: `β·t`, uniform along the axis;
//! * warm-up: `(a + g·(P − P̄))·(1 − exp(−(t − t₀)/τ))`, an exponential approach to a new
//!   level from the start of the test ([`super::effects::warm_up`]);
//! * thermal growth: `γ·(P − P̄)·t`, proportional to position;
//! * run offsets: one constant per run (zero-point instability).
//!
//! With the standard test cycle and regular timing a drift *is* a linear trend of the run
//! effects, so the two are told apart by a decomposition of the between-run variation:
//! its linear part in time (drift, 1 degree of freedom) and what a straight line leaves
//! (run offsets), each tested against the pure scatter. The run offsets are tested beyond
//! the best warm-up curve as well, found or not: what a smooth curve in time explains is
//! no zero shift. A curve at the longest time constant searched is barely bent, one more
//! trend of the run means: it is no warm-up when free run offsets explain the readings
//! better by BIC and are not found beyond it.
//! When the run offsets are real, a drift is judged against the run-to-run variation
//! instead (random run effects: only a trend larger than the zero shifts is a drift).
//! A warm-up, found by [`super::effects::warm_up::search`], joins the smooth part: the run offsets are
//! then what the drift *and* the warm-up leave, so that a smooth approach in time is never
//! taken for zero shifts.
//!
//! The fit of the time model that these tests and the warm-up search share is in
//! `time_fit.rs`.

use super::effects::run_offset::{self, RunTest};
use super::effects::warm_up::{self as warm, WarmEstimate, WarmTest};
use super::effects::{drift, thermal_growth};
use super::prep::Prep;
use super::time_fit::{CoefTest, DriftTest, Terms, TimeFit, fit};

/// The time tests on the active rows.
#[derive(Debug, Clone)]
pub(crate) struct TimeTests {
    /// Full model: thermal + run effects + drift, and the warm-up when found (the
    /// pure-error reference).
    pub full: TimeFit,
    /// The smooth part: thermal + drift, and the warm-up when found; no run effects.
    pub trend: TimeFit,
    pub(crate) sigma2: f64,
    pub df: f64,
    pub thermal: Option<CoefTest>,
    pub runs: Option<RunTest>,
    pub drift: Option<DriftTest>,
    /// The warm-up search (found when its `p` is below the level).
    pub warm: Option<WarmTest>,
}

impl TimeTests {
    /// The time constant of the warm-up when one is found at level `alpha`.
    pub(crate) fn warm_tau(&self, alpha: f64) -> Option<f64> {
        self.warm.as_ref().filter(|w| w.p < alpha).map(|w| w.tau)
    }
}

/// Runs the tests at level `alpha` each; a significant warm-up joins the smooth part and
/// the full model, and a significant thermal growth decides how the drift is read (see
/// [`DriftTest::origin`]).
pub(crate) fn tests(
    prep: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    alpha: f64,
) -> TimeTests {
    let all = Terms {
        thermal: true,
        runs: true,
        drift: true,
        warm: None,
        thermal_about: None,
    };
    let full = fit(prep, values, active, scale, all);
    let no_runs = Terms { runs: false, ..all };
    let trend = fit(prep, values, active, scale, no_runs);
    let df = full.df;
    let sigma2 = full.sigma2();
    let mut out = TimeTests {
        thermal: None,
        runs: None,
        drift: None,
        warm: None,
        sigma2,
        df,
        full,
        trend,
    };
    if !(df >= 1.0 && sigma2 > 0.0) {
        return out;
    }
    out.warm = warm::search(prep, values, active, scale, (&out.full, &out.trend), alpha);
    let warm_found = out.warm.as_ref().is_some_and(|w| w.p < alpha);
    if let Some(w) = out.warm.as_ref().filter(|_| warm_found) {
        out.full = w.full.clone();
        out.trend = w.smooth.clone();
        out.sigma2 = out.full.sigma2();
        out.df = out.full.df;
    }
    let (sigma2, df) = (out.sigma2, out.df);
    // Run offsets are what no smooth curve in time explains: tested beyond the linear
    // trend with the best warm-up curve, found or not, so that a curvature of the run
    // means is never taken for zero shifts; their sizes are what the smooth terms found
    // leave (below).
    out.runs = match out.warm.as_ref() {
        Some(w) => {
            run_offset::test(prep, &w.full, &w.smooth, w.full.sigma2(), w.full.df).map(|r| {
                RunTest {
                    offsets: run_offset::offsets(prep, &out.trend),
                    ..r
                }
            })
        }
        None => run_offset::test(prep, &out.full, &out.trend, sigma2, df),
    };
    let runs_real = out.runs.as_ref().is_some_and(|r| r.p < alpha);
    if warm_found {
        // Beside a warm-up the run means have given the curve its level and time
        // constant, and the few left are pooled with the scatter only where they show no
        // variation of their own ([`POOL`]).
        let runs_vary = out.runs.as_ref().is_some_and(|r| r.p < POOL);
        let reference = drift_reference(&out, runs_vary);
        let beside =
            warm::linear_tests(prep, values, active, scale, (sigma2, df), reference, alpha);
        out.thermal = beside.thermal;
        out.drift = beside.drift;
        if let Some(w) = out.warm.as_mut() {
            w.estimate = beside.kept.and_then(|f| WarmEstimate::of(&f, (w.ms, w.df)));
        }
    } else {
        out.thermal = thermal_growth::test(&out.full, sigma2, df);
        let thermal_found = out.thermal.as_ref().is_some_and(|t| t.p < alpha);
        out.drift = drift::test(
            prep,
            &out.trend,
            drift_reference(&out, runs_real),
            thermal_found,
        );
    }
    if runs_real {
        let found = found_smooth(&out, alpha);
        let smooth = fit(prep, values, active, scale, found);
        if let Some(r) = out.runs.as_mut() {
            r.offsets = run_offset::offsets(prep, &smooth);
        }
    }
    out
}

/// The smooth terms the tests find: run offsets are sized by what these leave, not by
/// what a drift fitted but not found would take (the straight line through the offsets,
/// which made the offsets of random runs look smaller than they are).
fn found_smooth(out: &TimeTests, alpha: f64) -> Terms {
    let found = |p: Option<f64>| p.is_some_and(|p| p < alpha);
    let thermal = found(out.thermal.as_ref().map(|t| t.p));
    Terms {
        thermal,
        runs: false,
        drift: thermal || found(out.drift.as_ref().map(|d| d.test.p)),
        warm: out.warm_tau(alpha),
        thermal_about: None,
    }
}

/// The level below which the run-to-run variation beside a warm-up is not pooled with the
/// scatter as a drift's reference. A drift is a trend of the run means, so its standard
/// error is the run-to-run variation's; the scatter, with its many more degrees of
/// freedom, may stand in only where the runs show no variation of their own. Whether they
/// do is a pretest of the reference, not a finding, and is made at the level that keeps
/// the drift's test near its nominal size: 25 % (Bozivich, Bancroft & Hartley 1956, "Power
/// of analysis of variance test procedures for certain incompletely specified models",
/// Ann. Math. Statist. 27, on "sometimes pooling"). At the findings' 0.1 % the run offsets
/// of 5–7 runs beside a warm-up were pooled as scatter, and what the curve left of them
/// was named a drift (4 of 200 axes of the sweep's warm-up + run offsets).
///
/// Without a warm-up the pretest stays at the findings' level: there a drift not found
/// leaves its course within the runs to the cells, where under the standard cycle it reads
/// as a reversal that varies along the axis (ISO 230-2 Annex A), and a drift beside run
/// offsets was then named so in 5 % of the sweep's axes instead of 1 %.
const POOL: f64 = 0.25;

/// What a drift is judged against: the scatter (mean square, degrees of freedom) or, when
/// the run means vary beyond the smooth model (at [`POOL`]), the run-to-run variation the
/// smooth model leaves.
pub(crate) fn drift_reference(tests: &TimeTests, runs_vary: bool) -> (f64, f64, &'static str) {
    if runs_vary {
        let df_lof_v = tests.runs.as_ref().map_or(1.0, |r| r.df1);
        (
            (tests.trend.rss - tests.full.rss).max(0.0) / df_lof_v,
            df_lof_v,
            "run-to-run variation",
        )
    } else {
        (tests.sigma2, tests.df, "scatter")
    }
}
