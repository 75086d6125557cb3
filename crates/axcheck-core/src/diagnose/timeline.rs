//! A kept effect in time drawn against the run means ([`TimeEffect`], its run means and
//! curve points, and how they are computed): what the report's time chart shows,
//! so that a reader sees the found drift line or warm-up curve against the data instead
//! of trusting its numbers.
//!
//! * Run means of the partial residuals for the effect in time (the component-plus-residual
//!   plot of Larsen and McCleary 1972, "The Use of Partial Residual Plots in Regression
//!   Analysis"): each reading less its target and direction's systematic deviation as the
//!   extended model has it — the mean of the cell's readings with the fitted effect in
//!   time taken out — and less the effect's mean over the readings; per run and
//!   direction, at the mean time of its readings. Under the standard cycle (ISO 230-2
//!   Fig. 1) a run and direction is one pass over the targets, so its mean follows the
//!   effect and averages the scatter down by √k. (The base model's residuals, each
//!   reading less its cell's mean, would put the ↑ means above a drift and the ↓ means
//!   below it: a cell's mean holds the drift at the cell's mean time, which is earlier
//!   for ↑ than for ↓.)
//! * The curve: the extended model's drift, warm-up and thermal growth at the mean target
//!   position (where the thermal growth's part in proportion to position is zero), less
//!   the effect's mean over the readings.
//! * The band: the curve ± 2σ/√k, σ the extended model's scatter and k the median
//!   number of readings of a run in one direction: where a run mean lies in 95 % of tests
//!   when the curve is all the time effect there is (normal scatter); run means outside
//!   show what the curve leaves (run offsets, a curve of another shape).

use super::analysis::Analysis;
use super::effects::Effect;
use super::fitted::Fitted;
use super::prep::TimeUnit;
use super::time_fit::warm_shape;
use crate::units::Direction;
use serde::Serialize;

/// A kept effect in time drawn against the run means (this module).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TimeEffect {
    /// The kept terms the curve holds: `drift`, `warm_up`, `thermal_growth`.
    pub terms: Vec<Effect>,
    /// Each run's mean partial residual for the effect (a reading less its target and
    /// direction's systematic deviation as the extended model has it, less the effect's
    /// mean over the readings), per direction.
    pub run_means: Vec<RunMean>,
    /// The fitted effect at the mean target position, less its mean over the readings
    /// (as the residuals are less their cell's mean), at times across the test.
    pub curve: Vec<CurvePoint>,
    /// Half-width of the band about the curve, 2σ/√k: σ the extended model's scatter, k
    /// the readings of a run in one direction; a run mean lies inside in 95 % of tests
    /// when the curve is all the time effect there is.
    pub band: f64,
    /// The extended model's scatter σ (the residuals after it lie within ±2σ).
    pub sigma: f64,
}

/// One run's mean partial residual in one direction.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunMean {
    /// Run label as in the file.
    pub run: u32,
    pub direction: Direction,
    /// Mean time of its readings, s (None without time stamps).
    pub time_s: Option<f64>,
    /// Mean rank of its readings in time (0-based).
    pub order: f64,
    pub mean: f64,
    pub readings: usize,
}

/// One point of a fitted curve in time.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CurvePoint {
    /// Time, s (None without time stamps).
    pub time_s: Option<f64>,
    /// Rank in time it falls at (the standard test cycle's order without time stamps).
    pub order: f64,
    pub value: f64,
}

/// Points of the drawn curve across the test.
const POINTS: usize = 121;

