//! The NMTBA accuracy definition as Hemingray, Cowley and Burdekin (1971, seed 003,
//! section 3.1) describe it.
//!
//! At each point the mean position and the scatter 3σ (σ with N − 1). The zero line lies
//! midway between the two extreme mean errors; the accuracy is the largest
//! |X̄i − zero| + 3σi. Bidirectional accuracy A_b pools both approach directions at a
//! point (so σ_b includes the lost motion: σ_b² ≈ σ_u² + L²/4); unidirectional accuracy
//! A_u is computed per direction. The lost motion at a point is the difference of the two
//! directional means, L_i = X̄i↑ − X̄i↓.

use super::stats::{argmax, mean, range, sample_sd};
use super::{DirectionResult, Evaluation, Parameter, Standard, StandardId, TargetResult};
use crate::measurement::AxisData;
use crate::units::Direction;

/// Largest |mean − zero| + 3σ over points, with the zero line midway between the extreme
/// means.
pub fn accuracy(means: &[f64], sigmas: &[f64]) -> (f64, f64) {
    let hi = means.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let lo = means.iter().copied().fold(f64::INFINITY, f64::min);
    let zero = (hi + lo) / 2.0;
    let worst = means
        .iter()
        .zip(sigmas)
        .map(|(m, s)| (m - zero).abs() + 3.0 * s)
        .fold(f64::NEG_INFINITY, f64::max);
    (worst, zero)
}

pub struct Nmtba;

impl Standard for Nmtba {
    fn id(&self) -> StandardId {
        StandardId::Nmtba
    }

    fn evaluate(&self, data: &AxisData) -> Evaluation {
        let n = data.runs();
        let targets: Vec<TargetResult> = (0..data.target_count())
            .map(|i| {
                let direction = |dir: Direction| {
                    let deviations = data.deviations(i, dir).to_vec();
                    let m = mean(&deviations);
                    let s = sample_sd(&deviations);
                    DirectionResult {
                        mean: m,
                        s,
                        range: range(&deviations),
                        upper: s.map(|s| m + 3.0 * s),
                        lower: s.map(|s| m - 3.0 * s),
                        repeatability: s.map(|s| 6.0 * s),
                        deviations,
                    }
                };
                let up = direction(Direction::Up);
                let down = direction(Direction::Down);
                let pooled: Vec<f64> = up
                    .deviations
                    .iter()
                    .chain(&down.deviations)
                    .copied()
                    .collect();
                let mut extra = vec![("lost_motion", up.mean - down.mean)];
                if n >= 2 {
                    extra.push(("sigma_bi", sample_sd(&pooled).unwrap_or(f64::NAN)));
                }
                TargetResult {
                    position: data.targets[i],
                    mean: mean(&pooled),
                    reversal: up.mean - down.mean,
                    repeatability: None,
                    up,
                    down,
                    extra,
                }
            })
            .collect();
        let plain = |key, label, name, value| {
            Parameter::plain(
                key,
                label,
                name,
                "NMTBA (Hemingray et al. 1971, 3.1)",
                value,
            )
        };
        let mut p = Vec::new();
        let mut notes = Vec::new();
        if n >= 2 {
            let means: Vec<f64> = targets.iter().map(|t| t.mean).collect();
            let sigma_b: Vec<f64> = targets
                .iter()
                .map(|t| {
                    t.extra
                        .iter()
                        .find(|(k, _)| *k == "sigma_bi")
                        .map_or(f64::NAN, |e| e.1)
                })
                .collect();
            let (a_b, zero) = accuracy(&means, &sigma_b);
            p.push(plain(
                "A",
                "A_b",
                "bidirectional accuracy max(|X̄i − zero| + 3σi)",
                a_b,
            ));
            for (key, label, name, d) in [
                ("A_up", "A_u↑", "unidirectional accuracy ↑", Direction::Up),
                (
                    "A_down",
                    "A_u↓",
                    "unidirectional accuracy ↓",
                    Direction::Down,
                ),
            ] {
                let m: Vec<f64> = targets.iter().map(|t| t.direction(d).mean).collect();
                let s: Vec<f64> = targets
                    .iter()
                    .map(|t| t.direction(d).s.unwrap_or(f64::NAN))
                    .collect();
                p.push(plain(key, label, name, accuracy(&m, &s).0));
            }
            p.push(plain(
                "zero",
                "zero",
                "zero line, midway between the extreme means",
                zero,
            ));
            let spread = argmax(sigma_b.iter().map(|s| 3.0 * s)).expect("at least one target");
            p.push(Parameter {
                at_target: Some(spread.0),
                ..plain(
                    "spread",
                    "3σ_b",
                    "largest bidirectional scatter 3σ",
                    spread.1,
                )
            });
            for (key, label, d) in [
                ("spread_up", "3σ_u↑", Direction::Up),
                ("spread_down", "3σ_u↓", Direction::Down),
            ] {
                let s = argmax(
                    targets
                        .iter()
                        .map(|t| 3.0 * t.direction(d).s.unwrap_or(f64::NAN)),
                )
                .expect("at least one target");
                p.push(Parameter {
                    at_target: Some(s.0),
                    ..plain(key, label, "largest unidirectional scatter 3σ", s.1)
                });
            }
        } else {
            notes.push("n = 1: no scatter, so the accuracies are not applicable".into());
        }
        let lost = argmax(targets.iter().map(|t| t.reversal.abs())).expect("at least one target");
        p.push(Parameter {
            at_target: Some(lost.0),
            ..plain("L_max", "L_max", "largest lost motion |X̄i↑ − X̄i↓|", lost.1)
        });
        p.push(plain(
            "L_mean",
            "L̄",
            "mean lost motion",
            targets.iter().map(|t| t.reversal).sum::<f64>() / targets.len() as f64,
        ));
        Evaluation {
            standard: StandardId::Nmtba,
            kind: data.kind,
            n,
            coverage_factor: 3.0,
            parameters: p,
            targets,
            notes,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_line_is_midway() {
        let (a, zero) = accuracy(&[1.0, -3.0, 0.0], &[0.1, 0.2, 0.0]);
        assert_eq!(zero, -1.0);
        assert!((a - (2.0 + 0.6)).abs() < 1e-12);
    }
}
