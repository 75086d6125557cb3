//! axcheck: positioning accuracy and repeatability of numerically controlled axes.
//!
//! The pipeline, one module per stage, in the order a run takes them: ([`plan`]: test
//! plans and part programs, before the measurement →) [`campaign`] loads and validates
//! the campaign file → [`measurement`] reads the test files → [`rules`] checks each test
//! plan against the standard → [`evaluate`] computes the standard's parameters (pure, no
//! I/O; [`crosscheck`] sets another tool's printed results beside them) → [`uncertainty`]
//! gives their U → [`judge`] decides against the limits (ISO 14253-1) → [`diagnose`]
//! checks the standard's error model and names the causes → [`compensate`] writes the
//! controllers' tables (→ [`verify`] compares a re-measurement with the prediction) →
//! `history` keeps every run and [`trend`] follows each axis across them → `export` and
//! `report` write the outputs. `session` runs one campaign in that order; [`batch`] runs
//! the stages of every axis in parallel, and [`results`] is what they give.
//!
//! The stages are crates of one workspace, each depending only on those below it
//! (README "Layout"): `axcheck-core` (the pure computation), `axcheck-campaign` (the
//! user's files to the result model), `axcheck-charts` (the charts as data) and this
//! package (history, reports, exporters, session, command line), which re-exports the
//! lower crates' modules under their names. Below the stages: [`axis_model`] (the axis's
//! error model, test plan and a simulated test), [`nde`] (the temperature correction),
//! [`files`] (all reading of user files, rooted), [`yaml`], [`units`], [`atomic`],
//! [`lock`] and [`safe_text`] (input text made safe for each output); [`simulate`] writes
//! simulation files and synthetic fleets.

// The documentation is for the developers of this workspace and is built with its
// private items (`cargo doc --document-private-items`), where a public item's doc may
// link to the private item it is built on.
#![allow(rustdoc::private_intra_doc_links)]

pub mod export;
pub mod history;
#[cfg(feature = "pdf")]
pub mod report;
#[cfg(all(feature = "pdf", feature = "parquet"))]
pub mod session;

pub use axcheck_campaign::{
    atomic, batch, campaign, files, inputs, judge, lock, measurement, one_file, panics, plan,
    results, safe_text, simulate, trend, yaml,
};
pub use axcheck_core::{
    axis_model, compensate, crosscheck, diagnose, evaluate, geometry, lang, nde, rules, suggest,
    uncertainty, units, verify,
};
