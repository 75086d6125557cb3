//! The coverage-band arithmetic that ISO 230-2 (k = 2) and GOST 27843 (k = 3) share:
//! per-target means, scatter, limits X̄ ± kS, repeatabilities and reversal, and the
//! axis-wide ranges built from them.

use super::stats::{argmax, mean, range};
use super::{DirectionResult, Parameter, ParameterDef, TargetResult};
use crate::measurement::AxisData;
use crate::units::Direction::{self, Down, Up};

/// One direction's results at a target: mean, scatter S by `scatter` (`None` when it
/// cannot be estimated, e.g. n = 1), range, limits X̄ ± kS and repeatability 2kS.
pub fn direction(
    deviations: Vec<f64>,
    k: f64,
    scatter: impl Fn(&[f64]) -> Option<f64>,
) -> DirectionResult {
    let mean = mean(&deviations);
    let s = scatter(&deviations);
    DirectionResult {
        mean,
        s,
        range: range(&deviations),
        upper: s.map(|s| mean + k * s),
        lower: s.map(|s| mean - k * s),
        repeatability: s.map(|s| 2.0 * k * s),
        deviations,
    }
}

/// Per-target results with coverage factor `k`; `scatter` estimates S from one
/// direction's n deviations (`None` when it cannot, e.g. n = 1).
pub fn per_target(
    data: &AxisData,
    k: f64,
    scatter: impl Fn(&[f64]) -> Option<f64>,
) -> Vec<TargetResult> {
    (0..data.target_count())
        .map(|i| {
            let up = direction(data.deviations(i, Direction::Up).to_vec(), k, &scatter);
            let down = direction(data.deviations(i, Direction::Down).to_vec(), k, &scatter);
            let reversal = up.mean - down.mean;
            // ISO 2.17 / GOST (8): Ri = max(kS↑ + kS↓ + |Bi|; 2kS↑; 2kS↓).
            let repeatability = match (up.s, down.s) {
                (Some(su), Some(sd)) => Some(
                    (k * su + k * sd + reversal.abs())
                        .max(2.0 * k * su)
                        .max(2.0 * k * sd),
                ),
                _ => None,
            };
            TargetResult {
                position: data.targets[i],
                mean: (up.mean + down.mean) / 2.0,
                reversal,
                repeatability,
                up,
                down,
                nmtba: None,
            }
        })
        .collect()
}

/// `max(upper) − min(lower)` over `directions` (ISO 2.22/2.23, GOST (10)), with the two
/// terms; `None` when S does not apply.
pub fn accuracy(targets: &[TargetResult], directions: &[Direction]) -> Option<(f64, f64, f64)> {
    let mut hi = f64::NEG_INFINITY;
    let mut lo = f64::INFINITY;
    for t in targets {
        for &d in directions {
            let r = t.direction(d);
            hi = hi.max(r.upper?);
            lo = lo.min(r.lower?);
        }
    }
    Some((hi - lo, hi, lo))
}

/// `max(X̄) − min(X̄)` over the directional means of `directions` (ISO 2.19/2.20).
pub fn systematic(targets: &[TargetResult], directions: &[Direction]) -> (f64, f64, f64) {
    spread(
        targets
            .iter()
            .flat_map(|t| directions.iter().map(move |&d| t.direction(d).mean)),
    )
}

/// `max − min` of `values`, with both terms.
pub fn spread(values: impl IntoIterator<Item = f64>) -> (f64, f64, f64) {
    let (hi, lo) = values
        .into_iter()
        .fold((f64::NEG_INFINITY, f64::INFINITY), |(hi, lo), v| {
            (hi.max(v), lo.min(v))
        });
    (hi - lo, hi, lo)
}

/// Largest unidirectional repeatability 2kS in direction `d`, with its target.
pub(crate) fn max_repeatability_in(targets: &[TargetResult], d: Direction) -> Option<(usize, f64)> {
    let values: Option<Vec<f64>> = targets
        .iter()
        .map(|t| t.direction(d).repeatability)
        .collect();
    argmax(values?)
}

/// Largest bidirectional repeatability Ri, with its target.
pub(crate) fn max_repeatability(targets: &[TargetResult]) -> Option<(usize, f64)> {
    let values: Option<Vec<f64>> = targets.iter().map(|t| t.repeatability).collect();
    argmax(values?)
}

/// Largest |Bi| with its target (ISO 2.13, GOST 1.16).
pub(crate) fn max_reversal(targets: &[TargetResult]) -> (usize, f64) {
    argmax(targets.iter().map(|t| t.reversal.abs())).expect("an axis has at least one target")
}

/// The accuracy parameters `[A, A↑, A↓]` as `defs` defines them (ISO 2.22/2.23, GOST
/// (10)): none when S does not apply (n = 1).
pub(crate) fn accuracies(
    targets: &[TargetResult],
    defs: [&'static ParameterDef; 3],
) -> Vec<Parameter> {
    let [both, up, down] = defs;
    [(both, &[Up, Down][..]), (up, &[Up]), (down, &[Down])]
        .into_iter()
        .filter_map(|(def, dirs)| accuracy(targets, dirs).map(|a| Parameter::spanned(def, a)))
        .collect()
}

/// The repeatability parameters `[R, R↑, R↓]` as `defs` defines them, each with the
/// target of its maximum (ISO 2.18, GOST (7), (8)): none when S does not apply.
pub fn repeatabilities(
    targets: &[TargetResult],
    defs: [&'static ParameterDef; 3],
) -> Vec<Parameter> {
    let [both, up, down] = defs;
    [
        max_repeatability(targets).map(|r| Parameter::located(both, r)),
        max_repeatability_in(targets, Up).map(|r| Parameter::located(up, r)),
        max_repeatability_in(targets, Down).map(|r| Parameter::located(down, r)),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// Mean of Bi (ISO 2.14, GOST 1.15).
pub(crate) fn mean_reversal(targets: &[TargetResult]) -> f64 {
    targets.iter().map(|t| t.reversal).sum::<f64>() / targets.len() as f64
}
