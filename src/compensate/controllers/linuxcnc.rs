//! `linuxcnc`: a joint compensation file of type 1 (`[JOINT_n] COMP_FILE = …`,
//! `COMP_FILE_TYPE = 1`): one line per point, `nominal forward_trim reverse_trim`, in the
//! joint's units (mm, or degrees on a rotary joint), three numbers and nothing else (the
//! loader stops at the first line that is not three numbers: no header, no comment).
//!
//! LinuxCNC adds the trim to the commanded joint position, interpolating linearly between
//! points on the commanded position and holding the end values beyond them, the forward
//! trim when moving in the positive direction (LinuxCNC source: `src/emc/motion/control.c`,
//! `compute_screw_comp`; the file read by `usrmotLoadComp` in `usrmotintf.cc`): so the
//! trim is the correction, −x̄↑ forward and −x̄↓ reverse. Nominal positions must increase
//! strictly; at most 256 points per joint (`EMCMOT_COMP_SIZE`). With a table, `BACKLASH`
//! is not used: the reversal is in the two columns. Notes go after the points, as `# `
//! lines: the loader stops reading at the first of them.
//!
//! Read back as the loader reads (`sscanf("%lf %lf %lf")` per line, `break` at the first
//! line that is not three numbers; text after the third number is ignored): type 1
//! (`nominal forward_trim reverse_trim`) and type 0 (`nominal forward_actual
//! reverse_actual`, trims = nominal − actual), told apart by their size, as the file does
//! not say which (a trim is near 0, an actual position near its nominal one; where the
//! sizes do not tell, every nominal position near 0, type 1, which axcheck writes). Refused, with
//! the line: a first line that is not three numbers (LinuxCNC would load no table), points
//! after the line where the loader stops (it would not load them), positions that do not
//! increase, more than 256 points.

use super::controller::{
    Backlash, Controller, Directions, Format, Reading, Refused, Spacing, Unreadable,
};
use super::reading::{self, Points, numbered};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed};

pub struct LinuxCnc;

/// Points per joint the motion controller holds (`EMCMOT_COMP_SIZE`).
const MAX_POINTS: usize = 256;

impl Controller for LinuxCnc {
    fn name(&self) -> &'static str {
        "linuxcnc"
    }

    fn extension(&self) -> &'static str {
        "txt"
    }

    /// Any increasing list of up to 256 points, forward and reverse trims, no wrap (a
    /// rotary joint's table covers the positions the joint takes); the file prints 0.1 nm
    /// or 1e-7°.
    fn format(&self) -> Format {
        Format {
            spacing: Spacing::Free,
            max_points: MAX_POINTS,
            directions: Directions::Bidirectional,
            modulo: false,
            quantum_um: 1e-4,
            quantum_arcsec: 3.6e-4,
        }
    }

    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        super::printed_increasing(&table.positions, 6)?;
        // Corrections in µm or arcsec, the file in mm or degrees.
        let per_unit = match table.kind {
            AxisKind::Linear => 1000.0,
            AxisKind::Rotary => 3600.0,
        };
        let mut out = String::new();
        for ((p, u), d) in table.positions.iter().zip(&table.up).zip(&table.down) {
            out.push_str(&format!(
                "{} {} {}\n",
                fmt_fixed(*p, 6),
                fmt_fixed(u / per_unit, 7),
                fmt_fixed(d / per_unit, 7)
            ));
        }
        out.push_str(&super::commented("# ", notes));
        Ok(out)
    }

    /// `BACKLASH` is not used while a table is loaded (`control.c`): the reversal goes
    /// into the two columns.
    fn backlash(&self) -> Backlash {
        Backlash::UnusedWithTable
    }

    fn read(&self, text: &str, reading: Reading) -> Result<Table, Unreadable> {
        let (rows, lines) = loaded_rows(text)?;
        if rows.len() > MAX_POINTS {
            return Err(Unreadable::at(
                lines[MAX_POINTS],
                format!(
                    "point {}: a joint holds at most {MAX_POINTS} (LinuxCNC: \"too many compensation entries\")",
                    MAX_POINTS + 1
                ),
            ));
        }
        let nominal: Vec<f64> = rows.iter().map(|r| r[0]).collect();
        reading::increasing(&nominal, &lines, "nominal")?;
        let trims = file_type(&rows);
        let per_unit = reading.kind.deviation_units_per_position_unit();
        let trim = |r: &[f64; 3], k: usize| match trims {
            FileType::Trims => r[k] * per_unit,
            FileType::Actual => (r[0] - r[k]) * per_unit,
        };
        let points = Points {
            kind: reading.kind,
            up: rows.iter().map(|r| trim(r, 1)).collect(),
            down: rows.iter().map(|r| trim(r, 2)).collect(),
            positions: nominal,
        };
        Ok(points.table(None, false, Default::default(), self.interpolation()))
    }
}

