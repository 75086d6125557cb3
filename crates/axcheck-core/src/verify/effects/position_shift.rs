//! `position_shift`: the table acted at positions shifted along the axis: the reference
//! point (machine zero) of the table is not the one of the measurement, the table's start
//! was entered off by an interval, or the laser's datum moved between the measurements.
//!
//! The shift is fitted, not picked from a few: χ² of the change measured against the
//! shifted table (new(P − s) − old(P)) is evaluated every eighth of the table's mean
//! interval h from −3 h to 3 h, and its least value refined by golden-section search within
//! an eighth of an interval either side. Picking among quarter intervals in a fixed order,
//! the simpler kept unless a later one was better by 9, named ¾ of a 118 mm interval
//! (88.5 mm) for a shift of one: on a smooth table neighbouring shifts differ little in χ²
//! (a shift of a linear table is only an offset, which is free), so the first acceptable one
//! won over the best. The fit is reported as the nearest quarter interval when that is
//! within the fit's 95 % interval (χ² less than 3.84 above the least, the 95 % point of χ²
//! with one degree of freedom), else as fitted.

use super::{Candidate, EffectContext, Key, VerifyEffect, chi2};
use crate::units::fmt_position;

pub struct PositionShift;

/// The coarse grid: steps per interval, and intervals either way.
const STEPS_PER_INTERVAL: f64 = 8.0;
const REACH_INTERVALS: f64 = 3.0;

/// χ² above the least within which a round shift (a quarter interval) is kept: the 95 %
/// point of χ² with one degree of freedom.
const ROUND_WITHIN: f64 = 3.841;

impl VerifyEffect for PositionShift {
    fn candidates(&self, ctx: &EffectContext) -> Vec<Candidate> {
        let h = ctx.interval();
        if h <= 0.0 {
            return Vec::new();
        }
        let fit = |s: f64| chi2(ctx.rows, &ctx.change_with(ctx.new, s));
        let shift = best_shift(&fit, h);
        if shift == 0.0 {
            return Vec::new();
        }
        let unit = ctx.new.kind.position_unit();
        vec![Candidate {
            key: Key::PositionShift,
            change: ctx.change_with(ctx.new, shift),
            params: vec![("shift", shift), ("intervals", shift / h)],
            what: format!(
                "the table acted {} {unit} {} along the axis ({} table intervals of {} {unit}): its reference point is not the measurement's",
                fmt_position(round_to(shift.abs(), 1e-3)),
                if shift > 0.0 { "further" } else { "back" },
                fmt_position(round_to(shift.abs() / h, 1e-2)),
                fmt_position(round_to(h, 1e-3))
            ),
        }]
    }
}

/// The shift (mm or deg) of least χ², as the nearest quarter interval `h` when that fits
/// within [`ROUND_WITHIN`]; 0 when no shift fits better than none.
fn best_shift(fit: &dyn Fn(f64) -> f64, h: f64) -> f64 {
    let step = h / STEPS_PER_INTERVAL;
    let reach = (REACH_INTERVALS * STEPS_PER_INTERVAL) as i32;
    // Smaller shifts first: of two that fit alike, the smaller is kept.
    let coarse = (1..=reach)
        .flat_map(|k| [k, -k])
        .map(|k| k as f64 * step)
        .map(|s| (s, fit(s)))
        .fold(
            (0.0, fit(0.0)),
            |best, (s, c)| if c < best.1 { (s, c) } else { best },
        );
    if coarse.0 == 0.0 {
        return 0.0;
    }
    let (shift, least) = golden(fit, coarse.0 - step, coarse.0 + step);
    let (shift, least) = if least < coarse.1 {
        (shift, least)
    } else {
        coarse
    };
    let round = (shift / (h / 4.0)).round() * h / 4.0;
    if round != 0.0 && fit(round) <= least + ROUND_WITHIN {
        round
    } else {
        shift
    }
}

/// The least of `f` on [a, b] by golden-section search (60 steps: far below a micrometre
/// over any interval), and its value.
fn golden(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (a, b);
    let mut c = b - ratio * (b - a);
    let mut d = a + ratio * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..60 {
        if fc < fd {
            (b, d, fd) = (d, c, fc);
            c = b - ratio * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + ratio * (b - a);
            fd = f(d);
        }
    }
    if fc < fd { (c, fc) } else { (d, fd) }
}

/// `x` rounded to a multiple of `q`, for the evidence.
fn round_to(x: f64, q: f64) -> f64 {
    (x / q).round() * q
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A parabola of least 3 at 47.3, interval 20: the fit finds 47.3 (not a quarter
    /// interval: 45 and 50 are far above); flattened tenfold, 45 is within 3.84 and named.
    #[test]
    fn the_shift_is_fitted_and_rounded_only_within_its_interval() {
        let sharp = |s: f64| 3.0 + 10.0 * (s - 47.3).powi(2);
        assert!((best_shift(&sharp, 20.0) - 47.3).abs() < 1e-6);
        let flat = |s: f64| 3.0 + 0.1 * (s - 47.3).powi(2);
        assert_eq!(best_shift(&flat, 20.0), 45.0);
        let none = |s: f64| 3.0 + s * s;
        assert_eq!(best_shift(&none, 20.0), 0.0);
    }
}
