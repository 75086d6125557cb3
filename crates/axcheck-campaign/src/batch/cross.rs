//! A straightness test's cross table (`compensation/M/X-EYX.*`, where its machine names a
//! controller that has one) built on the cross table active during the test, and — after
//! every test is read — the re-measurements that verify a loaded cross table compared with
//! its prediction, the same axis's other straightness re-measured tried as the wrong axis
//! (`compensate::cross::verify`).

use super::{Files, Tested};
use crate::campaign::AxisSpec;
use crate::campaign::model::{ActiveRaw, CompensationRaw};
use crate::campaign::stages::compensate::TableFile;
use crate::campaign::stages::cross::read_cross_table;
use crate::compensate::cross::build::{CrossActive, CrossCompensation, CrossRequest, compensate};
use crate::compensate::cross::verify::{CrossVerdict, OtherOutput, verify};
use crate::compensate::cross::{self, CrossFormat, CrossTable};
use crate::geometry::TestKind;
use crate::measurement::AxisData;
use crate::results::CrossOutcome;

/// The format of the machine's controller, or why it has none.
fn format(controller: &str) -> Result<&'static dyn CrossFormat, String> {
    cross::find(controller).ok_or_else(|| {
        format!(
            "the controller `{controller}` has no cross-axis table in axcheck (those that have one: {}); none written",
            cross::names().join(", ")
        )
    })
}

/// A table file the campaign names under `key`.
fn read(
    files: &Files,
    file: &str,
    key: &'static str,
    f: &dyn CrossFormat,
) -> Result<CrossTable, String> {
    read_cross_table(TableFile::Stated { files, file, key }, f).map_err(|e| e.to_string())
}

/// What was active during the test: `compensation.active`, else the table it verifies
/// (loaded since the measurement before), else unstated.
fn active(c: &CompensationRaw, files: &Files, f: &dyn CrossFormat) -> Result<CrossActive, String> {
    let key = "compensation.active";
    match (&c.active, &c.verifies) {
        (Some(ActiveRaw::Stated(s)), _) => match &s.file {
            Some(file) => Ok(CrossActive::Table {
                table: read(files, file, key, f)?,
                file: file.clone(),
            }),
            None => Ok(CrossActive::None),
        },
        (Some(ActiveRaw::None), _) => Ok(CrossActive::None),
        (None, Some(v)) => Ok(CrossActive::Table {
            table: read(files, &v.table, "compensation.verifies.table", f)?,
            file: v.table.clone(),
        }),
        (None, None) => Ok(CrossActive::Unstated),
    }
}

/// The cross table of the straightness test `data` of `axis`, where the machine names a
/// controller (`None` where it names none).
pub(super) fn table(
    controller: Option<&str>,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
) -> Option<Result<CrossCompensation, String>> {
    let controller = controller?;
    (axis.raw.test == TestKind::Straightness).then(|| build(controller, axis, data, files))
}

fn build(
    controller: &str,
    axis: &AxisSpec,
    data: &AxisData,
    files: &Files,
) -> Result<CrossCompensation, String> {
    let f = format(controller)?;
    let raw = &axis.raw;
    let c = raw.compensation.as_deref().cloned().unwrap_or_default();
    let active = active(&c, files, f)?;
    // Unnamed, the campaign's names stand in, unless the active table names them.
    let held = active.table().is_some();
    let direction = raw.direction.map(|d| d.to_ascii_uppercase().to_string());
    let named = c.input.is_some() && c.output.is_some();
    let request = CrossRequest {
        input: c
            .input
            .clone()
            .or_else(|| (!held).then(|| raw.name.clone())),
        output: c.output.clone().or_else(|| direction.filter(|_| !held)),
        interval_mm: c.interval,
        line: raw.line.unwrap_or_default(),
        active,
        // The exporter writes the files again under their names in `compensation/`.
        stem: String::new(),
    };
    let mut done = compensate(f, data, &request).map_err(|e| e.to_string())?;
    if !named && !held {
        done.warnings.push(format!(
            "the axes are named as the campaign names them ({} along {}): give `compensation.input` and `output` as the controller names them",
            done.table.output, done.table.input
        ));
    }
    Ok(done)
}

/// One re-measurement's case: its place in the batch, the measurement before, and the
/// tables loaded since and active before.
struct Case {
    index: usize,
    before: AxisData,
    new: CrossTable,
    old: Option<CrossTable>,
}

