//! `iso-7.1-conditions`: test conditions the report must state and the campaign does not.

use super::{Plan, Rule, Severity};

/// ISO 230-2:1997 7.1: the test report states, beside the results, the conditions of the
/// test (the instrument and its position, the temperature sensors and their positions,
/// the NDE correction, the date, the machine and the axis travel, the test equipment, the
/// positioning element and its expansion coefficient, the positions of the other axes and
/// the offsets, feed and dwell, the warm-up, the temperatures at the start and the end,
/// air pressure and humidity where they matter, the compensation active). A result whose
/// conditions are not stated cannot be repeated or compared with the next inspection; the
/// result stands, so the rule is a warning. The items and where a campaign states each:
/// `crate::campaign::clause7_1`. The rule applies to a campaign's tests only (a planned
/// test has no conditions yet).
pub(crate) const RULE: Rule = Rule {
    id: "iso-7.1-conditions",
    clause: "ISO 230-2 7.1",
    severity: Severity::Warning,
    checks: "every test condition the clause lists is stated (campaign `conditions:`, machine, date, or the file)",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let missing = plan.ctx.unstated.as_deref()?;
    (!missing.is_empty()).then(|| remembered(missing))
}

/// The message for `missing`, formatted once per worker while the tests it judges one
/// after another miss the same items (a fleet's axes mostly do).
fn remembered(missing: &[&'static str]) -> String {
    use std::cell::RefCell;
    thread_local! {
        static LAST: RefCell<(Vec<&'static str>, String)> = const { RefCell::new((Vec::new(), String::new())) };
    }
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        if last.0 != missing || last.1.is_empty() {
            *last = (missing.to_vec(), message(missing));
        }
        last.1.clone()
    })
}

fn message(missing: &[&'static str]) -> String {
    format!(
        "{} of the test conditions of clause 7.1 not stated: {}; state them under the axis's `conditions:` (instrument, equipment, temperatures …), the machine's `model` and `type`, the axis's `travel` and the campaign's `date`",
        missing.len(),
        (missing.iter().map(|m| lower_first(m)))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// `position of the measuring instrument` from the report's `Position of …` (an
/// acronym such as `NDE` kept).
fn lower_first(label: &str) -> String {
    let mut chars = label.chars();
    match (chars.next(), chars.next()) {
        (Some(first), Some(second)) if second.is_lowercase() => {
            first.to_lowercase().chain([second]).chain(chars).collect()
        }
        _ => label.to_string(),
    }
}
