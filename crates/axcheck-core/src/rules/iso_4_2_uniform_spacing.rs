//! `iso-4.2-uniform-spacing`: targets at equal intervals may alias periodic errors.

use super::{EPS, Plan, Rule, Severity};

/// ISO 230-2:1997 4.2: target positions are chosen as P_i = (i − 1)P + r, with r a
/// different offset at each target, so that periodic errors (lead screw, scale pitch) are
/// sampled at varying phases. Equal intervals may sample them at one phase only.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.2-uniform-spacing",
    clause: "ISO 230-2 4.2",
    severity: Severity::Warning,
    checks: "all intervals equal: periodic errors may alias",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let gaps = plan.gaps();
    if gaps.len() < 2 {
        return None;
    }
    let mean_gap = gaps.iter().sum::<f64>() / gaps.len() as f64;
    let uniform = gaps
        .iter()
        .all(|g| (g - mean_gap).abs() <= 1e-3 * mean_gap.abs().max(EPS));
    uniform.then(|| {
        format!(
            "all targets are {} apart: periodic errors (lead screw, scale pitch) may alias; vary the spacing with P_i = (i − 1)P + r",
            plan.at((mean_gap * 1000.0).round() / 1000.0)
        )
    })
}
