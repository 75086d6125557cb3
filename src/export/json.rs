//! `results.json`: everything, and a stable interface for scripts.
//!
//! Top level: `axcheck` (version), `campaign`, `counts`, `inputs` (the version, every file
//! read with its SHA-256, the options: [`crate::inputs`]), `axes`. One entry in `axes` per
//! test of an axis (most axes have one): `machine`, `axis`, `test`, `tests`, `file`,
//! `kind`, `standard`, `unit`, `n`, `verdict` (`pass`/`fail`/`noncompliant`/`error`),
//! `parameters` (keyed as in `axcheck eval --json`), `limits`, `checks`, `rules`
//! (`{id, clause, severity, message}`), `conditions`, `nde`, and `error` with the message
//! when the verdict is `error`; a straightness or angular test (ISO 230-1) has no
//! `standard` and `parameters` but `geometry` (`test`, `symbol`, `direction` or `about`,
//! its result as `eval --test … --json` prints it, `uncertainty`, `tolerance`), and its
//! `checks` are of `straightness`, `straightness_local` or `angular`. No time stamps or absolute paths: the same campaign gives
//! the same bytes.

use super::{ExportError, Exporter, OutputFile};
use crate::campaign::{CampaignInfo, Conditions, MachineInfo};
use crate::compensate::Compensation;
use crate::compensate::cross::build::CrossCompensation;
use crate::compensate::cross::verify::CrossVerification;
use crate::compensate::json::CompensationHead;
use crate::diagnose::DiagnosisJson;
use crate::diagnose::cross::OutOfTest;
use crate::evaluate::json::{ParameterSet, ParameterValues, TargetIndices};
use crate::judge::{Check, Judgement, Verdict};
use crate::nde::NdeCorrection;
use crate::results::{AxisTest, CampaignResult};
use crate::rules::Violation;
use crate::simulate::model_text;
use crate::uncertainty::{BudgetLine, Uncertainty};
use crate::units::{AxisKind, Travel};
use serde::Serialize;
use std::collections::BTreeMap;

pub(crate) struct JsonExporter;

/// The JSON of one test.
#[derive(Serialize)]
pub(crate) struct TestJson<'a> {
    machine: &'a str,
    machine_info: &'a MachineInfo,
    axis: &'a str,
    test: usize,
    tests: usize,
    /// The number of its report when the campaign or its machine is a certificate.
    #[serde(skip_serializing_if = "Option::is_none")]
    report_number: Option<String>,
    file: Option<&'a str>,
    /// The layout the file was read as (with the sheet of a workbook) and the notes on
    /// what was assumed or skipped.
    #[serde(skip_serializing_if = "Option::is_none")]
    recognised: Option<&'a crate::measurement::Recognised>,
    kind: Option<AxisKind>,
    standard: Option<&'static str>,
    unit: Option<&'static str>,
    position_unit: Option<&'static str>,
    #[serde(flatten)]
    declared: Option<Declared<'a>>,
    #[serde(flatten)]
    measured: Option<Measured>,
    verdict: Verdict,
    #[serde(flatten)]
    evaluation: Option<Evaluated<'a>>,
    /// The positioning test carried to the tool point (`tool_point:`), or why it was not.
    #[serde(skip_serializing_if = "Option::is_none")]
    tool_point: Option<ToolPointJson<'a>>,
    /// The fit of the means on the axis's angular tests (an Abbe error read off the beam).
    #[serde(skip_serializing_if = "Option::is_none")]
    abbe: Option<&'a crate::diagnose::abbe::AbbeFit>,
    /// A straightness or angular test (ISO 230-1): which, its result, U and tolerances.
    #[serde(skip_serializing_if = "Option::is_none")]
    geometry: Option<OtherJson<'a>>,
    #[serde(flatten)]
    judgement: Option<Judged<'a>>,
    rules: &'a [Violation],
    nde: Option<&'a NdeCorrection>,
    #[serde(skip_serializing_if = "Option::is_none")]
    uncertainty: Option<UncertaintyJson<'a>>,
    /// The checks whose U is over half the limit or over the value.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    large_uncertainty: Vec<crate::judge::LargeUncertainty>,
    /// The machine's controller's table for this test and the parameters it predicts.
    #[serde(skip_serializing_if = "Option::is_none")]
    compensation: Option<CompensationJson<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    diagnosis: Option<DiagnosisJson<'a>>,
    /// This test predicted by the models of the axis's other tests (several data files).
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    out_of_test: &'a [OutOfTest],
    /// The results the tool that wrote the file printed, beside axcheck's (as `eval --json`).
    #[serde(skip_serializing_if = "Option::is_none")]
    other_tool: Option<&'a crate::crosscheck::OtherTool>,
    /// Where the test verifies a table loaded since a measurement before: that measurement
    /// judged against the same limits (the axis as found) and this test (as left).
    #[serde(skip_serializing_if = "Option::is_none")]
    as_found: Option<StateJson<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    as_left: Option<StateJson<'a>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