/// The kept effects in time of the extended model `fit` against the run means; None when
/// it keeps none of drift, warm-up and thermal growth.
pub(crate) fn time_effect(a: &Analysis, fit: &Fitted, kept: &[Effect]) -> Option<TimeEffect> {
    let in_time = [Effect::Drift, Effect::WarmUp, Effect::ThermalGrowth];
    let terms: Vec<Effect> = kept
        .iter()
        .copied()
        .filter(|e| in_time.contains(e))
        .collect();
    let p = &a.basis.prep;
    if terms.is_empty() || p.rows.is_empty() {
        return None;
    }
    let time = &fit.pred.time;
    let effect = |t: f64| {
        let warm = time
            .tau
            .map_or(0.0, |tau| time.warm_a * warm_shape(t - p.t0, tau));
        time.beta * (t - p.tbar) + warm
    };
    // The fitted effect at each reading (its target's position included).
    let at_rows: Vec<f64> = (p.rows.iter())
        .map(|r| {
            let dp = p.positions[r.i] - p.pbar;
            let warm = time.tau.map_or(0.0, |tau| {
                (time.warm_a + time.warm_g * dp) * warm_shape(r.t - p.t0, tau)
            });
            (time.beta + time.gamma * dp) * (r.t - p.tbar) + warm
        })
        .collect();
    let mean_effect = at_rows.iter().sum::<f64>() / at_rows.len() as f64;
    let ranks = ranks_in_time(a);
    let curve = (0..POINTS)
        .map(|j| {
            let t = p.t0 + p.t_span * j as f64 / (POINTS - 1) as f64;
            CurvePoint {
                time_s: (p.time_unit == TimeUnit::Hours).then_some(t * 3600.0),
                order: rank_at(&ranks, t),
                value: effect(t) - mean_effect,
            }
        })
        .collect();
    let run_means = run_means(a, &at_rows, mean_effect);
    let mut counts: Vec<usize> = run_means.iter().map(|m| m.readings).collect();
    counts.sort_unstable();
    let k = counts.get(counts.len() / 2).copied().unwrap_or(1).max(1);
    let s2 = time.sigma2();
    let sigma = if s2 > 0.0 { s2.sqrt() } else { f64::NAN };
    Some(TimeEffect {
        terms,
        run_means,
        curve,
        band: 2.0 * sigma / (k as f64).sqrt(),
        sigma,
    })
}

/// Each run's mean partial residual per direction (each reading less its cell's mean
/// with the fitted effect `at_rows` taken out, less the effect's `mean`), at its
/// readings' mean time and rank; in the order of the runs, ↑ before ↓.
fn run_means(a: &Analysis, at_rows: &[f64], mean: f64) -> Vec<RunMean> {
    let (p, data) = (&a.basis.prep, a.basis.data);
    let all = vec![true; a.basis.x.len()];
    let without: Vec<f64> = a.basis.x.iter().zip(at_rows).map(|(x, e)| x - e).collect();
    let (systematic, _) = p.cell_means(&without, &all);
    let mut sums = vec![(0.0, 0.0, 0.0, 0usize); 2 * p.n];
    for (r, x) in p.rows.iter().zip(&a.basis.x) {
        let s = &mut sums[2 * r.run + r.d];
        s.0 += x - systematic[p.cell(r)] - mean;
        s.1 += data.readings[r.reading].time_s.unwrap_or(f64::NAN);
        s.2 += r.order as f64;
        s.3 += 1;
    }
    let timed = p.time_unit == TimeUnit::Hours;
    (sums.iter().enumerate())
        .filter(|(_, s)| s.3 > 0)
        .map(|(g, &(sum, time, order, count))| {
            let c = count as f64;
            RunMean {
                run: data.run_labels[g / 2],
                direction: if g % 2 == 0 {
                    Direction::Up
                } else {
                    Direction::Down
                },
                time_s: (timed && time.is_finite()).then(|| time / c),
                order: order / c,
                mean: sum / c,
                readings: count,
            }
        })
        .collect()
}

/// The readings' (time, rank) sorted by time.
fn ranks_in_time(a: &Analysis) -> Vec<(f64, f64)> {
    let mut v: Vec<(f64, f64)> = (a.basis.prep.rows.iter())
        .map(|r| (r.t, r.order as f64))
        .collect();
    v.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.total_cmp(&y.1)));
    v
}

/// The rank in time at time `t`, interpolated between the readings' (time, rank).
fn rank_at(ranks: &[(f64, f64)], t: f64) -> f64 {
    let after = ranks.partition_point(|&(tk, _)| tk < t);
    match (after.checked_sub(1).map(|k| ranks[k]), ranks.get(after)) {
        (Some((t0, r0)), Some(&(t1, r1))) if t1 > t0 => r0 + (r1 - r0) * (t - t0) / (t1 - t0),
        (_, Some(&(_, r1))) => r1,
        (Some((_, r0)), None) => r0,
        (None, None) => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Ranks 0, 1, 2 at times 0, 1, 3: 1.5 at t = 2 (halfway from 1 to 3), the ends held.
    #[test]
    fn rank_by_hand() {
        let ranks = [(0.0, 0.0), (1.0, 1.0), (3.0, 2.0)];
        assert_eq!(rank_at(&ranks, 2.0), 1.5);
        assert_eq!(rank_at(&ranks, 0.5), 0.5);
        assert_eq!(rank_at(&ranks, -1.0), 0.0);
        assert_eq!(rank_at(&ranks, 9.0), 2.0);
        assert_eq!(rank_at(&[], 1.0), 0.0);
    }
}
