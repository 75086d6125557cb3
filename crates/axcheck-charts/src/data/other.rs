//! The data of a straightness, angular or squareness test's report (`other-report.typ`):
//! header facts, verdict, each value with its U, limit and outcome, what the method
//! removed (the reference line's slope) or took (the square's error), the U budget and
//! its notes, and the chart of the means about the reference line.

use super::conditions::Row;
use super::{CampaignHeader, generator, num, pos, short_name};
use crate::charts::geometry::GeometryChart;
use crate::compensate::cross::verify::CrossFinding;
use crate::geometry::TestKind;
use crate::geometry::line::{Line, ReferenceLine};
use crate::judge::Conformance;
use crate::one_file::OtherResult;
use crate::results::{AxisTest, CampaignResult, OtherTested};
use crate::units::{AxisKind, Direction};
use serde::Serialize;

/// Everything `other-report.typ` shows.
#[derive(Serialize)]
pub struct OtherReport<'a> {
    campaign: CampaignHeader<'a>,
    campaign_short: String,
    /// `Straightness test report`, `Angular deviation test report`, `Squareness test report`.
    kind: String,
    title: String,
    facts: Vec<Row>,
    verdict: super::axis::VerdictText,
    unit: String,
    values: Vec<ValueRow>,
    /// What the method removed or took, a line each (`slope removed: 14.95 µm/m`).
    method: Vec<Row>,
    budget: Vec<BudgetRow>,
    expanded: String,
    /// Where U comes from, in words.
    u_method: &'static str,
    notes: &'a [String],
    /// A straightness test's cross table and its verification, a line each (empty: none).
    cross: Vec<Row>,
    has_chart: bool,
    chart_title: &'static str,
    /// The certificate block (`campaign.certificate`), absent for a plain test report.
    certificate: Option<super::certificate::CertificateSection<'a>>,
    /// The rules every measured test follows (the instrument's calibration) it breaks.
    findings: &'a [crate::rules::Violation],
    generator: String,
}

#[derive(Serialize)]
struct ValueRow {
    name: &'static str,
    value: String,
    u: String,
    limit: String,
    outcome: Option<Conformance>,
}

#[derive(Serialize)]
struct BudgetRow {
    contributor: String,
    u: String,
}

/// The report of `t`, a test with [`AxisTest::other`].
pub fn other_report<'a>(result: &'a CampaignResult, t: &'a AxisTest) -> Option<OtherReport<'a>> {
    let o = t.other()?;
    // In the language of the document being built ([`crate::words::numbers`]).
    let words = crate::words::Words::new(crate::words::numbers());
    let unit = if o.unit() == "um" {
        super::unit("µm")
    } else {
        "″".to_string()
    };
    Some(OtherReport {
        campaign: CampaignHeader::new(result),
        campaign_short: super::campaign_short(result),
        kind: words.get(match o.test {
            TestKind::Straightness => "other-kind-straightness",
            TestKind::Angular => "other-kind-angular",
            _ => "other-kind-squareness",
        }),
        title: format!(
            "{} — {}",
            short_name(&t.machine.id, super::SHORT_NAME),
            short_name(&t.axis_label(), super::AXIS_NAME)
        ),
        facts: facts(result, t, o),
        verdict: super::axis::VerdictText::new(
            t,
            &crate::words::Words::new(crate::words::numbers()),
        ),
        unit: unit.clone(),
        values: values(o),
        method: method(o),
        budget: (o.uncertainty.budget.lines.iter())
            .map(|l| BudgetRow {
                contributor: contributor(l.contributor),
                u: num(l.contribution),
            })
            .collect(),
        expanded: format!(
            "U = {} {unit} (k = {})",
            num(o.uncertainty.expanded),
            o.uncertainty.k
        ),
        u_method: match o.test {
            TestKind::Squareness => {
                "from the scatter of each straightness test's means about its reference line (the lines' inclinations) and the optical square's calibration"
            }
            _ => "from the scatter of the means at the value's extremes",
        },
        notes: &o.uncertainty.notes,
        cross: cross(o),
        has_chart: chart(o).is_some(),
        chart_title: match o.test {
            TestKind::Straightness => "Mean deviations about the reference line",
            _ => "Mean angular deviations along the axis",
        },
        certificate: super::certificate::certificate_section(
            result,
            &[t],
            result.report_number(t),
            &words,
        ),
        findings: t.findings(),
        generator: generator(),
    })
}

