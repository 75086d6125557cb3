//! Scatter variation: the scatter changes along the axis. VDI 3441 takes one scatter for
//! the whole axis, NMTBA one per target; Hemingray et al. 1971, §5.1 ask whether the
//! variation of the scatter along the axis is more than sampling explains.
//! Test ([`test()`]): the score test of a log-linear scatter in position on each
//! cell's residual sum of squares (residuals of the full time model, so that drift or
//! thermal growth do not pass for scatter), its tail exact for normal readings. Needs
//! n ≥ 3 and m ≥ 3. The term that confirms it takes the shape the data show (a line of
//! log σ², a curve, or one σ per target as NMTBA has it), chosen by held-out density
//! ([`super::super::shaped`]); a scatter that is large at one end in a step is one σ per
//! target, which a line smooths over.

use super::{Effect, Estimate, Finding, Rule as EffectRule, Term, Unrelated, WARM_UP_UNTESTED};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, POWER, plan_words};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, per_target_list};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::imhof;
use crate::diagnose::maths::linalg::least_squares;
use crate::diagnose::maths::stats::root_decreasing;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::shape::Shape;
use crate::diagnose::time_fit::TimeFit;
use crate::measurement::fmt_target;

/// A scatter σ that changes along the axis (log-linearly in position).
#[derive(Debug, Clone, PartialEq)]
pub struct ScatterVariation {
    /// Fitted σ at the first and last target, deviation unit.
    pub start: f64,
    pub end: f64,
    /// end / start.
    pub ratio: f64,
    /// The shape the held-out prediction chose (None: not judged).
    pub fitted_shape: Option<Shape>,
    /// σ per target as measured: (position, σ), deviation unit.
    pub per_target: Vec<(f64, f64)>,
    /// Beside real run offsets this plan could not test a warm-up, whose course within the
    /// first runs would widen the scatter along the axis as well ([`UNTESTED_WARM_UP`]).
    pub(crate) warm_up_untested: bool,
}

/// What a finding adds when the plan could not test a warm-up beside the run offsets: in
/// the standard cycle the readings at a target lie at times that differ along the axis,
/// so a curve in time within the first runs spreads them by amounts that change along it
/// (the reversal variation's finding says the same of Bi).
const UNTESTED_WARM_UP: &str = "; beside these run offsets this plan cannot test a warm-up, and a machine still warming up in the first runs would widen the scatter unevenly along the axis as well (its approaches to a target lie at times that differ along the axis)";

impl Fields for ScatterVariation {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let du = u.dev();
        let per_target = (self.per_target.iter().enumerate())
            .filter(|_| self.fitted_shape == Some(Shape::PerTarget))
            .map(|(i, (_, sigma))| (format!("scatter_target_{}_{du}", i + 1), *sigma));
        vec![
            (format!("scatter_start_{du}"), self.start),
            (format!("scatter_end_{du}"), self.end),
            ("ratio_end_to_start".into(), self.ratio),
        ]
        .into_iter()
        .chain(per_target)
        .collect()
    }

    fn advice(&self, u: Units) -> String {
        let first = if self.warm_up_untested {
            "re-test the warm machine (ISO 230-2 3.3) before looking for a mechanical cause, since a warm-up this plan could not test would make the scatter vary too; "
        } else {
            ""
        };
        let per_target = (self.fitted_shape == Some(Shape::PerTarget))
            .then(|| self.worst_target(u))
            .flatten();
        format!(
            "{first}{}: look for a mechanical cause there (screw support bearing, guideway or its lubrication, scale mounting); no compensation reduces scatter",
            per_target.unwrap_or_else(|| self.towards_an_end(u))
        )
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        let mut labels = Vec::new();
        if let Some(shape) = self.fitted_shape.filter(|s| *s != Shape::Line) {
            labels.push(("fitted_shape", shape.name()));
        }
        if self.warm_up_untested {
            labels.push(WARM_UP_UNTESTED);
        }
        labels
    }
}

impl ScatterVariation {
    /// The estimate in the shape the held-out prediction chose; in a shape other than a
    /// line the message lists σ at every target.
    pub(crate) fn reshape(f: &mut Finding, shape: Shape) {
        let Estimate::ScatterVariation(s) = &mut f.estimate else {
            return;
        };
        s.fitted_shape = Some(shape);
        if shape == Shape::Line {
            return;
        }
        f.message = format!(
            "the scatter changes {}: σ ≈ {} (z = {}, p = {}){}",
            shape.changes(),
            per_target_list(&s.per_target, f.units),
            fmt(f.evidence.value),
            fmt_p(f.evidence.p_value.unwrap_or(f64::NAN)),
            untested_words(s.warm_up_untested)
        );
    }

