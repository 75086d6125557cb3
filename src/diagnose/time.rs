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

use super::linalg::{LeastSquares, least_squares};
use super::prep::Prep;
use super::stats::{f_upper, t_two_sided};
use super::warm::{self, WarmEstimate, WarmTest};

/// Which time terms a fit has.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Terms {
    pub thermal: bool,
    pub runs: bool,
    pub drift: bool,
    /// A warm-up with this time constant (time units): two columns, uniform and in
    /// proportion to position, after all the others.
    pub warm: Option<f64>,
}

/// The share of a warm-up reached `dt` after the start of the test: 1 − exp(−dt/τ).
pub(crate) fn warm_shape(dt: f64, tau: f64) -> f64 {
    -(-dt / tau).exp_m1()
}

/// A fit of the time model with cell fixed effects.
#[derive(Debug, Clone)]
pub(crate) struct TimeFit {
    pub ls: LeastSquares,
    /// Row indices (into `Prep::rows`) in fit order.
    pub rows: Vec<usize>,
    /// Drift rate β per time unit (0 when absent or collinear).
    pub beta: f64,
    /// Thermal coefficient γ: deviation per position unit per time unit (about P̄).
    pub gamma: f64,
    /// Run effects, run 0 the reference (0).
    pub alpha: Vec<f64>,
    /// Column of each term in `ls`.
    pub thermal_col: Option<usize>,
    pub drift_col: Option<usize>,
    /// Column of the uniform warm-up; the position-proportional one follows it.
    pub warm_col: Option<usize>,
    /// Warm-up: its time constant, the uniform level a and the level per position unit g
    /// (about P̄) that the deviations approach (0 without the term).
    pub tau: Option<f64>,
    pub warm_a: f64,
    pub warm_g: f64,
    /// Residual degrees of freedom: active rows − cells with rows − rank.
    pub df: f64,
    /// Residual sum of squares in scaled units.
    pub rss: f64,
    /// Per-cell intercept: mean of (value − time effect) over the cell's active rows.
    pub intercepts: Vec<f64>,
    /// Residual per row (unscaled; NaN for inactive rows).
    pub residuals: Vec<f64>,
}

impl TimeFit {
    /// The time effect (without the cell intercept) at a row.
    pub fn effect(&self, prep: &Prep, k: usize) -> f64 {
        let (r, c) = (&prep.rows[k], &prep.clocks);
        let p = prep.positions[r.i] - prep.pbar;
        let mut e = self.beta * c.drift[k] + self.gamma * p * c.thermal[k];
        let run = c.run[k];
        if run > 0 && !self.alpha.is_empty() {
            e += self.alpha[run];
        }
        if let Some(tau) = self.tau {
            let level = self.warm_a + self.warm_g * p;
            e += level * warm_shape(c.warm[k], tau);
        }
        e
    }

    /// σ² estimate (scaled units): RSS/df.
    pub fn sigma2(&self) -> f64 {
        if self.df > 0.0 {
            self.rss / self.df
        } else {
            f64::NAN
        }
    }
}

/// Demeaning within cells and weighting by 1/scale, over the rows of a fit: what every
/// column and the values go through before the least squares.
pub(crate) struct CellDemean<'a> {
    cell_of: Vec<usize>,
    count: Vec<usize>,
    scale: &'a [f64],
}

