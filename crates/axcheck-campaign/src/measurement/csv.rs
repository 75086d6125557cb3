//! The canonical long CSV layout: one row per reading, units in the column names.
//!
//! ```text
//! target_mm,direction,run,deviation_um,time_s,temp_table_c
//! 6.711,up,1,-1.2,12.0,20.4
//! ```
//! Columns: `target_mm` or `target_deg`; one of `deviation_um`, `deviation_nm`,
//! `deviation_mm`, `deviation_arcsec`, `deviation_urad`, `deviation_deg`, `actual_mm`,
//! `actual_deg` (an
//! actual position P_ij gives X_ij = P_ij − P_i, ISO 230-2 clause 2.5); `direction`;
//! `run` (approach index j, 1-based); optional `time_s` and `temp_<name>_c`. Separators
//! `,`, `;` or tab; with `;` or tab a decimal comma is accepted. `#` lines are comments.
//!
//! The other laser tests of a linear axis (ISO 230-1) use the same table. A straightness
//! test is a linear one: deviations across the axis in `deviation_um` (`_nm`, `_mm`) at
//! `target_mm`. An angular test (roll, pitch, yaw) has angles at targets in mm
//! (`target_mm` with `deviation_arcsec`, `deviation_urad` or `deviation_deg`), read only
//! when the caller asks for one ([`read_for`] with [`Quantities::AnglesAlongLinear`]):
//! read for any other test, angles at mm are refused as an angular test's layout, and read
//! for an angular test, µm or degree targets are refused naming the column.

use super::cell::{Origin, Value};
use super::error::{ReadError, ReadErrorKind};
use super::table::{Quantities, Row, TableReader, mixed_units, not_for_angular, read_text};
use super::{AxisData, MAX_READINGS, MAX_TEMPERATURES, RawReading};
use crate::suggest::did_you_mean;
use crate::units::{AxisKind, Direction, fmt_fixed};
use std::io::BufRead;

/// What a column holds.
#[derive(Debug, Clone, PartialEq)]
enum Column {
    Target(AxisKind),
    /// Deviation with the factor to µm or arcsec.
    Deviation(AxisKind, f64),
    /// Actual position with the factor to µm or arcsec.
    Actual(AxisKind, f64),
    Direction,
    Run,
    TimeS,
    Temperature(usize),
}

const KNOWN: &[&str] = &[
    "target_mm",
    "target_deg",
    "deviation_um",
    "deviation_nm",
    "deviation_mm",
    "deviation_arcsec",
    "deviation_urad",
    "deviation_deg",
    "actual_mm",
    "actual_deg",
    "direction",
    "run",
    "time_s",
];

fn classify(name: &str, temps: &mut Vec<String>) -> Result<Column, ReadErrorKind> {
    use AxisKind::{Linear, Rotary};
    let column = match name {
        "target_mm" => Column::Target(Linear),
        "target_deg" => Column::Target(Rotary),
        "deviation_um" => Column::Deviation(Linear, 1.0),
        "deviation_nm" => Column::Deviation(Linear, 0.001),
        "deviation_mm" => Column::Deviation(Linear, 1000.0),
        "deviation_arcsec" => Column::Deviation(Rotary, 1.0),
        // 1 µrad = 0.648/π arcsec.
        "deviation_urad" => Column::Deviation(Rotary, 0.648 / std::f64::consts::PI),
        "deviation_deg" => Column::Deviation(Rotary, 3600.0),
        "actual_mm" => Column::Actual(Linear, 1000.0),
        "actual_deg" => Column::Actual(Rotary, 3600.0),
        "direction" => Column::Direction,
        "run" => Column::Run,
        "time_s" => Column::TimeS,
        _ => {
            if let Some(inner) = name.strip_prefix("temp_") {
                if let Some(sensor) = inner.strip_suffix("_c").filter(|s| !s.is_empty()) {
                    if temps.len() >= MAX_TEMPERATURES {
                        return Err(ReadErrorKind::TooManyTemperatures {
                            limit: MAX_TEMPERATURES,
                        });
                    }
                    temps.push(sensor.to_string());
                    return Ok(Column::Temperature(temps.len() - 1));
                }
                return Err(ReadErrorKind::MissingUnit {
                    name: name.into(),
                    expected: format!("`temp_{inner}_c` (°C)"),
                });
            }
            let missing = |expected: &str| ReadErrorKind::MissingUnit {
                name: name.into(),
                expected: expected.into(),
            };
            return Err(match name {
                "target" | "position" | "target_position" => {
                    missing("`target_mm` (linear) or `target_deg` (rotary)")
                }
                "deviation" | "error" | "dev" => {
                    missing("`deviation_um`, `deviation_mm`, `deviation_arcsec` or `deviation_deg`")
                }
                "actual" | "actual_position" | "reading" => missing("`actual_mm` or `actual_deg`"),
                "time" | "t" => missing("`time_s` (seconds from the start of the test)"),
                _ => ReadErrorKind::UnknownColumn {
                    name: name.into(),
                    suggestion: did_you_mean(name, KNOWN).map(str::to_string),
                },
            });
        }
    };
    Ok(column)
}

