//! `csv`: a generic table for any controller or spreadsheet: one row per grid point,
//! `position_mm,correction_up_um,correction_down_um` (rotary: `position_deg`,
//! `_arcsec`). The correction is the value the controller adds to reach the target: minus
//! the mean deviation x̄↑ / x̄↓ there (ISO 230-2 2.7: deviation = actual − target).
//! Notes go first, as `# ` lines (a spreadsheet shows them above the table).
//!
//! Read back: `#` lines and blank lines are skipped; the header names the units, which must
//! be the axis's; `position_mm,correction_um` (one column) is read as the same correction in
//! both directions; the positions must increase.

use super::controller::{Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable};
use super::reading::{self, Points, numbered};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed};

pub(crate) struct Csv;

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

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        let (pos, dev) = (table.kind.position_unit(), table.kind.deviation_unit());
        super::printed_increasing(&table.positions, 4)?;
        let mut out = super::commented("# ", notes);
        out.push_str(&format!(
            "position_{pos},correction_up_{dev},correction_down_{dev}\n"
        ));
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

    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
        let kind = reading.kind;
        let mut rows = numbered(text).filter(|(_, l)| {
            let t = l.trim();
            !t.is_empty() && !t.starts_with('#')
        });
        let (at, header) = rows
            .next()
            .ok_or_else(|| Unreadable::file("no header line and no points"))?;
        let columns = header_columns(header, kind, at)?;
        let mut points = Points::empty(kind);
        let mut lines = Vec::new();
        for (line, row) in rows {
            let fields: Vec<&str> = row.split(',').collect();
            if fields.len() != columns.len() {
                return Err(Unreadable::at(
                    line,
                    format!(
                        "{} field{}, but the header names {}",
                        fields.len(),
                        if fields.len() == 1 { "" } else { "s" },
                        columns.len()
                    ),
                ));
            }
            let value = |k: usize| reading::number(fields[k], line, &columns[k]);
            points.positions.push(value(0)?);
            points.up.push(value(1)?);
            points.down.push(value(columns.len() - 1)?);
            lines.push(line);
        }
        reading::enough(points.positions.len(), 1, "the table")?;
        reading::increasing(&points.positions, &lines, &columns[0])?;
        Ok(points.table(None, false, Default::default(), self.interpolation()))
    }
}

/// The header's columns: the position and one correction for both directions or one per
/// direction, in the axis's units.
fn header_columns(header: &str, kind: AxisKind, line: usize) -> Result<Vec<String>, Unreadable> {
    let (pos, dev) = (kind.position_unit(), kind.deviation_unit());
    let two = [
        format!("position_{pos}"),
        format!("correction_up_{dev}"),
        format!("correction_down_{dev}"),
    ];
    let one = [format!("position_{pos}"), format!("correction_{dev}")];
    let columns: Vec<String> = header.split(',').map(|c| c.trim().to_string()).collect();
    if columns == two || columns == one {
        return Ok(columns);
    }
    let other = match kind {
        AxisKind::Linear => "position_deg",
        AxisKind::Rotary => "position_mm",
    };
    let why = if columns.first().is_some_and(|c| c == other) {
        format!(
            "`{other}`: the table is for a {} axis, but the axis is {kind}",
            other_kind(kind)
        )
    } else {
        format!(
            "expected the header `{}` (or `{}`), got `{}`",
            two.join(","),
            one.join(","),
            header.trim()
        )
    };
    Err(Unreadable::at(line, why))
}

fn other_kind(kind: AxisKind) -> AxisKind {
    match kind {
        AxisKind::Linear => AxisKind::Rotary,
        AxisKind::Rotary => AxisKind::Linear,
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
            Csv.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/csv-linear.csv")
        );
        let rotary = axis(AxisKind::Rotary, &[0.0, 90.0], 2, |_, _| 1.0);
        let table = held_table(&Csv, &rotary, &Settings::default()).unwrap();
        assert!(Csv.write(&table, &[]).unwrap().starts_with(
            "position_deg,correction_up_arcsec,correction_down_arcsec\n0.0000,-1.0000,-1.0000\n"
        ));
    }
}
