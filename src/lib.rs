//! axcheck: positioning accuracy and repeatability of numerically controlled axes.
//!
//! The pipeline, one module per stage: [`measurement`] reads test files, [`evaluate`]
//! computes the parameters of a standard (pure, no I/O), [`simulate`] is the axis error
//! model that produces test data.

pub mod atomic;
pub mod evaluate;
pub mod measurement;
pub mod simulate;
pub mod units;
