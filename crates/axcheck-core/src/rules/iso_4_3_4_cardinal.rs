//! `iso-4.3.4-cardinal`: the principal positions are targets on a rotary axis up to 360°.

use super::{IsoPlan, Plan, Rule, Severity};

/// ISO 230-2:1997 4.3.4: the principal positions 0°, 90°, 180° and 270° are included
/// among the targets of a rotary axis wherever they lie inside the measurement travel.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.4-cardinal",
    clause: "ISO 230-2 4.3.4",
    severity: Severity::Error,
    checks: "0°, 90°, 180°, 270° are targets where inside the travel",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if plan.iso_plan() != Some(IsoPlan::Clause4_3_4) {
        return None;
    }
    plan.missing_cardinal_positions()
}
