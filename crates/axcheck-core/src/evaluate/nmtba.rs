//! The NMTBA accuracy definition as Hemingray, Cowley and Burdekin (1971, §3.1)
//! describe it.
//!
//! At each point the mean position and the scatter 3σ (σ with N − 1). The zero line lies
//! midway between the two extreme mean errors; the accuracy is the largest
//! |X̄i − zero| + 3σi. Bidirectional accuracy A_b pools both approach directions at a
//! point (so σ_b includes the lost motion: σ_b² ≈ σ_u² + L²/4); unidirectional accuracy
//! A_u is computed per direction. The lost motion at a point is the difference of the two
//! directional means, L_i = X̄i↑ − X̄i↓.

use super::band;
use super::catalogue::nmtba;
use super::stats::{argmax, mean, sample_sd};
use super::{Evaluation, NmtbaTarget, Parameter, Standard, StandardId, TargetResult};
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
                let up =
                    band::direction(data.deviations(i, Direction::Up).to_vec(), 3.0, sample_sd);
                let down =
                    band::direction(data.deviations(i, Direction::Down).to_vec(), 3.0, sample_sd);
                // Both directions pooled at the point: σ_b holds the lost motion too.
                let pooled: Vec<f64> = up
                    .deviations
                    .iter()
                    .chain(&down.deviations)
                    .copied()
                    .collect();
                TargetResult {
                    position: data.targets[i],
                    mean: mean(&pooled),
                    reversal: up.mean - down.mean,
                    repeatability: None,
                    nmtba: Some(NmtbaTarget {
                        lost_motion: up.mean - down.mean,
                        sigma_bi: (n >= 2).then(|| sample_sd(&pooled).unwrap_or(f64::NAN)),
                    }),
                    up,
                    down,
                }
            })
            .collect();
        let mut notes = Vec::new();
        let mut p = Vec::new();
        if n >= 2 {
            p = accuracies(&targets);
        } else {
            notes.push("n = 1: no scatter, so the accuracies are not applicable".into());
        }
        let lost = argmax(targets.iter().map(|t| t.reversal.abs())).expect("at least one target");
        p.push(Parameter::located(&nmtba::L_MAX, lost));
        p.push(Parameter::plain(
            &nmtba::L_MEAN,
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

/// A_b, A_u↑, A_u↓, the zero line and the largest scatters 3σ (n ≥ 2).
fn accuracies(targets: &[TargetResult]) -> Vec<Parameter> {
    let means: Vec<f64> = targets.iter().map(|t| t.mean).collect();
    let sigma_b: Vec<f64> = targets
        .iter()
        .map(|t| {
            t.nmtba
                .as_ref()
                .and_then(|x| x.sigma_bi)
                .unwrap_or(f64::NAN)
        })
        .collect();
    let (a_b, zero) = accuracy(&means, &sigma_b);
    let mut p = vec![Parameter::plain(&nmtba::A, a_b)];
    let sigma = |t: &TargetResult, d| t.direction(d).s.unwrap_or(f64::NAN);
    for (def, d) in [
        (&nmtba::A_UP, Direction::Up),
        (&nmtba::A_DOWN, Direction::Down),
    ] {
        let m: Vec<f64> = targets.iter().map(|t| t.direction(d).mean).collect();
        let s: Vec<f64> = targets.iter().map(|t| sigma(t, d)).collect();
        p.push(Parameter::plain(def, accuracy(&m, &s).0));
    }
    p.push(Parameter::plain(&nmtba::ZERO, zero));
    let spread = argmax(sigma_b.iter().map(|s| 3.0 * s)).expect("at least one target");
    p.push(Parameter::located(&nmtba::SPREAD, spread));
    for (def, d) in [
        (&nmtba::SPREAD_UP, Direction::Up),
        (&nmtba::SPREAD_DOWN, Direction::Down),
    ] {
        let s = argmax(targets.iter().map(|t| 3.0 * sigma(t, d))).expect("at least one target");
        p.push(Parameter::located(def, s));
    }
    p
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
