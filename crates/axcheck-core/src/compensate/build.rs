//! The table that cancels the mean deviations x̄↑ and x̄↓ (ISO 230-2 2.8), resampled onto
//! the controller's grid: one table per direction where the controller holds two, the mean
//! (and the reversal for its backlash parameter) where it holds one; folded onto one
//! revolution for a modulo table; added to the correction that was active during the test
//! (the deviations are what it left); shifted to zero at the reference point when one is
//! given.

use super::controllers::{Directions, Format};
use super::grid::REVOLUTION_DEG;
use super::table::{Table, linear};
use crate::measurement::AxisData;
use crate::units::Direction;

/// Mean deviation x̄ at each target for one direction (ISO 230-2 2.10).
pub fn means(data: &AxisData, direction: Direction) -> Vec<f64> {
    (0..data.target_count())
        .map(|i| {
            let d = data.deviations(i, direction);
            d.iter().sum::<f64>() / d.len() as f64
        })
        .collect()
}

/// The correction −x̄ at `p`: interpolated between the targets, and on a modulo table
/// the mean over every turn of the measured travel that passes `p` (a point no turn
/// passes holds the nearer end's value, as beyond the ends of a straight table).
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
    if values.is_empty() {
        return -linear(&data.targets, means, p);
    }
    values.iter().sum::<f64>() / values.len() as f64
}

/// The table for `data` alone on `positions` in `format`, as measured (no reference
/// point), wrapping over a revolution when `wraps`.
pub fn measured(data: &AxisData, positions: Vec<f64>, format: &Format, wraps: bool) -> Table {
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
        reference: positions[0],
        modulo_deg: wraps.then_some(REVOLUTION_DEG),
        place: Default::default(),
        interpolation: Default::default(),
        positions,
    };
    if let Directions::Unidirectional { backlash } = format.directions {
        one_table(&mut table, backlash);
    }
    table
}

/// `total`, the correction active during the test, added at each point and direction:
/// what the controller must hold for the measured deviations to vanish.
pub fn add(table: &mut Table, total: &Table) {
    for (k, p) in table.positions.iter().enumerate() {
        table.up[k] += total.correction(*p, Direction::Up);
        table.down[k] += total.correction(*p, Direction::Down);
    }
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

/// Shifts both directions so the correction written at `reference` is zero (the ↑ one,
/// or the mean on a one-table controller): homing there is unchanged. A constant changes
/// no ISO 230-2 parameter.
pub(crate) fn zero_at_reference(table: &mut Table, reference: f64, format: &Format) {
    table.reference = reference;
    let up = table.correction(reference, Direction::Up);
    let down = table.correction(reference, Direction::Down);
    let one_table = matches!(format.directions, Directions::Unidirectional { .. });
    let shift = if one_table { (up + down) / 2.0 } else { up };
    for v in table.up.iter_mut().chain(table.down.iter_mut()) {
        *v -= shift;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::controllers::Spacing;
    use crate::compensate::testing::axis;
    use crate::units::AxisKind;

    fn format(directions: Directions, modulo: bool) -> Format {
        Format {
            spacing: Spacing::Free,
            max_points: 1000,
            directions,
            modulo,
            quantum_um: 0.0,
            quantum_arcsec: 0.0,
        }
    }

    /// x̄↑ = 2 + 0.01·P µm, x̄↓ = x̄↑ − 4 µm (a reversal B = 4 µm) at 0, 100, 200 mm.
    fn data() -> AxisData {
        axis(AxisKind::Linear, &[0.0, 100.0, 200.0], 3, |p, d| {
            2.0 + 0.01 * p - if d == Direction::Down { 4.0 } else { 0.0 }
        })
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    #[test]
    fn bidirectional_corrections_are_minus_the_means_interpolated() {
        let f = format(Directions::Bidirectional, false);
        let t = measured(&data(), vec![0.0, 50.0, 200.0], &f, false);
        assert!(close(&t.up, &[-2.0, -2.5, -4.0]));
        assert!(close(&t.down, &[2.0, 1.5, 0.0]));
        assert_eq!(t.reference, 0.0);
    }

    /// One table: the mean −(x̄↑ + x̄↓)/2 = −(0.01·P); with a backlash parameter ↑ and ↓
    /// keep ∓2 µm about it (B̄ = x̄↑ − x̄↓ = 4 µm), without one both get the mean.
    #[test]
    fn one_table_controllers_get_the_mean_and_maybe_the_reversal() {
        let positions = vec![0.0, 100.0, 200.0];
        let with = format(Directions::Unidirectional { backlash: true }, false);
        let t = measured(&data(), positions.clone(), &with, false);
        assert!(close(&t.mean(), &[0.0, -1.0, -2.0]));
        assert!(close(&t.up, &[-2.0, -3.0, -4.0]));
        assert!((t.reversal_correction() - 4.0).abs() < 1e-12);
        let without = format(Directions::Unidirectional { backlash: false }, false);
        let t = measured(&data(), positions, &without, false);
        assert!(close(&t.up, &[0.0, -1.0, -2.0]) && t.up == t.down);
    }

    /// With the reference at 100 mm the ↑ correction is zero there: −3 µm added to all.
    #[test]
    fn the_reference_point_gets_zero() {
        let f = format(Directions::Bidirectional, false);
        let mut t = measured(&data(), vec![0.0, 100.0, 200.0], &f, false);
        zero_at_reference(&mut t, 100.0, &f);
        assert!(close(&t.up, &[1.0, 0.0, -1.0]));
        assert!(close(&t.down, &[5.0, 4.0, 3.0]));
        assert_eq!(t.reference, 100.0);
    }

    /// A rotary axis measured −90…450° (one and a half turns), x̄ = 10·sin(θ) + 0.01·θ
    /// arcsec: the modulo table at θ averages the turns that pass θ, and 0° and 360° get
    /// one value. At 90°: turns at 90 and 450 → −(10 + 0.9 + 10 + 4.5)/2 = −12.7.
    #[test]
    fn a_modulo_table_folds_the_turns() {
        let targets: Vec<f64> = (0..=12).map(|k| -90.0 + k as f64 * 45.0).collect();
        let data = axis(AxisKind::Rotary, &targets, 2, |p, _| {
            10.0 * p.to_radians().sin() + 0.01 * p
        });
        let f = format(Directions::Bidirectional, true);
        let positions: Vec<f64> = (0..=4).map(|k| k as f64 * 90.0).collect();
        let t = measured(
            &data,
            positions,
            &f,
            crate::compensate::grid::modulo(&data, &f),
        );
        assert_eq!(t.modulo_deg, Some(360.0));
        assert!((t.up[1] - -12.7).abs() < 1e-9, "{:?}", t.up);
        // 0°: turns at 0 and 360 → −(0 + 3.6)/2 = −1.8; 360°: turns at 0 and 360 as well.
        assert!((t.up[0] - -1.8).abs() < 1e-9 && t.up[0] == t.up[4]);
        // Looked up at 450° (= 90°) the correction is the 90° one.
        assert_eq!(t.correction(450.0, Direction::Up), t.up[1]);
    }
}
