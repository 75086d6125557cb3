//! `iso-4.3.5-runs`: one run or five on a rotary axis over 360°.

use super::{IsoPlan, Plan, Rule, Severity};

/// ISO 230-2:1997 4.3.5: over more than 360° the travel is measured with one approach per
/// direction (n = 1), or a range of up to 360° by the plan of 4.3.4 (n = 5). Two to four
/// runs follow neither plan.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.5-runs",
    clause: "ISO 230-2 4.3.5",
    severity: Severity::Error,
    checks: "rotary > 360°: n = 1 or n ≥ 5",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    (plan.iso_plan() == Some(IsoPlan::Clause4_3_5) && (2..5).contains(&n)).then(|| {
        format!(
            "n = {n}: a test over more than 360° uses n = 1 (clause 4.3.5) or n = 5 (clause 4.3.4)"
        )
    })
}
