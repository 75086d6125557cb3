//! `iso-4.3.5-spacing`: targets at most 45° apart on a rotary axis over 360°.

use super::{EPS, IsoPlan, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 4.3.5: a rotary axis over more than 360° is measured with target
/// positions at most 45° apart.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.5-spacing",
    clause: "ISO 230-2 4.3.5",
    severity: Severity::Error,
    checks: "rotary > 360°: every spacing ≤ 45°",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if plan.iso_plan() != Some(IsoPlan::Clause4_3_5) {
        return None;
    }
    let widest = plan.gaps().into_iter().fold(0.0, f64::max);
    (widest > 45.0 + EPS).then(|| {
        format!(
            "targets up to {}° apart; a rotary test over more than 360° needs a spacing of at most 45°",
            fmt_position((widest * 1000.0).round() / 1000.0)
        )
    })
}
