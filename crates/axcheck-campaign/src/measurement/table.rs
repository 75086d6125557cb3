//! The table the long and the wide layouts are read from, whether it comes from CSV text
//! or from a workbook's sheet: rows of fields, each the text as written (a CSV field, a
//! sheet's text cell) or a number (a sheet's numeric cell, taken as stored, never through
//! a locale's text), each with its place for errors (`file:line:column`, or the sheet and
//! cell).

use super::cell::{Field, Origin, Value};
use super::error::{Location, ReadError, ReadErrorKind};
use super::{AxisData, Lines};
use crate::units::AxisKind;
use std::borrow::Cow;
use std::io::BufRead;

/// One row: its 1-based line (CSV) or row (sheet) and its fields, one per header column.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Row<'a> {
    pub number: usize,
    pub fields: Vec<Field<'a>>,
}

/// What a table's units must be. A positioning or a straightness test has deviations of
/// its targets' kind (µm at mm, arcsec at degrees); an angular test of a linear axis
/// (roll, pitch, yaw) has angles at targets in mm, which a positioning test refuses as
/// mixed: the units, not the caller's word, keep one test from being read as the other.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) enum Quantities {
    #[default]
    OneKind,
    AnglesAlongLinear,
}

impl Quantities {
    /// The quantities of an angular test when `angular`, else of any other test.
    pub(crate) fn angular(angular: bool) -> Quantities {
        match angular {
            true => Quantities::AnglesAlongLinear,
            false => Quantities::OneKind,
        }
    }
}

/// The test an angular table is read for, as messages name it.
pub(crate) const ANGULAR_TEST: &str = "an angular test of a linear axis";

/// A column of the wrong quantity for an angular test: `expected` says what it takes.
pub(crate) fn not_for_angular(column: &str, expected: &str) -> ReadErrorKind {
    ReadErrorKind::WrongQuantity {
        column: column.to_string(),
        test: ANGULAR_TEST.into(),
        expected: expected.into(),
    }
}

pub(crate) trait TableReader: Sized {
    /// The layout's columns from the header row, their units checked as `quantities`
    /// asks, or why the header is wrong.
    fn from_header(header: &Row, place: &Origin, quantities: Quantities)
    -> Result<Self, ReadError>;
    /// One data row.
    fn add(&mut self, row: &Row, place: &Origin) -> Result<(), ReadError>;
    /// The validated test and what was assumed in reading it.
    fn finish(self, place: &Origin) -> Result<(AxisData, Vec<String>), ReadError>;
}

/// Which table a header row announces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum TableKind {
    /// One row per reading ([`super::csv`]).
    Long,
    /// One row per target, a column per run and direction ([`super::wide`]).
    Wide,
}

impl TableKind {
    pub fn name(self) -> &'static str {
        match self {
            TableKind::Long => "long table",
            TableKind::Wide => "wide table",
        }
    }
}

/// Reads a CSV table of layout `T` with the units `quantities` asks: the header is the
/// first line that is neither blank nor a `#` comment; its separator (`,`, `;` or tab)
/// holds for every line, and with `;` or tab a decimal comma is read. Returns the test and
/// what was assumed or skipped.
pub(crate) fn read_text<T: TableReader, R: BufRead>(
    reader: R,
    file: &str,
    quantities: Quantities,
) -> Result<(AxisData, Vec<String>), ReadError> {
    let mut lines = Lines::new(reader, file);
    let mut comments = 0usize;
    let (header_line, header) = loop {
        match lines.next_line()? {
            None => return Err(ReadError::new(Location::file(file), ReadErrorKind::Empty)),
            Some((_, text)) if text.trim().is_empty() => {}
            Some((_, text)) if text.trim_start().starts_with('#') => comments += 1,
            Some((number, text)) => break (number, text.to_string()),
        }
    };
    let sep = super::fields::detect_separator(&header);
    let place = Origin::text(file, sep != ',');
    let header_row = text_row(&header, sep, header_line, Vec::new());
    let mut table = T::from_header(&header_row, &place, quantities)?;
    let width = header_row.fields.len();
    let mut rows = 0usize;
    // One buffer of fields for every line: a field borrows its line, so the buffer is
    // emptied (keeping its room) before the next line is read.
    let mut spare = recycle(header_row.fields);
    while let Some((number, text)) = lines.next_line()? {
        // Blank or a comment: what the line starts with after its white space decides
        // (trimming its end too was 1.5 % of the gate's time).
        let lead = text.trim_start();
        if lead.is_empty() {
            continue;
        }
        if lead.starts_with('#') {
            comments += 1;
            continue;
        }
        let row = text_row(text, sep, number, spare);
        if row.fields.len() != width {
            let found = row.fields.len();
            let kind = ReadErrorKind::FieldCount {
                expected: width,
                found,
            };
            return Err(place.error(number, 1, kind));
        }
        table.add(&row, &place)?;
        spare = recycle(row.fields);
        rows += 1;
    }
    if rows == 0 {
        return Err(ReadError::new(
            place.line(header_line),
            ReadErrorKind::NoReadings,
        ));
    }
    let (data, table_notes) = table.finish(&place)?;
    let mut notes = Vec::new();
    match sep {
        ';' => notes.push("separator `;`, decimal comma or point".to_string()),
        '\t' => notes.push("separator tab, decimal comma or point".to_string()),
        _ => {}
    }
    if comments > 0 {
        let s = if comments == 1 { "" } else { "s" };
        notes.push(format!("{comments} comment line{s} (#) skipped"));
    }
    notes.extend(table_notes);
    Ok((data, notes))
}

