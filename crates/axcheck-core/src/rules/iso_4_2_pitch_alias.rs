//! `iso-4.2-pitch-alias`: every target interval a multiple of the declared pitch.

use super::{Plan, Rule, Severity};

/// ISO 230-2:1997 4.2: the offsets r of the target positions make periodic errors show.
/// When every interval is a whole number of lead-screw or encoder pitches, the periodic
/// error is sampled at one phase and hidden from the results.
pub(crate) const RULE: Rule = Rule {
    id: "iso-4.2-pitch-alias",
    clause: "ISO 230-2 4.2",
    severity: Severity::Warning,
    checks: "every interval is a multiple of the declared pitch",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let pitch = plan.ctx.pitch?;
    let gaps = plan.gaps();
    if gaps.len() < 2 {
        return None;
    }
    let multiple = |g: f64| {
        let k = g / pitch;
        (k - k.round()).abs() * pitch <= 0.01 * pitch
    };
    gaps.iter().all(|&g| multiple(g)).then(|| {
        format!(
            "every target spacing is a multiple of the {} pitch: the periodic error is sampled at one phase and hidden; offset the targets by varying amounts r",
            plan.at(pitch)
        )
    })
}
