//! `summary.md`: counts, the summary table and the list of problems, for people and for
//! CI job summaries.

use super::{ExportError, Exporter, OutputFile};
use crate::evaluate::Role;
use crate::results::{AxisTest, CampaignResult};
use crate::rules::Severity;
use crate::units::fmt_fixed;
use std::fmt::Write;

pub(crate) struct MarkdownExporter;

/// Text from input made safe for a table cell or a line: no HTML, no Markdown syntax, no
/// hidden characters.
fn cell(s: &str) -> String {
    crate::safe_text::markdown_text(s)
}

impl Exporter for MarkdownExporter {
    fn name(&self) -> &'static str {
        "markdown"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let mut out = header(result);
        out.push_str(
            "| machine | axis | file | standard | spec | n | A | E | M | R | B | unit | verdict |\n",
        );
        out.push_str("|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---|---|\n");
        for t in &result.tests {
            out.push_str(&row(t));
        }
        let problems: Vec<String> = result.tests.iter().flat_map(problems).collect();
        if !problems.is_empty() {
            out.push_str("\n## Findings\n\n");
            for p in problems {
                let _ = writeln!(out, "{p}");
            }
        }
        out.push_str(&inputs(result));
        // Every text from input went through `cell`; what axcheck composed around it (a
        // parameter's check, a rule's id) is made visible too, whatever it quotes.
        let out = crate::safe_text::visible(&out).into_owned();
        Ok(vec![OutputFile::new("summary.md", out.into_bytes())])
    }
}

/// The title, the campaign's facts and the verdict counts.
fn header(result: &CampaignResult) -> String {
    let info = &result.info;
    let mut facts: Vec<String> = [
        ("Site", &info.site),
        ("Purpose", &info.purpose),
        ("Date", &info.date),
        ("Inspector", &info.inspector),
    ]
    .into_iter()
    .filter_map(|(label, value)| value.as_ref().map(|v| format!("{label}: {}", cell(v))))
    .collect();
    facts.push(format!("Campaign file: {}", cell(&result.file_name)));
    let caveats: String = (result.caveats().iter())
        .map(|c| format!("- {}\n", cell(c)))
        .collect();
    format!(
        "# {}\n\n{}\n\n**{}** tests: {}\n\n{}{}",
        cell(&info.name),
        facts.join(" · "),
        result.tests.len(),
        result.counts_text(),
        caveats,
        if caveats.is_empty() { "" } else { "\n" }
    )
}

/// Files listed under "Inputs" before "… and N more".
const INPUTS_LISTED: usize = 200;

/// The files the run read with their SHA-256 and how it was run (nothing for a result no
/// run recorded).
fn inputs(result: &CampaignResult) -> String {
    let Some(list) = axcheck_charts::data::inputs::inputs_list(&result.inputs, INPUTS_LISTED, 64)
    else {
        return String::new();
    };
    let mut out = format!(
        "\n## Inputs\n\nMade by axcheck {} from {} files with: {}\n\n| file | SHA-256 |\n|---|---|\n",
        cell(&list.axcheck),
        list.total,
        cell(&list.command)
    );
    for r in &list.rows {
        let _ = writeln!(out, "| {} | {} |", cell(&r.path), r.sha256);
    }
    if list.more > 0 {
        let _ = writeln!(
            out,
            "\n… and {} more (results.json lists them all)",
            list.more
        );
    }
    out
}

/// A test's line of the table: its headline parameters (A, E, M, R, B of its standard).
fn row(t: &AxisTest) -> String {
    let e = t.evaluated().map(|e| &e.evaluation);
    let v = |role: Role| {
        e.and_then(|e| e.headline(role))
            .map_or("–".to_string(), |p| fmt_fixed(p.value, 2))
    };
    format!(
        "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        cell(&t.machine.id),
        cell(&t.axis_label()),
        cell(t.file.as_deref().unwrap_or("–")),
        t.positioning_standard().map_or("–", |s| s.key()),
        t.judgement()
            .map_or("–".to_string(), |j| cell(&j.limits.describe_labelled())),
        (e.map(|e| e.n)
            .or_else(|| t.other()?.data.as_ref().map(|d| d.runs())))
        .map_or("–".to_string(), |n| n.to_string()),
        v(Role::Accuracy),
        v(Role::Systematic),
        v(Role::MeanRange),
        v(Role::Repeatability),
        v(Role::Reversal),
        match t.deviation_symbol() {
            "" => "–",
            unit => unit,
        },
        verdict_cell(t)
    )
}

/// The verdict in bold, flagged when its U is large (over half a limit or over the
/// value): `**pass** (U large: A)`.
fn verdict_cell(t: &AxisTest) -> String {
    let large: Vec<String> = t
        .large_uncertainty()
        .into_iter()
        .map(|l| l.key.to_string())
        .collect();
    let verdict = match large.is_empty() {
        true => format!("**{}**", t.verdict()),
        false => format!("**{}** (U large: {})", t.verdict(), cell(&large.join(", "))),
    };
    // Another laser test has none of the columns' parameters: its values follow.
    match t.other() {
        Some(o) => format!("{verdict}: {}", other_values(o)),
        None => verdict,
    }
}

/// `straightness 8.12, local straightness 0.82`: the values of another laser test.
fn other_values(o: &crate::results::OtherTested) -> String {
    (o.values())
        .map(|(k, value, _)| {
            let name = crate::results::OtherTested::name(k);
            format!("{name} {}", fmt_fixed(value, 2))
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// What the findings list says of a test: its error, the parameters over their limits and
/// the test-plan rules it breaks or warns about.
fn problems(t: &AxisTest) -> Vec<String> {
    let label = cell(&t.label());
    let mut lines = Vec::new();
    if let Some(e) = t.error() {
        lines.push(format!("- **{label}**: error: {}", cell(e)));
    }
    for c in t.judgement().into_iter().flat_map(|j| j.failed()) {
        lines.push(format!("- **{label}**: {}", c.over_limit(2, "")));
    }
    for f in t.findings() {
        let kind = match f.severity {
            Severity::Error => "rule",
            Severity::Warning => "warning",
        };
        lines.push(format!(
            "- **{label}**: {kind} `{}` ({}): {}",
            f.id,
            f.clause,
            cell(&f.message)
        ));
    }
    lines
}