    /// Where the scatter is one value per target: the worst target against the median
    /// (None without a value).
    fn worst_target(&self, u: Units) -> Option<String> {
        let mut sigmas: Vec<f64> = self.per_target.iter().map(|t| t.1).collect();
        sigmas.sort_by(f64::total_cmp);
        let median = *sigmas.get(sigmas.len() / 2)?;
        let worst = (self.per_target.iter()).fold((f64::NAN, f64::NEG_INFINITY), |w, t| {
            if t.1 > w.1 { *t } else { w }
        });
        Some(format!(
            "the repeatability is worst at {} (σ {} {ds}, {}× the median target's {} {ds})",
            fmt_target(u.kind, worst.0),
            fmt(worst.1),
            fmt(worst.1 / median),
            fmt(median),
            ds = u.symbol()
        ))
    }

    /// Where the scatter changes along a line or a curve: towards which end, how much.
    fn towards_an_end(&self, u: Units) -> String {
        let (worse, ratio) = if self.end >= self.start {
            ("last", self.ratio)
        } else {
            ("first", 1.0 / self.ratio)
        };
        format!(
            "the repeatability is {}× worse towards the {worse} target (σ {} → {} {})",
            fmt(ratio),
            fmt(self.start),
            fmt(self.end),
            u.symbol()
        )
    }
}

/// [`UNTESTED_WARM_UP`] where the plan could not test the warm-up, else nothing.
fn untested_words(warm_up_untested: bool) -> &'static str {
    match warm_up_untested {
        true => UNTESTED_WARM_UP,
        false => "",
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    /// `warm_up_untested`: beside real run offsets the plan could not test a warm-up.
    pub(crate) fn find(
        &self,
        a: &Basis,
        scatter: Option<&ScatterTest>,
        warm_up_untested: bool,
    ) -> Vec<Finding> {
        let Some(s) = scatter.filter(|s| s.p < ALPHA) else {
            return Vec::new();
        };
        let (u, p) = (a.units, &a.prep);
        let ds = u.symbol();
        let ratio = s.sigma_hi / s.sigma_lo;
        let message = format!(
            "the scatter changes along the axis: σ ≈ {} {ds} at {} to {} {ds} at {} (z = {}, p = {}){}",
            fmt(s.sigma_lo),
            fmt_target(u.kind, p.lo),
            fmt(s.sigma_hi),
            fmt_target(u.kind, p.hi),
            fmt(s.z),
            fmt_p(s.p),
            untested_words(warm_up_untested)
        );
        vec![Finding {
            estimate: ScatterVariation {
                start: s.sigma_lo,
                end: s.sigma_hi,
                ratio,
                fitted_shape: None,
                per_target: (p.positions.iter().zip(&s.per_target))
                    .filter(|(_, sigma)| sigma.is_finite())
                    .map(|(p, sigma)| (*p, *sigma))
                    .collect(),
                warm_up_untested,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic: format!(
                    "score z of a log-linear scatter along the axis (exact tail, {} cells)",
                    s.cells
                ),
                value: s.z,
                p_value: Some(s.p),
                effect_size: Some(ratio),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    /// log σ² along the axis on a line (the test's log-linear scatter), a curve, or one
    /// value per target (NMTBA's scatter per target; Hemingray et al. 1971, §5.1),
    /// whichever predicts held-out readings' density best.
    fn term(&self) -> Term {
        Term::ShapedDensity(|t, shape| {
            t.scatter = true;
            t.scatter_shape = shape;
        })
    }

    /// Compared with tests simulated without it, each in its best shape (on 5 targets a
    /// random order fits a line as the real one, or its reverse, one time in 60, and one
    /// value per target is the same term in every order).
    fn unrelated(&self) -> Unrelated {
        Unrelated::SimulatedTests
    }

    /// A line as σ at both ends; another shape as σ at every target.
    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        if let Some(knots) = &fit.scatter_knots {
            model.scatter_knots = (a.prep.positions.iter().zip(knots))
                .map(|(p, s)| [*p, r4(*s)])
                .collect();
            return;
        }
        if let Some((lo, hi)) = fit.scatter_ends {
            model.scatter = r4(lo);
            model.scatter_end = Some(r4(hi));
        }
    }

    /// A scatter cannot be subtracted from the readings.
    fn removed(&self, _: &Basis, _: &Fitted) -> Option<Vec<f64>> {
        None
    }
}

/// The result of the scatter test.
#[derive(Debug, Clone)]
pub(crate) struct ScatterTest {
    /// The score of the log slope over its standard error.
    pub z: f64,
    pub p: f64,
    /// Cells with at least two readings.
    pub cells: usize,
    /// Fitted scatter σ at the first and last target, µm or arcsec.
    pub(crate) sigma_lo: f64,
    pub(crate) sigma_hi: f64,
    /// Relative scatter per cell (σ(P)/σ̄; mean square 1).
    pub(crate) rel_scale: Vec<f64>,
    /// σ per target as measured (√(Σ SS / Σ ν) over its cells; NaN without one).
    pub(crate) per_target: Vec<f64>,
}

/// The scatter per cell relative to √`sigma2` for the outlier test once a scatter variation
/// is found: the larger of the fitted log-linear scale and each target's own scale, so
/// that a scatter that changes in a step, which a log-linear fit smooths over, does not
/// make outliers of the readings where it is large.
///
/// A target's own scale is the root mean square of its readings but the largest (in both
/// directions, each direction's mean taken out): for that reading, the one an outlier
/// test of the target looks at, it is the scatter of the others, which the reading itself
/// does not inflate, as the externally studentised residual has it. It rests on a dozen
/// readings; a median of them (as before) rests on fewer in effect and came out low one
/// time in five where the scatter is large, just where its largest reading then looks
/// extreme. Its neighbours' readings with its own steady it.
///
/// Every reading counts, those a first pass took for outliers too (its residual from the
/// fit `full` of the others): with the scatter not yet modelled, that pass takes the
/// largest readings where the scatter is large, and leaving them out would shrink the
/// scale exactly there.
pub(crate) fn outlier_scale(prep: &Prep, t: &ScatterTest, full: &TimeFit, x: &[f64]) -> Vec<f64> {
    let mut by_target: Vec<Vec<f64>> = vec![Vec::new(); prep.m];
    for (k, r) in prep.rows.iter().enumerate() {
        let e = x[k] - full.intercepts[prep.cell(r)] - full.effect(prep, k);
        if e.is_finite() {
            by_target[r.i].push(e.abs());
        }
    }
    let sigma = full.sigma2().sqrt();
    // Each target's readings lose two degrees of freedom to their two cell means.
    let but_largest = |v: &mut Vec<f64>, targets: usize| {
        v.sort_by(f64::total_cmp);
        let df = v.len() as f64 - 1.0 - 2.0 * targets as f64;
        if df >= 3.0 && sigma > 0.0 {
            let ss: f64 = v[..v.len() - 1].iter().map(|e| e * e).sum();
            (ss / df).sqrt() / sigma
        } else {
            0.0
        }
    };
    let own: Vec<f64> = (0..prep.m)
        .map(|i| but_largest(&mut by_target[i].clone(), 1))
        .collect();
    let near: Vec<f64> = (0..prep.m)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(prep.m - 1));
            but_largest(&mut by_target[a..=b].concat(), b - a + 1)
        })
        .collect();
    (0..prep.cells())
        .map(|c| t.rel_scale[c].max(own[c / 2]).max(near[c / 2]))
        .collect()
}