/// Each straightness test that verifies a cross table compared with its prediction; the
/// machine's other straightness tests of the same axis that re-measure too are the other
/// outputs a table on the wrong axis would have moved.
pub(super) fn verify_all(tests: &mut [Tested], files: &Files) {
    let mut cases = Vec::new();
    for (index, (t, _)) in tests.iter().enumerate() {
        let Some(spec) = t.spec.as_deref() else {
            continue;
        };
        let verifies = spec
            .raw
            .compensation
            .as_ref()
            .and_then(|c| c.verifies.as_ref());
        let (Some(v), Some(_)) = (verifies, t.other()) else {
            continue;
        };
        if spec.raw.test != TestKind::Straightness {
            continue;
        }
        let case = t
            .machine
            .controller
            .as_deref()
            .ok_or_else(|| {
                "the machine names no controller: the verified table's format is not known"
                    .to_string()
            })
            .and_then(format)
            .and_then(|f| case(index, spec, v, files, f));
        cases.push((index, case));
    }
    let outputs: Vec<(usize, &Case)> = cases
        .iter()
        .filter_map(|(i, c)| Some((*i, c.as_ref().ok()?)))
        .collect();
    let mut results = Vec::new();
    for (index, case) in &cases {
        let result = case.as_ref().map_err(Clone::clone).and_then(|c| {
            let others = others(tests, &outputs, c);
            compare(tests, c, &others)
        });
        results.push((*index, result));
    }
    for (index, result) in results {
        if let Some(o) = tests[index].0.other_mut() {
            let cross = o.cross.get_or_insert_with(Box::default);
            withhold(cross, &result);
            cross.verification = Some(result);
        }
    }
}

fn case(
    index: usize,
    spec: &AxisSpec,
    v: &crate::campaign::model::VerifiesRaw,
    files: &Files,
    f: &dyn CrossFormat,
) -> Result<Case, String> {
    let path = files
        .resolve(&v.before)
        .map_err(|e| format!("compensation.verifies.before: {e}"))?;
    let before = crate::campaign::stages::read::read(spec, &path, files)
        .map_err(|e| e.to_string())?
        .data;
    let new = read(files, &v.table, "compensation.verifies.table", f)?;
    let old = match &v.active {
        Some(ActiveRaw::Stated(s)) => match &s.file {
            Some(file) => Some(read(files, file, "compensation.verifies.active", f)?),
            None => None,
        },
        _ => None,
    };
    Ok(Case {
        index,
        before,
        new,
        old,
    })
}

/// The other outputs along the same input: the same machine and axis, another letter.
fn others<'a>(
    tests: &'a [Tested],
    outputs: &[(usize, &'a Case)],
    c: &Case,
) -> Vec<OtherOutput<'a>> {
    let this = &tests[c.index].0;
    outputs
        .iter()
        .filter(|(i, _)| *i != c.index)
        .filter_map(|(i, o)| {
            let t = &tests[*i].0;
            let same = t.machine.id == this.machine.id && t.axis == this.axis;
            let after = t.other()?.data.as_ref()?;
            same.then_some(OtherOutput {
                output: &o.new.output,
                before: &o.before,
                after,
                own: Some((&o.new, o.old.as_ref())),
            })
        })
        .collect()
}

fn compare(
    tests: &[Tested],
    c: &Case,
    others: &[OtherOutput],
) -> Result<cross::verify::CrossVerification, String> {
    let t = &tests[c.index].0;
    let after = (t.other().and_then(|o| o.data.as_ref()))
        .ok_or_else(|| "the re-measurement's readings were not kept".to_string())?;
    let line = t.spec.as_ref().and_then(|s| s.raw.line).unwrap_or_default();
    verify(&c.before, after, (&c.new, c.old.as_ref()), line, others).ok_or_else(|| {
        "the measurement before and this one are not at the same targets (two or more)".into()
    })
}

/// A table built on a loaded table that the verification shows did not act as predicted
/// would be wrong too: it is not written, and the refusal says why.
fn withhold(cross: &mut CrossOutcome, result: &Result<cross::verify::CrossVerification, String>) {
    let Ok(v) = result else { return };
    let failed = matches!(
        v.verdict,
        CrossVerdict::NotEffective | CrossVerdict::MadeWorse
    );
    if failed && matches!(cross.table, Some(Ok(_))) {
        cross.table = Some(Err(format!(
            "withheld because the loaded cross table did not act as predicted ({}): a table built on it would be wrong too; correct the loading first",
            v.verdict.key()
        )));
    }
}
