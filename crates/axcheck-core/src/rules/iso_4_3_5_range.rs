//! `iso-4.3.5-range`: a rotary test beyond the five revolutions the standard covers.

use super::{EPS, IsoPlan, Plan, Rule, Severity};
use crate::units::fmt_position;

/// ISO 230-2:1997 4.3.5 covers rotary travels up to 1800° (five revolutions); a longer
/// test still gives figures, but the normal working range should be tested as well.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.3.5-range",
    clause: "ISO 230-2 4.3.5",
    severity: Severity::Warning,
    checks: "rotary over 1800° is beyond the standard",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    (plan.iso_plan() == Some(IsoPlan::Clause4_3_5) && plan.travel > 1800.0 + EPS).then(|| {
        format!(
            "measurement travel {}° exceeds the 1800° (5 revolutions) the standard covers; test the normal working range as well",
            fmt_position(plan.travel)
        )
    })
}
