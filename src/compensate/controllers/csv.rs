//! `csv`: a generic table for any controller or spreadsheet: one row per grid point,
//! `position_mm,correction_up_um,correction_down_um` (rotary: `position_deg`,
//! `_arcsec`). The correction is the value the controller adds to reach the target: minus
//! the mean deviation x̄↑ / x̄↓ there (ISO 230-2 2.7: deviation = actual − target).

use super::{Controller, Directions, Format, Refused, Spacing};
use crate::compensate::Table;
use crate::units::fmt_fixed;

pub struct Csv;

impl Controller for Csv {
    fn name(&self) -> &'static str {
        "csv"
    }

    fn extension(&self) -> &'static str {
        "csv"
    }

    /// Any points, both directions, no wrap; printed to 0.0001 µm or arcsec.
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Free,
            max_points: usize::MAX,
            directions: Directions::Bidirectional,
            modulo: false,
            quantum_um: 1e-4,
            quantum_arcsec: 1e-4,
        }
    }

    fn write(&self, table: &Table) -> Result<String, Refused> {
        let (pos, dev) = (table.kind.position_unit(), table.kind.deviation_unit());
        let mut out = format!("position_{pos},correction_up_{dev},correction_down_{dev}\n");
        for ((p, u), d) in table.positions.iter().zip(&table.up).zip(&table.down) {
            out.push_str(&format!(
                "{},{},{}\n",
                fmt_fixed(*p, 4),
                fmt_fixed(*u, 4),
                fmt_fixed(*d, 4)
            ));
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{axis, irregular_linear};
    use crate::compensate::{Settings, held_table};
    use crate::units::AxisKind;

    /// Targets 0, 30, 70, 100 mm; x̄↑ = 0, 3, −1, 2 µm; x̄↓ = x̄↑ + 2 µm. Every 25 mm: x̄↑
    /// interpolated is 0, 2.5, 1, −0.5, 2 (at 50: 3 + 20/40 × (−1 − 3) = 1), so the
    /// corrections −x̄↑ are 0, −2.5, −1, 0.5, −2 and −x̄↓ two less.
    #[test]
    fn golden_table_resampled_by_hand() {
        let data = irregular_linear();
        let settings = Settings {
            interval: Some(25.0),
            ..Default::default()
        };
        let table = held_table(&Csv, &data, &settings).unwrap();
        assert_eq!(
            Csv.write(&table).unwrap(),
            include_str!("../../../tests/data/compensation/csv-linear.csv")
        );
        let rotary = axis(AxisKind::Rotary, &[0.0, 90.0], 2, |_, _| 1.0);
        let table = held_table(&Csv, &rotary, &Settings::default()).unwrap();
        assert!(Csv.write(&table).unwrap().starts_with(
            "position_deg,correction_up_arcsec,correction_down_arcsec\n0.0000,-1.0000,-1.0000\n"
        ));
    }
}
