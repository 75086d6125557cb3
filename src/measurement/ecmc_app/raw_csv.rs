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
                let names = split_fields(l, ',')
                    .into_iter()
                    .map(|(_, f)| f.trim().to_ascii_lowercase())
                    .collect();
                break Header { names, line: n };
            }
            Some(_) => continue,
            None => return Err(error(file, 0, "the file is empty".into())),
        }
    };
    let cols = columns(&header, source, file)?;
    let at = |name: &str| header.find(name);
    let (cycle_col, dir, target) = (
        header.need("cycle", file)?,
        header.need("direction", file)?,
        header.need("target", file)?,
    );
    let (gain, offset, pv, time) = (
        at("reference_gain"),
        at("reference_offset"),
        at("selected_reference_pv"),
        at("timestamp"),
    );
    let mut points = Vec::new();
    let mut transform = Transform::NONE;
    let mut selected_pv = String::new();
    while let Some((line, text)) = lines.next_line()? {
        if text.trim().is_empty() {
            continue;
        }
        let cells: Vec<String> = split_fields(text, ',')
            .into_iter()
            .map(|(_, f)| f)
            .collect();
        if cells.len() != header.names.len() {
            return Err(error(
                file,
                line,
                format!(
                    "expected {} fields as in the header, found {}",
                    header.names.len(),
                    cells.len()
                ),
            ));
        }
        let cell = |k: usize| cells[k].trim();
        let number = |k: usize| number(cell(k), &header.names[k], file, line);
        let optional = |k: Option<usize>| -> Result<Option<f64>, ReadError> {
            match k {
                Some(k) if !cell(k).is_empty() => number(k).map(Some),
                _ => Ok(None),
            }
        };
        if let Some(k) = cols.pv.filter(|&k| cell(k).is_empty()) {
            return Err(error(
                file,
                line,
                format!(
                    "`{}` is empty: {} was not recorded at this point",
                    header.names[k],
                    source.describe()
                ),
            ));
        }
        if cols.reference {
            transform = Transform {
                gain: optional(gain)?.unwrap_or(1.0),
                offset: optional(offset)?.unwrap_or(0.0),
            };
        }
        if selected_pv.is_empty() {
            let named = cols.pv.or(pv);
            selected_pv = named.map(|k| cell(k).to_string()).unwrap_or_default();
        }
        let cycle_n = cycle(cell(cycle_col), "cycle", file, line)?;
        let direction = direction_at(cell(dir), "direction", file, line)?;
        let target_value = number(target)?;
        let error_value = match (transform.is_none(), cols.mean) {
            (false, Some(m)) => transform.error(number(m)?, target_value),
            _ => number(cols.error)?,
        };
        points.push(Point {
            cycle: cycle_n,
            direction,
            target: target_value,
            error: error_value,
            std: optional(cols.std).ok().flatten(),
            time: time.and_then(|k| timestamp(cell(k))),
            line,
        });
    }
    let name = match (source, selected_pv.as_str()) {
        (Source::Selected, "") => "the reference the app evaluated".to_string(),
        (Source::Selected, pv) => format!("reference `{pv}`, the one the app evaluated"),
        (Source::Reference(n), pv) if !pv.is_empty() => format!("reference {n} (`{pv}`)"),
        (other, _) => other.describe(),
    };
    let notes = notes(&name, transform, &points);
    let raw = readings(&points, file)?;
    Ok((
        AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), file)?,
        notes,
    ))
}