/// The axis as found or as left: a measurement's file, verdict, parameters, U and checks.
#[derive(Serialize)]
struct StateJson<'a> {
    file: &'a str,
    verdict: Verdict,
    parameters: ParameterValues<'a>,
    #[serde(rename = "U", skip_serializing_if = "Option::is_none")]
    expanded: Option<&'a BTreeMap<String, f64>>,
    #[serde(flatten)]
    judgement: Option<Judged<'a>>,
    rules: &'a [Violation],
    #[serde(skip_serializing_if = "Option::is_none")]
    error: Option<&'a str>,
}

impl<'a> StateJson<'a> {
    /// The as-found and as-left states of a test that verifies a table.
    fn pair(t: &'a AxisTest) -> Option<(StateJson<'a>, StateJson<'a>)> {
        let e = t.evaluated()?;
        let found = e.as_found.as_deref()?;
        let before = StateJson {
            file: &found.file,
            verdict: found.verdict,
            parameters: ParameterValues(&found.evaluation.parameters),
            expanded: found.uncertainty.as_ref().map(|u| &u.expanded),
            judgement: found.judgement.as_ref().map(Judged::new),
            rules: &found.findings,
            error: found.error.as_deref(),
        };
        let after = StateJson {
            file: t.file.as_deref().unwrap_or_default(),
            verdict: e.verdict,
            parameters: ParameterValues(&e.evaluation.parameters),
            expanded: e.uncertainty.as_ref().map(|u| &u.expanded),
            judgement: e.judgement.as_ref().map(Judged::new),
            rules: &e.findings,
            error: e.error.as_deref(),
        };
        Some((before, after))
    }
}

/// A straightness or angular test in `results.json`: the keys of `eval --test … --json`
/// (but the file's, given beside) with ISO 230-1's symbol and the tolerances as written.
#[derive(Serialize)]
struct OtherJson<'a> {
    test: crate::geometry::TestKind,
    #[serde(skip_serializing_if = "str::is_empty")]
    symbol: &'a str,
    /// A squareness's two axes, as its `axes:` names them.
    #[serde(skip_serializing_if = "Option::is_none")]
    axes: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    direction: Option<char>,
    #[serde(skip_serializing_if = "Option::is_none")]
    about: Option<char>,
    #[serde(skip_serializing_if = "Option::is_none")]
    n: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    targets_mm: Option<&'a [f64]>,
    #[serde(flatten)]
    result: &'a crate::one_file::OtherResult,
    uncertainty: &'a crate::geometry::uncertainty::Uncertain,
    tolerance: Vec<&'a str>,
    /// A squareness's straightness tests: `{symbol, file}` each.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    from: Vec<Source<'a>>,
    /// A straightness test's cross table (its first file under `compensation/`), or why
    /// none was written.
    #[serde(skip_serializing_if = "Option::is_none")]
    cross_table: Option<Done<'a, CrossCompensation>>,
    /// The comparison of this re-measurement with a loaded cross table's prediction.
    #[serde(skip_serializing_if = "Option::is_none")]
    cross_verification: Option<Done<'a, CrossVerification>>,
}

