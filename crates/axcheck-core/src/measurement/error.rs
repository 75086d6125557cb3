//! Errors from reading a measurement file: each names the file, the line and column
//! where there is one, what was found and what was expected.

use std::fmt;

/// Where in a measurement file something went wrong (1-based line and column); in a
/// workbook, the sheet with its row and column (shown as a cell, `C7`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    pub file: String,
    pub line: Option<usize>,
    pub column: Option<usize>,
    /// The sheet of a workbook: then `line` is its row and `column` its column.
    pub sheet: Option<String>,
}

impl Location {
    pub fn file(file: &str) -> Location {
        Location {
            file: file.to_string(),
            line: None,
            column: None,
            sheet: None,
        }
    }

    pub fn line(file: &str, line: usize) -> Location {
        Location {
            file: file.to_string(),
            line: Some(line),
            column: None,
            sheet: None,
        }
    }

    pub fn at(file: &str, line: usize, column: usize) -> Location {
        Location {
            file: file.to_string(),
            line: Some(line),
            column: Some(column),
            sheet: None,
        }
    }

    /// The same place in `sheet` of a workbook.
    pub(crate) fn in_sheet(self, sheet: &str) -> Location {
        Location {
            sheet: Some(sheet.to_string()),
            ..self
        }
    }
}

/// A spreadsheet column's letters: 1 → `A`, 27 → `AA`.
pub(crate) fn column_letters(column: usize) -> String {
    let mut letters = Vec::new();
    let mut c = column;
    while c > 0 {
        let rem = (c - 1) % 26;
        letters.push(b'A' + rem as u8);
        c = (c - 1) / 26;
    }
    letters.reverse();
    String::from_utf8(letters).unwrap_or_default()
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(sheet) = &self.sheet {
            write!(f, ", sheet \"{sheet}\"")?;
            return match (self.line, self.column) {
                (Some(row), Some(column)) => write!(f, ", cell {}{row}", column_letters(column)),
                (Some(row), None) => write!(f, ", row {row}"),
                _ => Ok(()),
            };
        }
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
            if let Some(column) = self.column {
                write!(f, ":{column}")?;
            }
        }
        Ok(())
    }
}

/// A measurement file that could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{location}: {kind}")]
pub struct ReadError {
    pub location: Location,
    /// Boxed: errors are rare and `Result<AxisData, ReadError>` stays small.
    pub kind: Box<ReadErrorKind>,
}

impl ReadError {
    pub fn new(location: Location, kind: ReadErrorKind) -> ReadError {
        ReadError {
            location,
            kind: Box::new(kind),
        }
    }
}

