//! Effects in time: drift, warm-up, thermal growth and run offsets.
//!
//! Every fit has a fixed effect per cell (target, direction), so only what changes
//! *between the approaches of one cell* identifies a time effect; the systematic
//! deviation, the reversal and any periodic error are absorbed by the cell effects.
//! Terms (Hemingray et al. 1971, §5.4 and conclusion 1; ISO 230-2 clause 3.3):
//!
//! * drift: `β·t`, uniform along the axis;
//! * warm-up: `(a + g·(P − P̄))·(1 − exp(−(t − t₀)/τ))`, an exponential approach to a new
//!   level from the start of the test ([`super::warm`]);
//! * thermal growth: `γ·(P − P̄)·t`, proportional to position;
//! * run offsets: one constant per run (zero-point instability).
//!
//! With the standard test cycle and regular timing a drift *is* a linear trend of the run
//! effects, so the two are told apart by a decomposition of the between-run variation:
//! its linear part in time (drift, 1 degree of freedom) and what a straight line leaves
//! (run offsets), each tested against the pure scatter. The run offsets are tested beyond
//! the best warm-up curve as well, found or not: what a smooth curve in time explains is
//! no zero shift.
//! When the run offsets are real, a drift is judged against the run-to-run variation
//! instead (random run effects: only a trend larger than the zero shifts is a drift).
//! A warm-up, found by [`super::warm::search`], joins the smooth part: the run offsets are
//! then what the drift *and* the warm-up leave, so that a smooth approach in time is never
//! taken for zero shifts.
//!
//! The fit of the time model that these tests and the warm-up search share is in
//! `time_fit.rs`.

use super::maths::stats::{f_upper, t_two_sided};
use super::prep::Prep;
use super::time_fit::{CoefTest, DriftTest, Terms, TimeFit, fit};
use super::warm::{self, WarmEstimate, WarmTest};

/// Run offsets beyond the smooth model (a linear drift and a warm-up curve).
#[derive(Debug, Clone)]
pub(crate) struct RunTest {
    pub f: f64,
    pub df1: f64,
    pub df2: f64,
    pub p: f64,
    /// Run effects after the drift fit, centred (mean 0), per run.
    pub offsets: Vec<f64>,
}

/// The time tests on the active rows.
#[derive(Debug, Clone)]
pub(crate) struct TimeTests {
    /// Full model: thermal + run effects + drift, and the warm-up when found (the
    /// pure-error reference).
    pub full: TimeFit,
    /// The smooth part: thermal + drift, and the warm-up when found; no run effects.
    pub trend: TimeFit,
    pub sigma2: f64,
    pub df: f64,
    pub thermal: Option<CoefTest>,
    pub runs: Option<RunTest>,
    pub drift: Option<DriftTest>,
    /// The warm-up search (found when its `p` is below the level).
    pub warm: Option<WarmTest>,
}

impl TimeTests {
    /// The time constant of the warm-up when one is found at level `alpha`.
    pub fn warm_tau(&self, alpha: f64) -> Option<f64> {
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
            run_test(prep, &w.full, &w.smooth, w.full.sigma2(), w.full.df).map(|r| RunTest {
                offsets: run_offsets(prep, &out.trend),
                ..r
            })
        }
        None => run_test(prep, &out.full, &out.trend, sigma2, df),
    };
    let runs_real = out.runs.as_ref().is_some_and(|r| r.p < alpha);
    if warm_found {
        let reference = drift_reference(&out, runs_real);
        let beside =
            warm::linear_tests(prep, values, active, scale, (sigma2, df), reference, alpha);
        out.thermal = beside.thermal;
        out.drift = beside.drift;
        if let Some(w) = out.warm.as_mut() {
            w.estimate = beside.kept.and_then(|f| WarmEstimate::of(&f, (w.ms, w.df)));
        }
    } else {
        out.thermal = thermal_test(&out.full, sigma2, df);
        let thermal_found = out.thermal.as_ref().is_some_and(|t| t.p < alpha);
        out.drift = drift_test(prep, &out, runs_real, thermal_found);
    }
    if runs_real {
        let found = found_smooth(&out, alpha);
        let smooth = fit(prep, values, active, scale, found);
        if let Some(r) = out.runs.as_mut() {
            r.offsets = run_offsets(prep, &smooth);
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
    }
}

