//! The time model fitted by least squares beside a fixed effect per cell: which terms a
//! fit has ([`Terms`]), the fit itself ([`fit`], [`TimeFit`]) and a coefficient's test; the
//! tests in time (`time.rs`) and the warm-up search (`warm.rs`) both read it.

use super::maths::linalg::{LeastSquares, least_squares};
use super::maths::stats::t_two_sided;
use super::prep::Prep;

/// Which time terms a fit has.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct Terms {
    pub thermal: bool,
    pub runs: bool,
    pub drift: bool,
    /// A warm-up with this time constant (time units): two columns, uniform and in
    /// proportion to position, after all the others.
    pub warm: Option<f64>,
    /// The thermal growth about this origin instead of about P̄: γ·(P − O)·t, which holds
    /// the time effect still at O (a declared origin without a drift beside it).
    pub(crate) thermal_about: Option<f64>,
}

/// The share of a warm-up reached `dt` after the start of the test: 1 − exp(−dt/τ).
pub(crate) fn warm_shape(dt: f64, tau: f64) -> f64 {
    -(-dt / tau).exp_m1()
}

/// A fit of the time model with cell fixed effects.
#[derive(Debug, Clone)]
pub(crate) struct TimeFit {
    pub(crate) ls: LeastSquares,
    /// Row indices (into `Prep::rows`) in fit order.
    pub rows: Vec<usize>,
    /// Drift rate β per time unit (0 when absent or collinear; with `thermal_about` it
    /// holds the growth's uniform part γ (P̄ − O), so that [`TimeFit::effect`] stays whole).
    pub(crate) beta: f64,
    /// Thermal coefficient γ: deviation per position unit per time unit (about P̄).
    pub(crate) gamma: f64,
    /// Run effects, run 0 the reference (0).
    pub alpha: Vec<f64>,
    /// Column of each term in `ls`.
    pub(crate) thermal_col: Option<usize>,
    pub(crate) drift_col: Option<usize>,
    /// Column of the uniform warm-up; the position-proportional one follows it.
    pub(crate) warm_col: Option<usize>,
    /// Warm-up: its time constant, the uniform level a and the level per position unit g
    /// (about P̄) that the deviations approach (0 without the term).
    pub tau: Option<f64>,
    pub(crate) warm_a: f64,
    pub(crate) warm_g: f64,
    /// Residual degrees of freedom: active rows − cells with rows − rank.
    pub df: f64,
    /// Residual sum of squares in scaled units.
    pub(crate) rss: f64,
    /// Per-cell intercept: mean of (value − time effect) over the cell's active rows.
    pub(crate) intercepts: Vec<f64>,
    /// Residual per row (unscaled; NaN for inactive rows).
    pub residuals: Vec<f64>,
}

impl TimeFit {
    /// The drift at `origin` when both the drift and the thermal columns are kept:
    /// β + γ (origin − P̄) and its variance in units of the mean square (from (XᵀX)⁻¹).
    pub(crate) fn drift_at(&self, prep: &Prep, origin: f64) -> Option<(f64, f64)> {
        let kept = |c: &usize| self.ls.kept[*c];
        let (bc, gc) = (self.drift_col.filter(kept)?, self.thermal_col.filter(kept)?);
        let a = origin - prep.pbar;
        let cov = &self.ls.cov;
        let var = cov[bc][bc] + a * a * cov[gc][gc] + 2.0 * a * cov[bc][gc];
        Some((self.beta + self.gamma * a, var))
    }

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
    pub(crate) fn sigma2(&self) -> f64 {
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
    let gamma = thermal_col.map_or(0.0, |c| ls.coef[c]);
    // A growth about O is one about P̄ plus the uniform trend γ (P̄ − O) (the drift's and
    // the growth's clocks are the same time about its mean).
    let about = terms.thermal_about.map_or(0.0, |o| gamma * (prep.pbar - o));
    let beta = drift_col.map_or(0.0, |c| ls.coef[c]) + about;
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
            let origin = terms.thermal_about.unwrap_or(prep.pbar);
            r.raw.push(
                rows.iter()
                    .map(|&k| (prep.positions[prep.rows[k].i] - origin) * c.thermal[k])
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

impl CoefTest {
    /// The two-sided t test of `estimate` with variance `var` (in units of the reference
    /// mean square `ms`) on `df` degrees of freedom; t = 0, p = 1 for a zero estimate.
    pub fn of(estimate: f64, var: f64, (ms, df): (f64, f64)) -> CoefTest {
        let se = (ms * var).sqrt();
        let (t, p) = if estimate == 0.0 {
            (0.0, 1.0)
        } else {
            let t = estimate / se;
            (t, t_two_sided(t, df))
        };
        CoefTest {
            estimate,
            se,
            t,
            p,
            df,
        }
    }
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