/// Tests the residuals (one per row, NaN for inactive rows) of a fit with pooled variance
/// `sigma2` on `df` degrees of freedom.
///
/// The model: σ²(P) = σ² exp(b (P − P̄)), each cell's sum of squares σ²(P) χ²(ν). The
/// statistic is the score of b at b = 0 (Cook & Weisberg 1983, "Diagnostics for
/// heteroscedasticity in regression", Biometrika 70): the share of the squares along
/// the axis, T = Σ (z − z̄) SS / Σ SS with z̄ weighted by ν. Its tail is exact for
/// normal readings, T > r being Σ (z − z̄ − r) χ²(ν) > 0 ([`imhof`]); two-sided, each
/// tail at half the level. An earlier test regressed the log cell variances on position:
/// with 3 runs a cell's log variance has a long lower tail (a cell of two close
/// readings), and a floor under it hid the slope, so that a stated ratio was found in a
/// third of tests. The reported z is the score over its standard error, √(Σ ν (z − z̄)²/2).
pub(crate) fn test(prep: &Prep, residuals: &[f64], sigma2: f64, df: f64) -> Option<ScatterTest> {
    let sq = Squares::along(prep, &prep.positions, residuals, sigma2, df)?;
    let total: f64 = sq.cells.iter().map(|c| c.ss).sum();
    let share: f64 = (sq.cells.iter().zip(&sq.d))
        .map(|(c, d)| d * c.ss)
        .sum::<f64>()
        / total;
    let nu_total: f64 = sq.cells.iter().map(|c| c.nu).sum();
    let z = share * nu_total / 2.0 / sq.info.sqrt();
    let upper = share_above(&sq.cells, &sq.d, share, |_| 1.0, imhof::TOLERANCE);
    let p = (2.0 * upper.min(1.0 - upper)).min(1.0);
    let (sigma_lo, sigma_hi, rel_scale) = sq.scale(prep, &prep.positions, sigma2);
    let mut own = vec![(0.0, 0.0); prep.m];
    for c in &sq.cells {
        own[c.target].0 += c.ss;
        own[c.target].1 += c.nu;
    }
    let per_target = (own.iter())
        .map(|&(ss, nu)| if nu > 0.0 { (ss / nu).sqrt() } else { f64::NAN })
        .collect();
    Some(ScatterTest {
        per_target,
        z,
        p,
        cells: sq.cells.len(),
        sigma_lo,
        sigma_hi,
        rel_scale,
    })
}

