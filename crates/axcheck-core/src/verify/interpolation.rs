//! The uncertainty of a mean before interpolated at a target of the re-measurement, where
//! the targets of the two measurements differ: the per-target χ² compares means at the
//! same positions, and a mean before between its targets is an estimate.
//!
//! Two parts, added in quadrature and taken as standard uncertainties (the difference of
//! two methods as the uncertainty of the cruder one):
//! - **curvature**: the linear value's difference from a cubic through the four nearest
//!   means before (a quadratic through three where fewer are on hand; beyond the ends,
//!   where the end mean is held, what the end interval's slope adds over the distance);
//! - **roughness**: what no interpolation between the targets follows (an error shorter
//!   than twice their spacing: a screw's pitch error between targets 100 mm apart): each
//!   interior mean before predicted by the cubic through its two neighbours either side,
//!   the mean square of the misses over both directions less what the means' own scatter
//!   (s/√n through the cubic's weights) explains, raised to its upper 95 % bound (ν/χ²_ν
//!   at 5 %, ν the interior targets: the two directions of a target share its error).
//!   Predicted across twice the spacing, it over-states the curvature part of a smooth
//!   error: conservative.
//!
//! Measured on the example campaign's axis models (tables acting as named, re-measured at
//! targets jittered anew, 40 seeds each): with the curvature part alone, VMC-07 X (a
//! 0.5 µm error of 10 mm pitch between targets 98 mm apart) left χ²/ν at 5.2 and every seed
//! beyond the 0.1 % point; with both, χ²/ν 0.48 and 1 seed of 40 (VMC-07 Z, 8 targets: 3;
//! GANTRY-1 X work: 2), the roughness of few targets being itself uncertain. A 4 µm sine of
//! 300 mm between targets 50 mm apart, without either part, was beyond it in 7 seeds of
//! 50. On the same targets nothing is added: re-measure at the targets before, as ISO
//! 230-2 asks of a re-measurement, for the test to see what the targets resolve.

use crate::compensate::build::means;
use crate::compensate::linear;
use crate::diagnose::stats::chi2_upper;
use crate::measurement::AxisData;
use crate::units::Direction;

/// A target of the re-measurement within this of a target before is on it (mm or deg).
const SAME_TARGET: f64 = 1e-3;

/// The standard uncertainty of the linear interpolation of `values` at `x` between
/// `positions`, `rough` the roughness ([`roughness`]); 0 on a position.
pub fn u(positions: &[f64], values: &[f64], x: f64, rough: f64) -> f64 {
    if positions.iter().any(|p| (p - x).abs() <= SAME_TARGET) {
        return 0.0;
    }
    curvature(positions, values, x).hypot(rough)
}

/// |cubic − linear| at `x` (see the module); beyond the ends the end slope over the
/// distance; 0 with fewer than two positions (two: a line, exact but beyond its ends).
pub(crate) fn curvature(positions: &[f64], values: &[f64], x: f64) -> f64 {
    let n = positions.len();
    if n < 2 {
        return 0.0;
    }
    let slope = |i: usize| (values[i + 1] - values[i]) / (positions[i + 1] - positions[i]);
    if x < positions[0] {
        return (slope(0) * (positions[0] - x)).abs();
    }
    if x > positions[n - 1] {
        return (slope(n - 2) * (x - positions[n - 1])).abs();
    }
    if n < 3 {
        return 0.0;
    }
    let k = positions.partition_point(|p| *p <= x).saturating_sub(1);
    // The four nearest points k − 1 … k + 2, moved inside the table at its ends.
    let first = k.saturating_sub(1).min(n.saturating_sub(4));
    let last = (first + 4).min(n);
    let smooth = lagrange(&positions[first..last], &values[first..last], x);
    (smooth - linear(positions, values, x)).abs()
}

