//! Compensation tables: from a measured axis to the correction its controller adds,
//! interpolated along the axis, and the parameters predicted after compensation.
//!
//! A deviation is actual − target (ISO 230-2 2.7). A controller that adds the correction c
//! to reach a target moves to target + c + X(target), so the correction that cancels the
//! mean deviation is c = −x̄ at each target and direction (↑ and ↓ separately where the
//! controller holds bidirectional tables). The prediction applies the table to the
//! measured readings as the controller would (linear interpolation between its points,
//! its quantisation) and evaluates the result again; the floor is the repeatability, which
//! no table removes.

pub mod controllers;

use crate::evaluate::{self, Evaluation, StandardId};
use crate::measurement::AxisData;
use crate::units::{AxisKind, Direction};
use serde::Serialize;

/// A correction table on the controller's grid: one correction per point and direction,
/// in the deviation unit (µm or arcsec).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table {
    #[serde(skip)]
    pub kind: AxisKind,
    /// Grid positions, mm or deg, ascending.
    pub positions: Vec<f64>,
    /// Correction added on approaches in the positive direction (↑).
    pub up: Vec<f64>,
    /// Correction added on approaches in the negative direction (↓).
    pub down: Vec<f64>,
}

/// Mean deviation x̄ at each target for one direction.
fn means(data: &AxisData, direction: Direction) -> Vec<f64> {
    (0..data.target_count())
        .map(|i| {
            let d = data.deviations(i, direction);
            d.iter().sum::<f64>() / d.len() as f64
        })
        .collect()
}

/// Linear interpolation of `values` at `positions` (ascending) at `x`; constant beyond the
/// ends (controllers hold the end value or refuse; the grid stays inside the travel).
pub fn linear(positions: &[f64], values: &[f64], x: f64) -> f64 {
    match positions.len() {
        0 => 0.0,
        1 => values[0],
        n => {
            if x <= positions[0] {
                return values[0];
            }
            if x >= positions[n - 1] {
                return values[n - 1];
            }
            let k = positions.partition_point(|p| *p <= x) - 1;
            let t = (x - positions[k]) / (positions[k + 1] - positions[k]);
            values[k] + t * (values[k + 1] - values[k])
        }
    }
}

/// The grid: the measured targets, or points every `interval` from the first target to
/// the last (the last point at or before the last target).
pub fn grid(data: &AxisData, interval: Option<f64>) -> Vec<f64> {
    let (first, last) = data.measurement_travel();
    match interval {
        None => data.targets.clone(),
        Some(step) => {
            let count = ((last - first) / step + 1e-9).floor() as usize + 1;
            (0..count).map(|k| first + k as f64 * step).collect()
        }
    }
}

/// The table that cancels the mean deviations, resampled onto `positions`.
pub fn table(data: &AxisData, positions: Vec<f64>) -> Table {
    let correction = |direction| {
        let m = means(data, direction);
        positions
            .iter()
            .map(|&p| -linear(&data.targets, &m, p))
            .collect()
    };
    Table {
        kind: data.kind,
        up: correction(Direction::Up),
        down: correction(Direction::Down),
        positions,
    }
}

impl Table {
    /// The correction the controller adds at `position` approached in `direction`.
    pub fn correction(&self, position: f64, direction: Direction) -> f64 {
        let values = match direction {
            Direction::Up => &self.up,
            Direction::Down => &self.down,
        };
        linear(&self.positions, values, position)
    }
}

/// The readings as they would be with `table` active: each deviation plus the correction
/// at its target and direction.
pub fn apply(table: &Table, data: &AxisData) -> AxisData {
    data.map_deviations(|r| r.deviation + table.correction(data.targets[r.target], r.direction))
}

/// A test's compensation by its machine's controller: the table, the file as the
/// controller loads it (or why it cannot hold the table) and the parameters predicted.
#[derive(Debug, Clone)]
pub struct Compensation {
    pub controller: &'static str,
    /// The file's extension.
    pub extension: &'static str,
    pub table: Table,
    pub file: Result<String, String>,
    pub predicted: Evaluation,
}

/// The compensation of `data` by `controller` on the measured targets.
pub fn compensation(
    controller: &dyn controllers::Controller,
    data: &AxisData,
    standard: StandardId,
) -> Compensation {
    let table = table(data, grid(data, None));
    Compensation {
        controller: controller.name(),
        extension: controller.extension(),
        file: controller.write(&table).map_err(|e| e.to_string()),
        predicted: predict(&table, data, standard).predicted,
        table,
    }
}

/// The parameters measured and predicted after compensation.
#[derive(Debug, Clone)]
pub struct Prediction {
    pub measured: Evaluation,
    pub predicted: Evaluation,
}

/// Evaluates `data` by `standard` as measured and with `table` applied.
pub fn predict(table: &Table, data: &AxisData, standard: StandardId) -> Prediction {
    Prediction {
        measured: evaluate::evaluate(data, standard),
        predicted: evaluate::evaluate(&apply(table, data), standard),
    }
}
