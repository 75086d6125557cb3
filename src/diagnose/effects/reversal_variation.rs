//! Reversal variation: the reversal value changes along the axis (lost motion; Hemingray
//! et al. 1971, §5.2). Tested in [`crate::diagnose::reversal`] on the Bi of the readings
//! corrected for the time effects: the slope of a straight line, and what the line leaves,
//! each at half the level.

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::reversal::ReversalTest;
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
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        let shape = if self.linear {
            "linear"
        } else {
            "not a straight line"
        };
        vec![("shape", shape)]
    }

    /// A backlash compensation is one value per axis: it removes the mean reversal B̄ and
    /// leaves half the range of the Bi on either side.
    fn advice(&self, u: Units) -> String {
        format!(
            "a backlash compensation (one value for the axis) leaves up to ±{} {} of reversal here (half the range of Bi, {} {}); compensate per position where the control has direction-dependent pitch tables, or look for the mechanical cause (screw wear, guideway preload) where the reversal is largest",
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
    pub(crate) fn find(&self, a: &Basis, reversal: Option<&ReversalTest>) -> Vec<Finding> {
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
                format!("F of Bi about a straight line ({}, {} df)", p.m - 2, r.df),
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
            "the reversal value changes along the axis: {} {ds} at {} to {} {ds} at {}{} (p = {})",
            fmt(b_lo),
            fmt_target(u.kind, p.lo),
            fmt(b_hi),
            fmt_target(u.kind, p.hi),
            if shape_hit && !slope_hit {
                format!(", not along a straight line (Bi range {} {ds})", fmt(range))
            } else {
                String::new()
            },
            fmt_p(p_value)
        );
        vec![Finding {
            estimate: ReversalVariation {
                slope,
                start: b_lo,
                end: b_hi,
                range,
                linear: slope_hit,
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
    fn term(&self) -> Term {
        Term::Readings(|t| t.reversal = true)
    }

    /// A line (or sinusoid) through the targets: compared with the same term along the
    /// targets in random orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TargetOrders
    }

    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.reversal = r4(fit.reversal[0]);
        model.reversal_end = Some(r4(fit.reversal[a.prep.m - 1]));
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