impl<'a> CellDemean<'a> {
    pub fn new(prep: &Prep, rows: &[usize], scale: &'a [f64]) -> CellDemean<'a> {
        let cell_of: Vec<usize> = rows.iter().map(|&k| prep.cell(&prep.rows[k])).collect();
        let mut count = vec![0usize; prep.cells()];
        for &c in &cell_of {
            count[c] += 1;
        }
        CellDemean {
            cell_of,
            count,
            scale,
        }
    }

    /// `v` (one value per fit row) minus its cell means, divided by the cell's scale.
    pub fn apply(&self, v: &[f64]) -> Vec<f64> {
        let mut sum = vec![0.0; self.count.len()];
        for (x, &c) in v.iter().zip(&self.cell_of) {
            sum[c] += x;
        }
        v.iter()
            .zip(&self.cell_of)
            .map(|(x, &c)| (x - sum[c] / self.count[c] as f64) / self.scale[c])
            .collect()
    }
}

/// The two warm-up columns at τ over `rows`, raw: the share reached, and that times the
/// position about P̄.
pub(crate) fn warm_columns(prep: &Prep, rows: &[usize], tau: f64) -> [Vec<f64>; 2] {
    let shape: Vec<f64> = rows
        .iter()
        .map(|&k| warm_shape(prep.clocks.warm[k], tau))
        .collect();
    let growth = rows
        .iter()
        .zip(&shape)
        .map(|(&k, e)| (prep.positions[prep.rows[k].i] - prep.pbar) * e)
        .collect();
    [shape, growth]
}

/// Fits `values` (one per row) over the `active` rows with cell effects and `terms`;
/// `scale` is a relative scatter per cell (rows are weighted by 1/scale²).
pub(crate) fn fit(
    prep: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    terms: Terms,
) -> TimeFit {
    let cells = prep.cells();
    let rows: Vec<usize> = (0..prep.rows.len()).filter(|&k| active[k]).collect();
    let Regressors {
        raw,
        thermal_col,
        drift_col,
        warm_col,
        run_cols,
    } = Regressors::of(prep, &rows, terms);
    // Demean within cells, then weight.
    let dm = CellDemean::new(prep, &rows, scale);
    let (cell_of, count) = (&dm.cell_of, &dm.count);
    let y: Vec<f64> = rows.iter().map(|&k| values[k]).collect();
    let cols: Vec<Vec<f64>> = raw.iter().map(|c| dm.apply(c)).collect();
    let ls = least_squares(&cols, &dm.apply(&y));
    let cells_used = count.iter().filter(|&&c| c > 0).count();
    let df = rows.len() as f64 - cells_used as f64 - ls.rank as f64;
    let beta = drift_col.map_or(0.0, |c| ls.coef[c]);
    let gamma = thermal_col.map_or(0.0, |c| ls.coef[c]);
    let (warm_a, warm_g) = warm_col.map_or((0.0, 0.0), |c| (ls.coef[c], ls.coef[c + 1]));
    let mut alpha = Vec::new();
    if terms.runs {
        alpha = vec![0.0; prep.n];
        for (j, &c) in run_cols.iter().enumerate() {
            alpha[j + 1] = ls.coef[c];
        }
    }
    // Intercepts and residuals.
    let mut fitted_raw = vec![0.0; rows.len()];
    for (col, b) in raw.iter().zip(&ls.coef) {
        for (f, x) in fitted_raw.iter_mut().zip(col) {
            *f += b * x;
        }
    }
    let intercepts = intercepts(&y, &fitted_raw, cell_of, count, cells);
    let mut residuals = vec![f64::NAN; prep.rows.len()];
    for (idx, &k) in rows.iter().enumerate() {
        residuals[k] = ls.residuals[idx] * scale[cell_of[idx]];
    }
    let rss = ls.rss;
    TimeFit {
        ls,
        rows,
        beta,
        gamma,
        alpha,
        thermal_col,
        drift_col,
        warm_col,
        tau: terms.warm,
        warm_a,
        warm_g,
        df,
        rss,
        intercepts,
        residuals,
    }
}

/// The raw regressors of a fit, one column a term, and where each term's columns are.
struct Regressors {
    raw: Vec<Vec<f64>>,
    thermal_col: Option<usize>,
    drift_col: Option<usize>,
    warm_col: Option<usize>,
    run_cols: Vec<usize>,
}

impl Regressors {
    /// The columns of `terms` over `rows`: thermal growth, the run offsets (run 0 the
    /// reference), the drift, the warm-up.
    fn of(prep: &Prep, rows: &[usize], terms: Terms) -> Regressors {
        let mut r = Regressors {
            raw: Vec::new(),
            thermal_col: None,
            drift_col: None,
            warm_col: None,
            run_cols: Vec::new(),
        };
        let c = &prep.clocks;
        if terms.thermal {
            r.thermal_col = Some(r.raw.len());
            r.raw.push(
                rows.iter()
                    .map(|&k| (prep.positions[prep.rows[k].i] - prep.pbar) * c.thermal[k])
                    .collect(),
            );
        }
        if terms.runs {
            for j in 1..prep.n {
                r.run_cols.push(r.raw.len());
                r.raw.push(
                    rows.iter()
                        .map(|&k| if c.run[k] == j { 1.0 } else { 0.0 })
                        .collect(),
                );
            }
        }
        if terms.drift {
            r.drift_col = Some(r.raw.len());
            r.raw.push(rows.iter().map(|&k| c.drift[k]).collect());
        }
        if let Some(tau) = terms.warm {
            r.warm_col = Some(r.raw.len());
            r.raw.extend(warm_columns(prep, rows, tau));
        }
        r
    }
}

/// Each cell's intercept: the mean of its values less the fitted terms.
fn intercepts(
    y: &[f64],
    fitted_raw: &[f64],
    cell_of: &[usize],
    count: &[usize],
    cells: usize,
) -> Vec<f64> {
    let mut sum = vec![0.0; cells];
    for ((yv, f), &c) in y.iter().zip(fitted_raw).zip(cell_of) {
        sum[c] += yv - f;
    }
    (0..cells)
        .map(|c| {
            if count[c] > 0 {
                sum[c] / count[c] as f64
            } else {
                f64::NAN
            }
        })
        .collect()
}

/// A coefficient's test.
#[derive(Debug, Clone)]
pub(crate) struct CoefTest {
    pub estimate: f64,
    pub se: f64,
    pub t: f64,
    pub p: f64,
    pub df: f64,
}

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

/// Drift, after thermal growth.
#[derive(Debug, Clone)]
pub(crate) struct DriftTest {
    pub test: CoefTest,
    /// The thermal origin chosen when thermal growth is present: the drift is the time
    /// effect there.
    pub origin: Option<f64>,
    /// What the drift was tested against: `scatter` or `run-to-run variation`.
    pub against: &'static str,
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
