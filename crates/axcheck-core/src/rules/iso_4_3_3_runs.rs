//! `iso-4.3.3-runs`: one run or five on a linear axis over 2000 mm.

use super::{IsoPlan, Plan, Rule, Severity};

/// ISO 230-2:1997 4.3.3: over more than 2000 mm the full travel is measured with one
/// approach per direction (n = 1), and a working range of up to 2000 mm may be tested by
/// the plan of 4.3.2 (n = 5). Two to four runs follow neither plan.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.3-runs",
    clause: "ISO 230-2 4.3.3",
    severity: Severity::Error,
    checks: "linear test > 2000 mm: n = 1 or n ≥ 5",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    (plan.iso_plan() == Some(IsoPlan::Clause4_3_3) && (2..5).contains(&n)).then(|| {
        format!(
            "n = {n}: a test over more than 2000 mm uses n = 1 (clause 4.3.3) or n = 5 (clause 4.3.2)"
        )
    })
}
