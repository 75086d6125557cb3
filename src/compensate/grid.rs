//! The controller's grid: the points of its table along the axis. Controllers that take
//! any increasing list get the measured targets; equidistant ones get points every
//! interval, aligned on the reference point and covering the measured travel, the
//! corrections interpolated between the targets; a modulo table covers one revolution.

use super::Settings;
use super::controllers::{Format, Refused, Spacing};
use crate::measurement::AxisData;
use crate::units::{AxisKind, fmt_fixed};

/// One revolution of a rotary axis, deg.
pub const REVOLUTION_DEG: f64 = 360.0;

/// Tolerance on positions (mm or deg): far below any controller's position unit.
const EPS: f64 = 1e-9;

/// The grid for `data` in `format`, or why the controller cannot hold it.
pub fn grid(data: &AxisData, format: &Format, settings: &Settings) -> Result<Vec<f64>, Refused> {
    let positions = match (settings.interval, format.spacing) {
        _ if modulo(data, format) => revolution(data, settings.interval)?,
        (None, Spacing::Free) => data.targets.clone(),
        (interval, _) => equidistant(data, interval, settings.reference)?,
    };
    if positions.len() > format.max_points {
        return Err(too_many(data, positions.len(), format.max_points));
    }
    Ok(positions)
}

/// Whether the table wraps: a rotary axis measured over a whole revolution, on a
/// controller that holds modulo tables.
pub fn modulo(data: &AxisData, format: &Format) -> bool {
    let (first, last) = data.measurement_travel();
    format.modulo && data.kind == AxisKind::Rotary && last - first >= REVOLUTION_DEG - EPS
}

/// Points every `interval` (default: the mean target spacing, to the micrometre or
/// 0.001°) through `reference` (default: the first target), from the last point at or
/// before the first target to the first at or after the last one.
fn equidistant(
    data: &AxisData,
    interval: Option<f64>,
    reference: Option<f64>,
) -> Result<Vec<f64>, Refused> {
    let (first, last) = data.measurement_travel();
    let step = interval.unwrap_or_else(|| mean_spacing(data));
    if step.is_nan() || step <= 0.0 {
        return Err(Refused::Grid(
            "one target only: give --interval for an equidistant table".into(),
        ));
    }
    let origin = reference.unwrap_or(first);
    let lo = ((first - origin) / step + EPS).floor() as i64;
    let hi = ((last - origin) / step - EPS).ceil() as i64;
    Ok((lo..=hi).map(|k| origin + k as f64 * step).collect())
}

/// The mean spacing of the targets, rounded to 0.001 (mm or deg).
fn mean_spacing(data: &AxisData) -> f64 {
    let (first, last) = data.measurement_travel();
    let gaps = data.target_count().saturating_sub(1).max(1) as f64;
    ((last - first) / gaps * 1000.0).round() / 1000.0
}

/// 0 to 360° every `interval` (default: the mean target spacing); the interval must
/// divide the revolution.
fn revolution(data: &AxisData, interval: Option<f64>) -> Result<Vec<f64>, Refused> {
    let step = interval.unwrap_or_else(|| mean_spacing(data));
    let count = REVOLUTION_DEG / step;
    if step.is_nan() || step <= 0.0 || (count - count.round()).abs() > 1e-6 {
        return Err(Refused::Grid(format!(
            "a modulo table needs an interval that divides 360°, got {}°",
            fmt_fixed(step, 4)
        )));
    }
    let count = count.round() as usize;
    Ok((0..=count).map(|k| k as f64 * step).collect())
}

fn too_many(data: &AxisData, points: usize, max: usize) -> Refused {
    let (first, last) = data.measurement_travel();
    let unit = data.kind.position_unit();
    let least = (last - first) / (max.saturating_sub(1).max(1)) as f64;
    Refused::Grid(format!(
        "{points} points, but the table holds at most {max}; choose --interval {} {unit} or more",
        fmt_fixed((least * 1000.0).ceil() / 1000.0, 3)
    ))
}
