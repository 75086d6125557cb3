//! What the diagnosis knows of an axis from the campaign.

use crate::campaign::AxisSpec;

/// The diagnosis's options from the axis: the pitch it looks for periodic error at, the
/// declared thermal origin and the standard.
pub fn options(axis: &AxisSpec) -> crate::diagnose::Options {
    crate::diagnose::Options {
        pitch: axis.raw.pitch,
        thermal_origin: axis.raw.thermal_origin,
        standard: axis.standard,
        ..crate::diagnose::Options::default()
    }
}