/// A result, or why there is none.
#[derive(Serialize)]
#[serde(untagged)]
enum Done<'a, T: Serialize> {
    Made {
        #[serde(skip_serializing_if = "Option::is_none")]
        file: Option<String>,
        #[serde(flatten)]
        value: &'a T,
    },
    Refused {
        refused: &'a str,
    },
}

impl<'a, T: Serialize> Done<'a, T> {
    fn new(result: &'a Result<T, String>) -> Done<'a, T> {
        match result {
            Ok(value) => Done::Made { file: None, value },
            Err(refused) => Done::Refused { refused },
        }
    }
}

#[derive(Serialize)]
struct Source<'a> {
    symbol: &'a str,
    file: &'a str,
}

impl<'a> OtherJson<'a> {
    fn new(t: &'a AxisTest) -> Option<OtherJson<'a>> {
        let o = t.other()?;
        let raw = t.spec.as_ref().map(|s| &s.raw);
        Some(OtherJson {
            test: o.test,
            symbol: &o.symbol,
            axes: raw.is_none().then_some(t.axis.as_str()),
            direction: raw
                .and_then(|r| r.direction)
                .map(|c| c.to_ascii_uppercase()),
            about: raw.and_then(|r| r.about).map(|c| c.to_ascii_uppercase()),
            n: o.data.as_ref().map(|d| d.runs()),
            targets_mm: o.data.as_ref().map(|d| d.targets.as_slice()),
            result: &o.result,
            uncertainty: &o.uncertainty,
            tolerance: o.tolerance.iter().map(String::as_str).collect(),
            from: (o.sources.iter())
                .map(|(symbol, file)| Source { symbol, file })
                .collect(),
            cross_table: (o.cross.as_deref())
                .and_then(|c| c.table.as_ref())
                .map(Done::new),
            cross_verification: (o.cross.as_deref())
                .and_then(|c| c.verification.as_ref())
                .map(Done::new),
        })
    }
}

/// A positioning test at the tool point: the offsets from the beam (mm, by axis letter),
/// the angular tests it was carried through, its parameters, checks and verdict there.
#[derive(Serialize)]
#[serde(untagged)]
enum ToolPointJson<'a> {
    Carried {
        offsets_mm: BTreeMap<String, f64>,
        rotations: &'a [String],
        parameters: ParameterValues<'a>,
        checks: &'a [Check],
        verdict: Verdict,
        notes: &'a [String],
    },
    Failed {
        error: &'a str,
    },
}

impl<'a> ToolPointJson<'a> {
    fn new(t: &'a AxisTest) -> Option<ToolPointJson<'a>> {
        let carried = t.evaluated()?.tool_point.as_deref()?;
        Some(match carried {
            Ok(p) => ToolPointJson::Carried {
                offsets_mm: (p.offsets_mm.iter())
                    .map(|(c, mm)| (c.to_ascii_lowercase().to_string(), *mm))
                    .collect(),
                rotations: &p.rotations,
                parameters: ParameterValues(&p.evaluation.parameters),
                checks: p.judgement.as_ref().map_or(&[][..], |j| &j.checks),
                verdict: p.verdict,
                notes: &p.notes,
            },
            Err(error) => ToolPointJson::Failed { error },
        })
    }
}

/// What the campaign declares of the axis.
#[derive(Serialize)]
struct Declared<'a> {
    travel: Option<Travel>,
    declared_measurement_travel: Option<[f64; 2]>,
    conditions: &'a Conditions,
}

/// What the measurement file holds.
#[derive(Serialize)]
struct Measured {
    measurement_travel: [f64; 2],
    readings: usize,
}

