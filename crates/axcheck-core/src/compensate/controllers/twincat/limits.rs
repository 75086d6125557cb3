//! The numbers of TwinCAT's spindle slope compensation lists that the writer and the
//! reader share: the entries a table may hold, the position and value steps.

use crate::units::AxisKind;

/// Entries per table before P-COMP-00059 (and its default since).
pub(super) const MAX_POINTS: usize = 1500;

/// Position steps per mm or per degree: 0.1 µm and 0.0001°.
pub(super) const STEPS_PER_POSITION_UNIT: f64 = 1e4;

/// Slack on a whole step (steps): float noise, far below the 0.1 µm step.
pub(super) const STEP_SLACK: f64 = 1e-3;

/// One value step in the deviation unit: 0.1 µm, or 0.0001° = 0.36″.
pub(super) fn value_step(kind: AxisKind) -> f64 {
    match kind {
        AxisKind::Linear => 0.1,
        AxisKind::Rotary => 0.36,
    }
}
