//! The wide table: one row per target, one column per run and direction.
//!
//! ```text
//! target_mm,up_1_um,down_1_um,up_2_um,down_2_um
//! 6.711,-1.2,0.6,-1.0,0.9
//! 175.077,-0.5,1.3,-0.4,1.5
//! ```
//! The first column is `target_mm` or `target_deg`; then, in any order, `up_J_UNIT` and
//! `down_J_UNIT` for every run J = 1 … n, UNIT as in the long layout's deviation columns
//! (`um`, `nm`, `mm` for a linear axis, `arcsec`, `urad`, `deg` for a rotary one).
//! Separators, quotes, decimal commas and `#` comments as in the long CSV ([`super::csv`]).
//!
//! The other laser tests of a linear axis (ISO 230-1) read as they do from the long CSV:
//! a straightness test is a linear table (`target_mm`, `up_1_um`, …: µm across the axis);
//! an angular test (roll, pitch, yaw) is angles at targets in mm (`target_mm`,
//! `up_1_arcsec`, `down_1_urad`, …), read only when the caller asks for one
//! ([`read_for`] with [`Quantities::AnglesAlongLinear`]). Angles at `target_mm` read for
//! any other test are refused as an angular test's layout; µm columns or `target_deg`
//! read for an angular test are refused naming the column and what it takes.
//!
//! A wide table has no times, so its order of measurement is assumed: the standard test
//! cycle (ISO 230-2:1997, Figure 1), run 1 up over the targets ascending, run 1 down over
//! them descending, then run 2, and so on — the order in which the long CSV's writer, the
//! simulator and the key=value layout list their readings. The diagnosis's drift and
//! warm-up checks rely on it; the notes say so.

use super::cell::Origin;
use super::error::{ReadError, ReadErrorKind};
use super::table::{Quantities, Row, TableReader, mixed_units, not_for_angular, read_text};
use super::{AxisData, MAX_READINGS, RawReading, fmt_target};
use crate::units::{AxisKind, Direction};
use std::io::BufRead;

/// True when a header's column is named like a run column (`up_…`, `down_…`): then the
/// header is a wide table's, and a malformed name gets the wide reader's message.
pub(crate) fn is_run_column(name: &str) -> bool {
    name.starts_with("up_") || name.starts_with("down_")
}

/// Parses the wide CSV layout.
pub fn parse<R: BufRead>(reader: R, file: &str) -> Result<AxisData, ReadError> {
    read(reader, file).map(|(data, _)| data)
}

/// Parses the wide CSV layout; also returns what was assumed or skipped.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
) -> Result<(AxisData, Vec<String>), ReadError> {
    read_for(reader, file, Quantities::OneKind)
}

/// Parses the wide CSV layout with the units `quantities` asks (an angular test's angles
/// at targets in mm, or one kind); also returns what was assumed or skipped.
pub(crate) fn read_for<R: BufRead>(
    reader: R,
    file: &str,
    quantities: Quantities,
) -> Result<(AxisData, Vec<String>), ReadError> {
    read_text::<WideTable, R>(reader, file, quantities)
}

/// One run column: its direction, run J and factor to µm or arcsec.
#[derive(Debug, Clone, Copy, PartialEq)]
struct RunColumn {
    direction: Direction,
    run: u32,
    kind: AxisKind,
    factor: f64,
}

/// Deviation units: name, axis kind, factor to µm or arcsec.
const UNITS: &[(&str, AxisKind, f64)] = &[
    ("um", AxisKind::Linear, 1.0),
    ("nm", AxisKind::Linear, 0.001),
    ("mm", AxisKind::Linear, 1000.0),
    ("arcsec", AxisKind::Rotary, 1.0),
    // 1 µrad = 0.648/π arcsec, as the long layout's `deviation_urad`.
    ("urad", AxisKind::Rotary, 0.648 / std::f64::consts::PI),
    ("deg", AxisKind::Rotary, 3600.0),
];

