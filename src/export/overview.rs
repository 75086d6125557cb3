//! The plant overview that `summary.html` and `summary.xlsx` share: one row per axis test
//! with the headline parameters of its standard (A, E, M, R, B by their role: GOST 27843's
//! R_max fills R), each with its expanded uncertainty U (k = 2), the parameter closest to
//! its limit, the verdict and how it was decided, what the plan rules, the diagnosis, the
//! compensation and the history say. Numbers are kept as numbers (for sorting) with the
//! text the reports print beside them (2 decimals, as the PDF summary).

use crate::evaluate::{ParamKey, Role};
use crate::history::AxisTrends;
use crate::judge::Verdict;
use crate::results::{AxisTest, CampaignResult};
use crate::units::{AxisKind, fmt_fixed, fmt_position};
use serde::Serialize;
use std::collections::BTreeMap;

/// The headline columns: their key and the role that fills them.
pub(crate) const HEADLINES: [(&str, Role); 5] = [
    ("A", Role::Accuracy),
    ("E", Role::Systematic),
    ("M", Role::MeanRange),
    ("R", Role::Repeatability),
    ("B", Role::Reversal),
];

/// One axis test.
#[derive(Debug, Serialize)]
pub struct Row<'a> {
    /// `MACHINE|AXIS|TEST`: unique in the campaign.
    pub id: String,
    pub machine: &'a str,
    pub axis: String,
    /// Index of the test among the axis's tests (1-based) and their number.
    pub test: usize,
    pub tests: usize,
    pub kind: Option<AxisKind>,
    /// The standard's title (`ISO 230-2:1997`).
    pub standard: Option<&'static str>,
    /// Length of the measurement travel, mm or degrees (rounded to 1e-6).
    pub travel: Option<f64>,
    /// `976.666 mm`, `360°`.
    pub(crate) travel_text: Option<String>,
    /// Runs per direction.
    pub n: Option<usize>,
    /// Deviation unit for people: `µm` or `arcsec`.
    pub unit: Option<&'static str>,
    /// Keyed `A`, `E`, `M`, `R`, `B` (only those the standard defines for this test).
    pub values: BTreeMap<&'static str, Headline>,
    pub worst: Option<Worst>,
    pub verdict: Verdict,
    /// `simple` or `iso14253-1`, when limits applied.
    pub decision_rule: Option<&'static str>,
    /// The plan rules of severity error the test breaks (they make it noncompliant).
    pub rules: Vec<&'static str>,
    /// The plan rules of severity warning it raises.
    pub warnings: Vec<&'static str>,
    /// The effects the diagnosis found (`none` when it found none; absent when not run).
    pub diagnosis: Option<Vec<&'static str>>,
    pub compensation: Option<CompensationE>,
    /// The parameters whose trend is flagged; absent when the run keeps no history.
    pub trend: Option<Vec<String>>,
    pub error: Option<&'a str>,
}

/// A headline parameter: its symbol in the test's standard, its value and U (k = 2).
#[derive(Debug, Serialize)]
pub struct Headline {
    pub key: &'static str,
    pub symbol: &'static str,
    pub value: f64,
    pub text: String,
    #[serde(rename = "U")]
    pub u: Option<f64>,
    #[serde(rename = "U_text")]
    pub(crate) u_text: Option<String>,
}

/// The check using the largest share of its tolerance: |value| / limit.
#[derive(Debug, Serialize)]
pub struct Worst {
    pub key: String,
    pub symbol: String,
    pub ratio: f64,
    pub text: String,
}

/// E (ISO 230-2 2.20, or the standard's systematic parameter) as measured and as
/// predicted with the controller's new table.
#[derive(Debug, Serialize)]
pub struct CompensationE {
    pub controller: &'static str,
    pub measured: f64,
    pub predicted: f64,
    /// `5.81 → 0.36`.
    pub text: String,
}

/// The rows in campaign order.
pub fn rows<'a>(result: &'a CampaignResult, trends: Option<&AxisTrends>) -> Vec<Row<'a>> {
    result.tests.iter().map(|t| row(t, trends)).collect()
}

/// `MACHINE|AXIS|TEST`.
pub(crate) fn test_id(t: &AxisTest) -> String {
    format!("{}|{}|{}", t.machine.id, t.axis_label(), t.test)
}

