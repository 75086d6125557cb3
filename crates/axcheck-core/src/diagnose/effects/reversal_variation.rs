//! Reversal variation: the reversal value changes along the axis (lost motion; Hemingray
//! et al. 1971, §5.2). Tested (below) on the Bi of the readings
//! corrected for the time effects: the slope of a straight line, and their spread about
//! their mean (a worn end or section, which a line misses), each at half the level.
//!
//! The test. ISO 230-2 2.12 defines Bi per target but reports one B and B̄ as if it were
//! one number. The Bi = X̄i↑ − X̄i↓ of readings corrected for the time effects (in the standard cycle a
//! drift reaches the down approaches later than the up ones and would show as a reversal
//! growing along the axis) have the known standard error σ√(1/n↑ + 1/n↓). Two tests:
//! the slope of a weighted straight line through the Bi (t-test, df of σ), and their
//! spread about the weighted mean B̄ (χ²/(m − 1) against σ², an F-test) for a reversal of
//! any shape — one worn target among five moves a line little, and the spread about a
//! line leaves out what the line took of it. With n = 1 the slope is tested against the
//! line's own residuals (df = m − 2).

use super::{Effect, Estimate, Finding, Rule as EffectRule, Term, Unrelated, WARM_UP_UNTESTED};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, plan_words, t_shift, with_unit};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, per_target_list, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::linalg::least_squares;
use crate::diagnose::maths::stats::{f_upper, t_two_sided};
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::shape::Shape;
use crate::measurement::fmt_target;
use crate::units::AxisKind;

/// A reversal value that changes along the axis.
#[derive(Debug, Clone, PartialEq)]
pub struct ReversalVariation {
    /// Slope of the fitted line: µm per m, or arcsec per deg.
    pub slope: f64,
    /// The line at the first and last target, deviation unit.
    pub start: f64,
    pub end: f64,
    /// max Bi − min Bi, deviation unit.
    pub range: f64,
    /// Whether the slope was found (else only the departure from a straight line).
    pub linear: bool,
    /// The shape the held-out prediction chose (None: not judged, n = 1).
    pub fitted_shape: Option<Shape>,
    /// Bi per target: (position, Bi), as measured (corrected for the time effects).
    pub per_target: Vec<(f64, f64)>,
    /// Beside real run offsets this plan could not test a warm-up, whose course within the
    /// first runs would tilt Bi along the axis as well ([`UNTESTED_WARM_UP`]).
    pub(crate) warm_up_untested: bool,
}

/// What a finding adds when the plan could not test a warm-up beside the run offsets. In
/// the standard cycle a target's ↑ and ↓ approaches of one run lie apart in time by an
/// interval that changes linearly along the axis, so a curve in time within the runs
/// makes Bi change along the axis (ISO 230-2 Annex A shows it for a drift); beside real
/// run offsets a warm-up is tested on what the offsets leave of it between the runs, which
/// a few runs may not let reach the level (its `detectable` is then none).
const UNTESTED_WARM_UP: &str = "; beside these run offsets this plan cannot test a warm-up, and a machine still warming up in the first runs would change Bi along the axis as well (its ↑ and ↓ approaches to a target lie apart in time by an interval that changes along the axis; ISO 230-2 Annex A)";

/// [`UNTESTED_WARM_UP`] where the plan could not test the warm-up, else nothing.
fn untested_words(warm_up_untested: bool) -> &'static str {
    match warm_up_untested {
        true => UNTESTED_WARM_UP,
        false => "",
    }
}