/// What was wrong, and what to change.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReadErrorKind {
    #[error("could not read the file: {0}")]
    Io(String),
    #[error(
        "the file is empty or holds only comments; expected a header line such as `target_mm,direction,run,deviation_um`"
    )]
    Empty,
    #[error("the file has a header but no readings; expected one row per reading after the header")]
    NoReadings,
    #[error("the line is not valid UTF-8 text; save the file as UTF-8")]
    InvalidUtf8,
    #[error(
        "the line is longer than {limit} bytes; a measurement file has short lines (is this the right file?)"
    )]
    LineTooLong { limit: usize },
    #[error("the file holds more than {limit} readings; split it into one file per test")]
    TooManyReadings { limit: usize },
    #[error(
        "unknown column `{name}`{}; expected target_mm|target_deg, deviation_um|deviation_mm|deviation_arcsec|deviation_deg or actual_mm|actual_deg, direction, run, and optionally time_s and temp_<name>_c",
        crate::suggest::phrase(suggestion.as_deref())
    )]
    UnknownColumn {
        name: String,
        suggestion: Option<String>,
    },
    #[error("column `{name}` has no unit; write {expected}")]
    MissingUnit { name: String, expected: String },
    #[error(
        "more than {limit} temperature columns (temp_<name>_c); keep the sensors of this test, at most {limit}"
    )]
    TooManyTemperatures { limit: usize },
    #[error("column `{name}` appears twice; keep one")]
    DuplicateColumn { name: String },
    #[error("missing column {expected}")]
    MissingColumn { expected: String },
    #[error("columns `{first}` and `{second}` both give the {what}; keep one")]
    ConflictingColumns {
        first: String,
        second: String,
        what: String,
    },
    #[error(
        "column `{deviation}` is {deviation_kind} but `{target}` is {target_kind}; use units of one kind (mm with µm for linear axes, deg with arcsec for rotary axes)"
    )]
    MixedUnits {
        target: String,
        target_kind: String,
        deviation: String,
        deviation_kind: String,
    },
    #[error("column `{column}`: {test} takes {expected}")]
    WrongQuantity {
        column: String,
        test: String,
        expected: String,
    },
    #[error(
        "{test} is read from the long CSV (target_mm, direction, run, deviation_arcsec, deviation_urad or deviation_deg), the wide CSV (target_mm, up_1_arcsec, down_1_arcsec, …) or either in an XLSX sheet; this file is {layout}"
    )]
    LayoutForTest { test: String, layout: String },
    #[error(
        "column `{deviation}` holds angles at targets in mm (`{target}`): this looks like an angular test of a linear axis (roll, pitch or yaw); evaluate it with `eval --test angular --direction A|B|C` (in a campaign, `test: angular` with `about:`), or give the deviations in um, nm or mm for a positioning or straightness test"
    )]
    AnglesAlongLinear { target: String, deviation: String },
    #[error(
        "{test} is not read from a Renishaw file: its header records no test type (`File type` says rtl or rta, a linear or a rotary axis, and nothing more), and the unit such a file would give a linear axis's angles in is not known; export the test from the laser software as CSV and read it as the long or wide CSV (target_mm with deviation_arcsec, or up_1_arcsec, down_1_arcsec, …)"
    )]
    RenishawTestNotRecorded { test: String },
    #[error("expected {expected} fields as in the header, found {found}")]
    FieldCount { expected: usize, found: usize },
    #[error("column `{column}`: expected a number, found `{found}`")]
    NotANumber { column: String, found: String },
    #[error("column `{column}`: expected a finite number, found `{found}`")]
    NonFinite { column: String, found: String },
    #[error(
        "column `direction`: unknown direction `{found}`{}; expected up/down (or +/-, ↑/↓, fwd/bwd, forward/reverse)",
        crate::suggest::phrase(suggestion.as_deref())
    )]
    UnknownDirection {
        found: String,
        suggestion: Option<String>,
    },
    #[error(
        "column `{column}`: {value} is not a plausible deviation (more than {limit} {unit}); check the column's unit"
    )]
    Implausible {
        column: String,
        value: String,
        limit: String,
        unit: String,
    },
    #[error(
        "target {value} {unit} is not a plausible position (more than {limit} {unit} from zero); check the target column and its unit"
    )]
    ImplausibleTarget {
        value: String,
        limit: String,
        unit: String,
    },
    #[error("column `run`: expected a run number 1, 2, 3 …, found `{found}`")]
    InvalidRun { found: String },
    #[error(
        "duplicate reading: target {target}, direction {direction}, run {run} was already given on line {first_line}"
    )]
    DuplicateReading {
        target: String,
        direction: String,
        run: u32,
        first_line: usize,
    },
    #[error(
        "target {target} has readings in direction {present} only; every target must be approached from both directions (ISO 230-2 clause 2.2, 4.3)"
    )]
    OneDirection { target: String, present: String },
    #[error(
        "ragged runs: target {target} direction {direction} has runs {has}, but the test has runs {expected}; every target needs the same runs in both directions"
    )]
    RaggedRuns {
        target: String,
        direction: String,
        has: String,
        expected: String,
    },
    #[error("{0}")]
    KeyValue(String),
    #[error("{0}")]
    EcmcApp(String),
    #[error(
        "{chosen} was asked for, but a {layout} file has one position source; a reference is chosen only in an ecmc ISO 230 app file"
    )]
    SourceOfOther { chosen: String, layout: String },
    // Renishaw .rtl/.rta
    #[error(
        "not a Renishaw .rtl/.rta file: {found}; such a file starts with `HEADER::`, then `TARGET DATA::`, `RUNS::`, `DEVIATIONS::` … `EOF::`"
    )]
    RenishawNotRenishaw { found: String },
    #[error(
        "the file holds more than {limit}; a Renishaw positioning test is far smaller (is this the right file?)"
    )]
    RenishawTooLarge { limit: String },
    #[error(
        "this is a Renishaw dynamic capture (.rtx: a `Data:` block of samples over time), not a positioning test; export the test as .rtl (linear) or .rta (rotary)"
    )]
    RenishawDynamic,
    #[error("no `{section}` section; {expected}")]
    RenishawMissingSection { section: String, expected: String },
    #[error(
        "section `{section}` appears twice (first on line {first_line}); a Renishaw file has each section once"
    )]
    RenishawDuplicateSection { section: String, first_line: usize },
    #[error(
        "the file ends inside `{section}` without `EOF::`: it looks cut short; copy the file again from the laser PC"
    )]
    RenishawNoEof { section: String },
    #[error("`{section}` has no `{key}` line; expected {expected}")]
    RenishawMissingKey {
        section: String,
        key: String,
        expected: String,
    },
    #[error("`{key}`: expected {expected}, found `{found}`")]
    RenishawBadValue {
        key: String,
        expected: String,
        found: String,
    },
    #[error("Target-count says {said} but {found} targets follow `Targets :`")]
    RenishawTargetCount { said: usize, found: usize },
    #[error("Run-count says {said} but {found}")]
    RenishawRunCount { said: usize, found: String },
    #[error("run {run} has no reading at target {target} ({position})")]
    RenishawMissingReading {
        run: u32,
        target: usize,
        position: String,
    },
    #[error("run {run} lists target {target} ({position}) twice (first on line {first_line})")]
    RenishawDuplicateReading {
        run: u32,
        target: usize,
        position: String,
        first_line: usize,
    },
    #[error("{0}")]
    Renishaw(String),
    #[error("column `{column}`: the cell is empty; expected a number")]
    EmptyCell { column: String },
    #[error("column `{column}`: expected a number, found {found}")]
    WrongCellType { column: String, found: String },
    #[error(
        "the file is {encoding} text; axcheck reads UTF-8: save it as UTF-8 (Excel: \"CSV UTF-8\"; Notepad: Encoding UTF-8) or convert it with `iconv -f UTF-16 -t UTF-8`"
    )]
    Utf16 { encoding: &'static str },
    #[error("no layout recognised; tried: {tried}")]
    Unrecognised { tried: String },
    #[error(
        "unknown column `{name}`{}; the wide layout has target_mm or target_deg first, then up_J_UNIT and down_J_UNIT for each run J (up_1_um, down_1_um, …; units um, nm, mm, arcsec, urad or deg)",
        crate::suggest::phrase(suggestion.as_deref())
    )]
    UnknownWideColumn {
        name: String,
        suggestion: Option<String>,
    },
    #[error("the first column is `{found}`; the wide layout starts with target_mm or target_deg")]
    TargetNotFirst { found: String },
    #[error(
        "no run columns after `{target}`; the wide layout has up_J_UNIT and down_J_UNIT for each run J (up_1_um, down_1_um, …)"
    )]
    NoRunColumns { target: String },
    #[error(
        "column `{column}` has no `{missing}`: every run is measured in both directions (ISO 230-2 clause 2.2, 4.3); add the column or remove this one"
    )]
    UnpairedRun { column: String, missing: String },
    #[error(
        "run {missing} has no columns but runs {found} have; number the runs 1 … n without gaps"
    )]
    MissingRun { missing: u32, found: String },
    #[error("target {target} already has a row ({first}); give each target one row")]
    DuplicateTarget { target: String, first: String },
    #[error("a sheet (\"{sheet}\") was named, but the file is a {layout}, not a workbook")]
    SheetOfText { sheet: String, layout: String },
    #[error(
        "the file is a ZIP archive but not an XLSX workbook ({reason}); save the sheet as .xlsx or CSV"
    )]
    NotABook { reason: String },
    #[error(
        "{what} workbooks are not read (their reader loads every cell of every sheet at once); save the sheet as .xlsx or CSV"
    )]
    UnsupportedBook { what: String },
    #[error(
        "no sheet named \"{name}\"{}; the book's sheets are {sheets}",
        crate::suggest::phrase(suggestion.as_deref())
    )]
    UnknownSheet {
        name: String,
        sheets: String,
        suggestion: Option<String>,
    },
    #[error("the book has no sheet")]
    NoSheets,
    #[error(
        "no header row in the first {rows} rows of the sheet that hold anything; expected one such as target_mm, direction, run, deviation_um (long) or target_mm, up_1_um, down_1_um, … (wide)"
    )]
    NoHeaderRow { rows: usize },
    #[error(
        "the sheet is empty; expected a header row such as target_mm, direction, run, deviation_um (long) or target_mm, up_1_um, down_1_um, … (wide), then the readings"
    )]
    EmptySheet,
    #[error(
        "the workbook is (or unpacks to) more than {limit_mib} MiB; the book of a positioning test is a few hundred kB (is this the right file?)"
    )]
    BookTooLarge { limit_mib: usize },
    #[error("the sheet has more than {limit} cells; keep one test per sheet")]
    TooManyCells { limit: usize },
    #[error(
        "the cell holds `{found}` but its column has no header; give the column a name or clear it"
    )]
    CellOutsideHeader { found: String },
    #[error(
        "the sheet's cells are not stored in row order; save the book again with a spreadsheet program"
    )]
    CellsOutOfOrder,
}

