//! Controllers: each writes a [`Table`] in its own file format, one file per controller
//! (as the exporters are), with its units, limits and sign convention.

pub mod csv;
pub mod linuxcnc;

use super::Table;

/// Why a controller cannot hold a table.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum Refused {
    #[error("{controller}: {reason}")]
    Cannot {
        controller: &'static str,
        reason: String,
    },
}

/// A controller's compensation file.
pub trait Controller: Sync {
    /// The name users give (`--controller NAME`, `controller:` in campaigns).
    fn name(&self) -> &'static str;
    /// The file extension of its table.
    fn extension(&self) -> &'static str;
    /// The table as the controller loads it.
    fn write(&self, table: &Table) -> Result<String, Refused>;
}

/// Every controller, by name.
pub const CONTROLLERS: &[&dyn Controller] = &[&csv::Csv, &linuxcnc::LinuxCnc];

/// The controller called `name`.
pub fn find(name: &str) -> Option<&'static dyn Controller> {
    CONTROLLERS.iter().copied().find(|c| c.name() == name)
}

/// The controllers' names, for messages.
pub fn names() -> Vec<&'static str> {
    CONTROLLERS.iter().map(|c| c.name()).collect()
}
