//! Scatter variation: the scatter changes along the axis (Hemingray et al. 1971, §5.1:
//! VDI 3441 takes one scatter for the axis, NMTBA one per target). Tested
//! (below): the log cell variances regressed on position.
//!
//! The test. VDI 3441 takes one scatter for the whole axis, NMTBA one per target; Hemingray et al.
//! 1971, §5.1 ask whether the variation of the scatter along the axis is more than
//! sampling explains.
//! Test: the log of each cell's residual variance (residuals of the full time model, so
//! that drift or thermal growth do not pass for scatter) regressed on position; a t-test
//! of the slope with the regression's own residual variance (df = cells − 2), which needs
//! no normality of the log variances. Needs n ≥ 3 and m ≥ 3.

use super::{Effect, Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, plan_words, t_shift};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::stats::{t_two_sided, trigamma};
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
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
}

impl Fields for ScatterVariation {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let du = u.dev();
        vec![
            (format!("scatter_start_{du}"), self.start),
            (format!("scatter_end_{du}"), self.end),
            ("ratio_end_to_start".into(), self.ratio),
        ]
    }

    fn advice(&self, u: Units) -> String {
        let (worse, ratio) = if self.end >= self.start {
            ("last", self.ratio)
        } else {
            ("first", 1.0 / self.ratio)
        };
        format!(
            "the repeatability is {}× worse towards the {worse} target (σ {} → {} {}): look for a mechanical cause there (screw support bearing, guideway or its lubrication, scale mounting); no compensation reduces scatter",
            fmt(ratio),
            fmt(self.start),
            fmt(self.end),
            u.symbol()
        )
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    pub(crate) fn find(&self, a: &Basis, scatter: Option<&ScatterTest>) -> Vec<Finding> {
        let Some(s) = scatter.filter(|s| s.p < ALPHA) else {
            return Vec::new();
        };
        let (u, p) = (a.units, &a.prep);
        let ds = u.symbol();
        let ratio = s.sigma_hi / s.sigma_lo;
        let message = format!(
            "the scatter changes along the axis: σ ≈ {} {ds} at {} to {} {ds} at {} (t = {}, p = {})",
            fmt(s.sigma_lo),
            fmt_target(u.kind, p.lo),
            fmt(s.sigma_hi),
            fmt_target(u.kind, p.hi),
            fmt(s.t),
            fmt_p(s.p)
        );
        vec![Finding {
            estimate: ScatterVariation {
                start: s.sigma_lo,
                end: s.sigma_hi,
                ratio,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic: format!(
                    "t of the slope of log cell variance on position (df {})",
                    s.df
                ),
                value: s.t,
                p_value: Some(s.p),
                effect_size: Some(ratio),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Density(|t| t.scatter = true)
    }

    /// A line (or sinusoid) through the targets: compared with the same term along the
    /// targets in random orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TargetOrders
    }

    fn extend(&self, _: &Basis, fit: &Fitted, model: &mut ErrorModel) {
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
    pub t: f64,
    pub p: f64,
    pub df: f64,
    /// Fitted scatter σ at the first and last target, µm or arcsec.
    pub sigma_lo: f64,
    pub sigma_hi: f64,
    /// Relative scatter per cell (σ(P)/σ̄; mean square 1).
    pub rel_scale: Vec<f64>,
}

/// The scatter per cell relative to √`sigma2` for the outlier test once a scatter variation
/// is found: the larger of the fitted log-linear scale and each target's own robust scale
/// (1.4826 × the median |residual| of its readings in both directions, which one outlier
/// does not inflate), so that a scatter that changes in a step, which a log-linear fit
/// smooths over, does not make outliers of the readings where it is large.
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
    let robust = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        if v.len() >= 4 && sigma > 0.0 {
            1.4826 * crate::diagnose::maths::stats::quantile_sorted(v, 0.5) / sigma
        } else {
            0.0
        }
    };
    // A target's own median rests on a dozen readings and comes out low by chance now and
    // then, just where its largest reading then looks extreme: its neighbours' readings
    // with its own steady it.
    let own: Vec<f64> = (0..prep.m)
        .map(|i| robust(&mut by_target[i].clone()))
        .collect();
    let near: Vec<f64> = (0..prep.m)
        .map(|i| {
            let (a, b) = (i.saturating_sub(1), (i + 1).min(prep.m - 1));
            robust(&mut by_target[a..=b].concat())
        })
        .collect();
    (0..prep.cells())
        .map(|c| t.rel_scale[c].max(own[c / 2]).max(near[c / 2]))
        .collect()
}

/// Tests the residuals (one per row, NaN for inactive rows) of a fit with pooled variance
/// `sigma2`.
pub(crate) fn test(prep: &Prep, residuals: &[f64], sigma2: f64) -> Option<ScatterTest> {
    test_along(prep, &prep.positions, residuals, sigma2)
}

/// [`test`] with the scatter along the targets at `along` (one per target: their
/// positions, or an unrelated order of them) instead of their positions.
pub(crate) fn test_along(
    prep: &Prep,
    along: &[f64],
    residuals: &[f64],
    sigma2: f64,
) -> Option<ScatterTest> {
    if prep.n < 3 || prep.m < 3 || sigma2.is_nan() || sigma2 <= 0.0 {
        return None;
    }
    let cells = prep.cells();
    let mut ss = vec![0.0; cells];
    let mut count = vec![0usize; cells];
    for (k, r) in prep.rows.iter().enumerate() {
        let e = residuals[k];
        if e.is_finite() {
            let c = prep.cell(r);
            ss[c] += e * e;
            count[c] += 1;
        }
    }
    // A cell of identical readings (a quantised instrument) has no log variance: floor it.
    let floor = 0.05 * sigma2;
    let mut xs = Vec::new();
    let mut ys = Vec::new();
    for c in 0..cells {
        if count[c] >= 2 {
            let v = (ss[c] / (count[c] - 1) as f64).max(floor);
            xs.push(along[c / 2] - prep.pbar);
            ys.push(v.ln());
        }
    }
    let k = xs.len();
    if k < 4 {
        return None;
    }
    let mx = xs.iter().sum::<f64>() / k as f64;
    let my = ys.iter().sum::<f64>() / k as f64;
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    if sxx.is_nan() || sxx <= 0.0 {
        return None;
    }
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let b = sxy / sxx;
    let a = my - b * mx;
    let rss: f64 = xs
        .iter()
        .zip(&ys)
        .map(|(x, y)| (y - a - b * x).powi(2))
        .sum();
    let df = (k - 2) as f64;
    let se = (rss / df / sxx).sqrt();
    let t = if se > 0.0 { b / se } else { 0.0 };
    let p = if se > 0.0 { t_two_sided(t, df) } else { 1.0 };
    // σ²(P) ∝ exp(a + b(P − P̄)), scaled so that its mean over the cells is the pooled σ².
    let shape = |p: f64| (a + b * (p - prep.pbar)).exp();
    let mean_shape = (0..cells).map(|c| shape(along[c / 2])).sum::<f64>() / cells as f64;
    let kappa = sigma2 / mean_shape;
    let rel_scale = (0..cells)
        .map(|c| (shape(along[c / 2]) / mean_shape).sqrt())
        .collect();
    Some(ScatterTest {
        t,
        p,
        df,
        sigma_lo: (kappa * shape(prep.lo)).sqrt(),
        sigma_hi: (kappa * shape(prep.hi)).sqrt(),
        rel_scale,
    })
}

/// What this plan confirms: a scatter changing log-linearly along the axis by a ratio
/// (σ at the last target over σ at the first, or its inverse) whose log slope reaches
/// the t shift of [`crate::diagnose::detectable::POWER`] at the level (df = cells − 2).
/// A cell's log variance on ν degrees of freedom scatters by ψ′(ν/2) (the trigamma
/// function); ν is the time model's df shared among the cells. σ's log changes by half
/// the variance's.
pub(crate) fn detectable(p: &Prep, df: f64) -> Detectable {
    let measure = "ratio_end_to_start".to_string();
    let cells = p.cells();
    if p.n < 3 || p.m < 3 || df.is_nan() || df <= 0.0 {
        return Detectable::untestable(
            Effect::ScatterVariation,
            measure,
            "a scatter per target needs at least three runs and three targets",
        );
    }
    let nu = df / cells as f64;
    let sxx = 2.0 * (p.positions.iter().map(|x| (x - p.pbar).powi(2))).sum::<f64>();
    let se_slope = (trigamma(nu / 2.0) / sxx).sqrt();
    let log_ratio = t_shift(ALPHA, cells as f64 - 2.0) * se_slope * p.length() / 2.0;
    let size = log_ratio.exp();
    let advice = format!(
        "{} a scatter that changes along the axis by less than a factor {} between its ends may go unconfirmed",
        plan_words(p.m, p.n),
        fmt(size)
    );
    Detectable::sized(Effect::ScatterVariation, measure, size, advice)
}