fn facts(result: &CampaignResult, t: &AxisTest, o: &OtherTested) -> Vec<Row> {
    let words = crate::words::Words::new(crate::words::numbers());
    let travel = o.data.as_ref().map(|d| {
        let (a, b) = d.measurement_travel();
        let (from, to) = (pos(AxisKind::Linear, a), pos(AxisKind::Linear, b));
        words.args("other-from-to", &[("from", &from), ("to", &to)])
    });
    let sources = (o.sources.iter())
        .map(|(symbol, file)| format!("{symbol} ({file})"))
        .collect::<Vec<_>>()
        .join(", ");
    let tolerance = o.tolerance.join("; ");
    Row::labelled(
        &words,
        [
            ("fact-machine", Some(t.machine.id.clone())),
            ("fact-test", Some(t.axis_label())),
            ("summary-file", t.file.clone()),
            (
                "fact-file-sha",
                super::inputs::short_sha256(&result.inputs, t.file.as_deref()),
            ),
            ("other-from-straightness", Some(sources)),
            ("fact-measurement-travel", travel),
            ("other-runs", o.data.as_ref().map(|d| d.runs().to_string())),
            (
                "other-targets",
                o.data.as_ref().map(|d| d.target_count().to_string()),
            ),
            (
                "other-tolerance",
                Some(tolerance)
                    .filter(|t| !t.is_empty())
                    .or(Some(words.get("other-none-stated"))),
            ),
            (
                "html-decision-rule",
                Some(o.judgement.rule.key().to_string()),
            ),
            (
                "summary-date",
                result.info.date.as_deref().map(|d| words.date(d)),
            ),
            ("fact-inspector", result.info.inspector.clone()),
        ],
    )
}

/// Each value a tolerance may limit, with U, its limit and outcome.
fn values(o: &OtherTested) -> Vec<ValueRow> {
    (o.values())
        .map(|(key, value, check)| ValueRow {
            name: OtherTested::name(key),
            value: num(value),
            u: num(o.uncertainty.expanded),
            limit: check.map_or("–".into(), |c| num(c.limit)),
            outcome: check.map(|c| c.outcome),
        })
        .collect()
}

/// The cross table written for the controller (or why none) and the verification of a
/// loaded one, as the report states them.
fn cross(o: &OtherTested) -> Vec<Row> {
    let Some(c) = o.cross.as_deref() else {
        return Vec::new();
    };
    let table = c.table.as_ref().map(|t| match t {
        Ok(t) => format!(
            "{} ({}): {} corrected as a function of {} at {} points; straightness {} µm measured, {} µm predicted; each value is added to {}'s command",
            t.format,
            t.mode_key(),
            t.table.output,
            t.table.input,
            t.table.positions_mm.len(),
            num(t.measured_um),
            num(t.predicted_um),
            t.table.output
        ),
        Err(why) => format!("not written: {why}"),
    });
    let warnings = (c.table.as_ref().and_then(|t| t.as_ref().ok()))
        .map(|t| t.warnings.join("; "))
        .filter(|w| !w.is_empty());
    let verification = c.verification.as_ref().map(|v| match v {
        Ok(v) => {
            let findings: Vec<String> = (v.findings.iter())
                .map(|f| match f {
                    CrossFinding::WrongAxis { output } => format!("wrong_axis: {output}"),
                    other => other.key().to_string(),
                })
                .collect();
            format!(
                "{}{}: straightness {} µm before, {} µm predicted, {} µm achieved (scatter of a mean {} µm)",
                v.verdict.key(),
                if findings.is_empty() { String::new() } else { format!(" ({})", findings.join(", ")) },
                num(v.before_um),
                num(v.predicted_um),
                num(v.achieved_um),
                num(v.scatter_um)
            )
        }
        Err(why) => format!("not made: {why}"),
    });
    Row::present([
        ("Cross-axis table", table),
        ("Table warnings", warnings),
        ("Loaded table verified", verification),
    ])
}

/// A budget line's contributor in words.
fn contributor(key: &str) -> String {
    match key {
        "repeatability" => "repeatability (the means' scatter at the extremes)".into(),
        "first_line" => "inclination of the first straightness test's line".into(),
        "second_line" => "inclination of the second straightness test's line".into(),
        "square" => "the optical square's calibration".into(),
        other => other.replace('_', " "),
    }
}