/// A run column's name (`up_3_um`), or what is wrong with it; `quantities` decides which
/// unit a column without one is told to have.
fn classify(name: &str, quantities: Quantities) -> Result<RunColumn, ReadErrorKind> {
    let unknown = |suggestion: Option<String>| ReadErrorKind::UnknownWideColumn {
        name: name.to_string(),
        suggestion,
    };
    let Some((direction, run, unit)) = loose_parts(name) else {
        return Err(unknown(None));
    };
    let canonical = |unit: &str| format!("{}_{run}_{unit}", direction.name());
    let Some(unit) = unit else {
        return Err(ReadErrorKind::MissingUnit {
            name: name.to_string(),
            expected: match quantities {
                Quantities::OneKind => format!(
                    "`{}` (or nm, mm; arcsec, urad or deg on a rotary axis)",
                    canonical("um")
                ),
                Quantities::AnglesAlongLinear => {
                    format!(
                        "`{}` (or urad, deg) for an angular test",
                        canonical("arcsec")
                    )
                }
            },
        });
    };
    let Some(&(unit_name, kind, factor)) = UNITS.iter().find(|(u, ..)| *u == unit) else {
        return Err(unknown(None));
    };
    if name != canonical(unit_name) {
        return Err(unknown(Some(canonical(unit_name))));
    }
    Ok(RunColumn {
        direction,
        run,
        kind,
        factor,
    })
}

/// The parts of a run column's name read loosely (`up1um`, `up_1_µm`, `down-2-um`), so a
/// near miss gets the right name as a suggestion: direction, run ≥ 1 and the unit if any.
fn loose_parts(name: &str) -> Option<(Direction, u32, Option<&'static str>)> {
    let (direction, rest) = if let Some(rest) = name.strip_prefix("up") {
        (Direction::Up, rest)
    } else {
        (Direction::Down, name.strip_prefix("down")?)
    };
    let rest = rest.trim_start_matches(['_', '-', ' ']);
    let digits = rest.len() - rest.trim_start_matches(|c: char| c.is_ascii_digit()).len();
    let run: u32 = rest[..digits].parse().ok().filter(|&r| r >= 1)?;
    let unit = rest[digits..].trim_start_matches(['_', '-', ' ']);
    let unit = match unit {
        "" => None,
        "µm" | "μm" | "micron" | "um" => Some("um"),
        "µrad" | "μrad" | "urad" => Some("urad"),
        other => Some(UNITS.iter().find(|(u, ..)| *u == other)?.0),
    };
    Some((direction, run, unit))
}

/// One target's row: its position, line and deviations in the order of the columns.
struct WideRow {
    target: f64,
    line: usize,
    deviations: Vec<f64>,
}

/// The wide table being read.
pub(crate) struct WideTable {
    /// The targets' kind (linear for an angular test of a linear axis).
    kind: AxisKind,
    /// The run columns' kind: its unit names a deviation in messages.
    value_kind: AxisKind,
    /// Column names as written (trimmed, lower case); the target's first.
    names: Vec<String>,
    /// The run columns, in the order of the header after the target.
    columns: Vec<RunColumn>,
    /// Run labels J, ascending.
    runs: Vec<u32>,
    rows: Vec<WideRow>,
}

impl TableReader for WideTable {
    fn from_header(
        header: &Row,
        place: &Origin,
        quantities: Quantities,
    ) -> Result<WideTable, ReadError> {
        let at = |k: usize, kind| place.error(header.number, header.fields[k].column, kind);
        let names: Vec<String> = header.fields.iter().map(|f| f.value.name()).collect();
        let kind = target_kind(&names[0], quantities).map_err(|e| at(0, e))?;
        let mut columns: Vec<RunColumn> = Vec::with_capacity(names.len() - 1);
        for (k, name) in names.iter().enumerate().skip(1) {
            if names[..k].contains(name) {
                let name = name.clone();
                return Err(at(k, ReadErrorKind::DuplicateColumn { name }));
            }
            let column = classify(name, quantities).map_err(|e| at(k, e))?;
            check_unit(&column, name, (&names[0], kind), quantities).map_err(|e| at(k, e))?;
            let same = |c: &RunColumn| c.direction == column.direction && c.run == column.run;
            if let Some(first) = columns.iter().position(same) {
                let kind = ReadErrorKind::ConflictingColumns {
                    first: names[first + 1].clone(),
                    second: name.clone(),
                    what: format!("{} reading of run {}", column.direction.name(), column.run),
                };
                return Err(at(k, kind));
            }
            columns.push(column);
        }
        if columns.is_empty() {
            let target = names[0].clone();
            return Err(at(0, ReadErrorKind::NoRunColumns { target }));
        }
        check_pairs(&columns, &names, &at)?;
        let runs =
            check_runs(&columns).map_err(|e| ReadError::new(place.line(header.number), e))?;
        Ok(WideTable {
            kind,
            value_kind: columns[0].kind,
            names,
            columns,
            runs,
            rows: Vec::new(),
        })
    }

