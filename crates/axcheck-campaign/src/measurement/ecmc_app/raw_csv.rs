//! The ecmc ISO 230 app's raw-points CSV ("Export CSV"): one row per point,
//! `cycle,direction,target,[reference_gain,reference_offset,]selected_reference_slot,
//! selected_reference_pv,reference_mean,reference_std,rbv_mean,rbv_std,command_mean,
//! ref_error,rbv_error,ref1_pv,ref1_mean,ref1_std,ref1_error,…,ref5_error,timestamp`
//! (the gain and offset columns since the app's version of 2026-03-19). Numbers at full
//! precision, Python's shortest form (`-6.1e-05`); the selected reference counted from 0
//! in `selected_reference_slot` and from 1 in the `refN_` columns; reference values raw.

use super::{
    Point, Source, Transform, cycle, direction_at, error, notes, number, readings, timestamp,
};
use crate::measurement::fields::split_fields;
use crate::measurement::{AxisData, Lines, ReadError};
use crate::units::AxisKind;
use std::io::BufRead;

/// Whether a header's column names (trimmed, lower case) are the app's.
pub fn looks_like(names: &[String]) -> bool {
    let has = |n: &str| names.iter().any(|x| x == n);
    has("cycle") && has("direction") && has("target") && has("selected_reference_slot")
}

/// The header's columns the reader uses.
struct Header {
    names: Vec<String>,
    line: usize,
}

impl Header {
    fn find(&self, name: &str) -> Option<usize> {
        self.names.iter().position(|n| n == name)
    }

    fn need(&self, name: &str, file: &str) -> Result<usize, ReadError> {
        self.find(name).ok_or_else(|| {
            error(
                file,
                self.line,
                format!("missing column `{name}` in the app's raw-points header"),
            )
        })
    }
}

/// Where `source`'s values are.
struct Columns {
    error: usize,
    mean: Option<usize>,
    std: Option<usize>,
    /// The PV column that must be set on every row (a reference that was recorded).
    pv: Option<usize>,
    /// Whether gain and offset apply.
    reference: bool,
}

fn columns(header: &Header, source: Source, file: &str) -> Result<Columns, ReadError> {
    let (prefix, error_name) = match source {
        Source::Selected => ("reference", "ref_error".to_string()),
        Source::Readback => ("rbv", "rbv_error".to_string()),
        Source::Reference(n) => {
            let p = format!("ref{n}");
            let e = format!("{p}_error");
            return Ok(Columns {
                error: header.need(&e, file)?,
                mean: header.find(&format!("{p}_mean")),
                std: header.find(&format!("{p}_std")),
                pv: header.find(&format!("{p}_pv")),
                reference: true,
            });
        }
    };
    Ok(Columns {
        error: header.need(&error_name, file)?,
        mean: header.find(&format!("{prefix}_mean")),
        std: header.find(&format!("{prefix}_std")),
        pv: None,
        reference: source != Source::Readback,
    })
}

/// Reads the CSV: the points of `source` as a linear axis, and the notes.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
    source: Source,
) -> Result<(AxisData, Vec<String>), ReadError> {
    let mut lines = Lines::new(reader, file);
    let header = loop {
        match lines.next_line()? {
            Some((n, l)) if !l.trim().is_empty() => {
                let names = (split_fields(l, ',').into_iter())
                    .map(|(_, f)| f.trim().to_ascii_lowercase())
                    .collect();
                break Header { names, line: n };
            }
            Some(_) => continue,
            None => return Err(error(file, 0, "the file is empty".into())),
        }
    };
    let layout = RowLayout::of(&header, source, file)?;
    let mut points = Vec::new();
    let (mut transform, mut pv_name) = (Transform::NONE, String::new());
    while let Some((line, text)) = lines.next_line()? {
        if text.trim().is_empty() {
            continue;
        }
        let cells: Vec<String> = split_fields(text, ',')
            .into_iter()
            .map(|(_, f)| f)
            .collect();
        let row = Row {
            cells: &cells,
            line,
            file,
            header: &header,
        };
        row.check_width()?;
        if let Some(t) = layout.transform(&row)? {
            transform = t;
        }
        if pv_name.is_empty() {
            pv_name = layout.pv_name(&row);
        }
        points.push(layout.point(&row, transform, source)?);
    }
    let name = match (source, pv_name.as_str()) {
        (Source::Selected, "") => "the reference the app evaluated".to_string(),
        (Source::Selected, pv) => format!("reference `{pv}`, the one the app evaluated"),
        (Source::Reference(n), pv) if !pv.is_empty() => format!("reference {n} (`{pv}`)"),
        (other, _) => other.describe(),
    };
    let notes = notes(&name, transform, &points);
    let raw = readings(&points, file)?;
    let data = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), file)?;
    Ok((data, notes))
}