impl ReversalVariation {
    /// The estimate in the shape the held-out prediction chose: its values at the first
    /// and last target from that shape; per target, the message lists every Bi.
    pub(crate) fn reshape(f: &mut Finding, shape: Shape) {
        let Estimate::ReversalVariation(r) = &mut f.estimate else {
            return;
        };
        r.fitted_shape = Some(shape);
        let (along, b): (Vec<f64>, Vec<f64>) = r.per_target.iter().copied().unzip();
        let fitted = shape.fit(&b, &along);
        if let (Some(first), Some(last)) = (fitted.first(), fitted.last()) {
            (r.start, r.end) = (*first, *last);
        }
        if shape == Shape::Line {
            return;
        }
        f.message = format!(
            "the reversal value changes {}, range {} {}: Bi = {} (p = {}){}",
            shape.changes(),
            fmt(r.range),
            f.units.symbol(),
            per_target_list(&r.per_target, f.units),
            fmt_p(f.evidence.p_value.unwrap_or(f64::NAN)),
            untested_words(r.warm_up_untested)
        );
    }
}

impl Fields for ReversalVariation {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let du = u.dev();
        let slope_key = match u.kind {
            AxisKind::Linear => "slope_um_per_m",
            AxisKind::Rotary => "slope_arcsec_per_deg",
        };
        vec![
            (slope_key.to_string(), self.slope),
            (format!("reversal_start_{du}"), self.start),
            (format!("reversal_end_{du}"), self.end),
            (format!("reversal_range_{du}"), self.range),
        ]
        .into_iter()
        .chain(
            (self.per_target.iter().enumerate())
                .filter(|_| self.fitted_shape == Some(Shape::PerTarget))
                .map(|(i, (_, b))| (format!("reversal_target_{}_{du}", i + 1), *b)),
        )
        .collect()
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        let shape = if self.linear {
            "linear"
        } else {
            "not a straight line"
        };
        let mut labels = vec![("shape", shape)];
        if let Some(fitted) = self.fitted_shape {
            labels.push(("fitted_shape", fitted.name()));
        }
        if self.warm_up_untested {
            labels.push(WARM_UP_UNTESTED);
        }
        labels
    }

    /// A backlash compensation is one value per axis: it removes the mean reversal B̄ and
    /// leaves half the range of the Bi on either side.
    fn advice(&self, u: Units) -> String {
        let first = if self.warm_up_untested {
            "re-test the warm machine (ISO 230-2 3.3) before compensating a reversal that varies, since a warm-up this plan could not test would make Bi vary too; "
        } else {
            ""
        };
        format!(
            "{first}a backlash compensation (one value for the axis) leaves up to ±{} {} of reversal here (half the range of Bi, {} {}); compensate per position where the control has direction-dependent pitch tables, or look for the mechanical cause (screw wear, guideway preload) where the reversal is largest",
            fmt(self.range / 2.0),
            u.symbol(),
            fmt(self.range),
            u.symbol()
        )
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    /// `warm_up_untested`: beside real run offsets the plan could not test a warm-up.
    pub(crate) fn find(
        &self,
        a: &Basis,
        reversal: Option<&ReversalTest>,
        warm_up_untested: bool,
    ) -> Vec<Finding> {
        let Some(r) = reversal else {
            return Vec::new();
        };
        let half = ALPHA / 2.0;
        let slope_hit = r.p_slope < half;
        let shape_hit = r.p_shape.is_some_and(|p| p < half);
        if !(slope_hit || shape_hit) {
            return Vec::new();
        }
        let (u, p) = (a.units, &a.prep);
        let ds = u.symbol();
        let slope = match u.kind {
            AxisKind::Linear => r.slope * 1000.0,
            AxisKind::Rotary => r.slope,
        };
        let (b_lo, b_hi) = (r.at(p.lo), r.at(p.hi));
        let finite: Vec<f64> = a.b.iter().copied().filter(|v| v.is_finite()).collect();
        let range = finite.iter().fold(f64::NEG_INFINITY, |a, v| a.max(*v))
            - finite.iter().fold(f64::INFINITY, |a, v| a.min(*v));
        let (statistic, value, p_value) = if slope_hit || !shape_hit {
            (
                format!("t of the slope of Bi along the axis (df {})", r.df),
                r.t_slope,
                r.p_slope,
            )
        } else {
            (
                format!("F of Bi about their mean ({}, {} df)", p.m - 1, r.df),
                r.f_shape.unwrap_or(f64::NAN),
                r.p_shape.unwrap_or(f64::NAN),
            )
        };
        let size = if slope_hit {
            (b_hi - b_lo).abs()
        } else {
            range
        };
        let message = format!(
            "the reversal value changes along the axis: {} {ds} at {} to {} {ds} at {}{} (p = {}){}",
            fmt(b_lo),
            fmt_target(u.kind, p.lo),
            fmt(b_hi),
            fmt_target(u.kind, p.hi),
            if shape_hit && !slope_hit {
                format!(
                    ", not only along a straight line (Bi range {} {ds})",
                    fmt(range)
                )
            } else {
                String::new()
            },
            fmt_p(p_value),
            untested_words(warm_up_untested)
        );
        vec![Finding {
            estimate: ReversalVariation {
                slope,
                start: b_lo,
                end: b_hi,
                range,
                linear: slope_hit,
                fitted_shape: None,
                per_target: (p.positions.iter().zip(&a.b))
                    .filter(|(_, b)| b.is_finite())
                    .map(|(p, b)| (*p, *b))
                    .collect(),
                warm_up_untested,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic,
                value,
                p_value: Some(p_value),
                effect_size: relative(size, a.sigma),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    /// A line, a curve or one value per target, whichever predicts held-out readings
    /// best.
    fn term(&self) -> Term {
        Term::Shaped(|t, shape| {
            t.reversal = true;
            t.reversal_shape = shape;
        })
    }

    /// One value per target is the same term in every order of the targets: compared
    /// with tests simulated without it.
    fn unrelated(&self) -> Unrelated {
        Unrelated::SimulatedTests
    }

    /// A line as the reversal at both ends; another shape as its value at every target.
    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.reversal = r4(fit.reversal[0]);
        model.reversal_end = Some(r4(fit.reversal[a.prep.m - 1]));
        if fit.reversal_shape != Shape::Line {
            model.reversal_end = None;
            model.reversal_knots = (a.prep.positions.iter().zip(&fit.reversal))
                .map(|(p, b)| [*p, r4(*b)])
                .collect();
        }
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        Some(
            a.prep
                .rows
                .iter()
                .map(|r| r.sign * (fit.reversal[r.i] - fit.reversal_mean) / 2.0)
                .collect(),
        )
    }
}

/// The result of the reversal tests.
#[derive(Debug, Clone)]
pub(crate) struct ReversalTest {
    /// Slope of B along the axis (deviation per position unit).
    pub slope: f64,
    /// B of the line at the mean position of the targets used.
    pub(crate) at_center: f64,
    pub center: f64,
    pub(crate) t_slope: f64,
    pub(crate) p_slope: f64,
    /// Standard error of the slope.
    pub(crate) se_slope: f64,
    pub df: f64,
    /// F of the Bi about their weighted mean (m − 1 and σ's df): a reversal that varies
    /// in any shape, a worn end or section as well as a line.
    pub(crate) f_shape: Option<f64>,
    pub(crate) p_shape: Option<f64>,
}

impl ReversalTest {
    /// The fitted reversal value at `p`.
    pub fn at(&self, p: f64) -> f64 {
        self.at_center + self.slope * (p - self.center)
    }
}

/// Tests the per-target reversal values `b` at `positions` with variances `var` (None:
/// unknown scatter, n = 1) whose scatter estimate has `df_sigma` degrees of freedom.
pub(crate) fn test(
    positions: &[f64],
    b: &[f64],
    var: Option<&[f64]>,
    df_sigma: f64,
) -> Option<ReversalTest> {
    let idx: Vec<usize> = (0..b.len())
        .filter(|&i| b[i].is_finite() && var.is_none_or(|v| v[i] > 0.0 && v[i].is_finite()))
        .collect();
    let m = idx.len();
    let w: Vec<f64> = idx
        .iter()
        .map(|&i| var.map_or(1.0, |v| 1.0 / v[i]))
        .collect();
    let sw: f64 = w.iter().sum();
    if m < 2 || sw.is_nan() || sw <= 0.0 {
        return None;
    }
    let center = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi * positions[i])
        .sum::<f64>()
        / sw;
    let one: Vec<f64> = w.iter().map(|wi| wi.sqrt()).collect();
    let x: Vec<f64> = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi.sqrt() * (positions[i] - center))
        .collect();
    let y: Vec<f64> = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi.sqrt() * b[i])
        .collect();
    let fit = least_squares(&[one, x], &y);
    if !fit.kept[1] {
        return None;
    }
    let slope = fit.coef[1];
    let at_center = fit.coef[0];
    match var {
        Some(_) => {
            if df_sigma.is_nan() || df_sigma < 1.0 {
                return None;
            }
            let t = slope / fit.cov[1][1].sqrt();
            // Bi about their weighted mean (the standard's one B̄), in units of their
            // standard errors: χ²/(m − 1) against σ².
            let bbar = idx.iter().zip(&w).map(|(&i, wi)| wi * b[i]).sum::<f64>() / sw;
            let rss0: f64 = idx
                .iter()
                .zip(&w)
                .map(|(&i, wi)| wi * (b[i] - bbar).powi(2))
                .sum();
            let (f_shape, p_shape) = if m >= 3 {
                let f = rss0 / (m - 1) as f64;
                (Some(f), Some(f_upper(f, (m - 1) as f64, df_sigma)))
            } else {
                (None, None)
            };
            Some(ReversalTest {
                slope,
                at_center,
                center,
                t_slope: t,
                p_slope: t_two_sided(t, df_sigma),
                se_slope: fit.cov[1][1].sqrt(),
                df: df_sigma,
                f_shape,
                p_shape,
            })
        }
        None => {
            if m < 4 {
                return None;
            }
            let df = (m - 2) as f64;
            let s2 = fit.rss / df;
            if s2.is_nan() || s2 <= 0.0 {
                return None;
            }
            let t = slope / (s2 * fit.cov[1][1]).sqrt();
            Some(ReversalTest {
                slope,
                at_center,
                center,
                t_slope: t,
                p_slope: t_two_sided(t, df),
                se_slope: (s2 * fit.cov[1][1]).sqrt(),
                df,
                f_shape: None,
                p_shape: None,
            })
        }
    }
}