#[derive(Serialize)]
struct Evaluated<'a> {
    n: usize,
    m: usize,
    parameters: ParameterValues<'a>,
    at_target: TargetIndices<'a>,
    notes: &'a [String],
    /// The ISO 230-2 7.1 test conditions stated neither by the campaign nor by the file.
    #[serde(skip_serializing_if = "<[_]>::is_empty")]
    conditions_not_stated: &'a [&'static str],
}

#[derive(Serialize)]
struct Judged<'a> {
    spec: Option<&'a str>,
    limits: BTreeMap<&'a str, f64>,
    checks: &'a [Check],
    failed: Vec<&'a str>,
    /// The checks within their uncertainty zone (ISO 14253-1).
    inconclusive: Vec<&'a str>,
    /// The decision rule that decided: `simple` or `iso14253-1`.
    decision_rule: &'static str,
    not_applicable_limits: &'a [String],
    no_tolerance: bool,
    /// An example spec's limit applies (`example: true`): not from a standard.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    example_limits: bool,
}

impl<'a> Judged<'a> {
    fn new(j: &'a Judgement) -> Judged<'a> {
        Judged {
            spec: j.limits.spec.as_deref(),
            limits: j
                .limits
                .values
                .iter()
                .map(|(k, (v, _))| (k.as_str(), *v))
                .collect(),
            checks: &j.checks,
            failed: j.failed().map(|c| c.key.as_str()).collect(),
            inconclusive: j.inconclusive().map(|c| c.key.as_str()).collect(),
            decision_rule: j.rule.key(),
            not_applicable_limits: &j.not_applicable,
            no_tolerance: j.limits.is_empty(),
            example_limits: j.limits.example,
        }
    }
}

/// A test's measurement uncertainty: U (k = 2) per parameter and the budget over the full
/// measurement travel, one line per contributor.
#[derive(Serialize)]
struct UncertaintyJson<'a> {
    k: f64,
    /// Deviation unit of U and of the budget: `um` or `arcsec`.
    unit: &'static str,
    #[serde(rename = "U")]
    expanded: &'a BTreeMap<String, f64>,
    /// The length the budget is for (the measurement travel), mm or deg.
    budget_length: f64,
    /// Combined standard uncertainty of the budget, deviation unit.
    budget_u_c: f64,
    budget: &'a [BudgetLine],
    notes: &'a [String],
}

impl<'a> UncertaintyJson<'a> {
    fn new(u: &'a Uncertainty) -> UncertaintyJson<'a> {
        UncertaintyJson {
            k: u.k,
            unit: u.unit,
            expanded: &u.expanded,
            budget_length: u.budget.length,
            budget_u_c: u.budget.combined,
            budget: &u.budget.lines,
            notes: &u.notes,
        }
    }
}

/// A test's compensation: the controller, whether the table builds on the active one, the
/// table file written (relative to the output folder) or why the controller refused it,
/// the parameters predicted with it, and the verification of a re-measurement.
#[derive(Serialize)]
struct CompensationJson<'a> {
    #[serde(flatten)]
    head: CompensationHead<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    refused: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    predicted: Option<ParameterSet<'a>>,
    /// What the active state leaves unsure (`active_compensation_unknown`, …) and why the
    /// table may not achieve the prediction (drift, aliasing, n = 1, outliers).
    warnings: &'a [crate::compensate::Warning],
    /// This test as the re-measurement of the table it verifies.
    #[serde(skip_serializing_if = "Option::is_none")]
    verification: Option<VerificationOutcome<'a>>,
}

/// A verification, or why it could not be made.
#[derive(Serialize)]
#[serde(untagged)]
enum VerificationOutcome<'a> {
    Done(crate::verify::VerificationJson<'a>),
    Failed { error: String },
}