/// The roughness of the means before (see the module), µm or arcsec; `s` their pooled
/// scatter. 0 with fewer than five targets (no interior mean has two neighbours a side).
pub(crate) fn roughness(before: &AxisData, s: f64) -> f64 {
    let q = &before.targets;
    let u_mean2 = s * s / before.runs() as f64;
    let (mut sum, mut count) = (0.0, 0usize);
    for d in [Direction::Up, Direction::Down] {
        let x = means(before, d);
        for k in 2..q.len().saturating_sub(2) {
            let xs = [q[k - 2], q[k - 1], q[k + 1], q[k + 2]];
            let ys = [x[k - 2], x[k - 1], x[k + 1], x[k + 2]];
            let weights: f64 = (0..4).map(|j| basis(&xs, j, q[k]).powi(2)).sum();
            let miss = x[k] - lagrange(&xs, &ys, q[k]);
            sum += miss * miss - u_mean2 * (1.0 + weights);
            count += 1;
        }
    }
    let targets = q.len().saturating_sub(4);
    match count {
        0 => 0.0,
        _ => (sum / count as f64 * upper_bound_factor(targets))
            .max(0.0)
            .sqrt(),
    }
}

/// The factor from a variance estimated on `targets` independent misses to its upper 95 %
/// bound: ν/χ²_ν(5 %), ν the targets (the two directions of a target share its error).
fn upper_bound_factor(targets: usize) -> f64 {
    let nu = targets.max(1) as f64;
    // χ²_ν(5 %) by bisection of its upper tail (decreasing in x).
    let (mut lo, mut hi) = (0.0, 10.0 * nu + 100.0);
    for _ in 0..100 {
        let mid = (lo + hi) / 2.0;
        if chi2_upper(mid, nu) > 0.95 {
            lo = mid
        } else {
            hi = mid
        }
    }
    nu / ((lo + hi) / 2.0)
}

/// The polynomial through the points (`xs`, `ys`) at `x` (Lagrange's form).
fn lagrange(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    (0..xs.len()).map(|i| basis(xs, i, x) * ys[i]).sum()
}

/// Lagrange's basis polynomial `i` of the points `xs` at `x`.
fn basis(xs: &[f64], i: usize, x: f64) -> f64 {
    let mut w = 1.0;
    for (j, &xj) in xs.iter().enumerate() {
        if j != i {
            w *= (x - xj) / (xs[i] - xj);
        }
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a straight line the interpolation is exact; on a parabola y = x² between 0 and
    /// 10 at 5 the linear value is 50, the true one 25: |25 − 50|; on a target (to 1 µm)
    /// nothing, roughness or not; 5 beyond the end the slope of the last interval (50)
    /// over 5: 250; the roughness adds in quadrature.
    #[test]
    fn the_interpolation_uncertainty_by_hand() {
        let p = [0.0, 10.0, 20.0, 30.0];
        let line = [1.0, 3.0, 5.0, 7.0];
        assert!(u(&p, &line, 14.0, 0.0) < 1e-12);
        let parabola = [0.0, 100.0, 400.0, 900.0];
        assert!((u(&p, &parabola, 5.0, 0.0) - 25.0).abs() < 1e-9);
        assert!((u(&p, &parabola, 25.0, 0.0) - 25.0).abs() < 1e-9);
        assert_eq!(u(&p, &parabola, 10.0005, 3.0), 0.0);
        assert!((u(&p, &parabola, 35.0, 0.0) - 250.0).abs() < 1e-9);
        assert!((u(&p, &line, -5.0, 0.0) - 1.0).abs() < 1e-12);
        assert!((u(&p, &line, 14.0, 3.0) - 3.0).abs() < 1e-12);
        assert_eq!(u(&p[..2], &parabola[..2], 5.0, 0.0), 0.0);
    }

    /// The cubic's weights at the middle of ±h, ±2h: −1/6, 2/3, 2/3, −1/6.
    #[test]
    fn the_cubic_weights_at_the_middle() {
        let xs = [-2.0, -1.0, 1.0, 2.0];
        let w: Vec<f64> = (0..4).map(|j| basis(&xs, j, 0.0)).collect();
        for (got, want) in w.iter().zip([-1.0 / 6.0, 2.0 / 3.0, 2.0 / 3.0, -1.0 / 6.0]) {
            assert!((got - want).abs() < 1e-12, "{w:?}");
        }
    }
}
