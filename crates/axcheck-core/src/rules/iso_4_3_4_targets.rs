//! `iso-4.3.4-targets`: enough targets on a rotary axis up to 360°.

use super::{EPS, IsoPlan, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 4.3.4, Table 1: the least number of target positions on a rotary axis
/// up to 360° grows with the travel: 3 up to 90°, 5 up to 180°, 8 beyond.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.4-targets",
    clause: "ISO 230-2 4.3.4, Table 1",
    severity: Severity::Error,
    checks: "rotary ≤ 360°: ≥ 3 (≤ 90°), 5 (≤ 180°), 8 (> 180°) targets",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if plan.iso_plan() != Some(IsoPlan::Clause4_3_4) {
        return None;
    }
    let need = if plan.travel <= 90.0 + EPS {
        3
    } else if plan.travel <= 180.0 + EPS {
        5
    } else {
        8
    };
    (plan.targets < need).then(|| {
        format!(
            "{} targets over {}°; Table 1 asks for at least {need}: add {} target(s)",
            plan.targets,
            fmt_position(plan.travel),
            need - plan.targets
        )
    })
}
