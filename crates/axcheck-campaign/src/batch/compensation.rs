//! A test's compensation as its campaign states it: the table active during the test and
//! the one it verifies, read from the controller's files beside the data (the same path
//! rules), and the verification of a re-measurement, each axis compared with the tables
//! loaded on its machine's other axes.

use super::{AxisTest, Files};
use crate::campaign::AxisSpec;
use crate::campaign::model::{ActiveRaw, ActiveStated, CompensationRaw};
use crate::compensate::controllers::{Controller, ReadAs};
use crate::compensate::{self, Active, Settings, Table, TableSlot};
use crate::measurement::AxisData;
use crate::results::StatedTableError;
use crate::units::AxisKind;
use crate::verify::{self, Effectiveness, Other, Verification};

/// What a re-measurement is compared with: the measurement before, and the corrections
/// active then and loaded since, as the controller adds them.
#[derive(Debug, Clone)]
pub struct VerifyCase {
    pub before: AxisData,
    pub old: Option<Table>,
    pub new: Table,
    /// The controller's name, for the effects of its own parameters.
    pub controller: &'static str,
    /// Notes on what was assumed (an unstated backlash).
    pub notes: Vec<String>,
}

/// The compensation settings of `axis` for `controller`, its active table read; or why
/// they cannot be had (a table file that is missing or unreadable, naming file and line).
pub fn settings(
    axis: &AxisSpec,
    controller: &dyn Controller,
    files: &Files,
) -> Result<Settings, StatedTableError> {
    let raw = axis.raw.compensation.clone().unwrap_or_default();
    let place = TableSlot {
        axis: raw.axis.clone(),
        measuring_system: raw.measuring_system,
        number: None,
    };
    let kind = axis.raw.kind;
    let active = match (&raw.active, &raw.verifies) {
        (Some(a), _) => Some(active(a, kind, controller, files, &place, "active")?),
        // A re-measurement: the table it verifies was active.
        (None, Some(v)) => {
            let stated = ActiveStated {
                file: Some(v.table.clone()),
                backlash_um: v.backlash_um,
                backlash_arcsec: v.backlash_arcsec,
            };
            Some(active(
                &ActiveRaw::Stated(stated),
                kind,
                controller,
                files,
                &place,
                "verifies.table",
            )?)
        }
        (None, None) => None,
    };
    Ok(Settings {
        interval: raw.interval,
        reference: raw.reference,
        pitch: axis.raw.pitch,
        place,
        active,
        conditions: axis.raw.conditions.compensation.clone(),
    })
}

/// A stated active state, its table read as `controller` reads it.
fn active(
    raw: &ActiveRaw,
    kind: AxisKind,
    controller: &dyn Controller,
    files: &Files,
    place: &TableSlot,
    key: &'static str,
) -> Result<Active, StatedTableError> {
    let ActiveRaw::Stated(s) = raw else {
        return Ok(Active::default());
    };
    let table = match &s.file {
        Some(file) => Some(read_table(file, kind, controller, files, place, key)?),
        None => None,
    };
    Ok(Active {
        table,
        file: s.file.clone(),
        backlash: s.backlash_um.or(s.backlash_arcsec),
    })
}

/// The table file `file` (relative to the campaign) as `controller` reads it.
fn read_table(
    file: &str,
    kind: AxisKind,
    controller: &dyn Controller,
    files: &Files,
    place: &TableSlot,
    key: &'static str,
) -> Result<Table, StatedTableError> {
    let path = files
        .resolve(file)
        .map_err(|refused| StatedTableError::Path { key, refused })?;
    let text = match files.read_to_string(&path) {
        Ok(text) => text,
        Err(e) => {
            let reason = e.to_string();
            return Err(StatedTableError::Unreadable { path, reason });
        }
    };
    let reading = ReadAs {
        kind,
        axis: place.axis.as_deref(),
    };
    controller
        .read(&text, reading)
        .map_err(|e| StatedTableError::NotATable {
            path,
            reason: e.to_string(),
            controller: controller.name(),
            key,
        })
}

/// What the re-measurement of `axis` is compared with, when it `verifies` a table: the
/// measurement before (corrected as this test is), the correction active then and the one
/// loaded since.
pub fn verify_case(
    axis: &AxisSpec,
    controller: &dyn Controller,
    files: &Files,
    settings: &Settings,
) -> Option<Result<VerifyCase, StatedTableError>> {
    let raw: &CompensationRaw = axis.raw.compensation.as_ref()?;
    let v = raw.verifies.as_ref()?;
    Some(case(axis, v, controller, files, settings))
}

