//! What the page shows of one axis test when its row is opened: its parameters with U and
//! limits (ISO 230-2 clause 2, judged as in the axis report), the plan rules' and the
//! diagnosis's findings with their advice, the compensation and its verification, links to
//! its report and table, and its charts (ISO 230-2 Fig. 2a and 2b, and its history).

use crate::evaluate::ParamKey;
use crate::history::AxisTrends;
use crate::judge::Conformance;
use crate::results::AxisTest;
use crate::units::fmt_fixed;
use axcheck_charts::chart_kit::scene::Scene;
use axcheck_charts::words::Words;
use serde::Serialize;

#[derive(Debug, Serialize)]
pub struct Detail<'a> {
    pub id: String,
    pub label: String,
    pub file: Option<&'a str>,
    pub standard: Option<&'static str>,
    /// The spec and band the limits come from, or that no tolerance applied.
    pub limits: Option<String>,
    pub unit: Option<String>,
    pub parameters: Vec<ParameterRow>,
    /// Parameters without a value here (those needing repeated runs, with n = 1).
    pub not_applicable: Vec<&'static str>,
    pub rules: &'a [crate::rules::Violation],
    pub diagnosis: Vec<DiagnosisFinding>,
    pub compensation: Option<CompensationDetail>,
    /// The verification of the table this test re-measures, in one line.
    pub verification: Option<String>,
    /// Relative links: the axis report (when PDFs are written) and the table.
    pub report: Option<String>,
    pub table: Option<String>,
    pub charts: Vec<Chart>,
    pub error: Option<&'a str>,
}

/// One parameter: symbol, name and clause, value, U (k = 2), its limit and the outcome of
/// its check (`pass`, `fail`, `inconclusive`) when it has one.
#[derive(Debug, Serialize)]
pub struct ParameterRow {
    pub symbol: &'static str,
    pub name: String,
    pub clause: &'static str,
    pub value: String,
    #[serde(rename = "U")]
    pub u: Option<String>,
    pub limit: Option<String>,
    pub outcome: Option<Conformance>,
}

#[derive(Debug, Serialize)]
pub(crate) struct DiagnosisFinding {
    pub effect: &'static str,
    pub message: String,
    pub advice: String,
}

#[derive(Debug, Serialize)]
pub(crate) struct CompensationDetail {
    pub controller: &'static str,
    /// `absolute` or `incremental`.
    pub mode: crate::compensate::Mode,
    pub active_file: Option<String>,
    /// Why no table was written.
    pub refused: Option<String>,
    pub warnings: Vec<String>,
}

/// A titled chart. Its scene goes into the block's scenes ([`super::scene::SceneBlock`]),
/// in the order of the block's tests and their charts.
#[derive(Debug, Serialize)]
pub struct Chart {
    /// `iso` (ISO 230-2 Fig. 2a, 2b) or `history`.
    pub group: &'static str,
    pub title: String,
    #[serde(skip)]
    pub scene: Scene,
}

/// Where the test's own files are, relative to the page.
pub struct Links {
    pub report: Option<String>,
    pub table: Option<String>,
}

pub fn detail<'a>(
    t: &'a AxisTest,
    trends: Option<&AxisTrends>,
    links: Links,
    words: &Words,
) -> Detail<'a> {
    let ev = t.evaluated();
    let unit = Some(t.deviation_symbol())
        .filter(|u| !u.is_empty())
        .map(|u| words.unit(u));
    Detail {
        id: super::super::overview::test_id(t),
        label: t.label(),
        file: t.file.as_deref(),
        standard: t.positioning_standard().map(|s| s.title()),
        limits: t.judgement().map(|j| j.limits.describe_labelled()),
        unit,
        parameters: parameters(t, words),
        not_applicable: (ev.map(|e| &e.evaluation).into_iter())
            .flat_map(|e| e.not_applicable().map(|d| d.symbol))
            .collect(),
        rules: t.findings(),
        diagnosis: (ev.and_then(|e| e.diagnosis.as_deref()).into_iter())
            .flat_map(|d| &d.findings)
            .map(|f| DiagnosisFinding {
                effect: f.effect().name(),
                message: f.message.clone(),
                advice: f.advice(),
            })
            .collect(),
        compensation: ev
            .and_then(|e| e.compensation.as_deref())
            .map(|c| CompensationDetail {
                controller: c.controller,
                mode: c.mode,
                active_file: c.active_file.clone(),
                refused: c.outcome.as_ref().err().map(ToString::to_string),
                warnings: c.warnings.iter().map(|w| w.message.clone()).collect(),
            }),
        verification: ev.and_then(|e| e.verification.as_deref()).map(|v| match v {
            Ok(v) => v.summary(t.deviation_symbol()),
            Err(e) => format!("not made: {e}"),
        }),
        report: links.report,
        table: links.table,
        charts: charts(t, trends, words),
        error: t.error(),
    }
}

fn parameters(t: &AxisTest, words: &Words) -> Vec<ParameterRow> {
    if let Some(o) = t.other() {
        return other_values(o);
    }
    let Some(e) = t.evaluated().map(|e| &e.evaluation) else {
        return Vec::new();
    };
    let check =
        |key: ParamKey| (t.judgement()).and_then(|j| j.checks.iter().find(|c| c.key == key));
    let u_of = |key: ParamKey| {
        t.evaluated()
            .and_then(|e| e.uncertainty.as_ref())
            .and_then(|u| u.expanded_of(key))
    };
    (e.parameters.iter())
        .map(|p| ParameterRow {
            symbol: p.symbol(),
            name: words.parameter(e.standard, p.def.key, p.name()),
            clause: p.clause(),
            value: words.number(&fmt_fixed(p.value, 2)),
            u: u_of(p.def.key).map(|u| words.number(&fmt_fixed(u, 2))),
            limit: check(p.def.key).map(|c| words.number(&fmt_fixed(c.limit, 2))),
            outcome: check(p.def.key).map(|c| c.outcome),
        })
        .collect()
}

/// A straightness or angular test's values, with U and their checks.
fn other_values(o: &crate::results::OtherTested) -> Vec<ParameterRow> {
    (o.values())
        .map(|(key, value, check)| ParameterRow {
            symbol: key.as_str(),
            name: crate::results::OtherTested::name(key).to_string(),
            clause: "ISO 230-1",
            value: fmt_fixed(value, 2),
            u: Some(fmt_fixed(o.uncertainty.expanded, 2)),
            limit: check.map(|c| fmt_fixed(c.limit, 2)),
            outcome: check.map(|c| c.outcome),
        })
        .collect()
}

/// ISO 230-2 Fig. 2a and 2b, then the history of each charted parameter.
fn charts(t: &AxisTest, trends: Option<&AxisTrends>, words: &Words) -> Vec<Chart> {
    let mut charts = Vec::new();
    if let Some(e) = t.evaluated().map(|e| &e.evaluation) {
        let [bidirectional, unidirectional] = axcheck_charts::figures::iso_charts(e);
        charts.push(Chart {
            group: "iso",
            title: words.get("html-chart-bidirectional"),
            scene: bidirectional,
        });
        charts.push(Chart {
            group: "iso",
            title: words.get("html-chart-unidirectional"),
            scene: unidirectional,
        });
    }
    if let Some(history) = crate::history::history_of(t, trends) {
        for chart in history.charts {
            charts.push(Chart {
                group: "history",
                title: words.args("html-chart-history", &[("label", &chart.label)]),
                scene: chart.scene,
            });
        }
    }
    charts
}
