//! The other laser tests of a linear axis, beside positioning: straightness
//! ([`straightness`]), angular deviations ([`angular`]: roll, pitch, yaw), squareness
//! between two axes ([`squareness`]), and the positioning deviation carried to the tool
//! point through the angular deviations ([`abbe`]). [`line`](mod@line) fits the reference straight
//! lines they share.
//!
//! The readings are an [`AxisData`] as for positioning:
//! targets along the axis (mm), runs, both directions; the deviation is the test's own
//! quantity (µm across the axis for straightness, arcsec for angular deviations). The
//! notation is ISO 230-1's (EYX, EZX: straightness of X in Y and Z; EAX, EBX, ECX: roll,
//! pitch and yaw of X). Pure: no file, no unit parsing.

pub mod abbe;
pub mod angular;
pub mod judge;
pub mod line;
pub mod optics;
pub mod squareness;
pub mod straightness;
pub mod tolerance;
pub mod uncertainty;

use crate::measurement::AxisData;
use crate::units::Direction;

/// Each target's mean reading in one direction (x̄ᵢ↑ or x̄ᵢ↓, as ISO 230-2 2.10 for
/// positioning), in the readings' unit.
pub fn means(data: &AxisData, direction: Direction) -> Vec<f64> {
    (0..data.target_count())
        .map(|i| crate::evaluate::stats::mean(data.deviations(i, direction)))
        .collect()
}

pub use crate::units::ARCSEC_PER_RAD;

/// Which laser test a file holds: a campaign axis's `test:` and `eval --test`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TestKind {
    /// ISO 230-2's positioning test (EXX for an X axis).
    #[default]
    Positioning,
    /// Straightness across the axis (EYX, EZX).
    Straightness,
    /// Roll, pitch or yaw (EAX, EBX, ECX).
    Angular,
    /// Squareness of two axes from two straightness tests.
    Squareness,
}

impl TestKind {
    pub const ALL: [TestKind; 4] = [
        TestKind::Positioning,
        TestKind::Straightness,
        TestKind::Angular,
        TestKind::Squareness,
    ];

    pub fn key(self) -> &'static str {
        match self {
            TestKind::Positioning => "positioning",
            TestKind::Straightness => "straightness",
            TestKind::Angular => "angular",
            TestKind::Squareness => "squareness",
        }
    }

    pub fn parse(key: &str) -> Option<TestKind> {
        TestKind::ALL.into_iter().find(|k| k.key() == key)
    }
}
