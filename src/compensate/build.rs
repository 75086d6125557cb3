//! The table that cancels the mean deviations x̄↑ and x̄↓ (ISO 230-2 2.8), resampled onto
//! the controller's grid: one table per direction where the controller holds two, the mean
//! (and the reversal for its backlash parameter) where it holds one; folded onto one
//! revolution for a modulo table; shifted to zero at the reference point when one is given.

use super::Settings;
use super::controllers::{Directions, Format};
use super::grid::{REVOLUTION_DEG, modulo};
use super::table::{Table, linear};
use crate::measurement::AxisData;
use crate::units::Direction;

/// Mean deviation x̄ at each target for one direction.
fn means(data: &AxisData, direction: Direction) -> Vec<f64> {
    (0..data.target_count())
        .map(|i| {
            let d = data.deviations(i, direction);
            d.iter().sum::<f64>() / d.len() as f64
        })
        .collect()
}

/// The correction −x̄ at `p`: interpolated between the targets, and on a modulo table
/// the mean over every turn of the measured travel that passes `p`.
fn correction_at(data: &AxisData, means: &[f64], p: f64, wraps: bool) -> f64 {
    if !wraps {
        return -linear(&data.targets, means, p);
    }
    let (first, last) = data.measurement_travel();
    let turns =
        ((first - p) / REVOLUTION_DEG).ceil() as i64..=((last - p) / REVOLUTION_DEG).floor() as i64;
    let values: Vec<f64> = turns
        .map(|k| -linear(&data.targets, means, p + k as f64 * REVOLUTION_DEG))
        .collect();
    values.iter().sum::<f64>() / values.len().max(1) as f64
}

/// The table for `data` on `positions` in `format`.
pub fn table(data: &AxisData, positions: Vec<f64>, format: &Format, settings: &Settings) -> Table {
    let wraps = modulo(data, format);
    let per_direction = |direction| {
        let m = means(data, direction);
        let mut c: Vec<f64> = positions
            .iter()
            .map(|&p| correction_at(data, &m, p, wraps))
            .collect();
        if wraps {
            // 0° and 360° are one position: one value.
            let ends = (c[0] + c[c.len() - 1]) / 2.0;
            let last = c.len() - 1;
            (c[0], c[last]) = (ends, ends);
        }
        c
    };
    let mut table = Table {
        kind: data.kind,
        up: per_direction(Direction::Up),
        down: per_direction(Direction::Down),
        reference: settings.reference.unwrap_or(positions[0]),
        modulo_deg: wraps.then_some(REVOLUTION_DEG),
        positions,
    };
    let one = match format.directions {
        Directions::Unidirectional { backlash } => {
            one_table(&mut table, backlash);
            true
        }
        Directions::Bidirectional => false,
    };
    if settings.reference.is_some() {
        zero_at_reference(&mut table, one);
    }
    table
}

/// One table per axis: the mean correction in both directions, ± half the mean reversal
/// where the controller's backlash parameter adds it on reversal.
fn one_table(table: &mut Table, backlash: bool) {
    let half = if backlash {
        table.reversal_correction() / 2.0
    } else {
        0.0
    };
    let mean = table.mean();
    table.up = mean.iter().map(|m| m - half).collect();
    table.down = mean.iter().map(|m| m + half).collect();
}

/// Shifts both directions so the correction written at the reference point is zero (the
/// ↑ one, or the mean on a one-table controller): homing there is unchanged. A constant
/// changes no ISO 230-2 parameter.
fn zero_at_reference(table: &mut Table, one_table: bool) {
    let up = table.correction(table.reference, Direction::Up);
    let down = table.correction(table.reference, Direction::Down);
    let shift = if one_table { (up + down) / 2.0 } else { up };
    for v in table.up.iter_mut().chain(table.down.iter_mut()) {
        *v -= shift;
    }
}
