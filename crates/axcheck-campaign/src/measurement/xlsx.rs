//! Workbooks: the long or the wide table in one sheet of an XLSX book, read with calamine
//! from memory.
//!
//! The sheet is the one named (`--sheet`, `data: {file, sheet}`), else the first. Its
//! header row is the first row holding anything (`#` comment rows aside) whose cells name
//! the long layout's columns ([`super::csv`]) or the wide layout's ([`super::wide`]);
//! rows above it (a title, a date) are skipped, at most [`HEADER_SEARCH_ROWS`], and the
//! notes say so. The table spans the header's first to last named column: a value
//! outside it is an error, not silently dropped. Numeric cells are taken as the numbers
//! stored, never through a locale's text; a text cell holding a number is read with a
//! decimal point (`1,234` could be a thousands separator). Errors name the sheet and cell:
//! `book.xlsx, sheet "X axis", cell C7: …`.
//!
//! Cells are streamed row by row rather than loaded as the sheet's dense used range (one
//! stray cell at XFD1048576 would ask for 1.7·10^10 cells), and their count is bounded.
//! For the same reason `.xls` (Excel 97–2003) and `.ods` books are refused with a clear
//! message: calamine reads those only whole, into dense ranges.
//!
//! The other laser tests of a linear axis (ISO 230-1) read from either table as from its
//! CSV: a straightness test is a linear table (µm across the axis at `target_mm`); an
//! angular test's sheet has angles at `target_mm` (`deviation_arcsec`, `_urad`, `_deg` in
//! the long table, `up_1_arcsec`, … in the wide one), read only when the caller asks for
//! one ([`read_for`] with [`Quantities::AnglesAlongLinear`]), with the same refusals as
//! the CSV readers, at the header's cell.

use super::cell::{Field, Origin, Value};
use super::csv::LongTable;
use super::error::{ReadError, ReadErrorKind};
use super::layout::table_kind;
use super::layout::{Layout, OLE_MAGIC, ReadTest, Recognised};
use super::table::{Quantities, Row, TableKind, TableReader};
use super::wide::WideTable;
use super::{AxisData, Location, MAX_READINGS};
use calamine::{DataRef, Reader as _, Xlsx};
use std::io::Cursor;

/// Most bytes a workbook may unpack to (its parts' sizes as its ZIP directory declares
/// them, which the unpacking holds to): a test's book unpacks to a few MB, and calamine
/// keeps some parts (the shared strings) whole in memory.
pub(crate) const MAX_BOOK_UNPACKED: u64 = 128 << 20;
/// Rows holding anything that may stand above the header (titles, dates, notes).
pub(crate) const HEADER_SEARCH_ROWS: usize = 20;
/// Most cells a sheet may hold: a long table of [`MAX_READINGS`] readings with a time and
/// a few temperatures, and then some.
pub(crate) const MAX_SHEET_CELLS: usize = 10 * MAX_READINGS;
/// The last column and row a sheet can have (XFD1048576).
const MAX_COLUMN: u32 = 16_384;
const MAX_ROW: u32 = 1_048_576;
/// Sheets named in a message at most.
const MAX_SHEETS_SHOWN: usize = 20;

/// Parses the sheet `sheet` (or the first) of the workbook in `bytes`.
pub fn parse(bytes: &[u8], file: &str, sheet: Option<&str>) -> Result<AxisData, ReadError> {
    read(bytes, file, sheet).map(|t| t.data)
}

/// Reads the sheet `sheet` (or the first) of the workbook in `bytes`, saying which sheet
/// and table it found and what it skipped.
pub(crate) fn read(bytes: &[u8], file: &str, sheet: Option<&str>) -> Result<ReadTest, ReadError> {
    read_for(bytes, file, sheet, Quantities::OneKind)
}

