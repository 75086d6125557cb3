//! The data of one axis test report (ISO 230-2 clause 7): header facts, verdict, the
//! parameters with their limits, the per-target table of Table 2, the test-plan findings
//! and the diagnosis.

use super::compensation::{CompensationSection, compensation_section};
use super::conditions::{Row, SensorRow, condition_rows, sensor_rows};
use super::uncertainty::{UncertaintySection, uncertainty_section};
use super::{AXIS_NAME, CampaignHeader, generator, num, opt, pos, s_symbol, short_name, symbol_of};
use crate::data::diagnosis::{DiagnosisSection, diagnosis_section};
use crate::evaluate::{DirectionResult, Evaluation, StandardId};
use crate::judge::{Conformance, Verdict};
use crate::measurement::FileInfo;
use crate::results::{AxisTest, CampaignResult};
use crate::rules::Violation;
use crate::units::{Travel, fmt_position};
use crate::words::Words;
use serde::Serialize;

/// Everything `axis-report.typ` shows.
#[derive(Serialize)]
pub struct AxisReport<'a> {
    campaign: CampaignHeader<'a>,
    /// The campaign's name for headings and footers ([`super::campaign_short`]).
    campaign_short: String,
    title: String,
    facts: Vec<Row>,
    /// Names the facts shorten, in full.
    full_names: Vec<Row>,
    verdict: VerdictText,
    unit: String,
    conditions: Vec<Row>,
    sensors: Vec<SensorRow<'a>>,
    parameters: Vec<ParameterRow>,
    coverage: String,
    s_symbol: &'static str,
    n: usize,
    targets: Vec<TargetRow>,
    notes: &'a [String],
    findings: &'a [Violation],
    has_charts: bool,
    diagnosis: Option<DiagnosisSection<'a>>,
    uncertainty: Option<UncertaintySection<'a>>,
    /// The table of the machine's controller (only when the machine names one).
    compensation: Option<CompensationSection<'a>>,
    /// The axis over the inspection history (only when the run keeps one).
    history: Option<super::trends::HistorySection>,
    /// The results the tool that wrote the file printed, beside axcheck's.
    other_tool: Option<super::other_tool::OtherToolSection<'a>>,
    /// The test carried to the tool point (`tool_point:`).
    tool_point: Option<super::tool_point::ToolPointSection<'a>>,
    /// The certificate block (`campaign.certificate`), absent for a plain test report.
    certificate: Option<super::certificate::CertificateSection<'a>>,
    /// The axis as found and as left, where the test verifies a table.
    as_found: Option<super::as_found::AsFoundSection<'a>>,
    generator: String,
}

impl AxisReport<'_> {
    /// The report with the axis's history section.
    pub fn with_history(mut self, history: super::trends::HistorySection) -> Self {
        self.history = Some(history);
        self
    }
}

/// The data of one axis report, in `words`' language (numbers too: build it inside
/// [`Words::scope`]).
pub fn axis_report<'a>(
    result: &'a CampaignResult,
    t: &'a AxisTest,
    words: &Words,
) -> AxisReport<'a> {
    let kind = t.kind();
    let ev = t.evaluated();
    let e = ev.map(|e| &e.evaluation);
    let conditions = t.spec.as_ref().map(|s| &*s.raw.conditions);
    AxisReport {
        campaign: CampaignHeader::new(result),
        campaign_short: super::campaign_short(result),
        // Shortened: the facts below print the names whole.
        title: words.args(
            "axis-title",
            &[
                ("machine", &short_name(&t.machine.id, super::SHORT_NAME)),
                ("axis", &short_name(&t.axis, AXIS_NAME)),
            ],
        ),
        facts: facts(result, t, words),
        full_names: full_names(t, words),
        verdict: VerdictText::new(t, words),
        unit: kind.map_or(String::new(), |k| words.unit(k.deviation_symbol())),
        conditions: match (conditions, kind) {
            (Some(c), Some(k)) => condition_rows(c, k, t, words),
            _ => Vec::new(),
        },
        sensors: conditions.map_or(Vec::new(), sensor_rows),
        parameters: e.map_or(Vec::new(), |e| parameter_rows(t, e, words)),
        coverage: e.map_or(String::new(), |e| fmt_position(e.coverage_factor)),
        s_symbol: s_symbol(t.standard()),
        n: e.map_or(0, |e| e.n),
        targets: e.map_or(Vec::new(), target_rows),
        notes: e.map_or(&[], |e| &e.notes),
        findings: t.findings(),
        has_charts: e.is_some(),
        diagnosis: ev.and_then(|e| e.diagnosis.as_deref()).map(|d| {
            let out_of_test = ev.map_or(&[][..], |e| &e.out_of_test);
            diagnosis_section(d, out_of_test, |key| symbol_of(t, key))
        }),
        uncertainty: ev
            .and_then(|e| e.uncertainty.as_ref())
            .zip(kind)
            .map(|(u, k)| uncertainty_section(t, u, k.deviation_symbol(), k.position_unit())),
        compensation: ev
            .and_then(|e| e.compensation.as_deref())
            .zip(e)
            .map(|(c, e)| compensation_section(c, e, ev.and_then(|e| e.verification.as_deref()))),
        history: None,
        other_tool: ev
            .and_then(|e| e.other_tool.as_deref())
            .map(super::other_tool::other_tool_section),
        tool_point: super::tool_point::tool_point_section(t),
        certificate: super::certificate::certificate_section(
            result,
            &[t],
            result.report_number(t),
            words,
        ),
        as_found: super::as_found::as_found_section(t, words),
        generator: generator(),
    }
}

