//! axcheck: positioning accuracy and repeatability of numerically controlled axes.
//!
//! The pipeline, one module per stage: [`campaign`] loads and validates campaign files,
//! [`measurement`] reads test files, [`rules`] checks each test plan against the standard,
//! [`evaluate`] computes the parameters of a standard (pure, no I/O), [`judge`] compares
//! them with tolerance limits, [`batch`] runs a whole campaign in parallel and [`export`]
//! writes its outputs; `history` keeps every run's results and [`trend`] follows each
//! axis across them. [`simulate`] is the axis error model that produces test data.

pub mod atomic;
pub mod axis_model;
pub mod batch;
pub mod campaign;
pub mod compensate;
pub mod crosscheck;
pub mod diagnose;
pub mod evaluate;
pub mod export;
pub mod files;
pub mod history;
pub mod judge;
pub mod lock;
pub mod measurement;
pub mod nde;
pub mod panics;
pub mod plan;
#[cfg(feature = "pdf")]
pub mod report;
pub mod rules;
#[cfg(all(feature = "pdf", feature = "parquet"))]
pub mod session;
pub mod simulate;
pub mod suggest;
pub mod trend;
pub mod uncertainty;
pub mod units;
pub mod verify;
pub mod yaml;
