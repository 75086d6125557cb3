//! `instrument-calibration-due`: the instrument's calibration had run out before the test.

use super::{Plan, Rule, Severity};

/// A result is traceable only through an instrument whose calibration is valid when it
/// measures (ISO/IEC 17025:2017 6.4.4, equipment verified before it is placed or returned
/// into service; 6.5, metrological traceability through an unbroken chain of
/// calibrations; 6.4.13 e), the due date of the next calibration among the equipment's
/// records). A test made after its instrument's stated due date is not traceable, so it
/// does not follow the method: `noncompliant`, like a broken test plan; so is one made
/// before the stated calibration (that calibration cannot show the instrument valid on the
/// day: the one before it must be stated). The rule applies where the campaign states the
/// instrument's `calibration: {calibrated_on, due}` and the test has a date (the file's,
/// else the campaign's), and to every test of a certificate (`unshown`).
pub(crate) const RULE: Rule = Rule {
    id: "instrument-calibration-due",
    clause: "ISO/IEC 17025:2017 6.4.4, 6.5",
    severity: Severity::Error,
    checks: "the instrument's calibration was valid on the test date (calibrated on or before it, due on or after it; in a certificate, stated)",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let c = plan.ctx.calibration.as_ref()?;
    if c.certifying
        && let Some(missing) = unshown(c)
    {
        return Some(missing);
    }
    let test_date = c.test_date.as_deref()?;
    let instrument = c.instrument.as_deref().unwrap_or("(unnamed)");
    let certificate =
        (c.certificate.as_deref()).map_or(String::new(), |n| format!(" (certificate {n})"));
    if let Some(on) = c.calibrated_on.as_deref().filter(|on| *on > test_date) {
        return Some(format!(
            "the instrument {instrument} was calibrated on {on}{certificate}, after the test on {test_date}: that calibration does not show it was valid on the day; state the calibration that was valid on {test_date}"
        ));
    }
    let due = c.due.as_deref()?;
    (due < test_date).then(|| {
        format!(
            "the calibration of the instrument {instrument}{certificate} was due on {due}, before the test on {test_date}: its results are not traceable; recalibrate the instrument and measure again"
        )
    })
}

/// What a certificate cannot show of the instrument's traceability (ISO/IEC 17025:2017
/// 7.8.4.1 c): the instrument, its certificate or its due date unstated.
fn unshown(c: &super::CalibrationDue) -> Option<String> {
    let why = "the campaign is a certificate (campaign.certificate), which must show how its results are traceable";
    let Some(instrument) = &c.instrument else {
        return Some(format!(
            "no instrument is stated (conditions.instrument): {why}; state the instrument with its calibration: {{certificate, calibrated_on, due, body}}"
        ));
    };
    let lacks = match (&c.certificate, &c.due) {
        (None, None) => "calibration certificate or due date",
        (None, Some(_)) => "calibration certificate",
        (Some(_), None) => "due date of its calibration",
        (Some(_), Some(_)) => return None,
    };
    Some(format!(
        "the instrument {instrument} states no {lacks} (conditions.instrument.calibration): {why}; copy them from the instrument's calibration certificate"
    ))
}