/// [`read`] with the units `quantities` asks (an angular test's angles at targets in mm,
/// or one kind).
pub(crate) fn read_for(
    bytes: &[u8],
    file: &str,
    sheet: Option<&str>,
    quantities: Quantities,
) -> Result<ReadTest, ReadError> {
    let whole = |kind| ReadError::new(Location::file(file), kind);
    if let Some(what) = unsupported(bytes) {
        let what = what.to_string();
        return Err(whole(ReadErrorKind::UnsupportedBook { what }));
    }
    check_unpacked_size(bytes).map_err(whole)?;
    let mut book = calamine(|| Xlsx::new(Cursor::new(bytes))).map_err(whole)?;
    let names = calamine(|| Ok::<_, String>(book.sheet_names())).map_err(whole)?;
    let (name, mut notes) = choose_sheet(&names, sheet).map_err(whole)?;
    let place = Origin::sheet(file, &name);
    let mut cells = calamine(|| book.worksheet_cells_reader(&name))
        .map_err(|kind| ReadError::new(place.whole(), kind))?;
    let mut sheet_reader = SheetReader::new(place.clone(), quantities);
    let mut row: Option<(u32, Vec<(u32, Value)>)> = None;
    let mut count = 0usize;
    while let Some(cell) =
        calamine(|| cells.next_cell()).map_err(|kind| ReadError::new(place.whole(), kind))?
    {
        let (r, c) = cell.get_position();
        let value = value_of(cell.get_value());
        if value.is_blank() {
            continue;
        }
        let at = |kind| place.error(r as usize + 1, c as usize + 1, kind);
        if r >= MAX_ROW || c >= MAX_COLUMN {
            let reason = "a cell lies beyond the sheet's last cell XFD1048576".to_string();
            return Err(at(ReadErrorKind::NotABook { reason }));
        }
        count += 1;
        if count > MAX_SHEET_CELLS {
            let limit = MAX_SHEET_CELLS;
            return Err(at(ReadErrorKind::TooManyCells { limit }));
        }
        match &mut row {
            Some((current, cells)) if *current == r => cells.push((c, value)),
            Some((current, _)) if *current > r => return Err(at(ReadErrorKind::CellsOutOfOrder)),
            _ => {
                if let Some((number, cells)) = row.take() {
                    sheet_reader.take_row(number as usize + 1, cells)?;
                }
                row = Some((r, vec![(c, value)]));
            }
        }
    }
    if let Some((number, cells)) = row.take() {
        sheet_reader.take_row(number as usize + 1, cells)?;
    }
    let (data, table, sheet_notes) = sheet_reader.finish()?;
    notes.extend(sheet_notes);
    Ok(ReadTest {
        data,
        recognised: Recognised {
            layout: Layout::Xlsx { sheet: name, table },
            notes,
            info: None,
            reported: None,
        },
    })
}

/// The kinds of workbook refused, recognised by their first bytes.
fn unsupported(bytes: &[u8]) -> Option<&'static str> {
    if bytes.starts_with(OLE_MAGIC) {
        return Some("Excel 97–2003 (.xls)");
    }
    // An OpenDocument file stores its `mimetype` first, uncompressed.
    let head = &bytes[..bytes.len().min(128)];
    let ods = b"application/vnd.oasis.opendocument.spreadsheet";
    head.windows(ods.len())
        .any(|w| w == ods)
        .then_some("OpenDocument (.ods)")
}

/// Refuses a book whose parts unpack to more than [`MAX_BOOK_UNPACKED`] (a ZIP bomb).
fn check_unpacked_size(bytes: &[u8]) -> Result<(), ReadErrorKind> {
    let mut archive = zip::ZipArchive::new(Cursor::new(bytes)).map_err(|e| not_a_book(&e))?;
    let mut total = 0u64;
    for k in 0..archive.len() {
        let part = archive.by_index_raw(k).map_err(|e| not_a_book(&e))?;
        total = total.saturating_add(part.size());
    }
    if total > MAX_BOOK_UNPACKED {
        return Err(ReadErrorKind::BookTooLarge {
            limit_mib: (MAX_BOOK_UNPACKED >> 20) as usize,
        });
    }
    Ok(())
}

/// A call into calamine: its error, or its panic on a damaged book (an overflowing cell
/// reference panics under overflow checks, found by fuzzing), as a book refused. Only
/// calamine is contained, so that a panic of this reader's own code stays a bug.
fn calamine<T, E: std::fmt::Display>(
    call: impl FnOnce() -> Result<T, E>,
) -> Result<T, ReadErrorKind> {
    match crate::panics::contained(call) {
        Ok(result) => result.map_err(|e| not_a_book(&e)),
        Err(panic) => Err(not_a_book(&format!("the workbook is damaged: {panic}"))),
    }
}

/// calamine's reason, kept short: a hostile file can make it long.
fn not_a_book(e: &dyn std::fmt::Display) -> ReadErrorKind {
    let mut reason: String = e.to_string().chars().take(160).collect();
    if reason.is_empty() {
        reason = "unreadable".into();
    }
    ReadErrorKind::NotABook { reason }
}

