//! `linuxcnc`: a joint compensation file (`[JOINT_n] COMP_FILE = …`), one line per point,
//! `nominal forward reverse`, in the joint's units (mm, or degrees on a rotary joint), of
//! `COMP_FILE_TYPE = 0` by default (LinuxCNC's default when the key is missing:
//! `inijoint.cc`, `findIntV("COMP_FILE_TYPE", …, 0, 0, 1)`) or `COMP_FILE_TYPE = 1` when
//! asked (`--comp-file-type 1`, `compensation: {comp_file_type: 1}`).
//!
//! What LinuxCNC does with the file (LinuxCNC source, github.com/LinuxCNC/linuxcnc, the same
//! at the commit Debian packages as 2.9.0~pre1, f1270d6ed7, and at master 5c41560e of
//! 2026-08-22):
//! - `usrmotLoadComp` (`src/emc/motion/usrmotintf.cc`) reads lines with
//!   `sscanf("%lf %lf %lf")` and stops (`break`) at the first line that is not three
//!   numbers: notes go after the points (a note first loads no point at all, silently).
//!   Type 0 lines are `nominal forward_actual reverse_actual`, converted to trims as
//!   `comp_forward = nom - fwd` ("convert to diffs"); type 1 lines are
//!   `nominal forward_trim reverse_trim`, taken as they are. Read with the other type, a
//!   file gives trims of about the nominal position (≈ 1190 mm at 1190 mm), which LinuxCNC
//!   ramps in at up to half the joint's speed: the file's notes and every listing of it
//!   state its type and the INI lines to set.
//! - `EMCMOT_SET_JOINT_COMP` (`command.c`): nominal positions must increase ("compensation
//!   values must increase"), at most 256 points (`EMCMOT_COMP_SIZE`, "too many compensation
//!   entries"); the slope to the next point is computed there.
//! - `compute_screw_comp` (`control.c`): the trim at the commanded joint position, linear
//!   between points, the forward one while `vel_cmd > 0` and the reverse one while
//!   `vel_cmd < 0` (kept when the joint stops), "is added to the joint_pos_cmd to create
//!   motor_pos_cmd". So the trim is the correction, −x̄↑ forward and −x̄↓ reverse. With a
//!   table, `BACKLASH` is not used. The value is ramped in (`backlash_filt`) at up to half
//!   the joint's velocity and acceleration, and the ramp can stop short of it by up to
//!   `MAX_ACCELERATION` × servo period² / 2 (from rest, a step between a quarter and a half
//!   of that is not ramped at all): a property of the controller, not of the table, seen
//!   on the real LinuxCNC of `linuxcnc_sim` and not in the prediction.
//! - The table (`motion.c`) is bounded by entries at −DBL_MAX and +DBL_MAX whose slopes
//!   are 0: beyond the first and last points their values are held. The lookup compares
//!   the joint position with the nominal ones and nothing else: no modulo, so a rotary
//!   joint's table covers the positions it lists, and the notes say so. The trims and
//!   slopes are held as `float` (`emcmot_comp_entry_t`, `motion.h`): about 7 significant
//!   digits, 6e-10 mm on a trim of 0.01 mm.
//!
//! LinuxCNC's INI documentation (`docs/src/config/ini-config.adoc`, `[JOINT_n]`) calls
//! type 1's values offsets "from nominal", with examples that read as the error rather than
//! the correction; axcheck follows the code, and a real LinuxCNC 2.9 (the test
//! `linuxcnc_sim`) applies each table as axcheck predicts, type 0 and 1, linear and rotary.
//!
//! Read back as the loader reads (text after the third number is ignored), type 0 or 1 as
//! the note axcheck writes says (`# COMP_FILE_TYPE = 0: …`); a file without it is told by
//! its size (a trim is near 0, an actual position near its nominal one; where the sizes do
//! not tell, every nominal position near 0, type 1). Refused, with the line: a first line
//! that is not three numbers (LinuxCNC would load no table), points after the line where
//! the loader stops (it would not load them), positions that do not increase, more than
//! 256 points.