/// One row of the file, for its fields and errors.
struct Row<'a> {
    cells: &'a [String],
    line: usize,
    file: &'a str,
    header: &'a Header,
}

impl Row<'_> {
    fn check_width(&self) -> Result<(), ReadError> {
        let (want, found) = (self.header.names.len(), self.cells.len());
        match want == found {
            true => Ok(()),
            false => Err(error(
                self.file,
                self.line,
                format!("expected {want} fields as in the header, found {found}"),
            )),
        }
    }

    fn cell(&self, k: usize) -> &str {
        self.cells[k].trim()
    }

    fn number(&self, k: usize) -> Result<f64, ReadError> {
        number(self.cell(k), &self.header.names[k], self.file, self.line)
    }

    /// The number in column `k`, when there is one.
    fn optional(&self, k: Option<usize>) -> Result<Option<f64>, ReadError> {
        match k {
            Some(k) if !self.cell(k).is_empty() => self.number(k).map(Some),
            _ => Ok(None),
        }
    }
}

/// Where a row's fields are.
struct RowLayout {
    columns: Columns,
    cycle: usize,
    direction: usize,
    target: usize,
    gain: Option<usize>,
    offset: Option<usize>,
    pv: Option<usize>,
    time: Option<usize>,
}

impl RowLayout {
    fn of(header: &Header, source: Source, file: &str) -> Result<RowLayout, ReadError> {
        Ok(RowLayout {
            columns: columns(header, source, file)?,
            cycle: header.need("cycle", file)?,
            direction: header.need("direction", file)?,
            target: header.need("target", file)?,
            gain: header.find("reference_gain"),
            offset: header.find("reference_offset"),
            pv: header.find("selected_reference_pv"),
            time: header.find("timestamp"),
        })
    }

    /// A reference's gain and offset on this row (`None` for the readback).
    fn transform(&self, row: &Row) -> Result<Option<Transform>, ReadError> {
        if !self.columns.reference {
            return Ok(None);
        }
        Ok(Some(Transform {
            gain: row.optional(self.gain)?.unwrap_or(1.0),
            offset: row.optional(self.offset)?.unwrap_or(0.0),
        }))
    }

    /// The PV of the source read (or of the reference the app evaluated).
    fn pv_name(&self, row: &Row) -> String {
        let named = self.columns.pv.or(self.pv);
        named.map(|k| row.cell(k).to_string()).unwrap_or_default()
    }

    fn point(&self, row: &Row, transform: Transform, source: Source) -> Result<Point, ReadError> {
        let (file, line) = (row.file, row.line);
        if let Some(k) = self.columns.pv.filter(|&k| row.cell(k).is_empty()) {
            let message = format!(
                "`{}` is empty: {} was not recorded at this point",
                row.header.names[k],
                source.describe()
            );
            return Err(error(file, line, message));
        }
        let target = row.number(self.target)?;
        let error_value = match (transform.is_none(), self.columns.mean) {
            (false, Some(m)) => transform.error(row.number(m)?, target),
            _ => row.number(self.columns.error)?,
        };
        Ok(Point {
            cycle: cycle(row.cell(self.cycle), "cycle", file, line)?,
            direction: direction_at(row.cell(self.direction), "direction", file, line)?,
            target,
            error: error_value,
            std: row.optional(self.columns.std).ok().flatten(),
            time: self.time.and_then(|k| timestamp(row.cell(k))),
            line,
        })
    }
}
