//! `iso-4.3.2-targets`: enough targets on a linear axis up to 2000 mm.

use super::{EPS, IsoPlan, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 4.3.2: on a linear axis up to 2000 mm at least five target positions are
/// chosen per metre of measurement travel, and at least five in all, so that the
/// parameters describe the whole travel rather than a few points of it.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.2-targets",
    clause: "ISO 230-2 4.3.2",
    severity: Severity::Error,
    checks: "linear test ≤ 2000 mm: ≥ 5 targets per metre and ≥ 5 in all",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if plan.iso_plan() != Some(IsoPlan::Clause4_3_2) {
        return None;
    }
    let need = ((5.0 * plan.travel / 1000.0) - EPS).ceil().max(5.0) as usize;
    (plan.targets < need).then(|| {
        format!(
            "{} targets over {} mm of measurement travel; at least 5 per metre and 5 in all are needed ({need}): add {} target(s)",
            plan.targets,
            fmt_position(plan.travel),
            need - plan.targets
        )
    })
}
