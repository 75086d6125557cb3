//! Command-line front end: parses arguments, calls the library, prints results.

pub mod campaign;
pub mod diagnose;
pub mod eval;
pub mod simulate;
pub mod text;