/// True when `name` (trimmed, lower case) is a long-layout column, or so nearly one that
/// the file is taken for a long CSV with a mistake in its header: a column without its
/// unit, or a misspelt one.
pub(crate) fn is_long_column(name: &str) -> bool {
    KNOWN.contains(&name)
        || name.starts_with("temp_")
        || UNITLESS.contains(&name)
        || did_you_mean(name, KNOWN).is_some()
}

/// Column names that lack their unit, each with the names to write instead.
const UNITLESS: &[&str] = &[
    "target",
    "position",
    "target_position",
    "deviation",
    "error",
    "dev",
    "actual",
    "actual_position",
    "reading",
    "time",
    "t",
];

/// Parses the long CSV layout.
pub fn parse<R: BufRead>(reader: R, file: &str) -> Result<AxisData, ReadError> {
    read(reader, file).map(|(data, _)| data)
}

/// Parses the long CSV layout; also returns what was assumed or skipped.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
) -> Result<(AxisData, Vec<String>), ReadError> {
    read_for(reader, file, Quantities::OneKind)
}

/// Parses the long CSV layout with the units `quantities` asks (an angular test's angles
/// at targets in mm, or one kind); also returns what was assumed.
pub(crate) fn read_for<R: BufRead>(
    reader: R,
    file: &str,
    quantities: Quantities,
) -> Result<(AxisData, Vec<String>), ReadError> {
    read_text::<LongTable, R>(reader, file, quantities)
}

/// The long table being read: what the header says (the columns, where the required ones
/// are, the units) and the readings so far.
pub(crate) struct LongTable {
    columns: Vec<Column>,
    /// Column names as written (trimmed, lower case), for messages.
    names: Vec<String>,
    /// Names of the `temp_<name>_c` columns.
    temps: Vec<String>,
    kind: AxisKind,
    /// The value column's kind: its unit names a deviation in messages (arcsec for an
    /// angular test of a linear axis).
    value_kind: AxisKind,
    target: usize,
    value: usize,
    direction: usize,
    run: usize,
    time: Option<usize>,
    /// Factor from the value column's unit to µm or arcsec.
    factor: f64,
    /// The value column holds actual positions P_ij, not deviations.
    is_actual: bool,
    raw: Vec<RawReading>,
}

impl TableReader for LongTable {
    fn from_header(
        header: &Row,
        place: &Origin,
        quantities: Quantities,
    ) -> Result<LongTable, ReadError> {
        LongTable::from_header_for(header, place, quantities)
    }

    fn add(&mut self, row: &Row, place: &Origin) -> Result<(), ReadError> {
        if self.raw.len() >= MAX_READINGS {
            return Err(ReadError::new(
                place.line(row.number),
                ReadErrorKind::TooManyReadings {
                    limit: MAX_READINGS,
                },
            ));
        }
        let reading = self.reading(row, place)?;
        self.raw.push(reading);
        Ok(())
    }