fn case(
    axis: &AxisSpec,
    v: &crate::campaign::model::VerifiesRaw,
    controller: &dyn Controller,
    files: &Files,
    settings: &Settings,
) -> Result<VerifyCase, StatedTableError> {
    let kind = axis.raw.kind;
    let path = files
        .resolve(&v.before)
        .map_err(|refused| StatedTableError::Path {
            key: "verifies.before",
            refused,
        })?;
    let read = crate::measurement::read_file_within(&path, &Default::default(), Some(files))
        .map_err(|e| StatedTableError::Before(Box::new(e)))?;
    let (before, _) = crate::campaign::stages::nde::apply(axis, read.data);
    let before_active = match &v.active {
        Some(a) => active(
            a,
            kind,
            controller,
            files,
            &settings.place,
            "verifies.active",
        )?,
        None => Active::default(),
    };
    // The verified table is the test's active one unless another is stated: read once.
    let stated = axis
        .raw
        .compensation
        .as_ref()
        .and_then(|c| c.active.as_ref());
    let table = match (
        stated,
        settings.active.as_ref().and_then(|a| a.table.clone()),
    ) {
        (None, Some(table)) => table,
        _ => read_table(
            &v.table,
            kind,
            controller,
            files,
            &settings.place,
            "verifies.table",
        )?,
    };
    let mut notes = Vec::new();
    let mut loaded = Active {
        table: Some(table),
        file: Some(v.table.clone()),
        backlash: v.backlash_um.or(v.backlash_arcsec),
    };
    if loaded.backlash.is_none() && before_active.backlash.is_some() {
        loaded.backlash = before_active.backlash;
        notes.push(
            "the backlash loaded with the table was not stated: taken as the one active before"
                .into(),
        );
    }
    let rule = controller.backlash();
    let new = loaded.total(rule, kind).ok_or(StatedTableError::Empty)?;
    Ok(VerifyCase {
        before,
        old: before_active.total(rule, kind),
        new,
        controller: controller.name(),
        notes,
    })
}

/// What a re-measurement that verifies a table is compared with, or why it cannot be.
pub type Case = Option<Result<Box<VerifyCase>, StatedTableError>>;

/// Each test with a verification case compared, the tables loaded on the other axes of
/// its machine tried as `wrong_axis`.
pub fn verify_all(tests: &mut [(AxisTest, Case)]) {
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

/// The compensation of a test by its machine's `controller` (none: no table), with the
/// warnings of its diagnosis (`diagnose` runs it when the run did not), and what its
/// re-measurement is compared with when it verifies a table.
pub fn for_test(
    controller: Option<&str>,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
    diagnosis: Option<&crate::diagnose::Diagnosis>,
    diagnose: impl FnOnce() -> crate::diagnose::Diagnosis,
) -> (Option<compensate::Compensation>, Case) {
    let Some(c) = controller.and_then(crate::compensate::controllers::find) else {
        return (None, None);
    };
    let file_type = axis
        .raw
        .compensation
        .as_ref()
        .and_then(|r| r.comp_file_type);
    // Checked when the campaign was loaded: only LinuxCNC's, 0 or 1.
    let c = crate::compensate::controllers::with_comp_file_type(c, file_type).unwrap_or(c);
    let own;
    let diagnosis = match diagnosis {
        Some(d) => d,
        None => {
            own = diagnose();
            &own
        }
    };
    let (compensation, case) = of_test(c, axis, data, files, diagnosis);
    (Some(compensation), case.map(|r| r.map(Box::new)))
}

/// The compensation of a test by `controller` as its axis states it, and what its
/// re-measurement is compared with when it verifies a table. A table file that cannot be
/// read leaves the compensation refused with the reason (the test is still judged).
pub fn of_test(
    controller: &dyn Controller,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
    diagnosis: &crate::diagnose::Diagnosis,
) -> (
    compensate::Compensation,
    Option<Result<VerifyCase, StatedTableError>>,
) {
    match settings(axis, controller, files) {
        Ok(s) => (
            compensate::compensation(controller, data, axis.standard, &s, diagnosis),
            verify_case(axis, controller, files, &s),
        ),
        Err(e) => {
            let verifies = axis
                .raw
                .compensation
                .as_ref()
                .is_some_and(|c| c.verifies.is_some());
            let refused = compensate::Compensation::refused(controller, &e.to_string());
            (refused, verifies.then_some(Err(e)))
        }
    }
}
