//! `gost-2.10-runs`: at least five measurements per target and direction (GOST 27843).

use super::{Plan, Rule, Severity};

/// GOST 27843-88 2.10: every target is measured at least five times in each direction;
/// the standard deviation S and with it the repeatability rest on these measurements.
pub(crate) const RULE: Rule = Rule {
    id: "gost-2.10-runs",
    clause: "GOST 27843 2.10",
    severity: Severity::Error,
    checks: "n ≥ 5",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    (plan.gost() && n < 5).then(|| {
        format!("n = {n} measurements per target and direction; GOST 27843 asks for at least 5")
    })
}
