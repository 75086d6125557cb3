//! Scatter variation: the scatter changes along the axis (Hemingray et al. 1971, §5.1:
//! VDI 3441 takes one scatter for the axis, NMTBA one per target). Tested in
//! [`crate::diagnose::scatter`]: the log cell variances regressed on position.

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::scatter::ScatterTest;
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