/// The rows LinuxCNC loads and their lines: from the first line while each line is three
/// numbers. A first line that is not, or points after the line where loading stops, are
/// refused: the joint would hold no table, or not all of it.
fn loaded_rows(text: &str) -> Result<(Vec<[f64; 3]>, Vec<usize>), Unreadable> {
    let mut lines = numbered(text);
    let mut rows = Vec::new();
    let mut at = Vec::new();
    let stop = loop {
        match lines.next() {
            None => break None,
            Some((line, l)) => match three_numbers(l) {
                Some(r) => {
                    rows.push(r);
                    at.push(line);
                }
                None => break Some((line, l)),
            },
        }
    };
    let Some((stop, stop_text)) = stop else {
        return reading::enough(rows.len(), 1, "the table").map(|_| (rows, at));
    };
    if rows.is_empty() {
        return Err(Unreadable::at(
            stop,
            format!(
                "`{}` is not three numbers (nominal, forward, reverse): LinuxCNC stops reading here and would load no table",
                stop_text.trim()
            ),
        ));
    }
    if let Some((line, _)) = lines.find(|(_, l)| three_numbers(l).is_some()) {
        return Err(Unreadable::at(
            line,
            format!(
                "a point after line {stop} (`{}`), where LinuxCNC stops reading: it would not be loaded; remove line {stop} or move it below the points",
                stop_text.trim()
            ),
        ));
    }
    Ok((rows, at))
}

/// Three numbers at the start of `line`, as `sscanf("%lf %lf %lf")` reads them (each
/// after optional white space; what follows the third is ignored); `None` when it would
/// not read three, or one is not a number of at most 1e12 (`nan`, `inf`).
fn three_numbers(line: &str) -> Option<[f64; 3]> {
    let mut rest = line;
    let mut out = [0.0; 3];
    for v in out.iter_mut() {
        let t = rest.trim_start();
        let n = reading::float_prefix(t);
        *v = t[..n]
            .parse::<f64>()
            .ok()
            .filter(|x| x.abs() <= reading::LARGEST)?;
        rest = &t[n..];
    }
    Some(out)
}

/// The type of a comp file (`COMP_FILE_TYPE`).
#[derive(Debug, PartialEq)]
enum FileType {
    /// Type 1: the trims themselves.
    Trims,
    /// Type 0: the actual positions, trims = nominal − actual.
    Actual,
}

/// Type 0 when the second and third columns are far nearer the nominal positions than 0
/// (a tenth of the distance or less), else type 1 (which axcheck writes): the sizes tell
/// unless every nominal position is near 0.
fn file_type(rows: &[[f64; 3]]) -> FileType {
    let largest = |f: &dyn Fn(&[f64; 3]) -> f64| rows.iter().map(f).fold(0.0, f64::max);
    let as_trims = largest(&|r| r[1].abs().max(r[2].abs()));
    let as_actual = largest(&|r| (r[0] - r[1]).abs().max((r[0] - r[2]).abs()));
    if as_actual * 10.0 < as_trims {
        FileType::Actual
    } else {
        FileType::Trims
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compensate::testing::{axis, irregular_linear};
    use crate::compensate::{Settings, held_table};
    use crate::units::Direction;

    /// Targets 0, 30, 70, 100 mm; x̄↑ = 0, 3, −1, 2 µm; x̄↓ = x̄↑ + 2 µm; every 25 mm with
    /// the reference at 50 mm. Corrections −x̄↑ on the grid: 0, −2.5, −1, 0.5, −2 µm; zero at
    /// 50 adds 1: trims ↑ 1, −1.5, 0, 1.5, −1 µm and ↓ two less, written in mm.
    #[test]
    fn golden_type_1_file_by_hand() {
        let data = irregular_linear();
        let settings = Settings {
            interval: Some(25.0),
            reference: Some(50.0),
            ..Default::default()
        };
        let table = held_table(&LinuxCnc, &data, &settings).unwrap();
        assert_eq!(
            LinuxCnc.write(&table, &[]).unwrap(),
            include_str!("../../../tests/data/compensation/linuxcnc-linear.txt")
        );
        // A rotary joint in degrees: x̄↑ = −3.6″, 7.2″ → trims 0.001°, −0.002°.
        let rotary = axis(AxisKind::Rotary, &[0.0, 90.0], 2, |p, d| match d {
            Direction::Up if p == 0.0 => -3.6,
            Direction::Up => 7.2,
            Direction::Down => 0.0,
        });
        let table = held_table(&LinuxCnc, &rotary, &Settings::default()).unwrap();
        assert_eq!(
            LinuxCnc.write(&table, &[]).unwrap(),
            "0.000000 0.0010000 0.0000000\n90.000000 -0.0020000 0.0000000\n"
        );
    }

    #[test]
    fn refuses_what_a_joint_cannot_hold() {
        let data = crate::compensate::testing::straight(0.0, 1.0, MAX_POINTS + 1);
        let err = crate::compensate::held_table(&LinuxCnc, &data, &Default::default())
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "257 points, but the table holds at most 256; choose an interval of 1.004 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
    }
}