/// A CSV line as a row of text fields, in `fields` (empty, its room reused).
fn text_row<'a>(text: &'a str, sep: char, number: usize, mut fields: Vec<Field<'a>>) -> Row<'a> {
    let plain = super::fields::plain_fields(text, sep, |column, text| {
        push_text(&mut fields, column, text)
    });
    if !plain {
        super::fields::fields_of(text, sep, |column, value| {
            fields.push(Field {
                column,
                value: Value::Text(value),
            });
        });
    }
    Row { number, fields }
}

/// Appends the field `text` at `column`, built where it goes in the vector: `push` built
/// each field on the stack and copied it from there (the copy stalled on the stores just
/// made: 7 % of the gate's time on 10 000 axes).
#[inline(always)]
fn push_text<'a>(fields: &mut Vec<Field<'a>>, column: usize, text: &'a str) {
    if fields.len() == fields.capacity() {
        fields.reserve(8);
    }
    let len = fields.len();
    fields.spare_capacity_mut()[0].write(Field {
        column,
        value: Value::Text(Cow::Borrowed(text)),
    });
    // SAFETY: the slot at `len` lies within the capacity and was just initialised.
    unsafe { fields.set_len(len + 1) };
}

/// An emptied buffer of fields, ready to borrow another line: the same allocation (the
/// collect of an empty vector of a same-sized type reuses it in place).
fn recycle<'b>(mut fields: Vec<Field<'_>>) -> Vec<Field<'b>> {
    fields.clear();
    fields
        .into_iter()
        .map(|_| unreachable!("emptied"))
        .collect()
}

/// A target column of one kind with a value column of the other, read for a test that
/// is not angular. Angles at targets in mm are an angular test's layout: said so, with
/// the option that reads them, rather than called mixed.
pub(crate) fn mixed_units(
    target: &str,
    kind: AxisKind,
    value: &str,
    value_kind: AxisKind,
) -> ReadErrorKind {
    if (kind, value_kind) == (AxisKind::Linear, AxisKind::Rotary) {
        return ReadErrorKind::AnglesAlongLinear {
            target: target.to_string(),
            deviation: value.to_string(),
        };
    }
    let describe = |k: AxisKind| match k {
        AxisKind::Linear => "a length".to_string(),
        AxisKind::Rotary => "an angle".to_string(),
    };
    ReadErrorKind::MixedUnits {
        target: target.to_string(),
        target_kind: describe(kind),
        deviation: value.to_string(),
        deviation_kind: describe(value_kind),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_from_text_and_cells() {
        let place = Origin::sheet("b.xlsx", "S");
        let field = |value| Field { column: 3, value };
        assert_eq!(place.number(7, &field(Value::Number(1.5)), "x"), Ok(1.5));
        assert_eq!(
            place.number(7, &field(Value::Text(" 2.5 ".into())), "x"),
            Ok(2.5)
        );
        let e = place
            .number(7, &field(Value::Text("1,5".into())), "up_1_um")
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "b.xlsx, sheet \"S\", cell C7: column `up_1_um`: expected a number, found `1,5`"
        );
        let e = place.number(7, &field(Value::Empty), "x").unwrap_err();
        assert!(e.to_string().contains("the cell is empty"), "{e}");
        let e = place
            .number(7, &field(Value::Other("the error #DIV/0!".into())), "x")
            .unwrap_err();
        assert!(e.to_string().ends_with("found the error #DIV/0!"), "{e}");
    }
}