impl<'a> CompensationJson<'a> {
    fn new(
        t: &'a AxisTest,
        c: &'a Compensation,
        file: Option<&std::path::Path>,
    ) -> CompensationJson<'a> {
        CompensationJson {
            head: CompensationHead::of(c),
            file: file.map(|p| p.to_string_lossy().replace('\\', "/")),
            refused: c.outcome.as_ref().err().map(ToString::to_string),
            predicted: c
                .outcome
                .as_ref()
                .ok()
                .map(|c| ParameterSet::of(&c.predicted)),
            warnings: &c.warnings,
            verification: t
                .evaluated()
                .and_then(|e| e.verification.as_deref())
                .map(|v| match v {
                    Ok(v) => VerificationOutcome::Done(v.json()),
                    Err(e) => VerificationOutcome::Failed {
                        error: e.to_string(),
                    },
                }),
        }
    }
}

/// The JSON view of one test.
pub(crate) fn test_json(t: &AxisTest) -> TestJson<'_> {
    let ev = t.evaluated();
    let (as_found, as_left) = StateJson::pair(t).unzip();
    TestJson {
        machine: &t.machine.id,
        machine_info: &t.machine,
        axis: &t.axis,
        test: t.test,
        tests: t.tests,
        report_number: None,
        file: t.file.as_deref(),
        recognised: t.recognised(),
        kind: t.kind(),
        standard: t.positioning_standard().map(|s| s.key()),
        unit: t.deviation_unit(),
        position_unit: t.kind().map(|k| k.position_unit()),
        declared: t.spec.as_ref().map(|spec| Declared {
            travel: spec.raw.travel,
            declared_measurement_travel: spec.raw.measurement_travel,
            conditions: &spec.raw.conditions,
        }),
        measured: (ev.and_then(|e| e.data.as_ref()))
            .or_else(|| t.other().and_then(|o| o.data.as_ref()))
            .map(|d| {
                let (a, b) = d.measurement_travel();
                Measured {
                    measurement_travel: [a, b],
                    readings: d.readings.len(),
                }
            }),
        verdict: t.verdict(),
        evaluation: ev.map(|ev| Evaluated {
            n: ev.evaluation.n,
            m: ev.evaluation.targets.len(),
            parameters: ParameterValues(&ev.evaluation.parameters),
            at_target: TargetIndices(&ev.evaluation.parameters),
            notes: &ev.evaluation.notes,
            conditions_not_stated: &ev.unstated,
        }),
        geometry: OtherJson::new(t),
        abbe: t.evaluated().and_then(|e| e.abbe.as_deref()),
        tool_point: ToolPointJson::new(t),
        judgement: t.judgement().map(Judged::new),
        rules: t.findings(),
        nde: ev.and_then(|e| e.nde.as_ref()),
        uncertainty: ev
            .and_then(|e| e.uncertainty.as_ref())
            .map(UncertaintyJson::new),
        large_uncertainty: t.large_uncertainty(),
        compensation: None,
        diagnosis: (ev.and_then(|e| e.diagnosis.as_deref())).map(|d| d.json(model_text)),
        out_of_test: ev.map_or(&[][..], |e| &e.out_of_test),
        other_tool: ev.and_then(|e| e.other_tool.as_deref()),
        as_found,
        as_left,
        error: t.error(),
    }
}

/// Everything of `results.json` but the axes (`"axes": []`, last).
#[derive(Serialize)]
struct Head<'a> {
    axcheck: &'static str,
    campaign: CampaignJson<'a>,
    counts: BTreeMap<Verdict, usize>,
    /// What the run read (each file's SHA-256) and how it was run (added in issue 47).
    inputs: &'a crate::inputs::Inputs,
    axes: [(); 0],
}

/// The campaign block as written, with its file name and the standard it resolves to
/// (in place of the one written, or after the file name when none was).
#[derive(Serialize)]
struct CampaignJson<'a> {
    #[serde(flatten)]
    info: CampaignInfo,
    file: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    standard: Option<&'static str>,
}