    fn add(&mut self, row: &Row, place: &Origin) -> Result<(), ReadError> {
        let readings = (self.rows.len() + 1) * self.columns.len();
        if readings > MAX_READINGS {
            let kind = ReadErrorKind::TooManyReadings {
                limit: MAX_READINGS,
            };
            return Err(ReadError::new(place.line(row.number), kind));
        }
        let fields = &row.fields;
        let target = place.number(row.number, &fields[0], &self.names[0])? + 0.0;
        let mut deviations = Vec::with_capacity(self.columns.len());
        for (k, column) in self.columns.iter().enumerate() {
            let field = &fields[k + 1];
            let name = &self.names[k + 1];
            let deviation = place.number(row.number, field, name)? * column.factor;
            if deviation.abs() > super::MAX_DEVIATION {
                let kind = ReadErrorKind::Implausible {
                    column: name.clone(),
                    value: field.value.shown(),
                    limit: format!("{}", super::MAX_DEVIATION),
                    unit: self.value_kind.deviation_unit().to_string(),
                };
                return Err(place.error(row.number, field.column, kind));
            }
            deviations.push(deviation);
        }
        self.rows.push(WideRow {
            target,
            line: row.number,
            deviations,
        });
        Ok(())
    }

    fn finish(mut self, place: &Origin) -> Result<(AxisData, Vec<String>), ReadError> {
        let ascending = self
            .rows
            .windows(2)
            .all(|w| w[0].target.total_cmp(&w[1].target).is_lt());
        self.rows
            .sort_by(|a, b| a.target.total_cmp(&b.target).then(a.line.cmp(&b.line)));
        if let Some(w) = self.rows.windows(2).find(|w| w[0].target == w[1].target) {
            let kind = ReadErrorKind::DuplicateTarget {
                target: fmt_target(self.kind, w[1].target),
                first: place.line_word(w[0].line),
            };
            return Err(ReadError::new(place.line(w[1].line), kind));
        }
        let raw = self.in_cycle_order();
        let (m, n) = (self.rows.len(), self.runs.len());
        let mut notes = vec![format!(
            "{m} targets × {n} runs per direction; order of measurement assumed: the standard test cycle (ISO 230-2:1997, Figure 1), each run up over the targets ascending, then down"
        )];
        if !ascending {
            notes.push("rows not in ascending target order: sorted by target".into());
        }
        let data = AxisData::from_raw_in(self.kind, raw, Vec::new(), place)?;
        Ok((data, notes))
    }
}

impl WideTable {
    /// Every reading in the standard test cycle: for each run, up over the targets
    /// ascending, then down over them descending.
    fn in_cycle_order(&self) -> Vec<RawReading> {
        let mut raw = Vec::with_capacity(self.rows.len() * self.columns.len());
        for &run in &self.runs {
            for direction in Direction::BOTH {
                let Some(k) = self
                    .columns
                    .iter()
                    .position(|c| c.run == run && c.direction == direction)
                else {
                    continue; // checked in the header: every run has both columns
                };
                let mut push = |row: &WideRow| {
                    raw.push(RawReading {
                        target: row.target,
                        direction,
                        run,
                        deviation: row.deviations[k],
                        time_s: None,
                        temps_c: Vec::new(),
                        line: row.line,
                    })
                };
                match direction {
                    Direction::Up => self.rows.iter().for_each(&mut push),
                    Direction::Down => self.rows.iter().rev().for_each(&mut push),
                }
            }
        }
        raw
    }
}

/// The targets' kind from the first column's name; an angular test's targets are along
/// a linear axis, in mm.
fn target_kind(name: &str, quantities: Quantities) -> Result<AxisKind, ReadErrorKind> {
    let kind = match name {
        "target_mm" => AxisKind::Linear,
        "target_deg" => AxisKind::Rotary,
        "target" => {
            let expected = match quantities {
                Quantities::OneKind => "`target_mm` (linear) or `target_deg` (rotary)",
                Quantities::AnglesAlongLinear => "`target_mm` (targets along the axis)",
            };
            let (name, expected) = (name.to_string(), expected.to_string());
            return Err(ReadErrorKind::MissingUnit { name, expected });
        }
        other => {
            let found = other.to_string();
            return Err(ReadErrorKind::TargetNotFirst { found });
        }
    };
    if quantities == Quantities::AnglesAlongLinear && kind != AxisKind::Linear {
        return Err(not_for_angular(
            name,
            "targets along the axis in mm (`target_mm`)",
        ));
    }
    Ok(kind)
}

