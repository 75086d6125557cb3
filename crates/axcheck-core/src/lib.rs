//! axcheck's core: the pure computation in the middle of the pipeline, in its order —
//! the readings of a test ([`measurement`], as the readers build them), the plan's rules
//! ([`rules`]), the standards' evaluation ([`evaluate`], with the NDE correction in
//! [`nde`] and other tools' results checked in [`crosscheck`]), the uncertainty
//! ([`uncertainty`]), the verdict against the limits ([`judge`], ISO 14253-1), the
//! diagnosis against the error model ([`diagnose`], [`axis_model`]), compensation tables
//! ([`compensate`]) and their verification ([`verify`]), and each axis's trend across
//! inspections ([`trend`]). Beside positioning, [`geometry`] evaluates the other laser tests of an
//! axis (straightness, angular deviations, squareness) and carries positioning to the tool
//! point. Before the measurement, [`plan`] gives the targets, the part
//! programs and the laser's target list. Units and names are in [`units`] and [`suggest`].
//!
//! Nothing here opens a file, parses YAML or draws a page: readers, campaigns, outputs and
//! the command line build on this crate.

// The documentation is for the developers of this workspace and is built with its
// private items (`cargo doc --document-private-items`), where a public item's doc may
// link to the private item it is built on.
#![allow(rustdoc::private_intra_doc_links)]

pub mod axis_model;
pub mod compensate;
pub mod crosscheck;
pub mod diagnose;
pub mod evaluate;
pub mod geometry;
pub mod judge;
pub mod lang;
pub mod measurement;
pub mod nde;
pub mod param_key;
pub mod plan;
pub mod rules;
pub mod suggest;
pub mod trend;
pub mod uncertainty;
pub mod units;
pub mod verify;
