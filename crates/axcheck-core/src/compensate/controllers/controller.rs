//! What every controller shares: the trait, what a table may be refused for, what it was
//! read as, the format a controller's table can take, and the helpers of its writers.
//! The controllers' files import this, and [`super`] only lists them.

use crate::compensate::table::{Interpolation, Table};
use crate::units::AxisKind;
use std::fmt;

/// Why a controller cannot hold a table.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Refused {
    /// The points: too many, or an interval the table cannot take.
    #[error("{0}")]
    Grid(String),
    /// A position or a value outside what the file can hold.
    #[error("{0}")]
    Range(String),
    /// The active compensation as stated does not fit the controller.
    #[error("{0}")]
    Active(String),
}

/// A table file that the controller would not load as a table, or not as the one meant:
/// where (line, field) and why.
#[derive(Debug, Clone, thiserror::Error, PartialEq)]
pub struct Unreadable {
    /// 1-based line of the file, where one is to blame.
    pub line: Option<usize>,
    /// The field (column, key or parameter) as the file names it.
    pub field: Option<String>,
    pub message: String,
}

impl Unreadable {
    /// An error of the whole file.
    pub fn file(message: impl Into<String>) -> Unreadable {
        Unreadable {
            line: None,
            field: None,
            message: message.into(),
        }
    }

    /// An error at `line` (1-based).
    pub fn at(line: usize, message: impl Into<String>) -> Unreadable {
        Unreadable {
            line: Some(line),
            ..Unreadable::file(message)
        }
    }

    /// An error of `field` at `line`.
    pub fn field(line: usize, field: impl Into<String>, message: impl Into<String>) -> Unreadable {
        Unreadable {
            line: Some(line),
            field: Some(field.into()),
            message: message.into(),
        }
    }
}

impl fmt::Display for Unreadable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.line, &self.field) {
            (Some(line), Some(field)) => write!(f, "line {line}, field `{field}`: "),
            (Some(line), None) => write!(f, "line {line}: "),
            (None, Some(field)) => write!(f, "field `{field}`: "),
            (None, None) => Ok(()),
        }?;
        f.write_str(&self.message)
    }
}

/// What the axis knows when its table file is read: the file holds no axis kind (mm or
/// degrees) and may hold several axes.
#[derive(Debug, Clone, Copy)]
pub struct ReadAs<'a> {
    pub kind: AxisKind,
    /// The axis's name on the controller, to pick its table from a file of several.
    pub axis: Option<&'a str>,
}

/// What becomes of a controller's backlash (reversal) parameter with its table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backlash {
    /// One table per axis and a backlash parameter whose new value the file states
    /// (Siemens MD32450): the active value plus the measured reversal.
    Stated,
    /// A table per direction corrects what remained, and the parameter stays as it was
    /// during the measurement (FANUC 1851/1852).
    Kept,
    /// A table per direction holds the reversal, and the parameter is set to 0
    /// (HEIDENHAIN MP_backLash, TwinCAT `lose`, any controller fed the generic CSV): an
    /// active backlash moves into the tables.
    Cleared,
    /// As `Cleared`, but the parameter does nothing while a table is loaded (LinuxCNC
    /// `BACKLASH`): it acted on the readings only when no table was active.
    UnusedWithTable,
    /// No backlash parameter beside the table (ecmc's encoder table): the reversal stays.
    Absent,
}

/// How the points of a table are spaced.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spacing {
    /// Any strictly increasing list: the measured targets by default.
    Free,
    /// A start and an interval: the corrections are resampled by interpolation.
    Equidistant,
}

/// The tables a controller holds per axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Directions {
    /// One per approach direction (↑ and ↓): the reversal is in the tables.
    Bidirectional,
    /// One for both directions (the mean correction); `backlash`: the controller adds
    /// the mean reversal on ↓ approaches from a parameter, whose value the file states.
    Unidirectional { backlash: bool },
}

/// What a controller's table can hold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Format {
    pub spacing: Spacing,
    /// Most points per table.
    pub max_points: usize,
    pub directions: Directions,
    /// Whether a table can wrap around one revolution of a rotary axis.
    pub modulo: bool,
    /// Smallest step of a correction on a linear axis, µm.
    pub(crate) quantum_um: f64,
    /// Smallest step of a correction on a rotary axis, arcsec.
    pub(crate) quantum_arcsec: f64,
}

impl Format {
    /// Smallest step of a correction in the deviation unit of `kind`.
    pub fn quantum(&self, kind: AxisKind) -> f64 {
        match kind {
            AxisKind::Linear => self.quantum_um,
            AxisKind::Rotary => self.quantum_arcsec,
        }
    }
}

