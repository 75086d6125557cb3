//! The data of the campaign summary: verdict counts, one row per axis test (what needs
//! attention first), the errors and the noncompliant test plans.

use super::{CampaignHeader, generator, num, pos, short_label, short_name, symbol_of};
use crate::evaluate::Role;
use crate::judge::Verdict;
use crate::results::{AxisTest, CampaignResult};
use crate::units::fmt_fixed;
use serde::Serialize;

/// Everything `summary.typ` shows.
#[derive(Serialize)]
pub struct Summary<'a> {
    campaign: CampaignHeader<'a>,
    /// The campaign's name for headings and footers ([`super::campaign_short`]).
    campaign_short: String,
    counts: Counts,
    /// What the verdicts rest on that a reader must know ([`CampaignResult::caveats`]).
    caveats: Vec<String>,
    rows: Vec<SummaryRow>,
    errors: Vec<Problem>,
    noncompliant: Vec<Problem>,
    has_chart: bool,
    /// The flagged series of the run's axes (only when the run keeps a history).
    trends: Option<super::trends::TrendsSummary>,
    /// The files the run read with the start of their SHA-256, and how it was run
    /// (`null` for a result no run recorded).
    inputs: Option<super::inputs::InputsList>,
    /// The certificate block (`campaign.certificate`) with every instrument of the run.
    certificate: Option<super::certificate::CertificateSection<'a>>,
    generator: String,
}

impl Summary<'_> {
    /// The summary with the trends of the run's axes.
    pub fn with_trends(mut self, trends: super::trends::TrendsSummary) -> Self {
        self.trends = Some(trends);
        self
    }
}

#[derive(Serialize)]
struct Counts {
    total: usize,
    pass: usize,
    fail: usize,
    noncompliant: usize,
    error: usize,
    /// Shown when a test was judged by ISO 14253-1.
    inconclusive: Option<usize>,
    /// Shown when a test had no limit applied.
    not_judged: Option<usize>,
}

/// One axis test: its headline parameters (A, E, R, B of its standard), the parameter
/// closest to its limit, the diagnosis and the verdict.
#[derive(Serialize)]
struct SummaryRow {
    /// Shortened ([`short_name`]): each axis report prints the names whole.
    machine: String,
    axis: String,
    travel: String,
    n: String,
    a: String,
    e: String,
    r: String,
    b: String,
    unit: String,
    worst: String,
    diagnosis: String,
    verdict: Verdict,
}

/// A test that could not be evaluated or whose plan breaks a rule, with why.
#[derive(Serialize)]
struct Problem {
    label: String,
    message: String,
}

/// The summary, rows sorted so that what needs attention comes first.
pub fn summary(result: &CampaignResult) -> Summary<'_> {
    let mut tests: Vec<&AxisTest> = result.tests.iter().collect();
    tests.sort_by_key(|t| t.verdict().attention_rank());
    let counts = result.counts();
    let with = |verdict: Verdict, message: fn(&AxisTest) -> String| -> Vec<Problem> {
        result
            .tests
            .iter()
            .filter(|t| t.verdict() == verdict)
            .map(|t| Problem {
                label: short_label(t),
                message: message(t),
            })
            .collect()
    };
    Summary {
        campaign: CampaignHeader::new(result),
        campaign_short: super::campaign_short(result),
        counts: Counts {
            total: result.tests.len(),
            pass: counts[&Verdict::Pass],
            fail: counts[&Verdict::Fail],
            noncompliant: counts[&Verdict::Noncompliant],
            error: counts[&Verdict::Error],
            inconclusive: result
                .uses_uncertainty_rule()
                .then(|| counts[&Verdict::Inconclusive]),
            not_judged: Some(counts[&Verdict::NotJudged]).filter(|n| *n > 0),
        },
        caveats: result.caveats_labelled(short_label),
        rows: tests.into_iter().map(row).collect(),
        errors: with(Verdict::Error, |t| {
            t.error().unwrap_or_default().to_string()
        }),
        noncompliant: with(Verdict::Noncompliant, AxisTest::broken_rules_text),
        has_chart: result
            .tests
            .iter()
            .any(|t| t.judgement().and_then(|j| j.worst()).is_some()),
        trends: None,
        inputs: super::inputs::inputs_list(
            &result.inputs,
            super::inputs::PDF_LISTED,
            super::inputs::PDF_DIGITS,
        ),
        certificate: {
            let all: Vec<&AxisTest> = result.tests.iter().collect();
            let words = crate::words::Words::new(crate::words::numbers());
            super::certificate::certificate_section(result, &all, None, &words)
        },
        generator: generator(),
    }
}

fn row(t: &AxisTest) -> SummaryRow {
    let e = t.evaluated().map(|e| &e.evaluation);
    let headline = |role: Role| {
        e.and_then(|e| e.headline(role))
            .map_or("–".to_string(), |p| num(p.value))
    };
    let data = (t.evaluated().and_then(|e| e.data.as_ref()))
        .or_else(|| t.other().and_then(|o| o.data.as_ref()));
    let travel = data.map_or("–".into(), |d| {
        let (a, b) = d.measurement_travel();
        pos(d.kind, ((b - a) * 1e6).round() / 1e6)
    });
    let worst = match t.judgement().and_then(|j| j.worst()) {
        Some(c) => format!(
            "{} {}",
            symbol_of(t, c.key),
            super::local(&fmt_fixed(c.ratio(), 2))
        ),
        None if t.no_tolerance() && (e.is_some() || t.other().is_some()) => {
            crate::words::Words::new(crate::words::numbers()).get("summary-no-tolerance")
        }
        None => "–".to_string(),
    };
    SummaryRow {
        machine: short_name(&t.machine.id, 40),
        axis: if t.tests > 1 {
            format!(
                "{} ({}/{})",
                short_name(&t.axis_label(), 30),
                t.test,
                t.tests
            )
        } else {
            short_name(&t.axis_label(), 30)
        },
        travel,
        n: (e.map(|e| e.n).or_else(|| data.map(|d| d.runs())))
            .map_or("–".into(), |n| n.to_string()),
        a: headline(Role::Accuracy),
        e: headline(Role::Systematic),
        r: headline(Role::Repeatability),
        b: headline(Role::Reversal),
        unit: super::unit(t.deviation_symbol()),
        worst,
        diagnosis: t
            .evaluated()
            .and_then(|e| e.diagnosis.as_deref())
            .map_or("–".to_string(), |d| d.effects_label().replace('_', " ")),
        verdict: t.verdict(),
    }
}