/// The fitted scatter per cell relative to √`sigma2` with the scatter along the targets
/// at `along` (one per target) in `shape`: what the held-out model with the term
/// predicts with.
pub(crate) fn scale_along(
    prep: &Prep,
    along: &[f64],
    residuals: &[f64],
    sigma2: f64,
    df: f64,
    shape: Shape,
) -> Option<Vec<f64>> {
    let sq = Squares::along(prep, along, residuals, sigma2, df)?;
    match shape {
        Shape::Line => Some(sq.scale(prep, along, sigma2).2),
        _ => Some(relative(&log_in_shape(&sq.cells, prep.m, shape))),
    }
}

/// The fitted σ per target in `shape` from the `residuals` of a fit with pooled variance
/// `sigma2` on `df` degrees of freedom: the scale of the held-out model with the term, at
/// the targets (the extended model's scatter knots). None where the test cannot be made.
pub(crate) fn sigma_per_target(
    prep: &Prep,
    residuals: &[f64],
    sigma2: f64,
    df: f64,
    shape: Shape,
) -> Option<Vec<f64>> {
    let sq = Squares::along(prep, &prep.positions, residuals, sigma2, df)?;
    let rel = match shape {
        Shape::Line => sq.scale(prep, &prep.positions, sigma2).2,
        _ => relative(&log_in_shape(&sq.cells, prep.m, shape)),
    };
    Some((0..prep.m).map(|i| rel[2 * i] * sigma2.sqrt()).collect())
}

/// σ per cell relative to the root mean square over the cells (mean square 1), from
/// log σ² per target.
fn relative(log_var: &[f64]) -> Vec<f64> {
    let cells = 2 * log_var.len();
    let var = |c: usize| libm::exp(log_var[c / 2]);
    let mean = (0..cells).map(var).sum::<f64>() / cells as f64;
    (0..cells).map(|c| (var(c) / mean).sqrt()).collect()
}

/// log σ² per target of `m` in a shape beyond the log-linear one: one value per target
/// (the maximum-likelihood σ² of its cells, Σ SS / Σ ν; a target without one gets the
/// mean of the others' logs), or a quadratic in position fitted by Fisher scoring as
/// [`log_linear`] is.
fn log_in_shape(cells: &[CellSquares], m: usize, shape: Shape) -> Vec<f64> {
    let mut per = vec![(0.0, 0.0); m];
    for c in cells {
        per[c.target].0 += c.ss;
        per[c.target].1 += c.nu;
    }
    let own: Vec<f64> = per
        .iter()
        .map(|&(ss, nu)| {
            if nu > 0.0 && ss > 0.0 {
                libm::log(ss / nu)
            } else {
                f64::NAN
            }
        })
        .collect();
    if shape == Shape::PerTarget {
        let known: Vec<f64> = own.iter().copied().filter(|v| v.is_finite()).collect();
        let mean = known.iter().sum::<f64>() / known.len().max(1) as f64;
        return own
            .iter()
            .map(|v| if v.is_finite() { *v } else { mean })
            .collect();
    }
    let z_of: Vec<f64> = (0..m)
        .map(|i| {
            cells
                .iter()
                .find(|c| c.target == i)
                .map_or(f64::NAN, |c| c.z)
        })
        .collect();
    let coef = log_quadratic(cells);
    z_of.iter()
        .zip(&own)
        .map(|(z, o)| match z.is_finite() {
            true => coef[0] + coef[1] * z + coef[2] * z * z,
            false => *o,
        })
        .collect()
}

