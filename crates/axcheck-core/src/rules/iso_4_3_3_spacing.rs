//! `iso-4.3.3-spacing`: targets close enough on a linear axis over 2000 mm.

use super::{EPS, IsoPlan, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 4.3.3: a linear axis over 2000 mm is measured over its whole travel with
/// a mean interval of at most 250 mm between target positions.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.3-spacing",
    clause: "ISO 230-2 4.3.3",
    severity: Severity::Error,
    checks: "linear test > 2000 mm: mean spacing ≤ 250 mm",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if plan.iso_plan() != Some(IsoPlan::Clause4_3_3) {
        return None;
    }
    let spacing = plan.travel / (plan.targets.max(2) - 1) as f64;
    if spacing <= 250.0 + EPS {
        return None;
    }
    let need = (plan.travel / 250.0 - EPS).ceil() as usize + 1;
    Some(format!(
        "mean target spacing {} mm over {} mm; an axis over 2000 mm needs a mean spacing of at most 250 mm: use at least {need} targets",
        fmt_position((spacing * 10.0).round() / 10.0),
        fmt_position(plan.travel)
    ))
}