/// A run column's unit against the target's (`target`: its name and kind): of one kind
/// for a positioning or straightness test, an angle for an angular test.
fn check_unit(
    column: &RunColumn,
    name: &str,
    (target, kind): (&str, AxisKind),
    quantities: Quantities,
) -> Result<(), ReadErrorKind> {
    match quantities {
        Quantities::OneKind if column.kind != kind => {
            Err(mixed_units(target, kind, name, column.kind))
        }
        Quantities::AnglesAlongLinear if column.kind != AxisKind::Rotary => {
            let canonical =
                |unit: &str| format!("`{}_{}_{unit}`", column.direction.name(), column.run);
            let expected = format!(
                "angular deviations ({}, {} or {}); µm are a positioning or straightness test's",
                canonical("arcsec"),
                canonical("urad"),
                canonical("deg")
            );
            Err(not_for_angular(name, &expected))
        }
        _ => Ok(()),
    }
}

/// Every run column has its partner in the other direction.
fn check_pairs(
    columns: &[RunColumn],
    names: &[String],
    at: &dyn Fn(usize, ReadErrorKind) -> ReadError,
) -> Result<(), ReadError> {
    for (k, c) in columns.iter().enumerate() {
        let other = match c.direction {
            Direction::Up => Direction::Down,
            Direction::Down => Direction::Up,
        };
        if !columns
            .iter()
            .any(|d| d.run == c.run && d.direction == other)
        {
            let unit = names[k + 1].rsplit('_').next().unwrap_or("um");
            let kind = ReadErrorKind::UnpairedRun {
                column: names[k + 1].clone(),
                missing: format!("{}_{}_{unit}", other.name(), c.run),
            };
            return Err(at(k + 1, kind));
        }
    }
    Ok(())
}