fn row<'a>(t: &'a AxisTest, trends: Option<&AxisTrends>) -> Row<'a> {
    let ev = t.evaluated();
    let e = ev.map(|e| &e.evaluation);
    let data = (ev.and_then(|e| e.data.as_ref())).or_else(|| t.other()?.data.as_ref());
    let travel = data.map(|d| {
        let (a, b) = d.measurement_travel();
        ((b - a) * 1e6).round() / 1e6
    });
    Row {
        id: test_id(t),
        machine: &t.machine.id,
        axis: t.axis_label(),
        test: t.test,
        tests: t.tests,
        kind: t.kind(),
        standard: t.positioning_standard().map(|s| s.title()),
        travel,
        travel_text: travel.zip(t.kind()).map(|(x, k)| travel_text(k, x)),
        n: e.map(|e| e.n).or_else(|| data.map(|d| d.runs())),
        unit: Some(t.deviation_symbol()).filter(|u| !u.is_empty()),
        values: headlines(t),
        worst: worst(t),
        verdict: t.verdict(),
        decision_rule: t
            .judgement()
            .filter(|j| !j.limits.is_empty())
            .map(|j| j.rule.key()),
        rules: t.broken_rules().map(|f| f.id).collect(),
        warnings: (t.findings().iter())
            .filter(|f| f.severity == crate::rules::Severity::Warning)
            .map(|f| f.id)
            .collect(),
        diagnosis: ev.and_then(|e| e.diagnosis.as_deref()).map(|d| {
            let mut effects: Vec<&'static str> =
                d.findings.iter().map(|f| f.effect().name()).collect();
            effects.dedup();
            effects
        }),
        compensation: compensation(t),
        trend: trends.map(|trends| {
            let m = &t.machine;
            (trends
                .axis(&m.id, m.serial.as_deref(), &t.axis_label())
                .iter())
            .filter(|(_, trend)| trend.flagged)
            .map(|(series, _)| series.parameter.clone())
            .collect()
        }),
        error: t.error(),
    }
}

/// `976.666 mm`, `360°`.
pub(crate) fn travel_text(kind: AxisKind, x: f64) -> String {
    match kind {
        AxisKind::Linear => format!("{} mm", fmt_position(x)),
        AxisKind::Rotary => format!("{}°", fmt_position(x)),
    }
}

/// The headline parameters and their U.
fn headlines(t: &AxisTest) -> BTreeMap<&'static str, Headline> {
    let Some(e) = t.evaluated().map(|e| &e.evaluation) else {
        return BTreeMap::new();
    };
    let u_of = |key: ParamKey| {
        t.evaluated()
            .and_then(|e| e.uncertainty.as_ref())
            .and_then(|u| u.expanded_of(key))
    };
    (HEADLINES.iter())
        .filter_map(|&(column, role)| {
            let p = e.headline(role)?;
            let u = u_of(p.def.key);
            Some((
                column,
                Headline {
                    key: p.key(),
                    symbol: p.symbol(),
                    value: p.value,
                    text: fmt_fixed(p.value, 2),
                    u,
                    u_text: u.map(|u| fmt_fixed(u, 2)),
                },
            ))
        })
        .collect()
}

fn worst(t: &AxisTest) -> Option<Worst> {
    let c = t.judgement()?.worst()?;
    let symbol = axcheck_charts::data::symbol_of(t, c.key);
    Some(Worst {
        text: format!("{symbol} {}", fmt_fixed(c.ratio(), 2)),
        key: c.key.to_string(),
        symbol,
        ratio: c.ratio(),
    })
}

fn compensation(t: &AxisTest) -> Option<CompensationE> {
    let c = t.evaluated().and_then(|e| e.compensation.as_deref())?;
    let done = c.outcome.as_ref().ok()?;
    let measured = t
        .evaluated()
        .map(|e| &e.evaluation)?
        .headline(Role::Systematic)?
        .value;
    let predicted = done.predicted.headline(Role::Systematic)?.value;
    Some(CompensationE {
        controller: c.controller,
        measured,
        predicted,
        text: format!("{} → {}", fmt_fixed(measured, 2), fmt_fixed(predicted, 2)),
    })
}
