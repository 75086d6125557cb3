//! The two measurements side by side: at each target of the re-measurement and in each
//! direction, the mean deviation before (interpolated where the targets differ), the
//! change the tables applied, the mean achieved, and the standard uncertainty of the
//! difference of two means, from each measurement's pooled scatter (ISO 230-2 2.15,
//! GUM 4.2: s/√n for a mean of n readings).
//!
//! Where the targets differ, the mean before at a target of the re-measurement is
//! interpolated linearly, and the interpolation's uncertainty joins the difference's
//! ([`super::interpolation`]).

use super::interpolation;
use crate::compensate::build::means;
use crate::compensate::{Table, linear};
use crate::evaluate::stats::sample_sd;
use crate::measurement::AxisData;
use crate::units::Direction;
use serde::Serialize;

/// One target and direction of the re-measurement.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ComparedTarget {
    /// Target position, mm or deg.
    pub position: f64,
    pub direction: Direction,
    /// Mean deviation before the table, µm or arcsec (interpolated between the targets of
    /// the measurement before where they differ).
    pub before: f64,
    /// The correction the new table adds here less the one active before: the predicted
    /// change.
    pub applied: f64,
    /// before + applied.
    pub predicted: f64,
    /// Mean deviation measured after the table was loaded.
    pub achieved: f64,
    /// achieved − predicted − the constant offset between the two measurements.
    pub difference: f64,
    /// Standard uncertainty of the difference of the two means, with the interpolation's
    /// where the mean before is interpolated.
    pub u: f64,
}

impl ComparedTarget {
    /// The change measured: achieved − before.
    pub fn change(&self) -> f64 {
        self.achieved - self.before
    }
}

/// The pooled standard deviation of a measurement's readings about their target means
/// (ISO 230-2 2.15 pooled over targets and directions); `None` for n = 1.
pub(crate) fn pooled_s(data: &AxisData) -> Option<f64> {
    let mut sum = 0.0;
    let mut count = 0usize;
    for i in 0..data.target_count() {
        for d in [Direction::Up, Direction::Down] {
            let s = sample_sd(data.deviations(i, d))?;
            sum += s * s;
            count += 1;
        }
    }
    (count > 0).then(|| (sum / count as f64).sqrt())
}

/// The standard uncertainty of a difference of a target mean after and one before, from
/// the pooled scatter `s` of before and after (s/√n each).
fn u_means(before: &AxisData, after: &AxisData, s: (f64, f64)) -> f64 {
    (s.0 * s.0 / before.runs() as f64 + s.1 * s.1 / after.runs() as f64).sqrt()
}

/// The rows of the re-measurement `after` against `before`, with `old` (the correction
/// active before; `None`: nothing) replaced by `new`; `s`: the pooled scatter of before
/// and after.
pub fn rows(
    before: &AxisData,
    after: &AxisData,
    old: Option<&Table>,
    new: &Table,
    s: (f64, f64),
) -> Vec<ComparedTarget> {
    let u = u_means(before, after, s);
    let rough = interpolation::roughness(before, s.0);
    let mut rows = Vec::with_capacity(2 * after.target_count());
    for d in [Direction::Up, Direction::Down] {
        let (b, a) = (means(before, d), means(after, d));
        for (i, &p) in after.targets.iter().enumerate() {
            let before_mean = linear(&before.targets, &b, p);
            let u_interpolation = interpolation::u(&before.targets, &b, p, rough);
            let applied = new.correction(p, d) - old.map_or(0.0, |t| t.correction(p, d));
            rows.push(ComparedTarget {
                position: p,
                direction: d,
                before: before_mean,
                applied,
                predicted: before_mean + applied,
                achieved: a[i],
                difference: 0.0,
                u: u.hypot(u_interpolation),
            });
        }
    }
    let offset = weighted_mean(rows.iter().map(|r| (r.achieved - r.predicted, r.u)));
    for r in rows.iter_mut() {
        r.difference = r.achieved - r.predicted - offset;
    }
    rows
}

/// The mean of values weighted by 1/u².
pub(crate) fn weighted_mean(values: impl Iterator<Item = (f64, f64)>) -> f64 {
    let (mut sum, mut weights) = (0.0, 0.0);
    for (v, u) in values {
        let w = 1.0 / (u * u);
        sum += w * v;
        weights += w;
    }
    if weights > 0.0 { sum / weights } else { 0.0 }
}