    fn finish(self, place: &Origin) -> Result<(AxisData, Vec<String>), ReadError> {
        let mut notes = Vec::new();
        if self.is_actual {
            notes.push(format!(
                "`{}` holds actual positions: deviations taken as actual − target (ISO 230-2 clause 2.5)",
                self.names[self.value]
            ));
        }
        if self.time.is_none() {
            notes.push("no time_s column: the rows are taken in the order of measurement".into());
        }
        let data = AxisData::from_raw_in(self.kind, self.raw, self.temps, place)?;
        Ok((data, notes))
    }
}

/// The header's units against the test's: one kind for a positioning or straightness
/// test, angular deviations at targets along a linear axis (mm) for an angular test.
/// `Err` holds the index of the column at fault and what is wrong with it.
fn check_quantities(
    names: &[String],
    (target, kind): (usize, AxisKind),
    (value, value_kind, is_actual): (usize, AxisKind, bool),
    quantities: Quantities,
) -> Result<(), (usize, ReadErrorKind)> {
    let wrong = |column: usize, expected: &str| (column, not_for_angular(&names[column], expected));
    match quantities {
        Quantities::OneKind if value_kind != kind => Err((
            value,
            mixed_units(&names[target], kind, &names[value], value_kind),
        )),
        Quantities::OneKind => Ok(()),
        Quantities::AnglesAlongLinear if kind != AxisKind::Linear => {
            Err(wrong(target, "targets along the axis in mm (`target_mm`)"))
        }
        Quantities::AnglesAlongLinear if value_kind != AxisKind::Rotary || is_actual => Err(wrong(
            value,
            "angular deviations (`deviation_arcsec`, `deviation_urad` or `deviation_deg`)",
        )),
        Quantities::AnglesAlongLinear => Ok(()),
    }
}

impl LongTable {
    /// The table's columns from its header, the units checked as `quantities` asks.
    fn from_header_for(
        header: &Row,
        place: &Origin,
        quantities: Quantities,
    ) -> Result<LongTable, ReadError> {
        let fields = classify_header(header, place)?;
        let header_err = |kind| ReadError::new(place.line(header.number), kind);
        let one = |pred: &dyn Fn(&Column) -> bool, what: &str, expected: &str| {
            fields.only(pred, what, expected).map_err(header_err)
        };
        let target = one(
            &|c| matches!(c, Column::Target(_)),
            "target position",
            "`target_mm` or `target_deg`",
        )?;
        let value = one(
            &|c| matches!(c, Column::Deviation(..) | Column::Actual(..)),
            "deviation",
            "`deviation_um` (or deviation_mm, deviation_arcsec, deviation_deg, actual_mm, actual_deg)",
        )?;
        let direction = one(&|c| *c == Column::Direction, "direction", "`direction`")?;
        let run = one(&|c| *c == Column::Run, "run", "`run`")?;
        let Header {
            columns,
            names,
            temps,
        } = fields;
        let time = columns.iter().position(|c| *c == Column::TimeS);
        let Column::Target(kind) = columns[target] else {
            unreachable!("target column classified above")
        };
        let (value_kind, factor, is_actual) = match columns[value] {
            Column::Deviation(k, f) => (k, f, false),
            Column::Actual(k, f) => (k, f, true),
            _ => unreachable!("value column classified above"),
        };
        // At the column's cell: the header names several, and this one is wrong.
        check_quantities(
            &names,
            (target, kind),
            (value, value_kind, is_actual),
            quantities,
        )
        .map_err(|(k, e)| place.error(header.number, header.fields[k].column, e))?;
        Ok(LongTable {
            columns,
            names,
            temps,
            kind,
            value_kind,
            target,
            value,
            direction,
            run,
            time,
            factor,
            is_actual,
            // A test holds a few hundred readings: room for them at once.
            raw: Vec::with_capacity(256),
        })
    }