/// Thermal growth: γ in the full model, against the pure scatter.
fn thermal_test(full: &TimeFit, sigma2: f64, df: f64) -> Option<CoefTest> {
    let c = full.thermal_col.filter(|&c| full.ls.kept[c])?;
    let se = (sigma2 * full.ls.cov[c][c]).sqrt();
    let t = full.gamma / se;
    Some(CoefTest {
        estimate: full.gamma,
        se,
        t,
        p: t_two_sided(t, df),
        df,
    })
}

/// Run offsets: what the trend model leaves to the run effects of the full model.
fn run_test(prep: &Prep, full: &TimeFit, trend: &TimeFit, sigma2: f64, df: f64) -> Option<RunTest> {
    let df_lof = full.ls.rank as f64 - trend.ls.rank as f64;
    if df_lof < 1.0 {
        return None;
    }
    let ms = (trend.rss - full.rss).max(0.0) / df_lof;
    let f = ms / sigma2;
    Some(RunTest {
        f,
        df1: df_lof,
        df2: df,
        p: f_upper(f, df_lof, df),
        offsets: run_offsets(prep, trend),
    })
}

/// Run effects after the smooth model: its mean residual per run, centred.
fn run_offsets(prep: &Prep, trend: &TimeFit) -> Vec<f64> {
    let mut sum = vec![0.0; prep.n];
    let mut count = vec![0usize; prep.n];
    for &k in &trend.rows {
        sum[prep.rows[k].run] += trend.residuals[k];
        count[prep.rows[k].run] += 1;
    }
    let mut offsets: Vec<f64> = sum
        .iter()
        .zip(&count)
        .map(|(s, &c)| if c > 0 { s / c as f64 } else { 0.0 })
        .collect();
    let mean = offsets.iter().sum::<f64>() / offsets.len() as f64;
    for o in &mut offsets {
        *o -= mean;
    }
    offsets
}

/// What a drift is judged against: the scatter (mean square, degrees of freedom) or, when
/// the run offsets are real, the run-to-run variation the smooth model leaves.
pub(crate) fn drift_reference(tests: &TimeTests, runs_real: bool) -> (f64, f64, &'static str) {
    if runs_real {
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

/// Drift: the trend model's β (with γ), against the scatter or, when the run offsets are
/// real, against the run-to-run variation; with a thermal growth found, at its origin.
fn drift_test(
    prep: &Prep,
    tests: &TimeTests,
    runs_real: bool,
    thermal_found: bool,
) -> Option<DriftTest> {
    let trend = &tests.trend;
    let bc = trend.drift_col.filter(|&c| trend.ls.kept[c])?;
    let (err_ms, err_df, against) = drift_reference(tests, runs_real);
    let tc = trend.thermal_col.filter(|&c| trend.ls.kept[c]);
    let (estimate, var, origin) = match (thermal_found, tc) {
        (true, Some(gc)) if trend.gamma != 0.0 => {
            // The position where the time effect vanishes; a screw's fixed end lies at
            // (or near) the measured travel, so within a quarter of the travel beyond its
            // ends the effect is all thermal growth.
            let p0 = prep.pbar - trend.beta / trend.gamma;
            let margin = 0.25 * prep.length();
            let o = p0.clamp(prep.lo - margin, prep.hi + margin);
            let a = o - prep.pbar;
            let est = trend.beta + trend.gamma * a;
            let cov = &trend.ls.cov;
            let v = cov[bc][bc] + a * a * cov[gc][gc] + 2.0 * a * cov[bc][gc];
            (est, v, Some(o))
        }
        _ => (trend.beta, trend.ls.cov[bc][bc], None),
    };
    let se = (err_ms * var).sqrt();
    let (t, p) = if estimate == 0.0 {
        (0.0, 1.0)
    } else {
        let t = estimate / se;
        (t, t_two_sided(t, err_df))
    };
    Some(DriftTest {
        test: CoefTest {
            estimate,
            se,
            t,
            p,
            df: err_df,
        },
        origin,
        against,
    })
}
