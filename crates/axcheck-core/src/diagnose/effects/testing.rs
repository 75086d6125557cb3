//! Tests' measurements in the standard cycle (ISO 230-2 Fig. 1): the targets up, then
//! down, run after run, a reading at fixed intervals.

use crate::measurement::{AxisData, RawReading};
use crate::units::{AxisKind, Direction};

/// A linear axis measured on `targets` in `runs` standard cycles, reading `k` (from 0) at
/// `first_s + every_s · k` seconds, its deviation `deviation(target, direction, time_s)`.
pub(crate) fn standard_cycle(
    targets: &[f64],
    runs: u32,
    (first_s, every_s): (f64, f64),
    deviation: impl Fn(f64, Direction, f64) -> f64,
) -> AxisData {
    let mut raw = Vec::new();
    let mut k = 0.0;
    for run in 1..=runs {
        let up = targets.iter().map(|&p| (p, Direction::Up));
        let down = targets.iter().rev().map(|&p| (p, Direction::Down));
        for (target, direction) in up.chain(down) {
            let time_s = first_s + every_s * k;
            k += 1.0;
            raw.push(RawReading {
                target,
                direction,
                run,
                deviation: deviation(target, direction, time_s),
                time_s: Some(time_s),
                temps_c: Vec::new(),
                line: 0,
            });
        }
    }
    AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "standard cycle").unwrap()
}