fn results_head(result: &CampaignResult) -> Head<'_> {
    let standard = result.standard.key();
    Head {
        axcheck: env!("CARGO_PKG_VERSION"),
        campaign: CampaignJson {
            info: CampaignInfo {
                standard: result.info.standard.as_ref().map(|_| standard.to_string()),
                ..result.info.clone()
            },
            file: &result.file_name,
            standard: result.info.standard.is_none().then_some(standard),
        },
        counts: result.counts(),
        inputs: &result.inputs,
        axes: [],
    }
}

/// `json` with the hidden characters serde_json writes raw (DEL, C1, bidirectional
/// controls) as JSON escapes: the same strings, which no terminal or viewer acts on.
fn shown(json: Vec<u8>) -> Vec<u8> {
    match String::from_utf8(json) {
        Ok(text) => match crate::safe_text::visible(&text) {
            std::borrow::Cow::Owned(shown) => shown.into_bytes(),
            std::borrow::Cow::Borrowed(_) => text.into_bytes(),
        },
        Err(e) => e.into_bytes(),
    }
}

/// Axes serialised at once (in parallel) before they are written: bounds the memory of a
/// plant's `results.json` (58 kB an axis with its diagnosis) to a few megabytes.
const AXES_PER_CHUNK: usize = 256;

/// `results.json`, pretty-printed, into `out`: the axes are serialised in parallel chunks
/// (1 000 axes are 48 MB, 0.8 s of one core) and set into the head as `to_vec_pretty` would
/// place them.
pub(crate) fn write_results_json(
    result: &CampaignResult,
    out: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    use rayon::prelude::*;
    let head = shown(serde_json::to_vec_pretty(&results_head(result))?);
    let empty = b"\"axes\": []\n}";
    if result.tests.is_empty() || !head.ends_with(empty) {
        out.write_all(&head)?;
        return out.write_all(b"\n");
    }
    out.write_all(&head[..head.len() - b"[]\n}".len()])?;
    out.write_all(b"[\n")?;
    let tables = super::compensation::table_paths(result);
    // One table path per test; zipped, as the elements written.
    let count = result.tests.len().min(tables.len());
    for (chunk, (tests, tables)) in (result.tests.chunks(AXES_PER_CHUNK))
        .zip(tables.chunks(AXES_PER_CHUNK))
        .enumerate()
    {
        let axes: Vec<Vec<u8>> = (tests.par_iter().zip(tables))
            .map(|(t, table)| axis_json(result, t, table.as_deref()))
            .collect::<Result<_, _>>()?;
        for (i, axis) in axes.iter().enumerate() {
            // An element of the top-level object's array: four spaces deeper than standalone.
            for line in axis.split_inclusive(|&b| b == b'\n') {
                out.write_all(b"    ")?;
                out.write_all(line)?;
            }
            let last = chunk * AXES_PER_CHUNK + i + 1 == count;
            out.write_all(if last { b"\n" } else { b",\n" })?;
        }
    }
    out.write_all(b"  ]\n}\n")
}

/// One test's JSON, standalone and pretty-printed.
fn axis_json(
    result: &CampaignResult,
    t: &AxisTest,
    table: Option<&std::path::Path>,
) -> serde_json::Result<Vec<u8>> {
    let mut json = test_json(t);
    json.report_number = result.report_number(t);
    let cross = (json.geometry.as_mut()).and_then(|g| g.cross_table.as_mut());
    if let (Some(Done::Made { file, .. }), Some(path)) = (cross, table) {
        *file = Some(path.to_string_lossy().replace('\\', "/"));
    }
    json.compensation = t
        .evaluated()
        .and_then(|e| e.compensation.as_deref())
        .map(|c| CompensationJson::new(t, c, table));
    serde_json::to_vec_pretty(&json).map(shown)
}

impl Exporter for JsonExporter {
    fn name(&self) -> &'static str {
        "json"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        Ok(vec![OutputFile {
            path: "results.json".into(),
            body: super::Body::Streamed(Box::new(move |out| write_results_json(result, out))),
        }])
    }
}
