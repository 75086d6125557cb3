//! `iso-4.3.2-runs`: five approaches per direction on a linear axis up to 2000 mm.

use super::{IsoPlan, Plan, Rule, Severity};

/// ISO 230-2:1997 4.3.2: every target of a linear axis up to 2000 mm is approached five
/// times in each direction (n = 5); the estimator of the standard uncertainty, and with
/// it the repeatability R, rests on these runs.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.2-runs",
    clause: "ISO 230-2 4.3.2",
    severity: Severity::Error,
    checks: "linear test ≤ 2000 mm: n ≥ 5 per direction",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    (plan.iso_plan() == Some(IsoPlan::Clause4_3_2) && n < 5).then(|| {
        format!(
            "n = {n} approaches per direction; a linear axis up to 2000 mm needs 5 at every target"
        )
    })
}