/// The maximum-likelihood log σ²(z) = c₀ + c₁z + c₂z² from the cells' squares: Fisher
/// scoring of the gamma GLM with a log link (McCullagh & Nelder 1989, §8.3), weights ν,
/// the linear predictor kept within a factor 10⁶ of the pooled variance.
fn log_quadratic(cells: &[CellSquares]) -> [f64; 3] {
    let nu: f64 = cells.iter().map(|c| c.nu).sum();
    let pooled = libm::log(cells.iter().map(|c| c.ss).sum::<f64>() / nu);
    let limit = libm::log(1e6);
    let mut coef = [pooled, 0.0, 0.0];
    for _ in 0..50 {
        let eta = |z: f64| {
            (coef[0] + coef[1] * z + coef[2] * z * z).clamp(pooled - limit, pooled + limit)
        };
        let w: Vec<f64> = cells.iter().map(|c| c.nu.sqrt()).collect();
        let cols: Vec<Vec<f64>> = (0..3)
            .map(|d| cells.iter().zip(&w).map(|(c, w)| w * c.z.powi(d)).collect())
            .collect();
        let y: Vec<f64> = (cells.iter().zip(&w))
            .map(|(c, w)| {
                let e = eta(c.z);
                w * (e + (c.ss / c.nu) / libm::exp(e) - 1.0)
            })
            .collect();
        let fit = least_squares(&cols, &y);
        let next = [fit.coef[0], fit.coef[1], fit.coef[2]];
        let done = (0..3).all(|d| (next[d] - coef[d]).abs() < 1e-10 * (1.0 + coef[d].abs()));
        coef = next;
        if done {
            break;
        }
    }
    coef
}

/// The cells' squares the test and the fit read, with z − z̄ and the information of b.
struct Squares {
    cells: Vec<CellSquares>,
    d: Vec<f64>,
    info: f64,
}

impl Squares {
    /// None when the test cannot be made: fewer than 3 runs or targets, 4 cells, or no
    /// scatter.
    fn along(
        prep: &Prep,
        along: &[f64],
        residuals: &[f64],
        sigma2: f64,
        df: f64,
    ) -> Option<Squares> {
        if prep.n < 3 || prep.m < 3 || !(sigma2 > 0.0 && df > 0.0) {
            return None;
        }
        let cells = cell_squares(prep, along, residuals, df);
        let total: f64 = cells.iter().map(|c| c.ss).sum();
        if cells.len() < 4 || total.is_nan() || total <= 0.0 {
            return None;
        }
        let d = centred(&cells);
        let info: f64 = cells.iter().zip(&d).map(|(c, d)| c.nu * d * d / 2.0).sum();
        (info > 0.0).then_some(Squares { cells, d, info })
    }

    /// σ at the first and last target and the relative scale per cell of the maximum-
    /// likelihood fit ([`log_linear`]), scaled so that the mean of σ² over the cells is
    /// the pooled `sigma2`.
    fn scale(&self, prep: &Prep, along: &[f64], sigma2: f64) -> (f64, f64, Vec<f64>) {
        let (a, b) = log_linear(&self.cells);
        let shape = |p: f64| libm::exp(a + b * (p - prep.pbar));
        let cells = prep.cells();
        let mean_shape = (0..cells).map(|c| shape(along[c / 2])).sum::<f64>() / cells as f64;
        let kappa = sigma2 / mean_shape;
        let rel_scale = (0..cells)
            .map(|c| (shape(along[c / 2]) / mean_shape).sqrt())
            .collect();
        (
            (kappa * shape(prep.lo)).sqrt(),
            (kappa * shape(prep.hi)).sqrt(),
            rel_scale,
        )
    }
}

/// One cell's squares: its position about P̄, the sum of its squared residuals and its
/// share ν of the residual degrees of freedom.
struct CellSquares {
    /// The cell's target.
    target: usize,
    z: f64,
    ss: f64,
    nu: f64,
}

/// The cells with at least two residuals, each with its share of `df` (a cell of c
/// readings has c − 1 of the cell means' residual df; the time model's other terms take
/// theirs from every cell alike).
fn cell_squares(prep: &Prep, along: &[f64], residuals: &[f64], df: f64) -> Vec<CellSquares> {
    let mut ss = vec![0.0; prep.cells()];
    let mut count = vec![0usize; prep.cells()];
    for (k, r) in prep.rows.iter().enumerate() {
        let e = residuals[k];
        if e.is_finite() {
            ss[prep.cell(r)] += e * e;
            count[prep.cell(r)] += 1;
        }
    }
    let within: usize = count.iter().filter(|&&c| c >= 2).map(|c| c - 1).sum();
    let share = df / within.max(1) as f64;
    (0..prep.cells())
        .filter(|&c| count[c] >= 2)
        .map(|c| CellSquares {
            target: c / 2,
            z: along[c / 2] - prep.pbar,
            ss: ss[c],
            nu: (count[c] - 1) as f64 * share,
        })
        .collect()
}

/// z − z̄ per cell, z̄ weighted by ν.
fn centred(cells: &[CellSquares]) -> Vec<f64> {
    let nu: f64 = cells.iter().map(|c| c.nu).sum();
    let zbar = cells.iter().map(|c| c.nu * c.z).sum::<f64>() / nu;
    cells.iter().map(|c| c.z - zbar).collect()
}