/// The sheet to read and a note on the choice: the one named (exactly), or the first.
fn choose_sheet(
    names: &[String],
    wanted: Option<&str>,
) -> Result<(String, Vec<String>), ReadErrorKind> {
    let listed = || {
        let mut shown: Vec<String> = names
            .iter()
            .take(MAX_SHEETS_SHOWN)
            .map(|n| format!("\"{n}\""))
            .collect();
        if names.len() > MAX_SHEETS_SHOWN {
            shown.push(format!("… ({} sheets)", names.len()));
        }
        shown.join(", ")
    };
    let Some(first) = names.first() else {
        return Err(ReadErrorKind::NoSheets);
    };
    match wanted {
        Some(name) if names.iter().any(|n| n == name) => Ok((name.to_string(), Vec::new())),
        Some(name) => {
            let lower: Vec<String> = names.iter().map(|n| n.to_lowercase()).collect();
            let candidates: Vec<&str> = lower.iter().map(String::as_str).collect();
            let suggestion = lower
                .iter()
                .position(|n| *n == name.trim().to_lowercase())
                .or_else(|| {
                    let hit = crate::suggest::did_you_mean(&name.to_lowercase(), &candidates)?;
                    candidates.iter().position(|c| *c == hit)
                })
                .map(|k| names[k].clone());
            Err(ReadErrorKind::UnknownSheet {
                name: name.to_string(),
                sheets: listed(),
                suggestion,
            })
        }
        None if names.len() == 1 => Ok((first.clone(), Vec::new())),
        None => Ok((
            first.clone(),
            vec![format!(
                "no sheet named: the first of {} read (the book has {}); name another with --sheet or data: {{file, sheet}}",
                names.len(),
                listed()
            )],
        )),
    }
}

/// A cell as the table readers see it.
fn value_of(cell: &DataRef) -> Value<'static> {
    match cell {
        DataRef::Int(i) => Value::Number(*i as f64),
        DataRef::Float(x) => Value::Number(*x),
        DataRef::String(s) => Value::Text(s.clone().into()),
        DataRef::SharedString(s) => Value::Text((*s).to_string().into()),
        DataRef::Bool(b) => Value::Other(format!(
            "the truth value {}",
            if *b { "TRUE" } else { "FALSE" }
        )),
        DataRef::DateTime(_) => Value::Other("a date or time".into()),
        DataRef::DateTimeIso(s) | DataRef::DurationIso(s) => Value::Other(format!(
            "the date or time {}",
            s.chars().take(40).collect::<String>()
        )),
        DataRef::Error(e) => Value::Other(format!("the error {e}")),
        DataRef::Empty => Value::Empty,
    }
}

/// The table found in a sheet.
enum Table {
    Long(LongTable),
    Wide(WideTable),
}

/// The table of a sheet, once its header is found.
struct Found {
    table: Table,
    kind: TableKind,
    /// The header's first and last column (1-based) and its row.
    first: usize,
    last: usize,
    header_row: usize,
}

/// A sheet being read row by row: looking for the header, then feeding the table.
struct SheetReader {
    place: Origin,
    /// The units the table's header must have.
    quantities: Quantities,
    table: Option<Found>,
    /// Rows above the header that held something.
    skipped: Vec<usize>,
    comments: usize,
    rows: usize,
}

impl SheetReader {
    fn new(place: Origin, quantities: Quantities) -> SheetReader {
        SheetReader {
            place,
            quantities,
            table: None,
            skipped: Vec::new(),
            comments: 0,
            rows: 0,
        }
    }

    /// One row's cells (0-based columns, none blank, in the order stored).
    fn take_row(&mut self, number: usize, mut cells: Vec<(u32, Value)>) -> Result<(), ReadError> {
        cells.sort_by_key(|(c, _)| *c);
        let is_comment = matches!(&cells[0].1, Value::Text(t) if t.trim_start().starts_with('#'));
        if is_comment {
            self.comments += 1;
            return Ok(());
        }
        let place = &self.place;
        let Some(Found {
            table, first, last, ..
        }) = &mut self.table
        else {
            return self.header(number, &cells);
        };
        let mut fields: Vec<Field> = (*first..=*last)
            .map(|column| Field {
                column,
                value: Value::Empty,
            })
            .collect();
        for (c, value) in cells {
            let column = c as usize + 1;
            if column < *first || column > *last {
                let found = value.shown().chars().take(40).collect();
                return Err(place.error(
                    number,
                    column,
                    ReadErrorKind::CellOutsideHeader { found },
                ));
            }
            fields[column - *first].value = value;
        }
        let row = Row { number, fields };
        match table {
            Table::Long(t) => t.add(&row, place)?,
            Table::Wide(t) => t.add(&row, place)?,
        }
        self.rows += 1;
        Ok(())
    }