/// A name in the two-column facts: whole when short, else shortened with a pointer to
/// [`full_names`] (a 10 000-character name in a half-width column filled nine pages).
fn in_facts(name: &str, max: usize, words: &Words) -> String {
    if name.chars().count() <= max {
        name.to_string()
    } else {
        words.args("in-full-below", &[("name", &short_name(name, max))])
    }
}

/// The machine's and the axis's names in full, across the text width, where the facts
/// shorten them: each printed whole once.
fn full_names(t: &AxisTest, words: &Words) -> Vec<Row> {
    Row::labelled(
        words,
        [
            (
                "fact-machine-in-full",
                (t.machine.id.chars().count() > super::SHORT_NAME).then(|| t.machine.id.clone()),
            ),
            (
                "fact-axis-in-full",
                (t.axis.chars().count() > AXIS_NAME).then(|| t.axis.clone()),
            ),
        ],
    )
}

/// The header facts: machine, axis, travels, file, standard, spec, date and inspector.
fn facts(result: &CampaignResult, t: &AxisTest, words: &Words) -> Vec<Row> {
    let m = &t.machine;
    let kind = t.kind();
    let travel = t
        .spec
        .as_ref()
        .and_then(|s| s.raw.travel)
        .zip(kind)
        .map(|(tr, k)| match tr {
            Travel::Length(l) => pos(k, l),
            Travel::Range([a, b]) => format!("{} … {}", pos(k, a), pos(k, b)),
        });
    let measured = t.evaluated().and_then(|e| e.data.as_ref()).map(|d| {
        let (a, b) = d.measurement_travel();
        format!("{} … {}", pos(d.kind, a), pos(d.kind, b))
    });
    let axis = format!(
        "{}{}",
        in_facts(&t.axis, AXIS_NAME, words),
        kind.map_or(String::new(), |k| format!(
            " ({})",
            words.get(&format!("axis-kind-{k}"))
        ))
    );
    let test = (t.tests > 1).then(|| {
        let (test, tests) = (t.test.to_string(), t.tests.to_string());
        words.args("fact-test-of", &[("test", &test), ("tests", &tests)])
    });
    // What the file says of itself fills what the campaign leaves out, marked as such.
    let info = t.recognised().and_then(|r| r.info.as_ref());
    let file = |f: fn(&FileInfo) -> &Option<String>| {
        info.and_then(|i| f(i).as_ref())
            .map(|v| words.args("from-measurement-file", &[("value", v)]))
    };
    let differs = |f: fn(&FileInfo) -> &Option<String>, campaign: &str| {
        info.and_then(|i| f(i).clone())
            .filter(|v| v.trim() != campaign)
    };
    Row::labelled(
        words,
        [
            (
                "fact-machine",
                Some(in_facts(&m.id, super::SHORT_NAME, words)),
            ),
            ("fact-machine-in-file", differs(|i| &i.machine, &m.id)),
            ("fact-model", m.model.clone()),
            (
                "fact-serial",
                m.serial.clone().or_else(|| file(|i| &i.serial)),
            ),
            ("fact-type", m.machine_type.clone()),
            (
                "fact-location",
                m.location.clone().or_else(|| file(|i| &i.location)),
            ),
            ("fact-axis", Some(axis)),
            ("fact-axis-in-file", differs(|i| &i.axis, &t.axis)),
            ("fact-axis-travel", travel),
            ("fact-measurement-travel", measured),
            ("fact-measurement-file", t.file.clone()),
            (
                "fact-file-sha",
                super::inputs::short_sha256(&result.inputs, t.file.as_deref()),
            ),
            ("fact-test", test),
            ("fact-standard", t.standard().map(|s| words.standard(s))),
            (
                "fact-spec",
                t.judgement().map(|j| spec_words(&j.limits, words)),
            ),
            (
                "fact-date",
                (result.info.date.clone())
                    .or_else(|| file(|i| &i.date))
                    .map(|d| words.date(&d)),
            ),
            (
                "fact-inspector",
                result
                    .info
                    .inspector
                    .clone()
                    .or_else(|| file(|i| &i.operator)),
            ),
        ],
    )
}