/// P(T > `share`) when each cell's sum of squares is `variance(z)` χ²(ν): P(Σ (d − share)
/// variance χ²(ν) > 0).
fn share_above(
    cells: &[CellSquares],
    d: &[f64],
    share: f64,
    variance: impl Fn(f64) -> f64,
    tolerance: f64,
) -> f64 {
    let terms: Vec<(f64, f64)> = (cells.iter().zip(d))
        .map(|(c, d)| ((d - share) * variance(c.z), c.nu))
        .collect();
    imhof::combination_positive(&terms, tolerance)
}

/// The maximum-likelihood (a, b) of σ²(z) = exp(a + b z) from the cells' squares: Fisher
/// scoring of the gamma GLM with a log link (McCullagh & Nelder 1989, §8.3), weights ν;
/// the slope kept within a factor 10⁶ of σ² over the cells (all-equal readings at one
/// end would send it to infinity).
fn log_linear(cells: &[CellSquares]) -> (f64, f64) {
    let nu: f64 = cells.iter().map(|c| c.nu).sum();
    let (zlo, zhi) = (cells.iter().map(|c| c.z))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), z| {
            (l.min(z), h.max(z))
        });
    let limit = libm::log(1e6) / (zhi - zlo).max(f64::MIN_POSITIVE);
    let mut a = libm::log(cells.iter().map(|c| c.ss).sum::<f64>() / nu);
    let mut b = 0.0;
    for _ in 0..50 {
        // Working response η + (s² − μ)/μ, weight ν: weighted least squares on z.
        let work: Vec<(f64, f64, f64)> = cells
            .iter()
            .map(|c| {
                let eta = a + b * c.z;
                (c.z, eta + (c.ss / c.nu) / libm::exp(eta) - 1.0, c.nu)
            })
            .collect();
        let sw: f64 = work.iter().map(|w| w.2).sum();
        let zm = work.iter().map(|w| w.2 * w.0).sum::<f64>() / sw;
        let ym = work.iter().map(|w| w.2 * w.1).sum::<f64>() / sw;
        let szz: f64 = work.iter().map(|w| w.2 * (w.0 - zm).powi(2)).sum();
        let szy: f64 = work.iter().map(|w| w.2 * (w.0 - zm) * (w.1 - ym)).sum();
        let nb = (szy / szz).clamp(-limit, limit);
        let na = ym - nb * zm;
        let done = (nb - b).abs() * (zhi - zlo) < 1e-10 && (na - a).abs() < 1e-10;
        (a, b) = (na, nb);
        if done {
            break;
        }
    }
    (a, b)
}

/// The largest ratio of σ between the axis' ends a plan is asked to confirm: beyond it
/// the readings at one end would be noise, no longer a scatter that changes along the
/// axis (on 5 targets and 3 runs the test's power approaches 81 % only as the ratio
/// goes to thousands).
const LARGEST_RATIO: f64 = 10.0;