use super::controller::{
    Backlash, Controller, Directions, Format, ReadAs, Refused, Spacing, Unreadable,
};
use super::reading::{self, Points, numbered};
use crate::compensate::table::Table;
use crate::units::{AxisKind, fmt_fixed, fmt_position};

/// The writer and reader of one `COMP_FILE_TYPE`.
pub struct LinuxCnc {
    file_type: FileType,
}

impl LinuxCnc {
    /// Type 0, LinuxCNC's default: actual positions.
    pub const TYPE_0: LinuxCnc = LinuxCnc {
        file_type: FileType::Actual,
    };
    /// Type 1: trims.
    pub const TYPE_1: LinuxCnc = LinuxCnc {
        file_type: FileType::Trims,
    };

    /// The controller writing `COMP_FILE_TYPE = n` files, for n = 0 or 1.
    pub(crate) fn of_type(n: u8) -> Option<&'static LinuxCnc> {
        match n {
            0 => Some(&Self::TYPE_0),
            1 => Some(&Self::TYPE_1),
            _ => None,
        }
    }

    /// What the INI must say for this file, `<file>` standing for its path; for a rotary
    /// joint, that the lookup does not wrap, over `covered` (first, last) when known.
    fn notes(&self, kind: AxisKind, covered: Option<(f64, f64)>) -> Vec<String> {
        let n = self.file_type.number();
        let unit = kind.position_unit();
        let (columns, other) = match self.file_type {
            FileType::Actual => (
                format!(
                    "nominal, forward actual and reverse actual position ({unit}); LinuxCNC corrects by nominal − actual"
                ),
                "as type 1",
            ),
            FileType::Trims => (
                format!(
                    "nominal, forward trim and reverse trim ({unit}); LinuxCNC adds the trim to the commanded position"
                ),
                "as type 0 (LinuxCNC's default when the key is missing)",
            ),
        };
        let mut notes = vec![format!(
            "{TYPE_NOTE}{n}: {columns}. In the joint's `[JOINT_n]` section of the INI: `COMP_FILE = <file>` and `COMP_FILE_TYPE = {n}`; read {other}, each correction would be about the nominal position."
        )];
        if kind == AxisKind::Rotary {
            let covers = covered.map_or("the joint positions it lists".to_string(), |(a, b)| {
                format!(
                    "joint positions {} to {} {unit}",
                    fmt_position(a),
                    fmt_position(b)
                )
            });
            notes.push(format!(
                "Rotary joint: LinuxCNC's comp lookup does not wrap (no modulo): the table covers {covers}; beyond them its end values are held."
            ));
        }
        notes
    }
}

/// Points per joint the motion controller holds (`EMCMOT_COMP_SIZE`).
const MAX_POINTS: usize = 256;