    /// One data row as a reading.
    fn reading(&self, row: &Row, place: &Origin) -> Result<RawReading, ReadError> {
        let number = row.number;
        let fields = &row.fields;
        if fields.len() != self.columns.len() {
            let kind = ReadErrorKind::FieldCount {
                expected: self.columns.len(),
                found: fields.len(),
            };
            return Err(place.error(number, 1, kind));
        }
        let number_at = |k: usize| place.number(number, &fields[k], &self.names[k]);
        let target = number_at(self.target)? + 0.0; // normalise -0.0
        let deviation = self.deviation(target, number_at(self.value)?);
        if deviation.abs() > super::MAX_DEVIATION {
            let field = &fields[self.value];
            let kind = ReadErrorKind::Implausible {
                column: self.names[self.value].clone(),
                value: field.value.shown(),
                limit: format!("{}", super::MAX_DEVIATION),
                unit: self.value_kind.deviation_unit().to_string(),
            };
            return Err(place.error(number, field.column, kind));
        }
        let d = &fields[self.direction];
        let direction = match &d.value {
            Value::Text(text) => Direction::parse(text),
            _ => None,
        }
        .ok_or_else(|| place.error(number, d.column, unknown_direction(&d.value.shown())))?;
        let r = &fields[self.run];
        let run = parse_run(&r.value).ok_or_else(|| {
            let found = r.value.shown();
            place.error(number, r.column, ReadErrorKind::InvalidRun { found })
        })?;
        let time_s = self.time.map(number_at).transpose()?;
        let mut temps_c = vec![0.0; self.temps.len()];
        for (k, column) in self.columns.iter().enumerate() {
            if let Column::Temperature(t) = column {
                temps_c[*t] = number_at(k)?;
            }
        }
        Ok(RawReading {
            target,
            direction,
            run,
            deviation,
            time_s,
            temps_c,
            line: number,
        })
    }

    /// X_ij in µm or arcsec from the value column.
    fn deviation(&self, target: f64, value: f64) -> f64 {
        if self.is_actual {
            // Subtract in the file's unit first, then scale: keeps 0.1 µm exact-ish.
            (value - target) * self.factor
        } else {
            value * self.factor
        }
    }
}

/// The header's fields: what each column holds, its name, and the temperature sensors.
struct Header {
    columns: Vec<Column>,
    names: Vec<String>,
    temps: Vec<String>,
}

impl Header {
    /// The one column `pred` picks: none is a missing column, two are a conflict.
    fn only(
        &self,
        pred: &dyn Fn(&Column) -> bool,
        what: &str,
        expected: &str,
    ) -> Result<usize, ReadErrorKind> {
        let found: Vec<usize> = (0..self.columns.len())
            .filter(|&k| pred(&self.columns[k]))
            .collect();
        match found.as_slice() {
            [] => Err(ReadErrorKind::MissingColumn {
                expected: expected.into(),
            }),
            [k] => Ok(*k),
            [a, b, ..] => Err(ReadErrorKind::ConflictingColumns {
                first: self.names[*a].clone(),
                second: self.names[*b].clone(),
                what: what.into(),
            }),
        }
    }
}

/// Classifies every header field; a column named twice is an error.
fn classify_header(header: &Row, place: &Origin) -> Result<Header, ReadError> {
    let mut temps = Vec::new();
    let mut columns = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for field in &header.fields {
        let err = |kind| place.error(header.number, field.column, kind);
        let name = field.value.name();
        let column = classify(&name, &mut temps).map_err(err)?;
        if names.contains(&name) {
            return Err(err(ReadErrorKind::DuplicateColumn { name }));
        }
        columns.push(column);
        names.push(name);
    }
    Ok(Header {
        columns,
        names,
        temps,
    })
}

/// A direction that is none of the spellings [`Direction::parse`] knows.
fn unknown_direction(text: &str) -> ReadErrorKind {
    let found = text.trim().to_string();
    let suggestion = did_you_mean(&found, &["up", "down", "forward", "reverse", "fwd", "bwd"])
        .map(str::to_string);
    ReadErrorKind::UnknownDirection { found, suggestion }
}