/// What the test was judged by, as [`crate::judge::Limits::describe_labelled`] says it,
/// in `words`' language (the spec's own name and range as the spec file writes them).
pub(super) fn spec_words(limits: &crate::judge::Limits, words: &Words) -> String {
    use crate::judge::LimitSource;
    let axis = limits.values.values().any(|(_, s)| *s == LimitSource::Axis);
    let what = match (&limits.spec, limits.is_empty()) {
        (_, true) => words.get("spec-no-tolerance"),
        (Some(spec), false) if axis => words.args("spec-plus-axis", &[("spec", spec)]),
        (Some(spec), false) => spec.clone(),
        (None, false) => words.get("spec-axis-tolerances"),
    };
    match limits.example {
        true => words.args("spec-example", &[("spec", &what)]),
        false => what,
    }
}

/// `M = 0.57 ± 0.80 µm against its limit 10.00 µm: U over the value` in `words`' language
/// ([`crate::judge::LargeUncertainty::text`]).
fn large_uncertainty(t: &AxisTest, l: &crate::judge::LargeUncertainty, words: &Words) -> String {
    let why = match (l.over_half_limit(), l.over_value) {
        (true, true) => "large-u-why-both",
        (true, false) => "large-u-why-half",
        _ => "large-u-why-value",
    };
    words.args(
        "large-u",
        &[
            ("symbol", &symbol_of(t, l.key)),
            ("value", &num(l.value.abs())),
            ("u", &num(l.expanded)),
            ("limit", &num(l.limit)),
            ("unit", &words.unit(t.deviation_symbol())),
            ("why", &words.get(why)),
        ],
    )
}

/// The verdict in words.
#[derive(Serialize)]
pub(super) struct VerdictText {
    key: Verdict,
    word: String,
    detail: String,
}

impl VerdictText {
    pub(super) fn new(t: &AxisTest, words: &Words) -> VerdictText {
        let detail = match t.verdict() {
            Verdict::NotJudged => words.get("verdict-detail-not-judged"),
            Verdict::Pass => match t.judgement().map_or(0, |j| j.checks.len()) {
                1 => words.get("verdict-detail-pass-one"),
                n => words.args("verdict-detail-pass-all", &[("count", &n.to_string())]),
            },
            Verdict::Fail => {
                let failed: Vec<String> = (t.judgement().into_iter())
                    .flat_map(|j| j.failed())
                    .map(|c| symbol_of(t, c.key))
                    .collect();
                words.args("verdict-detail-fail", &[("symbols", &failed.join(", "))])
            }
            Verdict::Noncompliant => {
                let rules: Vec<&str> = t.broken_rules().map(|f| f.id).collect();
                words.args(
                    "verdict-detail-noncompliant",
                    &[("rules", &rules.join(", "))],
                )
            }
            Verdict::Error => t.error().unwrap_or_default().to_string(),
            Verdict::Inconclusive => {
                let unit = t.deviation_symbol();
                let zone: Vec<String> = (t.inconclusive())
                    .map(|c| {
                        words.args(
                            "verdict-zone",
                            &[
                                ("symbol", &symbol_of(t, c.key)),
                                ("value", &num(c.value)),
                                ("u", &num(c.expanded_uncertainty.unwrap_or(0.0))),
                                ("limit", &num(c.limit)),
                                ("unit", unit),
                            ],
                        )
                    })
                    .collect();
                words.args("verdict-detail-inconclusive", &[("zone", &zone.join("; "))])
            }
        };
        let large: Vec<String> = (t.large_uncertainty().iter())
            .map(|l| large_uncertainty(t, l, words))
            .collect();
        let detail = match large.is_empty() {
            true => detail,
            false => words.args(
                "verdict-large-uncertainty",
                &[("detail", &detail), ("list", &large.join("; "))],
            ),
        };
        VerdictText {
            key: t.verdict(),
            word: words.verdict(t.verdict().name()),
            detail,
        }
    }
}

