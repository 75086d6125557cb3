//! Residual data for the diagnosis charts: each reading against the base and the
//! extended model, the systematic deviation along the axis and the periodogram: their
//! types and how they are computed.

use super::analysis::Analysis;
use super::effects::Effect;
use super::fitted::Fitted;
use super::maths::linalg::smooth_trend;
use super::timeline::{self, TimeEffect};
use crate::units::Direction;
use serde::Serialize;

/// A reading's residuals, for charts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResidualPoint {
    /// Rank in time (time stamps, or the standard test cycle's order without them).
    pub order: usize,
    pub time_s: Option<f64>,
    pub position: f64,
    pub direction: Direction,
    /// Run label as in the file.
    pub run: u32,
    /// Reading minus its cell mean (target and direction).
    pub residual: f64,
    /// Reading minus the extended model's prediction.
    pub extended_residual: f64,
}

/// The systematic deviation along the axis, for charts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxisPoint {
    pub position: f64,
    /// Bidirectional mean X̄i of the readings corrected for time effects.
    pub mean: f64,
    /// Its smooth (cubic) trend.
    pub trend: f64,
    /// mean − trend: what the periodic search looks at.
    pub residual: f64,
    /// Reversal value Bi of the corrected readings.
    pub reversal: f64,
}

/// One point of the periodogram.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeriodogramPoint {
    pub period: f64,
    /// Normalised power: the share of the trend residuals' sum of squares a sinusoid of
    /// this period explains.
    pub power: f64,
}

/// Residual data for charts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Residuals {
    pub readings: Vec<ResidualPoint>,
    pub along_axis: Vec<AxisPoint>,
    /// Lomb–Scargle periodogram of `along_axis` residuals.
    pub periodogram: Vec<PeriodogramPoint>,
    /// The kept drift, warm-up or thermal growth against the run means (None when the
    /// extended model keeps none of them).
    pub time_effect: Option<TimeEffect>,
}

/// The residuals of `a` with the extended model `fit` of the `kept` effects.
pub(crate) fn residuals(a: &Analysis, fit: &Fitted, kept: &[Effect]) -> Residuals {
    let (p, data) = (&a.basis.prep, a.basis.data);
    let all = vec![true; a.basis.x.len()];
    let (raw_means, _) = p.cell_means(&a.basis.x, &all);
    let mut readings: Vec<ResidualPoint> = p
        .rows
        .iter()
        .zip(&a.basis.x)
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
    let trend = smooth_trend(&p.positions, &a.basis.means);
    let along_axis = (0..p.m)
        .map(|i| AxisPoint {
            position: p.positions[i],
            mean: a.basis.means[i],
            trend: trend[i],
            residual: a.basis.means[i] - trend[i],
            reversal: a.basis.b[i],
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
