//! `gost-2.8-cardinal`: the principal positions are targets on a rotary axis (GOST 27843).

use super::{Plan, Rule, Severity};
use crate::units::AxisKind;

/// GOST 27843-88 2.8: a rotary axis is measured at 0°, 90°, 180° and 270° among its
/// target positions, in every turn of the travel.
pub(crate) const RULE: Rule = Rule {
    id: "gost-2.8-cardinal",
    clause: "GOST 27843 2.8",
    severity: Severity::Error,
    checks: "0°, 90°, 180°, 270° are targets",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if !plan.gost() || plan.ctx.kind != AxisKind::Rotary {
        return None;
    }
    plan.missing_cardinal_positions()
}