/// A run number: a positive integer (`3`, ` 3 `, `3.0`, or a sheet's number 3).
fn parse_run(value: &Value) -> Option<u32> {
    match value {
        Value::Text(text) => {
            let t = text.trim();
            let t = t.strip_suffix(".0").unwrap_or(t);
            t.parse::<u32>().ok().filter(|&r| r >= 1)
        }
        Value::Number(x) if x.fract() == 0.0 && *x >= 1.0 && *x <= f64::from(u32::MAX) => {
            Some(*x as u32)
        }
        _ => None,
    }
}

/// Writes `data` in the long CSV layout, readings in measurement order; `comments` become
/// leading `#` lines. Deviations with 4 decimals, times with 3: the same input always
/// gives the same bytes.
pub fn write(data: &AxisData, comments: &[String]) -> String {
    let kind = data.kind;
    write_in(data, comments, kind.position_unit(), kind.deviation_unit())
}

/// [`write()`] for an angular test of a linear axis: angles (arcsec) at targets in mm.
pub fn write_angular(data: &AxisData, comments: &[String]) -> String {
    write_in(data, comments, "mm", "arcsec")
}

fn write_in(data: &AxisData, comments: &[String], position: &str, deviation: &str) -> String {
    let mut out = String::with_capacity(64 * data.readings.len() + 256);
    for c in comments {
        for line in c.lines() {
            out.push_str("# ");
            out.push_str(line);
            out.push('\n');
        }
    }
    let times = data.has_times();
    out.push_str(&format!(
        "target_{position},direction,run,deviation_{deviation}"
    ));
    if times {
        out.push_str(",time_s");
    }
    for name in &data.temperature_names {
        out.push_str(&format!(",temp_{name}_c"));
    }
    out.push('\n');
    for (k, r) in data.readings.iter().enumerate() {
        out.push_str(&crate::units::fmt_position(data.targets[r.target]));
        out.push(',');
        out.push_str(r.direction.name());
        out.push(',');
        out.push_str(&data.run_labels[r.run].to_string());
        out.push(',');
        out.push_str(&fmt_fixed(r.deviation, 4));
        if times {
            out.push(',');
            out.push_str(&fmt_fixed(r.time_s.unwrap_or(0.0), 3));
        }
        for t in &data.temperatures_c[k] {
            out.push(',');
            out.push_str(&fmt_fixed(*t, 3));
        }
        out.push('\n');
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_str(text: &str) -> Result<AxisData, ReadError> {
        parse(text.as_bytes(), "t.csv")
    }

    const SMALL: &str = "target_mm,direction,run,deviation_um\n\
        0,up,1,1.0\n0,down,1,2.0\n10,up,1,3.0\n10,down,1,4.0\n\
        0,up,2,1.5\n0,down,2,2.5\n10,up,2,3.5\n10,down,2,4.5\n";

    #[test]
    fn reads_the_canonical_layout() {
        let d = parse_str(SMALL).unwrap();
        assert_eq!(d.kind, AxisKind::Linear);
        assert_eq!(d.targets, vec![0.0, 10.0]);
        assert_eq!(d.runs(), 2);
        assert_eq!(d.deviations(1, Direction::Down), &[4.0, 4.5]);
        assert_eq!(d.readings.len(), 8);
        assert_eq!(d.readings[0].line, 2);
    }

    #[test]
    fn semicolons_decimal_commas_bom_crlf_and_comments() {
        let text = "\u{feff}# GOST table\r\ntarget_mm;direction;run;deviation_um\r\n\
            0;↑;1;-2,6\r\n0;↓;1;2,3\r\n# mid comment\r\n150,71;+;1;0,2\r\n150,71;-;1;5,4\r\n";
        let d = parse_str(text).unwrap();
        assert_eq!(d.targets, vec![0.0, 150.71]);
        assert_eq!(d.deviations(0, Direction::Up), &[-2.6]);
        assert_eq!(d.deviations(1, Direction::Down), &[5.4]);
    }

    #[test]
    fn actual_positions_and_unit_scaling() {
        let text = "target_deg,direction,run,actual_deg\n90,up,1,90.001\n90,down,1,89.999\n";
        let d = parse_str(text).unwrap();
        assert_eq!(d.kind, AxisKind::Rotary);
        assert!((d.deviation(0, Direction::Up, 0) - 3.6).abs() < 1e-6);
        assert!((d.deviation(0, Direction::Down, 0) + 3.6).abs() < 1e-6);
        let text = "target_mm,direction,run,deviation_mm\n5,up,1,0.0012\n5,down,1,-0.0005\n";
        let d = parse_str(text).unwrap();
        assert!((d.deviation(0, Direction::Up, 0) - 1.2).abs() < 1e-9);
    }

    #[test]
    fn quoted_header_and_time_and_temperatures() {
        let text = "\"target_mm\",\"direction\",\"run\",\"deviation_um\",time_s,temp_screw_c\n\
            0,up,1,1,0.5,20.1\n0,down,1,2,9.5,20.2\n";
        let d = parse_str(text).unwrap();
        assert_eq!(d.temperature_names, vec!["screw".to_string()]);
        assert_eq!(d.temperatures_c[1], vec![20.2]);
        assert_eq!(d.readings[1].time_s, Some(9.5));
        assert!(d.has_times());
    }

    #[test]
    fn round_trips_through_the_writer() {
        let d = parse_str(SMALL).unwrap();
        let text = write(&d, &["made by a test".into()]);
        let again = parse_str(&text).unwrap();
        assert_eq!(d.targets, again.targets);
        for i in 0..2 {
            for dir in Direction::BOTH {
                assert_eq!(d.deviations(i, dir), again.deviations(i, dir));
            }
        }
        assert!(text.starts_with("# made by a test\ntarget_mm,direction,run,deviation_um\n"));
    }

    /// An angular test's table is read only for one, and reads only angles at mm.
    #[test]
    fn an_angular_tests_units_are_enforced_both_ways() {
        let pitch = "target_mm,direction,run,deviation_urad\n0,up,1,10\n0,down,1,-10\n";
        let (d, _) = read_for(pitch.as_bytes(), "p.csv", Quantities::AnglesAlongLinear).unwrap();
        assert_eq!(d.kind, AxisKind::Linear);
        assert!((d.deviation(0, Direction::Up, 0) - 2.062_648_06).abs() < 1e-8);
        let e = parse(pitch.as_bytes(), "p.csv").unwrap_err();
        assert_eq!(e.kind.field().as_deref(), Some("deviation_urad"));
        assert!(
            e.to_string().starts_with("p.csv:1:25: column `deviation_urad` holds angles at targets in mm (`target_mm`): this looks like an angular test of a linear axis"),
            "{e}"
        );
        let err = |text: &str| {
            read_for(text.as_bytes(), "p.csv", Quantities::AnglesAlongLinear)
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            err("target_mm,direction,run,deviation_um\n"),
            "p.csv:1:25: column `deviation_um`: an angular test of a linear axis takes angular deviations (`deviation_arcsec`, `deviation_urad` or `deviation_deg`)"
        );
        assert!(
            err("target_mm,direction,run,actual_deg\n")
                .contains("column `actual_deg`: an angular test")
        );
        assert!(err("target_deg,direction,run,deviation_arcsec\n").contains("column `target_deg`: an angular test of a linear axis takes targets along the axis in mm"));
        assert!(
            err("target_mm,direction,run,deviation_arcsec\n0,up,1,2e5\n")
                .ends_with("2e5 is not a plausible deviation (more than 100000 arcsec); check the column's unit")
        );
        // A rotary axis's positioning test keeps its angles at degrees.
        assert!(
            parse(
                "target_deg,direction,run,deviation_urad\n0,up,1,1\n0,down,1,1\n".as_bytes(),
                "r.csv"
            )
            .is_ok()
        );
    }
}