/// The run labels, ascending: 1 … n without gaps (a missing number is a deleted column
/// far more often than a run deliberately left out).
fn check_runs(columns: &[RunColumn]) -> Result<Vec<u32>, ReadErrorKind> {
    let mut runs: Vec<u32> = columns.iter().map(|c| c.run).collect();
    runs.sort_unstable();
    runs.dedup();
    if let Some(missing) = (1..).zip(&runs).find(|(k, r)| *k != **r).map(|(k, _)| k) {
        let found = runs
            .iter()
            .map(u32::to_string)
            .collect::<Vec<_>>()
            .join(",");
        return Err(ReadErrorKind::MissingRun { missing, found });
    }
    Ok(runs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_str(text: &str) -> Result<AxisData, ReadError> {
        parse(text.as_bytes(), "w.csv")
    }

    const SMALL: &str = "target_mm,up_1_um,down_1_um,up_2_um,down_2_um\n\
        0,1.0,2.0,1.5,2.5\n10,3.0,4.0,3.5,4.5\n";

    #[test]
    fn reads_the_wide_layout_in_the_standard_cycle() {
        let d = parse_str(SMALL).unwrap();
        assert_eq!(d.targets, vec![0.0, 10.0]);
        assert_eq!(d.runs(), 2);
        assert_eq!(d.deviations(1, Direction::Down), &[4.0, 4.5]);
        let order: Vec<(usize, Direction, usize)> = d
            .readings
            .iter()
            .map(|r| (r.target, r.direction, r.run))
            .collect();
        use Direction::{Down, Up};
        assert_eq!(
            order,
            vec![
                (0, Up, 0),
                (1, Up, 0),
                (1, Down, 0),
                (0, Down, 0),
                (0, Up, 1),
                (1, Up, 1),
                (1, Down, 1),
                (0, Down, 1)
            ]
        );
    }

    #[test]
    fn decimal_commas_units_and_descending_rows() {
        let text = "# Prüfprotokoll\ntarget_deg;down_1_deg;up_1_arcsec\n90;0,001;-3,6\n0;0;1\n";
        let (d, notes) = read(text.as_bytes(), "w.csv").unwrap();
        assert_eq!(d.kind, AxisKind::Rotary);
        assert_eq!(d.targets, vec![0.0, 90.0]);
        assert!((d.deviation(1, Direction::Down, 0) - 3.6).abs() < 1e-9);
        assert_eq!(d.deviation(1, Direction::Up, 0), -3.6);
        let all = notes.join("\n");
        assert!(all.contains("separator `;`"), "{all}");
        assert!(all.contains("1 comment line (#) skipped"), "{all}");
        assert!(all.contains("sorted by target"), "{all}");
    }

    #[test]
    fn header_mistakes_are_named() {
        let err = |text: &str| parse_str(text).unwrap_err().to_string();
        assert_eq!(
            err("target_mm,up1_um,down_1_um\n"),
            "w.csv:1:11: unknown column `up1_um` (did you mean `up_1_um`?); the wide layout has target_mm or target_deg first, then up_J_UNIT and down_J_UNIT for each run J (up_1_um, down_1_um, …; units um, nm, mm, arcsec, urad or deg)"
        );
        assert!(err("up_1_um,target_mm,down_1_um\n").contains("the first column is `up_1_um`"));
        assert!(err("target_mm,up_1,down_1_um\n").contains("`up_1` has no unit; write `up_1_um`"));
        assert!(
            err("target_mm,up_1_um,down_1_um,up_2_um\n").contains("`up_2_um` has no `down_2_um`")
        );
        assert!(err("target_mm,up_1_um,down_1_um,up_1_um\n").contains("`up_1_um` appears twice"));
        assert!(
            err("target_mm,up_1_um,down_1_um,up_1_mm\n")
                .contains("both give the up reading of run 1")
        );
        assert!(
            err("target_mm,up_1_um,down_1_um,up_3_um,down_3_um\n")
                .contains("run 2 has no columns but runs 1,3 have")
        );
        assert!(
            err("target_deg,up_1_um,down_1_um\n")
                .contains("column `up_1_um` is a length but `target_deg` is an angle")
        );
        assert!(err("target_mm\n0\n").contains("no run columns after `target_mm`"));
    }

    #[test]
    fn row_mistakes_are_named() {
        let err = |rows: &str| {
            parse_str(&format!("target_mm,up_1_um,down_1_um\n{rows}"))
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err("0,1,\n"),
            "w.csv:2:5: column `down_1_um`: the cell is empty; expected a number"
        );
        assert!(
            err("0,1,x\n")
                .starts_with("w.csv:2:5: column `down_1_um`: expected a number, found `x`")
        );
        assert!(err("0,1\n").contains("expected 3 fields"));
        assert_eq!(
            err("0,1,2\n5,1,2\n0,3,4\n"),
            "w.csv:4: target 0 mm already has a row (line 2); give each target one row"
        );
        assert!(err("0,1,1e9\n").contains("not a plausible deviation"));
    }

    fn angular(text: &str) -> Result<(AxisData, Vec<String>), ReadError> {
        read_for(text.as_bytes(), "p.csv", Quantities::AnglesAlongLinear)
    }

    /// The long layout of the same angles: what the wide one must read to.
    const PITCH_LONG: &str = "target_mm,direction,run,deviation_arcsec\n\
        0,up,1,-0.131\n500,up,1,9.829\n1000,up,1,19.927\n\
        1000,down,1,19.736\n500,down,1,9.954\n0,down,1,-0.014\n\
        0,up,2,0.042\n500,up,2,9.911\n1000,up,2,20.050\n\
        1000,down,2,19.902\n500,down,2,10.020\n0,down,2,0.077\n";

    #[test]
    fn an_angular_test_reads_angles_at_mm_as_the_long_layout_does() {
        let text = "target_mm,up_1_arcsec,down_1_arcsec,up_2_arcsec,down_2_arcsec\n\
            0,-0.131,-0.014,0.042,0.077\n500,9.829,9.954,9.911,10.020\n\
            1000,19.927,19.736,20.050,19.902\n";
        let (wide, notes) = angular(text).unwrap();
        let long = super::super::csv::read_for(
            PITCH_LONG.as_bytes(),
            "p.csv",
            Quantities::AnglesAlongLinear,
        )
        .unwrap()
        .0;
        assert_eq!(wide.kind, AxisKind::Linear, "targets along a linear axis");
        assert_eq!(wide.targets, vec![0.0, 500.0, 1000.0]);
        assert_eq!(wide.deviations(1, Direction::Down), &[9.954, 10.020]);
        for i in 0..3 {
            for d in Direction::BOTH {
                assert_eq!(wide.deviations(i, d), long.deviations(i, d));
            }
        }
        assert!(
            notes[0].starts_with("3 targets × 2 runs per direction"),
            "{notes:?}"
        );
    }

    #[test]
    fn an_angular_test_converts_urad_and_deg_to_arcsec() {
        let text = "target_mm;up_1_urad;down_1_deg\n0;0;0\n100;100;0,001\n";
        let (d, _) = angular(text).unwrap();
        // 100 µrad = 100 · 0.648/π = 20.6265″; 0.001° = 3.6″.
        assert!((d.deviation(1, Direction::Up, 0) - 20.626_480_6).abs() < 1e-6);
        assert!((d.deviation(1, Direction::Down, 0) - 3.6).abs() < 1e-9);
        let (rotary, _) = read(
            "target_deg,up_1_urad,down_1_urad\n90,1000,-1000\n".as_bytes(),
            "r.csv",
        )
        .unwrap();
        assert!((rotary.deviation(0, Direction::Up, 0) - 206.264_806).abs() < 1e-5);
    }

    #[test]
    fn angles_at_mm_read_for_another_test_are_named_an_angular_test() {
        let e = parse_str("target_mm,up_1_arcsec,down_1_arcsec\n0,1,2\n").unwrap_err();
        assert_eq!(e.kind.field().as_deref(), Some("up_1_arcsec"));
        assert_eq!(
            e.to_string(),
            "w.csv:1:11: column `up_1_arcsec` holds angles at targets in mm (`target_mm`): this looks like an angular test of a linear axis (roll, pitch or yaw); evaluate it with `eval --test angular --direction A|B|C` (in a campaign, `test: angular` with `about:`), or give the deviations in um, nm or mm for a positioning or straightness test"
        );
    }

    #[test]
    fn an_angular_test_refuses_lengths_and_degree_targets_by_column() {
        let err = |text: &str| angular(text).unwrap_err().to_string();
        assert_eq!(
            err("target_mm,up_1_arcsec,down_1_um\n0,1,2\n"),
            "p.csv:1:23: column `down_1_um`: an angular test of a linear axis takes angular deviations (`down_1_arcsec`, `down_1_urad` or `down_1_deg`); µm are a positioning or straightness test's"
        );
        assert_eq!(
            err("target_deg,up_1_arcsec,down_1_arcsec\n0,1,2\n"),
            "p.csv:1:1: column `target_deg`: an angular test of a linear axis takes targets along the axis in mm (`target_mm`)"
        );
        assert!(err("target_mm,up_1,down_1_arcsec\n").contains(
            "`up_1` has no unit; write `up_1_arcsec` (or urad, deg) for an angular test"
        ));
        assert!(
            err("target,up_1_arcsec,down_1_arcsec\n")
                .contains("write `target_mm` (targets along the axis)")
        );
        assert_eq!(
            err("target_mm,up_1_arcsec,down_1_arcsec\n0,1,2e5\n"),
            "p.csv:2:5: column `down_1_arcsec`: 2e5 is not a plausible deviation (more than 100000 arcsec); check the column's unit"
        );
    }

    /// A straightness test is a linear table: µm across the axis at targets in mm, read
    /// as a positioning test's (the units say nothing more, and need not).
    #[test]
    fn a_straightness_test_reads_as_a_linear_table() {
        let text = "target_mm,up_1_um,down_1_um,up_2_nm,down_2_nm\n\
            0,0.0,0.4,100,500\n250,2.1,2.6,2200,2700\n500,-1.3,-0.9,-1200,-800\n";
        let (d, _) = read(text.as_bytes(), "eyx.csv").unwrap();
        assert_eq!(d.kind, AxisKind::Linear);
        assert_eq!(d.targets, vec![0.0, 250.0, 500.0]);
        assert_eq!(d.deviations(1, Direction::Up), &[2.1, 2.2]);
        assert_eq!(d.deviations(2, Direction::Down), &[-0.9, -0.8]);
        let e = angular(text).unwrap_err().to_string();
        assert!(
            e.starts_with("p.csv:1:11: column `up_1_um`: an angular test"),
            "{e}"
        );
    }
}
