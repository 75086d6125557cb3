//! Controllers: each writes a [`Table`] in its own file format and reads it back as the
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
    &linuxcnc::LinuxCnc,
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
