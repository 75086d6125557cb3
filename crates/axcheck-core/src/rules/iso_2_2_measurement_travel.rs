//! `iso-2.2-measurement-travel`: the targets lie inside the declared measurement travel.

use super::{EPS, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 2.2: the measurement travel is the part of the axis travel over which
/// data are taken, from the first to the last target. Targets outside the declared one
/// mean the declaration or the data are wrong.
pub(crate) const RULE: Rule = Rule {
    id: "iso-2.2-measurement-travel",
    clause: "ISO 230-2 2.2",
    severity: Severity::Error,
    checks: "targets lie inside the declared measurement travel",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let [a, b] = plan.ctx.measurement_travel?;
    if plan.first >= a - EPS && plan.last <= b + EPS {
        return None;
    }
    let unit = plan.unit();
    Some(format!(
        "targets {}…{} {unit} lie outside the declared measurement travel [{}, {}] {unit}; correct measurement_travel or the data",
        fmt_position(plan.first),
        fmt_position(plan.last),
        fmt_position(a),
        fmt_position(b)
    ))
}