    /// A row before the header: the header if it names a layout's columns, else skipped
    /// (a row of one cell is a title, whatever it says: `Run 3` is not a header).
    fn header(&mut self, number: usize, cells: &[(u32, Value)]) -> Result<(), ReadError> {
        let names: Vec<String> = cells.iter().map(|(_, v)| v.name()).collect();
        let kind = (names.len() > 1).then(|| table_kind(&names)).flatten();
        let Some(kind) = kind else {
            self.skipped.push(number);
            if self.skipped.len() >= HEADER_SEARCH_ROWS {
                let rows = HEADER_SEARCH_ROWS;
                return Err(ReadError::new(
                    self.place.whole(),
                    ReadErrorKind::NoHeaderRow { rows },
                ));
            }
            return Ok(());
        };
        let first = cells[0].0 as usize + 1;
        let last = cells[cells.len() - 1].0 as usize + 1;
        let mut fields: Vec<Field> = (first..=last)
            .map(|column| Field {
                column,
                value: Value::Empty,
            })
            .collect();
        for (c, value) in cells {
            fields[*c as usize + 1 - first].value = value.clone();
        }
        let header = Row { number, fields };
        let (place, quantities) = (&self.place, self.quantities);
        let table = match kind {
            TableKind::Long => Table::Long(LongTable::from_header(&header, place, quantities)?),
            TableKind::Wide => Table::Wide(WideTable::from_header(&header, place, quantities)?),
        };
        self.table = Some(Found {
            table,
            kind,
            first,
            last,
            header_row: number,
        });
        Ok(())
    }

    /// The test, its table's kind and the notes.
    fn finish(self) -> Result<(AxisData, TableKind, Vec<String>), ReadError> {
        let Some(Found {
            table,
            kind,
            header_row,
            ..
        }) = self.table
        else {
            let kind = if self.skipped.is_empty() {
                ReadErrorKind::EmptySheet
            } else {
                ReadErrorKind::NoHeaderRow {
                    rows: self.skipped.len(),
                }
            };
            return Err(ReadError::new(self.place.whole(), kind));
        };
        if self.rows == 0 {
            return Err(ReadError::new(
                self.place.line(header_row),
                ReadErrorKind::NoReadings,
            ));
        }
        let mut notes = Vec::new();
        if !self.skipped.is_empty() {
            let rows: Vec<String> = self.skipped.iter().map(usize::to_string).collect();
            let s = if rows.len() == 1 { "" } else { "s" };
            notes.push(format!(
                "row{s} {} above the header (row {header_row}) skipped",
                rows.join(", ")
            ));
        }
        if self.comments > 0 {
            let s = if self.comments == 1 { "" } else { "s" };
            notes.push(format!("{} comment row{s} (#) skipped", self.comments));
        }
        let (data, table_notes) = match table {
            Table::Long(t) => t.finish(&self.place)?,
            Table::Wide(t) => t.finish(&self.place)?,
        };
        notes.extend(table_notes);
        Ok((data, kind, notes))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::Direction;

    #[test]
    fn sheet_choice() {
        let names: Vec<String> = ["Sheet1", "X axis"].iter().map(|s| s.to_string()).collect();
        assert_eq!(choose_sheet(&names, Some("X axis")).unwrap().0, "X axis");
        let (first, notes) = choose_sheet(&names, None).unwrap();
        assert_eq!(first, "Sheet1");
        assert!(notes[0].contains("the first of 2 read"), "{notes:?}");
        let e = choose_sheet(&names, Some("x axis")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "no sheet named \"x axis\" (did you mean `X axis`?); the book's sheets are \"Sheet1\", \"X axis\""
        );
        assert_eq!(
            choose_sheet(&[], None).unwrap_err(),
            ReadErrorKind::NoSheets
        );
    }

    #[test]
    fn refuses_what_it_does_not_read() {
        let mut ods = b"PK\x03\x04".to_vec();
        ods.extend_from_slice(&[0; 26]);
        ods.extend_from_slice(b"mimetypeapplication/vnd.oasis.opendocument.spreadsheet");
        let e = parse(&ods, "b.ods", None).unwrap_err().to_string();
        assert!(
            e.starts_with("b.ods: OpenDocument (.ods) workbooks are not read"),
            "{e}"
        );
        let e = parse(OLE_MAGIC, "b.xls", None).unwrap_err().to_string();
        assert!(e.contains("Excel 97–2003 (.xls)"), "{e}");
        let e = parse(b"PK\x03\x04junk", "b.xlsx", None)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("b.xlsx: the file is a ZIP archive but not an XLSX workbook ("),
            "{e}"
        );
    }