/// What this plan confirms: a scatter changing log-linearly along the axis by a ratio
/// (σ at the last target over σ at the first, or its inverse) that the test finds in
/// [`POWER`] of tests at the level, each tail at half of it. The test's critical share
/// is exact for normal readings ([`imhof`]). Its power reads each cell's sum of squares
/// as what the time model `fit` leaves of it under that scatter ([`expected_squares`]):
/// the model's columns take their degrees of freedom mostly from the rows that scatter
/// most, so a scatter that grows along the axis shows less in the residuals than in the
/// readings (read as the uniform shares the test's null takes, the stated ratio was
/// found in 40 % of tests).
pub(crate) fn detectable(p: &Prep, fit: &TimeFit) -> Detectable {
    let measure = "ratio_end_to_start".to_string();
    let untestable = || {
        Detectable::untestable(
            Effect::ScatterVariation,
            measure.clone(),
            "a scatter per target needs at least three runs and four cells of readings",
        )
    };
    let df = fit.df;
    if p.n < 3 || p.m < 3 || df.is_nan() || df <= 0.0 {
        return untestable();
    }
    // The fit's cells, each with its share of the df, as the test reads them.
    let mut rows: Vec<f64> = vec![f64::NAN; p.rows.len()];
    for &k in &fit.rows {
        rows[k] = 0.0;
    }
    let cells = cell_squares(p, &p.positions, &rows, df);
    if cells.len() < 4 {
        return untestable();
    }
    let d = centred(&cells);
    let (lo, hi) = (
        d.iter().copied().fold(f64::INFINITY, f64::min),
        d.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    // The critical share to 1e-6 of the tail's log, the power to 1e-4: the size to about
    // 1e-4.
    let tail = |r: f64| share_above(&cells, &d, r, |_| 1.0, 1e-9);
    let critical = root_decreasing(
        |r| libm::log(tail(r).max(1e-300)),
        libm::log(ALPHA / 2.0),
        (lo, hi),
        1e-6,
    );
    // Power of the upper tail at a growing σ (the lower tail's adds nothing there).
    let length = p.hi - p.lo;
    let power = |log_ratio: f64| {
        let b = 2.0 * log_ratio / length.max(f64::MIN_POSITIVE);
        let left = expected_squares(p, fit, |z| libm::exp(b * z));
        let terms: Vec<(f64, f64)> = (left.iter().zip(&d))
            .map(|(&(mean, nu), d)| ((d - critical) * mean / nu, nu))
            .collect();
        imhof::combination_positive(&terms, 1e-5)
    };
    if power(libm::log(LARGEST_RATIO)) < POWER {
        return Detectable::untestable(
            Effect::ScatterVariation,
            measure,
            &format!(
                "{} no scatter changing along the axis by up to a factor {} is found in {} % of tests (the time model's drift, thermal growth and run offsets take their degrees of freedom mostly from the readings that scatter most; more runs or targets are needed)",
                plan_words(p.m, p.n),
                LARGEST_RATIO,
                (100.0 * POWER).round()
            ),
        );
    }
    let log_ratio = root_decreasing(|r| -power(r), -POWER, (0.0, libm::log(LARGEST_RATIO)), 1e-4);
    let size = libm::exp(log_ratio);
    let advice = format!(
        "{} a scatter that changes along the axis by less than a factor {} between its ends may go unconfirmed",
        plan_words(p.m, p.n),
        fmt(size)
    );
    Detectable::sized(Effect::ScatterVariation, measure, size, advice)
}

/// Per cell with at least two of the fit's rows (in the order of [`cell_squares`]): the
/// expected sum of squared residuals the time model `fit` leaves when the readings
/// scatter with variance `variance(z)` (z the position about P̄), and its degrees of
/// freedom. With the cell means free and the model's columns demeaned within the cells
/// (orthonormal rows q_k, S = Σ σ²_k q_k q_kᵀ), a cell of c readings and leverage L
/// keeps E\[SS\] = σ²(c − 1 − 2L) + Σ q_kᵀ S q_k over its rows, on c − 1 − L degrees of
/// freedom (with σ constant: σ² (c − 1 − L)).
fn expected_squares(p: &Prep, fit: &TimeFit, variance: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
    let q: Vec<Vec<f64>> = (0..fit.rows.len()).map(|i| fit.ls.basis_row(i)).collect();
    let rank = fit.ls.rank;
    let cell_of: Vec<usize> = fit.rows.iter().map(|&k| p.cell(&p.rows[k])).collect();
    let var_of = |c: usize| variance(p.positions[c / 2] - p.pbar);
    let mut s = vec![vec![0.0; rank]; rank];
    for (qk, &c) in q.iter().zip(&cell_of) {
        let v = var_of(c);
        for (a, row) in s.iter_mut().enumerate() {
            for (b, x) in row.iter_mut().enumerate() {
                *x += v * qk[a] * qk[b];
            }
        }
    }
    let mut count = vec![0usize; p.cells()];
    let mut leverage = vec![0.0; p.cells()];
    let mut spread = vec![0.0; p.cells()];
    for (qk, &c) in q.iter().zip(&cell_of) {
        count[c] += 1;
        leverage[c] += qk.iter().map(|x| x * x).sum::<f64>();
        spread[c] += (0..rank)
            .map(|a| qk[a] * (0..rank).map(|b| s[a][b] * qk[b]).sum::<f64>())
            .sum::<f64>();
    }
    (0..p.cells())
        .filter(|&c| count[c] >= 2)
        .map(|c| {
            let within = (count[c] - 1) as f64;
            let mean = var_of(c) * (within - 2.0 * leverage[c]) + spread[c];
            (mean, (within - leverage[c]).max(f64::MIN_POSITIVE))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::testing::standard_cycle;
    use crate::diagnose::maths::linalg::least_squares;
    use crate::diagnose::time_fit::{Terms, fit};
    use crate::measurement::AxisData;

    fn cell(target: usize, z: f64, ss: f64, nu: f64) -> CellSquares {
        CellSquares { target, z, ss, nu }
    }

    /// One σ per target is the maximum-likelihood σ² of its cells, Σ SS / Σ ν; a target
    /// without cells takes the mean of the others' logs.
    #[test]
    fn per_target_is_each_targets_pooled_variance() {
        let cells = [
            cell(0, -1.0, 2.0, 2.0),
            cell(0, -1.0, 6.0, 2.0),
            cell(2, 1.0, 9.0, 1.0),
        ];
        let got = log_in_shape(&cells, 3, Shape::PerTarget);
        let want = [libm::log(8.0 / 4.0), 0.0, libm::log(9.0)];
        assert!((got[0] - want[0]).abs() < 1e-15 && (got[2] - want[2]).abs() < 1e-15);
        assert!(
            (got[1] - (want[0] + want[2]) / 2.0).abs() < 1e-15,
            "{got:?}"
        );
        // Relative σ per cell: mean square 1.
        let rel = relative(&got);
        let ms = rel.iter().map(|r| r * r).sum::<f64>() / rel.len() as f64;
        assert!((ms - 1.0).abs() < 1e-12, "{rel:?}");
    }

    /// Squares that lie on a log-quadratic exactly are its maximum-likelihood fit.
    #[test]
    fn a_log_quadratic_is_recovered() {
        let q = |z: f64| 0.3 - 0.8 * z + 1.1 * z * z;
        let cells: Vec<CellSquares> = (0..7)
            .map(|i| {
                let z = -1.5 + 0.5 * i as f64;
                cell(i, z, 3.0 * libm::exp(q(z)), 3.0)
            })
            .collect();
        let c = log_quadratic(&cells);
        for (got, want) in c.iter().zip([0.3, -0.8, 1.1]) {
            assert!((got - want).abs() < 1e-9, "{c:?}");
        }
        let curve = log_in_shape(&cells, 7, Shape::Curve);
        assert!((curve[6] - q(1.5)).abs() < 1e-9, "{curve:?}");
    }

    /// 5 targets, 3 runs under the standard cycle, a reading every 30 s.
    fn plan() -> AxisData {
        let targets: Vec<f64> = (0..5).map(|i| 100.0 * i as f64).collect();
        standard_cycle(&targets, 3, (0.0, 30.0), |_, _, _| 0.0)
    }

    /// The expected squares against the hat matrix of the whole design (cell indicators
    /// and the time model's raw columns, orthonormalised afresh): E[SS_c] = Σ over the
    /// cell's rows k and all rows j of M_kj² σ²_j with M = I − H; with σ constant they
    /// sum to the residual df times σ².
    #[test]
    fn expected_squares_match_the_hat_matrix() {
        let data = plan();
        let p = Prep::new(&data);
        let rows = p.rows.len();
        let zeros = vec![0.0; rows];
        let all = vec![true; rows];
        let ones = vec![1.0; p.cells()];
        let terms = Terms {
            thermal: true,
            runs: true,
            drift: true,
            warm: None,
            thermal_about: None,
        };
        let f = fit(&p, &zeros, &all, &ones, terms);
        let c = &p.clocks;
        let mut cols: Vec<Vec<f64>> = (0..p.cells())
            .map(|cell| {
                (0..rows)
                    .map(|k| f64::from(u8::from(p.cell(&p.rows[k]) == cell)))
                    .collect()
            })
            .collect();
        cols.push(
            (0..rows)
                .map(|k| (p.positions[p.rows[k].i] - p.pbar) * c.thermal[k])
                .collect(),
        );
        for j in 1..p.n {
            cols.push(
                (0..rows)
                    .map(|k| f64::from(u8::from(c.run[k] == j)))
                    .collect(),
            );
        }
        cols.push(c.drift.clone());
        let whole = least_squares(&cols, &zeros);
        let q: Vec<Vec<f64>> = (0..rows).map(|k| whole.basis_row(k)).collect();
        let b = 0.004;
        let sigma2 = |k: usize| (b * (p.positions[p.rows[k].i] - p.pbar)).exp();
        let mut want = vec![0.0; p.cells()];
        for k in 0..rows {
            for j in 0..rows {
                let h: f64 = q[k].iter().zip(&q[j]).map(|(a, b)| a * b).sum();
                let m = f64::from(u8::from(k == j)) - h;
                want[p.cell(&p.rows[k])] += m * m * sigma2(j);
            }
        }
        let got = expected_squares(&p, &f, |z| (b * z).exp());
        assert_eq!(got.len(), p.cells());
        for (g, w) in got.iter().zip(&want) {
            assert!((g.0 - w).abs() < 1e-9 * w, "{} vs {w}", g.0);
        }
        let flat = expected_squares(&p, &f, |_| 2.0);
        let total: f64 = flat.iter().map(|g| g.0).sum();
        let nu: f64 = flat.iter().map(|g| g.1).sum();
        assert!(
            (total - 2.0 * f.df).abs() < 1e-9,
            "{total} vs {}",
            2.0 * f.df
        );
        assert!((nu - f.df).abs() < 1e-9, "{nu} vs {}", f.df);
    }
}
