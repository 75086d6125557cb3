//! The controller's grid: the points of its table along the axis. Controllers that take
//! any increasing list get the measured targets; equidistant ones get points every
//! interval, aligned on the reference point and covering the measured travel, the
//! corrections interpolated between the targets; a modulo table covers one revolution.

use super::Settings;
use super::controllers::controller::{Format, Refused, Spacing};
use crate::measurement::AxisData;
use crate::units::{AxisKind, fmt_fixed};

/// One revolution of a rotary axis, deg.
pub(crate) const REVOLUTION_DEG: f64 = 360.0;

/// Tolerance on positions (mm or deg): far below any controller's position unit.
const EPS: f64 = 1e-9;

/// The grid for `data` in `format`, or why the controller cannot hold it.
pub fn grid(data: &AxisData, format: &Format, settings: &Settings) -> Result<Vec<f64>, Refused> {
    let positions = match (settings.interval, format.spacing) {
        (None, Spacing::Free) if modulo(data, format) && one_turn(data) => data.targets.clone(),
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
    let step = interval.unwrap_or_else(|| dividing_step(mean_spacing(data)));
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

/// Whether the targets are one turn exactly, 0° to 360°: a controller that takes any
/// points keeps them.
fn one_turn(data: &AxisData) -> bool {
    let (first, last) = data.measurement_travel();
    first.abs() < EPS && (last - REVOLUTION_DEG).abs() < EPS
}

/// The interval nearest `spacing` that divides the revolution into a whole number of
/// 0.001° steps (360°/k for k a divisor of 360 000: every controller's position unit
/// divides it), the finer of two as near.
fn dividing_step(spacing: f64) -> f64 {
    let wanted = REVOLUTION_DEG / spacing;
    // 360 000 = 2⁶·3²·5⁴: its divisors are 2^a·3^b·5^c.
    let counts = (0..=6u32).flat_map(|a| {
        (0..=2u32)
            .flat_map(move |b| (0..=4u32).map(move |c| 2u32.pow(a) * 3u32.pow(b) * 5u32.pow(c)))
    });
    let best = counts.min_by(|a, b| {
        let d = |k: &u32| (f64::from(*k) - wanted).abs();
        d(a).total_cmp(&d(b)).then(b.cmp(a))
    });
    best.map_or(spacing, |k| REVOLUTION_DEG / f64::from(k))
}

fn too_many(data: &AxisData, points: usize, max: usize) -> Refused {
    let (first, last) = data.measurement_travel();
    let unit = data.kind.position_unit();
    let least = (last - first) / (max.saturating_sub(1).max(1)) as f64;
    Refused::Grid(format!(
        "{points} points, but the table holds at most {max}; choose an interval of {} {unit} or more (--interval, or compensation: {{interval}} in a campaign)",
        fmt_fixed((least * 1000.0).ceil() / 1000.0, 3)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::controllers::Directions;
    use crate::compensate::testing::{axis, straight};
    use crate::units::AxisKind;

    fn format(spacing: Spacing, modulo: bool) -> Format {
        Format {
            spacing,
            max_points: 100,
            directions: Directions::Bidirectional,
            modulo,
            quantum_um: 0.1,
            quantum_arcsec: 0.1,
        }
    }

    fn settings(interval: Option<f64>, reference: Option<f64>) -> Settings {
        Settings {
            interval,
            reference,
            ..Default::default()
        }
    }

    /// Targets 3, 7, 12, 20: free spacing keeps them; equidistant without an interval
    /// takes the mean spacing 17/3 = 5.667 mm from the first target and covers the last
    /// (3 + 3 × 5.667 = 20.001 ≥ 20).
    #[test]
    fn free_keeps_the_targets_equidistant_covers_the_travel() {
        let data = axis(AxisKind::Linear, &[3.0, 7.0, 12.0, 20.0], 2, |_, _| 0.0);
        let free = grid(&data, &format(Spacing::Free, false), &Settings::default()).unwrap();
        assert_eq!(free, [3.0, 7.0, 12.0, 20.0]);
        let eq = grid(
            &data,
            &format(Spacing::Equidistant, false),
            &Settings::default(),
        )
        .unwrap();
        assert_eq!(eq.len(), 4);
        assert!((eq[1] - 8.667).abs() < 1e-9 && (eq[3] - 20.001).abs() < 1e-9);
    }

    /// Every 5 mm through the reference 10.5 over the travel 3…20: from 0.5 (at or before
    /// 3) to 20.5 (at or after 20), 5 points.
    #[test]
    fn an_interval_through_the_reference() {
        let data = axis(AxisKind::Linear, &[3.0, 7.0, 12.0, 20.0], 2, |_, _| 0.0);
        let g = grid(
            &data,
            &format(Spacing::Free, false),
            &settings(Some(5.0), Some(10.5)),
        )
        .unwrap();
        assert_eq!(g, [0.5, 5.5, 10.5, 15.5, 20.5]);
    }

    /// A rotary axis measured 0…360° every 45° on a modulo controller: 0…360 every 45°;
    /// an interval of 50° does not divide the revolution and is refused.
    #[test]
    fn a_whole_revolution_gives_a_modulo_grid() {
        let targets: Vec<f64> = (0..=8).map(|k| k as f64 * 45.0).collect();
        let data = axis(AxisKind::Rotary, &targets, 2, |_, _| 0.0);
        let f = format(Spacing::Equidistant, true);
        assert!(modulo(&data, &f));
        assert!(!modulo(&data, &format(Spacing::Equidistant, false)));
        assert_eq!(grid(&data, &f, &Settings::default()).unwrap(), targets);
        let err = grid(&data, &f, &settings(Some(50.0), None)).unwrap_err();
        assert_eq!(
            err.to_string(),
            "a modulo table needs an interval that divides 360°, got 50.0000°"
        );
    }

    /// 1 000 mm every 5 mm is 201 points, over the 100 the format holds: the least
    /// interval that fits is 1000/99 = 10.102 mm, rounded up to the micrometre.
    #[test]
    fn too_many_points_names_the_interval_that_fits() {
        let data = straight(0.0, 250.0, 5);
        let err = grid(
            &data,
            &format(Spacing::Equidistant, false),
            &settings(Some(5.0), None),
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "201 points, but the table holds at most 100; choose an interval of 10.102 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
    }
}
