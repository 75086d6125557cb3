//! The correction table as a controller holds it, and its effect on the readings.
//!
//! A deviation is actual − target (ISO 230-2 2.7). A controller that adds the correction c
//! to reach a target moves to target + c + X(target), so the correction that cancels the
//! mean deviation is c = −x̄ at each target and direction.

use crate::measurement::AxisData;
use crate::units::{AxisKind, Direction};
use serde::Serialize;

/// A correction table on the controller's grid: one correction per point and direction,
/// in the deviation unit (µm or arcsec). A controller with one table per axis holds
/// `up` = `down` (or `down` − `up` constant, the reversal its backlash parameter adds).
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
    /// The reference point (mm or deg), a grid point: where the controller's table starts
    /// counting (FANUC) or the correction is zero (with `--reference`).
    pub reference: f64,
    /// One revolution (deg) when the table wraps around a rotary axis: positions from 0
    /// to the revolution, the last point the first one again.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub modulo_deg: Option<f64>,
    /// Where the table sits on the controller: its axis name and the controller's own
    /// numbering, for formats that name them.
    #[serde(skip)]
    pub place: TableSlot,
    /// How the controller applies the table between its points.
    pub interpolation: Interpolation,
}

/// Where a table sits on the controller, as the user gives it or an active table's file
/// names it; each format reads the part it has, and a table built on an active one keeps
/// its place.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TableSlot {
    /// The axis's name on the controller (HEIDENHAIN's column `X`, Siemens' machine axis
    /// `X1`, TwinCAT's logical number `2` as given); `None`: the file carries a placeholder
    /// the control cannot load, to replace.
    pub axis: Option<String>,
    /// Siemens: the measuring system, 0 (the first encoder) or 1 (a direct, second
    /// measuring system the axis is closed on); `None`: 0.
    pub measuring_system: Option<u8>,
    /// TwinCAT: the axis's logical number `kopf.achs_nr` of the active list (`axis`, when
    /// given, comes first); FANUC: the first pitch error number of the + direction table
    /// (3621); `None`: the format's default.
    pub number: Option<usize>,
}

/// How a controller applies its table between points.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Interpolation {
    /// Linearly between points, the end values held beyond them.
    #[default]
    Linear,
    /// Each point's value from that point to the next (a staircase: FANUC outputs a
    /// section's value where the axis passes its point); the first value before the first
    /// point.
    Steps,
}

/// Linear interpolation of `values` at `positions` (ascending) at `x`; constant beyond the
/// ends (controllers hold the end value; the grid covers the travel).
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

/// The value of the last point at or before `x` (the first value before the table).
pub fn step(positions: &[f64], values: &[f64], x: f64) -> f64 {
    // A position within 1e-9 of a point is that point (targets on the grid).
    let k = positions.partition_point(|p| *p <= x + 1e-9);
    values.get(k.saturating_sub(1)).copied().unwrap_or(0.0)
}

/// `position` folded into one revolution [0, `revolution`).
pub fn wrap(position: f64, revolution: f64) -> f64 {
    position.rem_euclid(revolution)
}

impl Table {
    /// The correction the controller adds at `position` approached in `direction`
    /// (a modulo table looks up the position within the revolution).
    pub fn correction(&self, position: f64, direction: Direction) -> f64 {
        let values = match direction {
            Direction::Up => &self.up,
            Direction::Down => &self.down,
        };
        let x = self.modulo_deg.map_or(position, |r| wrap(position, r));
        match self.interpolation {
            Interpolation::Linear => linear(&self.positions, values, x),
            Interpolation::Steps => step(&self.positions, values, x),
        }
    }

    /// The direction-independent part at each point: (c↑ + c↓)/2, what a controller with
    /// one table per axis holds.
    pub fn mean(&self) -> Vec<f64> {
        self.up
            .iter()
            .zip(&self.down)
            .map(|(u, d)| (u + d) / 2.0)
            .collect()
    }

    /// The correction a backlash parameter adds on ↓ approaches relative to ↑ ones,
    /// c↓ − c↑ averaged over the points (= x̄↑ − x̄↓, the mean reversal B̄ of ISO 230-2 2.14).
    pub(crate) fn reversal_correction(&self) -> f64 {
        let n = self.positions.len().max(1) as f64;
        self.up
            .iter()
            .zip(&self.down)
            .map(|(u, d)| d - u)
            .sum::<f64>()
            / n
    }

    /// The table with every correction rounded to `quantum` (the controller's unit).
    pub(crate) fn quantised(mut self, quantum: f64) -> Table {
        if quantum > 0.0 {
            for v in self.up.iter_mut().chain(self.down.iter_mut()) {
                *v = (*v / quantum).round() * quantum;
            }
        }
        self
    }
}

/// The readings as they would be with `table` active: each deviation plus the correction
/// at its target and direction.
pub fn apply(table: &Table, data: &AxisData) -> AxisData {
    apply_change(table, None, data)
}

/// The readings as they would be with `new` active in place of `old` (the correction
/// active during the test; `None`: nothing): each deviation plus the difference of the
/// two corrections at its target and direction.
pub fn apply_change(new: &Table, old: Option<&Table>, data: &AxisData) -> AxisData {
    data.map_deviations(|r| {
        let p = data.targets[r.target];
        let before = old.map_or(0.0, |t| t.correction(p, r.direction));
        r.deviation + new.correction(p, r.direction) - before
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points 0, 10, 20 with 1, 2, 3: linear gives 1.5 at 5 and holds the ends; steps give
    /// the last point's value at or before x (a target within 1e-9 of a point is on it).
    #[test]
    fn linear_and_steps_by_hand() {
        let (p, v) = ([0.0, 10.0, 20.0], [1.0, 2.0, 3.0]);
        assert_eq!(linear(&p, &v, 5.0), 1.5);
        assert_eq!(linear(&p, &v, -5.0), 1.0);
        assert_eq!(linear(&p, &v, 25.0), 3.0);
        for (x, want) in [
            (-5.0, 1.0),
            (0.0, 1.0),
            (9.99, 1.0),
            (10.0 - 1e-12, 2.0),
            (15.0, 2.0),
            (25.0, 3.0),
        ] {
            assert_eq!(step(&p, &v, x), want, "at {x}");
        }
    }
}
