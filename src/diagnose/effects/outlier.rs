//! Outliers: readings inconsistent with the rest (Hemingray et al. 1971, §5.3: the scatter
//! estimate is only as good as its readings). Found in [`crate::diagnose::outliers`] by
//! externally studentised residuals in the full time model, Bonferroni over all readings.

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::{ErrorModel, Outlier as SimulatedOutlier};
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::outliers::Hit;
use crate::measurement::fmt_target;
use crate::units::Direction;

/// One reading off by more than the rest explain.
#[derive(Debug, Clone, PartialEq)]
pub struct Outlier {
    /// Run label as in the file.
    pub run: u32,
    /// Target number, from 1.
    pub target: usize,
    pub direction: Direction,
    /// Target position, mm or deg.
    pub position: f64,
    /// The reading minus what the rest predict, deviation unit.
    pub size: f64,
}

impl Fields for Outlier {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        vec![
            ("run".into(), f64::from(self.run)),
            ("target".into(), self.target as f64),
            (format!("position_{}", u.pos()), self.position),
            (format!("size_{}", u.dev()), self.size),
        ]
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        vec![("direction", self.direction.name())]
    }

    fn advice(&self, u: Units) -> String {
        format!(
            "re-measure the {} approach to target {} ({}) in run {}; where its cause is known (a disturbed beam, a knock) exclude that reading with a note in the test report: the parameters here include it",
            self.direction.name(),
            self.target,
            fmt_target(u.kind, self.position),
            self.run
        )
    }
}

fn direction(d: usize) -> Direction {
    if d == 0 {
        Direction::Up
    } else {
        Direction::Down
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    pub(crate) fn find(&self, a: &Basis, hits: &[Hit]) -> Vec<Finding> {
        let u = a.units;
        hits
            .iter()
            .map(|h| {
                let r = &a.prep.rows[h.row];
                let dir = direction(r.d);
                let run = a.data.run_labels[r.run];
                let position = a.prep.positions[r.i];
                let message = format!(
                    "reading of run {run}, {}, target {} ({}) is off by {} {} from what the rest predict (t = {}, adjusted p = {})",
                    dir.name(),
                    r.i + 1,
                    fmt_target(u.kind, position),
                    fmt(h.size),
                    u.symbol(),
                    fmt(h.t),
                    fmt_p(h.p_adj)
                );
                Finding {
                    estimate: Outlier {
                        run,
                        target: r.i + 1,
                        direction: dir,
                        position,
                        size: h.size,
                    }
                    .into(),
                    units: u,
                    evidence: Evidence {
                        statistic: "externally studentised residual (Bonferroni over all readings)"
                            .into(),
                        value: h.t,
                        p_value: Some(h.p_adj),
                        effect_size: relative(h.size.abs(), a.sigma),
                    },
                    message,
                }
            })
            .collect()
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Readings(|t| t.outliers = true)
    }

    /// Readings left out of the fit: compared with as many ordinary readings left out.
    fn unrelated(&self) -> Unrelated {
        Unrelated::OrdinaryReadings
    }

    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.outliers = fit
            .outliers
            .iter()
            .map(|&(row, size)| {
                let r = &a.prep.rows[row];
                SimulatedOutlier {
                    run: r.run as u32 + 1,
                    direction: direction(r.d),
                    target: r.i + 1,
                    size: r4(size),
                }
            })
            .collect();
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        let mut v = vec![0.0; a.x.len()];
        for &(row, size) in &fit.outliers {
            v[row] = size;
        }
        Some(v)
    }
}
