//! Axes with known deviations for the controllers' hand-worked examples.

use crate::measurement::{AxisData, RawReading};
use crate::units::{AxisKind, Direction};

/// An axis of `kind` with the given targets and `runs` approaches per direction, each
/// deviation `deviation(target, direction)` (the same on every run: x̄ = the value).
pub fn axis(
    kind: AxisKind,
    targets: &[f64],
    runs: u32,
    deviation: impl Fn(f64, Direction) -> f64,
) -> AxisData {
    let mut raw = Vec::new();
    for run in 1..=runs {
        for direction in [Direction::Up, Direction::Down] {
            for &target in targets {
                raw.push(RawReading {
                    target,
                    direction,
                    run,
                    deviation: deviation(target, direction),
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(kind, raw, vec![], "test").expect("a complete test")
}

/// A linear axis with `count` targets every `step` mm from `first`, no deviation.
pub fn straight(first: f64, step: f64, count: usize) -> AxisData {
    let targets: Vec<f64> = (0..count).map(|k| first + k as f64 * step).collect();
    axis(AxisKind::Linear, &targets, 2, |_, _| 0.0)
}