/// A line of the results table.
#[derive(Serialize)]
struct ParameterRow {
    symbol: &'static str,
    name: String,
    clause: String,
    value: String,
    /// The expanded uncertainty U (k = 2) of the value, `±0.87`, or `–`.
    u: String,
    limit: String,
    margin: String,
    status: &'static str,
    at: String,
}

/// The parameters of the standard with value, limit, margin and status, then the
/// standard's parameters that do not apply with n = 1 (ISO 230-2 clause 5.2).
fn parameter_rows(t: &AxisTest, e: &Evaluation, words: &Words) -> Vec<ParameterRow> {
    let mut rows: Vec<ParameterRow> = e
        .parameters
        .iter()
        .map(|p| {
            let check = t
                .judgement()
                .and_then(|j| j.checks.iter().find(|c| c.key == p.def.key));
            let at = if let Some(i) = p.at_target {
                let position = pos(e.kind, e.targets[i].position);
                words.args(
                    "at-target",
                    &[("i", &(i + 1).to_string()), ("position", &position)],
                )
            } else if let Some((hi, lo)) = p.span {
                format!("{} − ({})", num(hi), num(lo))
            } else {
                String::new()
            };
            ParameterRow {
                symbol: p.symbol(),
                name: words.parameter(e.standard, p.def.key, p.name()),
                clause: p
                    .clause()
                    .replace(" (GB/T 17421.2 amendment No. 1)", ", amd. 1"),
                value: num(p.value),
                u: t.evaluated()
                    .and_then(|e| e.uncertainty.as_ref())
                    .and_then(|u| u.expanded_of(p.def.key))
                    .map_or("–".into(), |u| format!("±{}", num(u))),
                limit: check.map_or("–".into(), |c| num(c.limit)),
                margin: check.map_or("–".into(), |c| num(c.margin)),
                status: check.map_or("", |c| match c.outcome {
                    Conformance::Pass => "pass",
                    Conformance::Fail => "fail",
                    Conformance::Inconclusive => "inconclusive",
                }),
                at,
            }
        })
        .collect();
    rows.extend(e.not_applicable().map(|def| ParameterRow {
        symbol: def.symbol,
        name: words.parameter(e.standard, def.key, def.name),
        clause: match e.standard {
            StandardId::Iso230_2 | StandardId::Gbt17421_2 => "ISO 230-2 5.2".to_string(),
            _ => def.clause.to_string(),
        },
        value: words.get("not-applicable"),
        u: "–".into(),
        limit: "–".into(),
        margin: "–".into(),
        status: "n/a",
        at: format!("n = {}", e.n),
    }));
    rows
}

/// A column of the per-target table (ISO 230-2 Table 2).
#[derive(Serialize)]
struct TargetRow {
    i: String,
    position: String,
    up: DirectionColumn,
    down: DirectionColumn,
    b: String,
    r: String,
    mean: String,
}

/// One direction's readings and statistics at a target.
#[derive(Serialize)]
struct DirectionColumn {
    x: Vec<String>,
    mean: String,
    s: String,
    ks: String,
    upper: String,
    lower: String,
    r: String,
}

impl DirectionColumn {
    fn new(d: &DirectionResult, k: f64) -> DirectionColumn {
        DirectionColumn {
            x: d.deviations.iter().map(|&x| num(x)).collect(),
            mean: num(d.mean),
            s: opt(d.s),
            ks: opt(d.s.map(|s| k * s)),
            upper: opt(d.upper),
            lower: opt(d.lower),
            r: opt(d.repeatability),
        }
    }
}

fn target_rows(e: &Evaluation) -> Vec<TargetRow> {
    let k = e.coverage_factor;
    e.targets
        .iter()
        .enumerate()
        .map(|(i, t)| TargetRow {
            i: (i + 1).to_string(),
            position: super::local(&fmt_position(t.position).replace('-', "−")),
            up: DirectionColumn::new(&t.up, k),
            down: DirectionColumn::new(&t.down, k),
            b: num(t.reversal),
            r: opt(t.repeatability),
            mean: num(t.mean),
        })
        .collect()
}
