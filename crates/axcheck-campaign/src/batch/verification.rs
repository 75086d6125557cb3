//! Each re-measurement that verifies a table compared with its prediction, the tables
//! loaded on its machine's other axes tried as the wrong axis (ISO 230-2 tests before and
//! after; the comparison is the core's [`crate::verify`]).

use super::AxisTest;
use crate::campaign::stages::compensate::{Case, StatedTableError, VerifyCase};
use crate::compensate::{self, Table};
use crate::measurement::AxisData;
use crate::verify::{self, Effectiveness, Other, Verification};

/// Each test with a verification case compared, the tables loaded on the other axes of
/// its machine tried as `wrong_axis`.
pub(crate) fn verify_all(tests: &mut [(AxisTest, Case)]) {
    let loaded: Vec<(String, String, Table)> = tests
        .iter()
        .filter_map(|(t, case)| {
            let case = case.as_ref()?.as_ref().ok()?;
            Some((t.machine.id.clone(), t.axis.clone(), case.new.clone()))
        })
        .collect();
    for (t, case) in tests.iter_mut() {
        let Some(case) = case.take() else {
            continue;
        };
        let Some(spec) = t.spec.clone() else {
            continue;
        };
        let (machine, axis) = (t.machine.id.clone(), t.axis.clone());
        let Some(e) = t.evaluated_mut() else {
            continue;
        };
        let Some(after) = e.data.as_ref() else {
            continue;
        };
        let others: Vec<Other> = loaded
            .iter()
            .filter(|(m, a, _)| *m == machine && *a != axis)
            .map(|(_, a, table)| Other {
                axis: a.clone(),
                new: table.clone(),
            })
            .collect();
        let verification = case.and_then(|c| compare(&c, after, &others, spec.standard));
        if let (Ok(v), Some(c)) = (&verification, e.compensation.as_mut()) {
            withhold(c, v);
        }
        e.verification = Some(Box::new(verification));
    }
}

/// A table built on a stated active table that the verification shows did not act as
/// stated is wrong too: it is not written, and the refusal says why.
fn withhold(c: &mut compensate::Compensation, v: &Verification) {
    let failed = matches!(
        v.verdict,
        Effectiveness::NotEffective | Effectiveness::MadeWorse | Effectiveness::TableMismatch
    );
    if v.findings.is_empty() && !failed || c.outcome.is_err() {
        return;
    }
    let found: Vec<&str> = v.findings.iter().map(|f| f.effect.name()).collect();
    let what = if found.is_empty() {
        v.verdict.name().to_string()
    } else {
        format!("{} ({})", v.verdict.name(), found.join(", "))
    };
    c.outcome = Err(compensate::NoTable {
        controller: c.controller,
        reason: format!(
            "the verification of the table active during this test found it {what}: it did not act as stated, so a table built on it would be wrong; correct how it was loaded and measure again"
        ),
    });
}

/// The verification of one case.
fn compare(
    case: &VerifyCase,
    after: &AxisData,
    others: &[Other],
    standard: crate::evaluate::StandardId,
) -> Result<Verification, StatedTableError> {
    let input = verify::VerifyInput {
        before: &case.before,
        after,
        old: case.old.as_ref(),
        new: &case.new,
        others,
        controller: crate::compensate::controllers::find(case.controller),
        standard,
    };
    let mut v = verify::verify(&input)?;
    v.notes.extend(case.notes.iter().cloned());
    Ok(v)
}
