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

/// The value at the target `p` (one of `targets`).
pub fn at(p: f64, targets: &[f64], values: &[f64]) -> f64 {
    values[targets.iter().position(|t| *t == p).expect("a target")]
}

/// The hand-worked linear axis of the controllers' examples: targets 0, 30, 70, 100 mm,
/// x̄↑ = 0, 3, −1, 2 µm and x̄↓ = x̄↑ + 2 µm.
pub(crate) fn irregular_linear() -> AxisData {
    let targets = [0.0, 30.0, 70.0, 100.0];
    axis(AxisKind::Linear, &targets, 2, |p, direction| {
        let up = at(p, &targets, &[0.0, 3.0, -1.0, 2.0]);
        if direction == Direction::Up {
            up
        } else {
            up + 2.0
        }
    })
}

/// The hand-worked linear axis of the TwinCAT and HEIDENHAIN examples: targets −100, −70,
/// −55, −20, 0 mm, x̄↑ = 0, 3.0, 1.53, −2.0, 1.0 µm and x̄↓ = x̄↑ + 2.0 µm.
pub(crate) fn negative_linear() -> AxisData {
    let targets = [-100.0, -70.0, -55.0, -20.0, 0.0];
    let up = [0.0, 3.0, 1.53, -2.0, 1.0];
    axis(AxisKind::Linear, &targets, 2, |p, direction| {
        at(p, &targets, &up)
            + if direction == Direction::Down {
                2.0
            } else {
                0.0
            }
    })
}

/// The hand-worked rotary axis of the TwinCAT and HEIDENHAIN examples: every 45° over
/// 0…360°, x̄↑ = 1.0, 3.6, 7.3, −1.8, 2.0″ at 0, 90, 180, 270, 360° (0 at the odd
/// multiples of 45°) and x̄↓ = x̄↑ − 1.44″.
pub(crate) fn quarter_turns_rotary() -> AxisData {
    let targets: Vec<f64> = (0..=8).map(|k| k as f64 * 45.0).collect();
    axis(AxisKind::Rotary, &targets, 2, |p, direction| {
        let up = match p as i64 {
            0 => 1.0,
            90 => 3.6,
            180 => 7.3,
            270 => -1.8,
            360 => 2.0,
            _ => 0.0,
        };
        up - if direction == Direction::Down {
            1.44
        } else {
            0.0
        }
    })
}

/// The hand-worked rotary axis of the Siemens and ecmc examples: targets 0, 90, 180, 270,
/// 360°, x̄↑ = 0, 3.6, −7.2, 1.8, 3.6″ and x̄↓ = x̄↑ + 3.6″.
pub(crate) fn whole_turn_rotary() -> AxisData {
    let targets = [0.0, 90.0, 180.0, 270.0, 360.0];
    axis(AxisKind::Rotary, &targets, 2, |p, direction| {
        let up = at(p, &targets, &[0.0, 3.6, -7.2, 1.8, 3.6]);
        if direction == Direction::Up {
            up
        } else {
            up + 3.6
        }
    })
}