/// How axcheck's note naming the file's type starts, the type's number after it.
const TYPE_NOTE: &str = "COMP_FILE_TYPE = ";

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

    /// Type 0 prints each actual position as the printed nominal one minus the trim, so
    /// that the loader's `nom - fwd` gives the trim to the last digit.
    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused> {
        super::finite(table)?;
        super::printed_increasing(&table.positions, 6)?;
        // Corrections in µm or arcsec, the file in mm or degrees.
        let per_unit = table.kind.deviation_units_per_position_unit();
        let mut out = String::new();
        for ((p, u), d) in table.positions.iter().zip(&table.up).zip(&table.down) {
            let nominal = fmt_fixed(*p, 6);
            let printed: f64 = nominal.parse().unwrap_or(*p);
            let column = |trim: f64| match self.file_type {
                FileType::Trims => fmt_fixed(trim, 7),
                FileType::Actual => fmt_fixed(printed - trim, 7),
            };
            out.push_str(&format!(
                "{nominal} {} {}\n",
                column(u / per_unit),
                column(d / per_unit)
            ));
        }
        let covered = table.positions.first().zip(table.positions.last());
        let own = self.notes(table.kind, covered.map(|(a, b)| (*a, *b)));
        out.push_str(&super::commented("# ", &own));
        out.push_str(&super::commented("# ", notes));
        Ok(out)
    }

    fn loading(&self, kind: AxisKind) -> Vec<String> {
        self.notes(kind, None)
    }

    /// `BACKLASH` is not used while a table is loaded (`control.c`): the reversal goes
    /// into the two columns.
    fn backlash(&self) -> Backlash {
        Backlash::UnusedWithTable
    }

    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
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
        let file_type = stated_type(text).unwrap_or_else(|| file_type(&rows));
        let per_unit = reading.kind.deviation_units_per_position_unit();
        let trim = |r: &[f64; 3], k: usize| match file_type {
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
                    within_bounds(&r, line, l)?;
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
/// not read three.
fn three_numbers(line: &str) -> Option<[f64; 3]> {
    let mut rest = line;
    let mut out = [0.0; 3];
    for v in out.iter_mut() {
        let t = rest.trim_start();
        let n = reading::float_prefix(t);
        *v = t[..n].parse::<f64>().ok()?;
        rest = &t[n..];
    }
    Some(out)
}

/// A row LinuxCNC loads whose numbers are all within [`reading::LARGEST`]: one beyond it
/// (`1e300 0 0`, which overflows to infinity in µm) is refused at its line, not dropped.
fn within_bounds(row: &[f64; 3], line: usize, text: &str) -> Result<(), Unreadable> {
    let fields = ["nominal", "forward", "reverse"];
    let Some(k) = (row.iter()).position(|v| !v.is_finite() || v.abs() > reading::LARGEST) else {
        return Ok(());
    };
    let shown = match row[k].abs() < 1e15 {
        true => row[k].to_string(),
        false => format!("{:e}", row[k]),
    };
    Err(Unreadable::field(
        line,
        fields[k],
        format!(
            "expected a number of at most 1e12, got {shown} in `{}`; LinuxCNC would load it: correct the line or remove it",
            text.trim()
        ),
    ))
}

/// The type of a comp file (`COMP_FILE_TYPE`).
#[derive(Debug, Clone, Copy, PartialEq)]
enum FileType {
    /// Type 0: the actual positions, trims = nominal − actual.
    Actual,
    /// Type 1: the trims themselves.
    Trims,
}

impl FileType {
    /// Its `COMP_FILE_TYPE`.
    fn number(self) -> u8 {
        match self {
            FileType::Actual => 0,
            FileType::Trims => 1,
        }
    }
}

/// The type axcheck's note states (`# COMP_FILE_TYPE = 0: …`), if the file has one.
fn stated_type(text: &str) -> Option<FileType> {
    numbered(text).find_map(|(_, line)| {
        let rest = line.trim_start().strip_prefix('#')?.trim_start();
        match rest.strip_prefix(TYPE_NOTE)?.split(':').next()? {
            "0" => Some(FileType::Actual),
            "1" => Some(FileType::Trims),
            _ => None,
        }
    })
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
    /// 50 adds 1: trims ↑ 1, −1.5, 0, 1.5, −1 µm and ↓ two less, written in mm: as they are
    /// in type 1, as nominal − trim in type 0 (0.001 at 0 mm ↑ is −0.0010000). The file's
    /// type and INI lines are its first notes, after the points.
    #[test]
    fn golden_files_by_hand() {
        let data = irregular_linear();
        let settings = Settings {
            interval: Some(25.0),
            reference: Some(50.0),
            ..Default::default()
        };
        let table = held_table(&LinuxCnc::TYPE_0, &data, &settings).unwrap();
        let notes = ["Warning: a note".to_string()];
        for (controller, golden) in [
            (
                &LinuxCnc::TYPE_0,
                include_str!("../../../../../tests/data/compensation/linuxcnc-linear.txt"),
            ),
            (
                &LinuxCnc::TYPE_1,
                include_str!("../../../../../tests/data/compensation/linuxcnc-linear-type1.txt"),
            ),
        ] {
            assert_eq!(controller.write(&table, &notes).unwrap(), golden);
            let back = controller.read(golden, reading(AxisKind::Linear)).unwrap();
            let read = back.up.iter().chain(&back.down);
            for (r, t) in read.zip(table.up.iter().chain(&table.down)) {
                assert!((r - t).abs() < 1e-9, "{r} µm read, {t} µm written");
            }
        }
        // A rotary joint in degrees: x̄↑ = −3.6″, 7.2″ → trims 0.001°, −0.002°.
        let rotary = axis(AxisKind::Rotary, &[0.0, 90.0], 2, |p, d| match d {
            Direction::Up if p == 0.0 => -3.6,
            Direction::Up => 7.2,
            Direction::Down => 0.0,
        });
        let table = held_table(&LinuxCnc::TYPE_0, &rotary, &Settings::default()).unwrap();
        assert_eq!(
            LinuxCnc::TYPE_0.write(&table, &[]).unwrap(),
            include_str!("../../../../../tests/data/compensation/linuxcnc-rotary.txt")
        );
    }

    fn reading(kind: AxisKind) -> ReadAs<'static> {
        ReadAs { kind, axis: None }
    }

    /// The type note decides where the sizes would not: `0 0.001 0.002` is trims of 1 and
    /// 2 µm by size, and −1 and −2 µm as type 0 (nominal − actual) when the note says so;
    /// a note before the points is not one (LinuxCNC would load nothing).
    #[test]
    fn the_type_note_decides() {
        let points = "0 0.001 0.002\n0.5 0.001 0.002\n";
        let by_size = LinuxCnc::TYPE_0
            .read(points, reading(AxisKind::Linear))
            .unwrap();
        assert_eq!(by_size.up, [1.0, 1.0]);
        for (note, up) in [
            ("# COMP_FILE_TYPE = 0: x\n", -1.0),
            ("# COMP_FILE_TYPE = 1: x\n", 1.0),
        ] {
            let t = LinuxCnc::TYPE_1
                .read(&format!("{points}{note}"), reading(AxisKind::Linear))
                .unwrap();
            assert!((t.up[0] - up).abs() < 1e-9, "{note}: {:?}", t.up);
        }
        let first = format!("# COMP_FILE_TYPE = 0: x\n{points}");
        assert!(
            LinuxCnc::TYPE_0
                .read(&first, reading(AxisKind::Linear))
                .is_err()
        );
    }

    /// A last point beyond 1e12 is refused at its line, not dropped (it left a one-point
    /// table).
    #[test]
    fn a_value_over_the_bound_is_refused_not_dropped() {
        let text = "0 0.001 0.002\n1e300 0 0\n";
        let e = LinuxCnc::TYPE_1
            .read(text, reading(AxisKind::Linear))
            .unwrap_err();
        assert_eq!((e.line, e.field.as_deref()), (Some(2), Some("nominal")));
        assert!(
            e.message
                .starts_with("expected a number of at most 1e12, got 1e300"),
            "{e}"
        );
        let e = LinuxCnc::TYPE_1
            .read(
                "0 0.001 0.002\n5 0 -2e13\n7 0 0\n",
                reading(AxisKind::Linear),
            )
            .unwrap_err();
        assert_eq!((e.line, e.field.as_deref()), (Some(2), Some("reverse")));
    }

    #[test]
    fn refuses_what_a_joint_cannot_hold() {
        let data = crate::compensate::testing::straight(0.0, 1.0, MAX_POINTS + 1);
        let err = crate::compensate::held_table(&LinuxCnc::TYPE_0, &data, &Default::default())
            .unwrap_err()
            .to_string();
        assert_eq!(
            err,
            "257 points, but the table holds at most 256; choose an interval of 1.004 mm or more (--interval, or compensation: {interval} in a campaign)"
        );
    }
}
