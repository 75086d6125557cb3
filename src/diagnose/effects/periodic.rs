//! Periodic error along the axis (lead screw, scale, worm, encoder; Hemingray et al. 1971,
//! §4). Searched in [`crate::diagnose::periodic`]: a Lomb–Scargle periodogram of the target
//! means about a cubic trend, the declared pitch tested first. Judged by the
//! leave-targets-out RMS of the target means (a periodic error costs between the
//! targets, not at them).

use super::{Rule as EffectRule, Term, Unrelated};
use crate::diagnose::analysis::Analysis;
use crate::diagnose::finding::{Evidence, Fields, Finding, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::periodic::Resolution;
use crate::simulate::{ErrorModel, PeriodicTerm};
use crate::units::AxisKind;
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

impl EffectRule for Rule {
    fn find(&self, a: &Analysis) -> Vec<Finding> {
        let ps = &a.periodic;
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

    fn term(&self) -> Term {
        Term::TargetMeans
    }

    /// A line (or sinusoid) through the targets: compared with the same term along the
    /// targets in random orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TargetOrders
    }

    fn extend(&self, _: &Analysis, fit: &Fitted, model: &mut ErrorModel) {
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

    fn removed(&self, a: &Analysis, fit: &Fitted) -> Option<Vec<f64>> {
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

/// The short fine-step test that measures a periodic error of pitch `pitch` (or looks for
/// one): Hemingray et al. 1971, §4.
fn short_test(kind: AxisKind, pitch: Option<f64>) -> String {
    match (kind, pitch) {
        (AxisKind::Linear, Some(p)) => format!(
            "to measure it, add a short test over about {} mm (at least three pitches) with steps of about {} mm (a tenth of the pitch or finer), as Hemingray et al. 1971, §4 recommend (25 mm with 0.5 mm steps)",
            fmt_position_round((3.0 * p).max(25.0)),
            fmt_position_round((p / 10.0).min(0.5))
        ),
        (AxisKind::Linear, None) => "to look for a lead-screw or scale periodic error, add a short test of about 25 mm with about 0.5 mm steps (Hemingray et al. 1971, §4)".to_string(),
        (AxisKind::Rotary, Some(p)) => format!(
            "to measure it, add a short test over at least three pitches ({} deg) with steps of about {} deg (a tenth of the pitch), after Hemingray et al. 1971, §4",
            fmt_position_round(3.0 * p),
            fmt_position_round(p / 10.0)
        ),
        (AxisKind::Rotary, None) => "to look for a periodic error (worm, encoder), add a short test over a few periods with steps of a tenth of the period (Hemingray et al. 1971, §4)".to_string(),
    }
}

/// Notes on what the plan can resolve of a periodic error (Hemingray et al. 1971, §4).
pub(crate) fn plan_notes(
    res: &Resolution,
    pitch: Option<f64>,
    kind: AxisKind,
    notes: &mut Vec<String>,
) {
    let pu = kind.position_unit();
    let advice = short_test(kind, pitch);
    if !res.applicable {
        let spacing = if res.spacing.is_finite() {
            format!(
                "targets about {} {pu} apart over {} {pu}",
                fmt_position_round(res.spacing),
                fmt_position_round(res.length)
            )
        } else {
            "a single target".to_string()
        };
        notes.push(format!(
            "periodic error not assessed: with {spacing} the plan resolves no period (it would need periods between twice the spacing and a third of the travel, at least a factor of two apart, and at least 10 targets); {advice}"
        ));
    } else if let Some(p) = pitch {
        if p < res.p_min {
            notes.push(format!(
                "the declared pitch {} {pu} is shorter than twice the target spacing ({} {pu}): the plan cannot resolve it; {advice}",
                fmt_position_round(p),
                fmt_position_round(res.spacing)
            ));
        } else if p > res.length / 2.0 {
            notes.push(format!(
                "the declared pitch {} {pu} repeats fewer than twice over the measured travel: it cannot be told from the progressive error",
                fmt_position_round(p)
            ));
        }
    }
}

fn fmt_position_round(v: f64) -> String {
    crate::units::fmt_position((v * 1000.0).round() / 1000.0)
}
