//! Residual data for the diagnosis charts: each reading against the base and the
//! extended model, the systematic deviation along the axis and the periodogram.

use super::analysis::{Analysis, smooth_trend};
use super::effects::Effect;
use super::fitted::Fitted;
use super::timeline;
use super::{AxisPoint, PeriodogramPoint, ResidualPoint, Residuals};

/// The residuals of `a` with the extended model `fit` of the `kept` effects.
pub(crate) fn residuals(a: &Analysis, fit: &Fitted, kept: &[Effect]) -> Residuals {
    let (p, data) = (&a.prep, a.data);
    let all = vec![true; a.x.len()];
    let (raw_means, _) = p.cell_means(&a.x, &all);
    let mut readings: Vec<ResidualPoint> = p
        .rows
        .iter()
        .zip(&a.x)
        .enumerate()
        .map(|(k, (r, x))| ResidualPoint {
            order: r.order,
            time_s: data.readings[r.reading].time_s,
            position: p.positions[r.i],
            direction: data.readings[r.reading].direction,
            run: data.run_labels[r.run],
            residual: x - raw_means[p.cell(r)],
            extended_residual: x - fit.pred.predict(p, k),
        })
        .collect();
    readings.sort_by_key(|r| r.order);
    let trend = smooth_trend(&p.positions, &a.means);
    let along_axis = (0..p.m)
        .map(|i| AxisPoint {
            position: p.positions[i],
            mean: a.means[i],
            trend: trend[i],
            residual: a.means[i] - trend[i],
            reversal: a.b[i],
        })
        .collect();
    Residuals {
        readings,
        along_axis,
        periodogram: a
            .periodic
            .periodogram
            .iter()
            .map(|&(period, power)| PeriodogramPoint { period, power })
            .collect(),
        time_effect: timeline::time_effect(a, fit, kept),
    }
}
