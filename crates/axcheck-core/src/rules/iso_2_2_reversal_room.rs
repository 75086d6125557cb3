//! `iso-2.2-reversal-room`: the first and last targets can be approached from both sides.

use super::{EPS, Plan, Rule, Severity};
use crate::units::{AxisKind, Travel, fmt_position};

/// ISO 230-2:1997 2.2: the measurement travel is chosen so that the first and last
/// targets can be approached in both directions, which needs room beyond them in the
/// axis travel. A rotary axis turning a full revolution has no ends.
pub(crate) const RULE: Rule = Rule {
    id: "iso-2.2-reversal-room",
    clause: "ISO 230-2 2.2",
    severity: Severity::Error,
    checks: "first and last targets can be approached from both sides (axis travel given)",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let axis_travel = plan.ctx.axis_travel?;
    let full_turn = plan.ctx.kind == AxisKind::Rotary && axis_travel.length() >= 360.0 - EPS;
    if full_turn {
        return None;
    }
    let unit = plan.unit();
    match axis_travel {
        Travel::Length(t) if plan.travel >= t - EPS => Some(format!(
            "the measurement travel ({} {unit}) uses the whole axis travel ({} {unit}): the first and last targets cannot be approached from both sides; move them inwards",
            fmt_position(plan.travel),
            fmt_position(t)
        )),
        Travel::Range([a, b]) if plan.first <= a + EPS || plan.last >= b - EPS => Some(format!(
            "targets {}…{} {unit} reach the ends of the axis travel [{}, {}] {unit}: the first and last targets cannot be approached from both sides; move them inwards",
            fmt_position(plan.first),
            fmt_position(plan.last),
            fmt_position(a),
            fmt_position(b)
        )),
        _ => None,
    }
}