    /// A sheet fed row by row as calamine streams it: `rows[r]` is row r + 1, text cells
    /// for text and numbers for numbers, from column A.
    fn sheet(
        rows: &[&[&str]],
        quantities: Quantities,
    ) -> Result<(AxisData, TableKind, Vec<String>), ReadError> {
        let mut reader = SheetReader::new(Origin::sheet("b.xlsx", "EBX"), quantities);
        for (r, row) in rows.iter().enumerate() {
            let cells = (row.iter().enumerate())
                .map(|(c, text)| {
                    let value = match text.parse::<f64>() {
                        Ok(x) => Value::Number(x),
                        Err(_) => Value::Text(text.to_string().into()),
                    };
                    (c as u32, value)
                })
                .collect();
            reader.take_row(r + 1, cells)?;
        }
        reader.finish()
    }

    const ANGULAR: Quantities = Quantities::AnglesAlongLinear;

    /// An angular test in either table of a sheet: the same angles, whichever table.
    #[test]
    fn an_angular_test_reads_from_the_long_and_the_wide_table() {
        let wide: &[&[&str]] = &[
            &["Pitch of X"],
            &["target_mm", "up_1_arcsec", "down_1_arcsec"],
            &["0", "-0.131", "-0.014"],
            &["500", "9.829", "9.954"],
        ];
        let long: &[&[&str]] = &[
            &["target_mm", "direction", "run", "deviation_urad"],
            &["0", "up", "1", "-0.635"],
            &["500", "up", "1", "47.652"],
            &["500", "down", "1", "48.258"],
            &["0", "down", "1", "-0.068"],
        ];
        let (w, kind, notes) = sheet(wide, ANGULAR).unwrap();
        assert_eq!(kind, TableKind::Wide);
        assert_eq!(w.targets, vec![0.0, 500.0]);
        assert_eq!(w.deviations(1, Direction::Down), &[9.954]);
        assert_eq!(notes[0], "row 1 above the header (row 2) skipped");
        let (l, kind, _) = sheet(long, ANGULAR).unwrap();
        assert_eq!(kind, TableKind::Long);
        // 47.652 µrad = 47.652 · 0.648/π″ = 9.829″ to 0.001″.
        for i in 0..2 {
            for d in Direction::BOTH {
                let (a, b) = (l.deviations(i, d)[0], w.deviations(i, d)[0]);
                assert!((a - b).abs() < 5e-4, "{i} {d:?}: {a} {b}");
            }
        }
    }

    /// The CSV readers' refusals, at the header's cell.
    #[test]
    fn a_sheets_units_are_the_tests() {
        let err = |rows: &[&[&str]], q| sheet(rows, q).unwrap_err().to_string();
        let angles: &[&[&str]] = &[
            &["target_mm", "up_1_arcsec", "down_1_arcsec"],
            &["0", "1", "2"],
        ];
        let e = err(angles, Quantities::OneKind);
        assert!(
            e.starts_with("b.xlsx, sheet \"EBX\", cell B1: column `up_1_arcsec` holds angles at targets in mm (`target_mm`): this looks like an angular test"),
            "{e}"
        );
        let lengths: &[&[&str]] = &[
            &["target_mm", "direction", "run", "deviation_um"],
            &["0", "up", "1", "2"],
        ];
        assert_eq!(
            err(lengths, ANGULAR),
            "b.xlsx, sheet \"EBX\", cell D1: column `deviation_um`: an angular test of a linear axis takes angular deviations (`deviation_arcsec`, `deviation_urad` or `deviation_deg`)"
        );
        let degrees: &[&[&str]] = &[
            &["target_deg", "up_1_arcsec", "down_1_arcsec"],
            &["0", "1", "2"],
        ];
        assert!(err(degrees, ANGULAR).contains("cell A1: column `target_deg`: an angular test"));
        // A straightness test's sheet is a linear table, read as such.
        let (d, _, _) = sheet(
            &[&["target_mm", "up_1_um", "down_1_um"], &["0", "1.5", "2"]],
            Quantities::OneKind,
        )
        .unwrap();
        assert_eq!(d.deviations(0, Direction::Up), &[1.5]);
    }
}
