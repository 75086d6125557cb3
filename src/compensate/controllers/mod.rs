//! Controllers: each writes a [`Table`] in its own file format, one file per controller
//! (as the exporters are), and declares what its table can hold ([`Format`]): the spacing
//! of its points, how many, one table per direction or one per axis, modulo tables, the
//! unit its values are rounded to.

pub mod csv;
pub mod ecmc;
pub mod fanuc;
pub mod heidenhain;
pub mod linuxcnc;
pub mod siemens_840d;
pub mod twincat;

use super::{Interpolation, Table};
use crate::units::AxisKind;

/// Why a controller cannot hold a table.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Refused {
    /// The points: too many, or an interval the table cannot take.
    #[error("{0}")]
    Grid(String),
    /// A position or a value outside what the file can hold.
    #[error("{0}")]
    Range(String),
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
    pub quantum_um: f64,
    /// Smallest step of a correction on a rotary axis, arcsec.
    pub quantum_arcsec: f64,
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
    /// The held table as the controller loads it.
    fn write(&self, table: &Table) -> Result<String, Refused>;
}

/// Every controller, by name.
pub const CONTROLLERS: &[&dyn Controller] = &[
    &csv::Csv,
    &linuxcnc::LinuxCnc,
    &siemens_840d::Siemens840d,
    &fanuc::Fanuc,
    &heidenhain::Heidenhain,
    &twincat::TwinCat,
    &ecmc::Ecmc,
];

/// The controller called `name`.
pub fn find(name: &str) -> Option<&'static dyn Controller> {
    CONTROLLERS.iter().copied().find(|c| c.name() == name)
}

/// The controllers' names, for messages.
pub fn names() -> Vec<&'static str> {
    CONTROLLERS.iter().map(|c| c.name()).collect()
}
