//! Controllers: each writes a [`Table`](crate::compensate::table::Table) in its own file format and reads it back as the
//! controller would load it, one file per controller (as the exporters are), and declares
//! what its table can hold ([`Format`]): the spacing of its points, how many, one table per
//! direction or one per axis, modulo tables, the unit its values are rounded to, and what
//! becomes of its backlash parameter ([`Backlash`]).

pub mod controller;
pub mod csv;
pub mod ecmc;
pub mod fanuc;
pub mod heidenhain;
pub mod linuxcnc;
mod reading;
pub mod siemens_840d;
pub mod twincat;

pub use controller::*;

/// Every controller, by name.
pub const CONTROLLERS: &[&dyn Controller] = &[
    &csv::Csv,
    &linuxcnc::LinuxCnc::TYPE_0,
    &siemens_840d::Siemens840d,
    &fanuc::Fanuc,
    &heidenhain::Heidenhain,
    &twincat::TwinCat,
    &ecmc::Ecmc::CURRENT,
    &ecmc::Ecmc::V9_6,
];

/// The controller called `name`.
pub fn find(name: &str) -> Option<&'static dyn Controller> {
    CONTROLLERS.iter().copied().find(|c| c.name() == name)
}

/// The controllers' names, for messages.
pub fn names() -> Vec<&'static str> {
    CONTROLLERS.iter().map(|c| c.name()).collect()
}

/// `controller` writing LinuxCNC's `COMP_FILE_TYPE = file_type` (0 or 1; `None`: as it
/// is), or why not: the type is LinuxCNC's alone.
pub fn with_comp_file_type(
    controller: &'static dyn Controller,
    file_type: Option<u8>,
) -> Result<&'static dyn Controller, CompFileTypeError> {
    let Some(n) = file_type else {
        return Ok(controller);
    };
    if controller.name() != linuxcnc::LinuxCnc::TYPE_0.name() {
        return Err(CompFileTypeError::NotLinuxCnc {
            controller: controller.name(),
        });
    }
    match linuxcnc::LinuxCnc::of_type(n) {
        Some(c) => Ok(c),
        None => Err(CompFileTypeError::Unknown(n)),
    }
}

/// Why a comp file type cannot be written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum CompFileTypeError {
    #[error("the comp file type is LinuxCNC's COMP_FILE_TYPE, not a setting of {controller}")]
    NotLinuxCnc { controller: &'static str },
    #[error("LinuxCNC's COMP_FILE_TYPE is 0 (actual positions) or 1 (trims), not {0}")]
    Unknown(u8),
}