/// What this plan confirms: a reversal changing linearly by the size over the measured
/// travel. Its test of the slope of Bi at half the level finds a change Δ in
/// [`crate::diagnose::detectable::POWER`] of tests when Δ / se(Δ) reaches the t shift of
/// that power, se(Δ) being the slope's standard error times the travel.
pub(crate) fn detectable(p: &Prep, u: Units, r: Option<&ReversalTest>) -> Detectable {
    let measure = format!("change_over_axis_{}", u.dev());
    let Some(r) = r else {
        return Detectable::untestable(
            Effect::ReversalVariation,
            measure,
            "Bi along the axis need two targets with both directions, and a scatter or four targets",
        );
    };
    let size = t_shift(ALPHA / 2.0, r.df) * r.se_slope * (p.hi - p.lo);
    // Equally spaced targets over the same travel: se(slope) ∝ 1/√Σ(x − x̄)², and
    // Σ(x − x̄)² = L²·m(m + 1)/(12(m − 1)).
    let spread = |m: f64| m * (m + 1.0) / (12.0 * (m - 1.0));
    let more = (p.m < 10).then_some(10);
    let with_more = more.map(|k| size * (spread(p.m as f64) / spread(k as f64)).sqrt());
    let advice = format!(
        "{} a reversal variation under {} over the axis may go unconfirmed",
        plan_words(p.m, p.n),
        with_unit(size, u)
    );
    let mut x = Detectable::sized(Effect::ReversalVariation, measure, size, advice);
    if let (Some(k), Some(s), Some(_)) = (more, with_more, x.size) {
        x.advice += &format!(
            "; {k} targets over the same travel would confirm about {}",
            with_unit(s, u)
        );
        x.more_targets = more;
        x.size_with_more_targets = with_more;
    }
    x
}
