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
    use crate::units::AxisKind;

    /// Two points: x̄↑ = 1.5, x̄↓ = −0.5 at 0 mm and x̄↑ = −2, x̄↓ = 0 at 100 mm give the
    /// corrections −1.5, 0.5 and 2, 0.
    #[test]
    fn header_units_and_signs_by_hand() {
        let table = Table {
            kind: AxisKind::Linear,
            positions: vec![0.0, 100.0],
            up: vec![-1.5, 2.0],
            down: vec![0.5, 0.0],
            reference: 0.0,
            modulo_deg: None,
            axis: None,
        };
        assert_eq!(
            Csv.write(&table).unwrap(),
            "position_mm,correction_up_um,correction_down_um\n0.0000,-1.5000,0.5000\n100.0000,2.0000,0.0000\n"
        );
        let rotary = Table {
            kind: AxisKind::Rotary,
            ..table
        };
        assert!(
            Csv.write(&rotary)
                .unwrap()
                .starts_with("position_deg,correction_up_arcsec,")
        );
    }
}