impl ReadErrorKind {
    /// The column, key or section the failure is about, as the file names it
    /// (`deviation_um`, `direction`, a Renishaw key); `None` when it is about the whole
    /// file. For a program that points at the field (the Python package's `ReadError`).
    pub fn field(&self) -> Option<String> {
        use ReadErrorKind::*;
        let named = |s: &str| Some(s.to_string());
        match self {
            NotANumber { column, .. }
            | NonFinite { column, .. }
            | Implausible { column, .. }
            | EmptyCell { column }
            | WrongCellType { column, .. }
            | UnpairedRun { column, .. }
            | WrongQuantity { column, .. } => named(column),
            AnglesAlongLinear { deviation, .. } => named(deviation),
            UnknownColumn { name, .. }
            | MissingUnit { name, .. }
            | DuplicateColumn { name }
            | UnknownWideColumn { name, .. } => named(name),
            MissingColumn { expected } => named(expected),
            UnknownDirection { .. } => named("direction"),
            InvalidRun { .. } => named("run"),
            ImplausibleTarget { .. } | DuplicateTarget { .. } => named("target"),
            TargetNotFirst { found } => named(found),
            RenishawMissingKey { key, .. } | RenishawBadValue { key, .. } => named(key),
            RenishawMissingSection { section, .. }
            | RenishawDuplicateSection { section, .. }
            | RenishawNoEof { section } => named(section),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A failure about one column names it; one about the whole file names none.
    #[test]
    fn the_field_of_a_failure() {
        let column = |c: &str| ReadErrorKind::NotANumber {
            column: c.into(),
            found: "abc".into(),
        };
        assert_eq!(
            column("deviation_um").field().as_deref(),
            Some("deviation_um")
        );
        let direction = ReadErrorKind::UnknownDirection {
            found: "sideways".into(),
            suggestion: None,
        };
        assert_eq!(direction.field().as_deref(), Some("direction"));
        assert_eq!(ReadErrorKind::Empty.field(), None);
    }

    #[test]
    fn location_display() {
        assert_eq!(Location::at("a.csv", 3, 7).to_string(), "a.csv:3:7");
        assert_eq!(Location::line("a.csv", 3).to_string(), "a.csv:3");
        assert_eq!(Location::file("a.csv").to_string(), "a.csv");
        let cell = Location::at("b.xlsx", 7, 3).in_sheet("X axis");
        assert_eq!(cell.to_string(), "b.xlsx, sheet \"X axis\", cell C7");
        let row = Location::line("b.xlsx", 2).in_sheet("S");
        assert_eq!(row.to_string(), "b.xlsx, sheet \"S\", row 2");
        assert_eq!(column_letters(26), "Z");
        assert_eq!(column_letters(28), "AB");
        assert_eq!(column_letters(16384), "XFD");
    }
}
