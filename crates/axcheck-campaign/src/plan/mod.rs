//! Test plans. The targets, rules, part programs and laser target lists are the core's
//! [`axcheck_core::plan`]; here the plan as a file ([`file`](mod@file)).

pub use axcheck_core::plan::*;

pub mod file;