fn line_name(line: ReferenceLine) -> &'static str {
    match line {
        ReferenceLine::LeastSquares => "least squares",
        ReferenceLine::EndPoint => "end points",
    }
}

/// What the method removed or took.
fn method(o: &OtherTested) -> Vec<Row> {
    let slope = |l: &Line| format!("{} µm/m", num(l.slope_um_per_m));
    match &o.result {
        OtherResult::Straightness(s) => Row::present([
            ("Reference line", Some(line_name(s.line).to_string())),
            ("Slope removed", Some(slope(&s.bidirectional.line))),
            (
                "Straightness ↑ / ↓",
                Some(format!(
                    "{} / {} µm",
                    num(s.up.deviation_um),
                    num(s.down.deviation_um)
                )),
            ),
            (
                "Reversal (largest |x̄↑ − x̄↓|)",
                Some(format!(
                    "{} µm at target {}",
                    num(s.reversal_um),
                    s.reversal_target_index
                )),
            ),
            (
                "Local straightness",
                s.local.as_ref().map(|l| {
                    format!(
                        "{} µm over {} mm ({} to {} mm)",
                        num(l.deviation_um),
                        num(l.length_mm),
                        num(l.from_mm),
                        num(l.to_mm)
                    )
                }),
            ),
        ]),
        OtherResult::Angular(a) => Row::present([
            (
                "Range ↑ / ↓",
                Some(format!("{} / {}″", num(a.up_arcsec), num(a.down_arcsec))),
            ),
            (
                "Repeatability (largest 4sᵢ)",
                a.repeatability_arcsec.map(|r| format!("{}″", num(r))),
            ),
            ("Reversal", Some(format!("{}″", num(a.reversal_arcsec)))),
        ]),
        OtherResult::Squareness(s) => Row::present([
            ("Reference lines", Some(line_name(s.line).to_string())),
            (
                "θ₁, θ₂ (inclinations)",
                Some(format!(
                    "{}″, {}″",
                    num(s.squareness.first_arcsec),
                    num(s.squareness.second_arcsec)
                )),
            ),
            (
                "Optical square's error",
                Some(format!("{}″", num(s.squareness.square_error_arcsec))),
            ),
            (
                "Included angle − 90°",
                Some(format!(
                    "{}″ ({} µm/m)",
                    num(s.squareness.over_ninety_arcsec),
                    num(s.squareness.error_um_per_m)
                )),
            ),
            (
                "Sign",
                Some(match s.squareness.convention {
                    crate::geometry::squareness::Convention::OverNinetyPositive => {
                        "positive when the angle is larger than 90° (HP 5528A §21)".to_string()
                    }
                    crate::geometry::squareness::Convention::UnderNinetyPositive => {
                        "positive when the angle is smaller than 90°".to_string()
                    }
                }),
            ),
        ]),
    }
}

/// The chart of a straightness (about its reference line) or an angular test.
pub fn chart(o: &OtherTested) -> Option<GeometryChart> {
    let data = o.data.as_ref()?;
    let words = crate::words::Words::new(crate::words::numbers());
    let means = crate::geometry::means;
    let (up, down) = (means(data, Direction::Up), means(data, Direction::Down));
    let positions = data.targets.clone();
    match &o.result {
        OtherResult::Straightness(s) => {
            let line = &s.bidirectional.line;
            let about = |v: &[f64]| -> Vec<f64> {
                v.iter()
                    .zip(&positions)
                    .map(|(y, x)| y - line.at(*x))
                    .collect()
            };
            Some(GeometryChart {
                up: about(&up),
                down: about(&down),
                mean: Some(s.residuals_um.clone()),
                position_label: words.args("other-chart-position", &[("unit", &super::unit("mm"))]),
                deviation_label: words.args(
                    "other-chart-deviation",
                    &[("line", line_name(s.line)), ("unit", &super::unit("µm"))],
                ),
                texts: ["x̄i↑", "x̄i↓", "mean of x̄i↑ and x̄i↓"],
                positions,
            })
        }
        OtherResult::Angular(_) => Some(GeometryChart {
            up,
            down,
            mean: None,
            position_label: words.args("other-chart-position", &[("unit", &super::unit("mm"))]),
            deviation_label: words.args("other-chart-angular", &[("unit", &super::unit("arcsec"))]),
            texts: ["x̄i↑", "x̄i↓", ""],
            positions,
        }),
        OtherResult::Squareness(_) => None,
    }
}
