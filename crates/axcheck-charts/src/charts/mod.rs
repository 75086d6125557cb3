//! The charts of the reports, one file each: ISO 230-2's figures ([`iso`]), the
//! tolerance usage ([`usage`]), the model checks and decision zones ([`check`]), the diagnosis's residuals
//! and periodogram ([`diagnosis`]), a compensation and its verification, an axis's history
//! ([`trend`]), the other laser tests' means ([`geometry`]). Each draws a [`crate::chart_kit::scene::Scene`] with the chart kit.

pub mod check;
pub mod compensation;
pub mod diagnosis;
pub mod geometry;
pub mod iso;
pub mod trend;
pub mod usage;
pub mod verification;

pub use iso::*;
pub use usage::*;
