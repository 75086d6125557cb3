//! Inspection trends. The fit is the core's [`axcheck_core::trend`]; here its views for
//! people and tables ([`view`]).

pub use axcheck_core::trend::*;

pub mod view;
