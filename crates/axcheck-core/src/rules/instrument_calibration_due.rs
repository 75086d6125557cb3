//! `instrument-calibration-due`: the instrument's calibration had run out before the test.

use super::{Plan, Rule, Severity};

/// A result is traceable only through an instrument whose calibration is valid when it
/// measures (ISO/IEC 17025:2017 6.4.4, equipment verified before it is placed or returned
/// into service; 6.5, metrological traceability through an unbroken chain of
/// calibrations; 6.4.13 e), the due date of the next calibration among the equipment's
/// records). A test made after its instrument's stated due date is not traceable, so it
/// does not follow the method: `noncompliant`, like a broken test plan. The rule applies
/// where the campaign states the instrument's `calibration: {due: …}` and the test has a
/// date (the file's, else the campaign's).
pub(crate) const RULE: Rule = Rule {
    id: "instrument-calibration-due",
    clause: "ISO/IEC 17025:2017 6.4.4, 6.5",
    severity: Severity::Error,
    checks: "the instrument's calibration was still valid on the test date (its stated due date is not before it)",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let c = plan.ctx.calibration.as_ref()?;
    (c.due.as_str() < c.test_date.as_str()).then(|| {
        let certificate = c
            .certificate
            .as_deref()
            .map_or(String::new(), |n| format!(" (certificate {n})"));
        format!(
            "the calibration of the instrument {}{certificate} was due on {}, before the test on {}: its results are not traceable; recalibrate the instrument and measure again",
            c.instrument, c.due, c.test_date
        )
    })
}
