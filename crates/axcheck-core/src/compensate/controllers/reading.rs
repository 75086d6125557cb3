//! What every table reader needs: numbered lines, numbers read where they stand (their
//! line and field named when they are not numbers), the points in order, and the table
//! put together in the correction convention of [`Table`].

use super::controller::Unreadable;
use crate::compensate::{Interpolation, Table, TableSlot};
use crate::units::AxisKind;

/// The lines of `text`, numbered from 1, without their line ends (`\n` or `\r\n`).
pub fn numbered(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(k, line)| (k + 1, line.strip_suffix('\r').unwrap_or(line)))
}

/// Larger than any position or correction a table holds (mm, degrees or their 0.1 µm
/// steps): a number beyond it is refused, so that converting units never overflows.
pub(crate) const LARGEST: f64 = 1e12;

/// A finite number as written in `field` at `line` (`1.5`, `-0.0020`, `+0.0025`, `1e-3`),
/// at most [`LARGEST`] in size.
pub fn number(text: &str, line: usize, field: &str) -> Result<f64, Unreadable> {
    let t = text.trim();
    let t = t.strip_prefix('+').unwrap_or(t);
    match t.parse::<f64>() {
        Ok(v) if v.abs() <= LARGEST => Ok(v),
        Ok(_) => Err(Unreadable::field(
            line,
            field,
            format!("expected a number of at most 1e12, got `{}`", text.trim()),
        )),
        Err(_) => Err(Unreadable::field(
            line,
            field,
            format!("expected a number, got `{}`", text.trim()),
        )),
    }
}

/// A whole number ≥ 0 as written in `field` at `line`.
pub fn whole(text: &str, line: usize, field: &str) -> Result<usize, Unreadable> {
    text.trim().parse::<usize>().map_err(|_| {
        Unreadable::field(
            line,
            field,
            format!("expected a whole number ≥ 0, got `{}`", text.trim()),
        )
    })
}

/// An integer as written in `field` at `line`.
pub fn integer(text: &str, line: usize, field: &str) -> Result<i64, Unreadable> {
    let t = text.trim();
    t.strip_prefix('+')
        .unwrap_or(t)
        .parse::<i64>()
        .map_err(|_| Unreadable::field(line, field, format!("expected an integer, got `{t}`")))
}

/// Positions that increase strictly, `lines[k]` the line of `positions[k]`.
pub fn increasing(positions: &[f64], lines: &[usize], field: &str) -> Result<(), Unreadable> {
    for k in 1..positions.len() {
        if positions[k] <= positions[k - 1] {
            return Err(Unreadable::field(
                lines[k],
                field,
                format!(
                    "the positions must increase: {} follows {}",
                    positions[k],
                    positions[k - 1]
                ),
            ));
        }
    }
    Ok(())
}

/// The table of points read from a file, before it becomes a [`Table`]: positions in mm
/// or degrees and corrections in µm or arcsec, the convention's sign already applied.
pub struct Points {
    pub kind: AxisKind,
    pub positions: Vec<f64>,
    pub up: Vec<f64>,
    pub down: Vec<f64>,
}

impl Points {
    /// No points yet, of an axis of `kind`.
    pub fn empty(kind: AxisKind) -> Points {
        Points {
            kind,
            positions: Vec::new(),
            up: Vec::new(),
            down: Vec::new(),
        }
    }

    /// The table, with its reference at `reference` (else the first point), wrapping over
    /// a revolution when `modulo`.
    pub fn table(
        self,
        reference: Option<f64>,
        modulo: bool,
        place: TableSlot,
        interpolation: Interpolation,
    ) -> Table {
        Table {
            kind: self.kind,
            reference: reference.unwrap_or(self.positions[0]),
            modulo_deg: modulo.then_some(crate::compensate::grid::REVOLUTION_DEG),
            place,
            interpolation,
            positions: self.positions,
            up: self.up,
            down: self.down,
        }
    }
}

/// Whether a rotary table of `positions` covers exactly one revolution, 0 to 360°: read as a
/// modulo table (its two ends are one position).
pub(crate) fn one_revolution(kind: AxisKind, positions: &[f64]) -> bool {
    let revolution = crate::compensate::grid::REVOLUTION_DEG;
    kind == AxisKind::Rotary
        && positions.len() > 2
        && positions[0].abs() < 1e-9
        && (positions[positions.len() - 1] - revolution).abs() < 1e-9
}

/// At least `least` points, else why the file holds no usable table.
pub fn enough(count: usize, least: usize, what: &str) -> Result<(), Unreadable> {
    if count < least {
        return Err(Unreadable::file(format!(
            "{count} point{} of {what}: a table needs at least {least}",
            if count == 1 { "" } else { "s" }
        )));
    }
    Ok(())
}

/// The length of the decimal number at the start of `t` (sign, digits, point, exponent),
/// 0 when there is none.
pub(crate) fn float_prefix(t: &str) -> usize {
    let b = t.as_bytes();
    let digits = |mut i: usize| {
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        i
    };
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let int_end = digits(i);
    let mut end = int_end;
    if b.get(end) == Some(&b'.') {
        end = digits(end + 1);
    }
    if end == i || (end == i + 1 && int_end == i) {
        return 0; // no digit
    }
    i = end;
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let j = i + 1 + usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
        let k = digits(j);
        if k > j {
            end = k;
        }
    }
    end
}
