//! `gost-2.7-targets`: at least 11 targets on any two metres (GOST 27843).

use super::{EPS, Plan, Rule, Severity};
use crate::units::AxisKind;

/// GOST 27843-88 2.7: a linear axis has at least 11 target positions on any two metres
/// of its travel; a travel up to 2 m has at least 11 in all.
pub(crate) const RULE: Rule = Rule {
    id: "gost-2.7-targets",
    clause: "GOST 27843 2.7",
    severity: Severity::Error,
    checks: "≥ 11 targets on any two metres",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    if !plan.gost() || plan.ctx.kind != AxisKind::Linear {
        return None;
    }
    let fewest = fewest_on_two_metres(plan)?;
    (fewest < 11).then(|| {
        format!(
            "{fewest} targets on a 2 m stretch; GOST 27843 asks for at least 11 on any two metres: add {}",
            11 - fewest
        )
    })
}

/// The fewest targets in a 2 m window starting at a target (all of them up to 2 m).
fn fewest_on_two_metres(plan: &Plan) -> Option<usize> {
    let targets = &plan.data.targets;
    if plan.travel <= 2000.0 + EPS {
        return Some(plan.targets);
    }
    targets
        .iter()
        .filter(|&&t| t + 2000.0 <= plan.last + EPS)
        .map(|&t| {
            targets
                .iter()
                .filter(|&&x| x >= t - EPS && x <= t + 2000.0 + EPS)
                .count()
        })
        .min()
}