/// A controller's compensation file.
pub trait Controller: Sync {
    /// The name users give (`--controller NAME`, `controller:` in campaigns).
    fn name(&self) -> &'static str;
    /// The file extension of its table.
    fn extension(&self) -> &'static str;
    /// What its table can hold.
    fn format(&self) -> Format;
    /// How it applies the table between points: linearly unless it says otherwise.
    fn interpolation(&self) -> Interpolation {
        Interpolation::Linear
    }
    /// The table as the controller holds it: by default its corrections rounded to the
    /// format's unit. The prediction applies this table.
    fn hold(&self, table: Table) -> Result<Table, Refused> {
        let quantum = self.format().quantum(table.kind);
        Ok(table.quantised(quantum))
    }
    /// What becomes of the backlash parameter: stated by the file (one table and a
    /// parameter), absent (one table, none), or cleared into the tables (a table per
    /// direction) unless the controller says otherwise.
    fn backlash(&self) -> Backlash {
        match self.format().directions {
            Directions::Unidirectional { backlash: true } => Backlash::Stated,
            Directions::Unidirectional { backlash: false } => Backlash::Absent,
            Directions::Bidirectional => Backlash::Cleared,
        }
    }
    /// The held table as the controller loads it; `notes` go where the format takes
    /// comments (each a line of text without the comment mark), or nowhere where it takes
    /// none.
    fn write(&self, table: &Table, notes: &[String]) -> Result<String, Refused>;
    /// What the controller must be told to load a file of an axis of `kind` as written
    /// (LinuxCNC: its type and INI lines), `<file>` standing for the file's path: the
    /// listings print it with the table. Nothing by default.
    fn loading(&self, _kind: AxisKind) -> Vec<String> {
        Vec::new()
    }
    /// The table a file holds, as the controller would load it: its points, the
    /// correction added in each direction (the correction convention of [`Table`], the
    /// format's sign undone), its place; what the controller would refuse, or read
    /// otherwise than the file seems to say, is refused with its line and field.
    fn read(&self, text: &str, reading: ReadAs) -> Result<Table, Unreadable>;
    /// What to fill in before the control can load the file, when the format names the
    /// axis and `table.place` does not give it: the placeholder written instead (one the
    /// control cannot load, never a valid axis) and what replaces it. `None`: nothing.
    fn unnamed_axis(&self, table: &Table) -> Option<String> {
        let _ = table;
        None
    }
}

/// Every position and correction finite: a value rounded to the controller's unit can
/// overflow to infinity (a read table's 1e308 µm), which no file holds.
pub fn finite(table: &Table) -> Result<(), Refused> {
    let values = table.positions.iter().chain(&table.up).chain(&table.down);
    match values.copied().find(|v| !v.is_finite()) {
        None => Ok(()),
        Some(v) => Err(Refused::Range(format!("a value of {v} cannot be written"))),
    }
}

/// Positions that stay strictly increasing when printed with `decimals` places (as the
/// file gives them to the controller), else why the file cannot hold them.
pub(crate) fn printed_increasing(positions: &[f64], decimals: usize) -> Result<(), Refused> {
    let scale = 10f64.powi(decimals as i32);
    // The value as printed, not (p · 10ⁿ).round(): that rounds the product, which may round
    // the other way than the decimal expansion the file gets (25.0000005 is printed
    // 25.000000, but 25.0000005 · 10⁶ is 25000000.5, rounded up).
    let printed = |p: f64| {
        crate::units::fmt_fixed(p, decimals)
            .parse::<f64>()
            .unwrap_or(f64::NAN)
    };
    match positions
        .windows(2)
        .find(|w| printed(w[1]) <= printed(w[0]))
    {
        None => Ok(()),
        Some(w) => Err(Refused::Grid(format!(
            "the positions must increase by at least {} (the file's precision): {} and {} do not",
            crate::units::fmt_fixed(1.0 / scale, decimals),
            crate::units::fmt_fixed(w[0], decimals),
            crate::units::fmt_fixed(w[1], decimals)
        ))),
    }
}

/// What a file says where it names an axis that was not given: `<`, `?` and `>` are in no
/// control's axis names (SINUMERIK identifiers are letters, digits and `_`; HEIDENHAIN file
/// names exclude them), so the control refuses the file instead of loading it onto an axis
/// the name happens to mean (`AX1`, SINUMERIK's machine axis 1).
pub(crate) const AXIS_PLACEHOLDER: &str = "<AXIS?>";

/// The axis's name on the controller as the file can hold it (letters, digits and `_`: a
/// blank, a bracket or a comma would break the file's syntax), or [`AXIS_PLACEHOLDER`]
/// when none is given.
pub fn axis_name(table: &Table) -> Result<&str, Refused> {
    match table.place.axis.as_deref() {
        None => Ok(AXIS_PLACEHOLDER),
        Some(name)
            if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') =>
        {
            Ok(name)
        }
        Some(name) => Err(Refused::Grid(format!(
            "the axis name `{}` is not a name the file can hold (letters, digits and _)",
            name.escape_debug()
        ))),
    }
}

/// `notes` as comment lines starting with `mark`.
pub(crate) fn commented(mark: &str, notes: &[String]) -> String {
    notes.iter().map(|n| format!("{mark}{n}\n")).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two positions printed alike are refused although their product with 10ⁿ rounds
    /// apart (found by the `controllers` fuzz target: an ecmc table whose positions 25 and
    /// 25.0000005 were both written as 25.000000, which ecmc refuses).
    #[test]
    fn positions_printed_alike_are_refused() {
        assert_eq!(crate::units::fmt_fixed(25.0000005, 6), "25.000000");
        assert!(printed_increasing(&[0.0, 25.0, 25.0000005, 100.0], 6).is_err());
        assert!(printed_increasing(&[0.0, 25.0, 25.000001, 100.0], 6).is_ok());
        assert!(printed_increasing(&[0.0, 0.00004, 1.0], 4).is_err());
        assert!(printed_increasing(&[0.0, 0.0001, 1.0], 4).is_ok());
    }
}
