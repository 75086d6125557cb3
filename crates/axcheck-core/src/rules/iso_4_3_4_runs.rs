//! `iso-4.3.4-runs`: five approaches per direction on a rotary axis up to 360°.

use super::{IsoPlan, Plan, Rule, Severity};

/// ISO 230-2:1997 4.3.4 with 5.1: every target of a rotary axis up to 360° is approached
/// five times in each direction, as on a linear axis.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.4-runs",
    clause: "ISO 230-2 4.3.4, 5.1",
    severity: Severity::Error,
    checks: "rotary ≤ 360°: n ≥ 5",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    (plan.iso_plan() == Some(IsoPlan::Clause4_3_4) && n < 5).then(|| {
        format!(
            "n = {n} approaches per direction; a rotary axis up to 360° needs 5 at every target"
        )
    })
}
