//! Periodic error along the axis (lead screw, scale, worm, encoder; Hemingray et al. 1971,
//! §4). Searched in [`crate::diagnose::periodic`]: a Lomb–Scargle periodogram of the target
//! means about a cubic trend, the declared pitch tested first. Judged by the
//! leave-targets-out RMS of the target means (a periodic error costs between the
//! targets, not at them).

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::{ErrorModel, PeriodicTerm};
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::periodic::Search;
use crate::diagnose::periodic::short_test;
use std::f64::consts::TAU;

/// A periodic error A·sin(2π·P/period + phase).
#[derive(Debug, Clone, PartialEq)]
pub struct Periodic {
    /// mm or deg.
    pub period: f64,
    /// Deviation unit.
    pub amplitude: f64,
    pub phase_deg: f64,
    /// How many periods the measured travel holds.
    pub repeats_in_travel: f64,
    /// Whether the period is the declared pitch (else the highest periodogram peak).
    pub from_pitch: bool,
}

impl Fields for Periodic {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        vec![
            (format!("period_{}", u.pos()), self.period),
            (format!("amplitude_{}", u.dev()), self.amplitude),
            ("phase_deg".into(), self.phase_deg),
            ("repeats_in_travel".into(), self.repeats_in_travel),
        ]
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        let candidate = if self.from_pitch {
            "declared pitch"
        } else {
            "periodogram peak"
        };
        vec![("candidate", candidate)]
    }

    /// A compensation table follows a period only with about four entries per period;
    /// the short test measures it (Hemingray et al. 1971, §4).
    fn advice(&self, u: Units) -> String {
        format!(
            "{}; correct it at its source (lead screw, scale or encoder interpolation) or with a cyclic compensation: a pitch compensation table follows a {} {} period only with entries at most {} {} apart",
            short_test(u.kind, Some(self.period)),
            fmt(self.period),
            u.pos(),
            fmt(self.period / 4.0),
            u.pos()
        )
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    pub(crate) fn find(&self, a: &Basis, ps: &Search) -> Vec<Finding> {
        let Some(peak) = ps.peak.as_ref() else {
            return Vec::new();
        };
        let u = a.units;
        let message = format!(
            "a periodic error of period {} {} and amplitude {} {} along the axis ({}; false-alarm probability {})",
            fmt(peak.period),
            u.pos(),
            fmt(peak.amplitude),
            u.symbol(),
            if ps.from_pitch {
                "at the declared pitch"
            } else {
                "highest periodogram peak"
            },
            fmt_p(ps.fap)
        );
        vec![Finding {
            estimate: Periodic {
                period: peak.period,
                amplitude: peak.amplitude,
                phase_deg: peak.phase_deg,
                repeats_in_travel: a.length() / peak.period,
                from_pitch: ps.from_pitch,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic: format!(
                    "Lomb–Scargle F (2, {} df) over a cubic trend{}",
                    a.prep.m as i64 - 6,
                    if ps.from_pitch {
                        ", at the declared pitch"
                    } else {
                        ", highest peak"
                    }
                ),
                value: peak.f_stat,
                p_value: Some(ps.fap),
                effect_size: relative(peak.amplitude, a.sigma),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::TargetMeans
    }

    /// A line (or sinusoid) through the targets: compared with the same term along the
    /// targets in random orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TargetOrders
    }

    fn extend(&self, _: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.periodic = fit
            .periodic
            .iter()
            .map(|p| PeriodicTerm {
                pitch: p.period,
                amplitude: r4(p.amplitude),
                phase_deg: r4(p.phase_deg),
            })
            .collect();
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        fit.periodic.as_ref().map(|p| {
            let phase = p.phase_deg.to_radians();
            a.prep
                .rows
                .iter()
                .map(|r| p.amplitude * (TAU * a.prep.positions[r.i] / p.period + phase).sin())
                .collect()
        })
    }
}
