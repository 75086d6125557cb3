//! `summary.md`: counts, the summary table and the list of problems, for people and for
//! CI job summaries.

use super::{ExportError, Exporter, OutputFile};
use crate::batch::CampaignResult;
use crate::evaluate::Role;
use crate::judge::Verdict;
use crate::units::fmt_fixed;
use std::fmt::Write;

pub struct Markdown;

fn cell(s: &str) -> String {
    s.replace('|', "\\|").replace('\n', " ")
}

impl Exporter for Markdown {
    fn name(&self) -> &'static str {
        "markdown"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        let mut out = String::new();
        let info = &result.info;
        let _ = writeln!(out, "# {}\n", cell(&info.name));
        let mut facts = Vec::new();
        for (label, value) in [
            ("Site", &info.site),
            ("Purpose", &info.purpose),
            ("Date", &info.date),
            ("Inspector", &info.inspector),
        ] {
            if let Some(v) = value {
                facts.push(format!("{label}: {}", cell(v)));
            }
        }
        facts.push(format!("Campaign file: {}", cell(&result.file_name)));
        let _ = writeln!(out, "{}\n", facts.join(" · "));
        let counts = result.counts();
        let _ = writeln!(
            out,
            "**{}** tests: {} pass, {} fail, {} noncompliant, {} error\n",
            result.tests.len(),
            counts[&Verdict::Pass],
            counts[&Verdict::Fail],
            counts[&Verdict::Noncompliant],
            counts[&Verdict::Error]
        );
        let _ = writeln!(
            out,
            "| machine | axis | file | standard | spec | n | A | E | M | R | B | unit | verdict |"
        );
        let _ = writeln!(
            out,
            "|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---|---|"
        );
        for t in &result.tests {
            let e = t.evaluation.as_ref();
            let v = |role: Role| {
                e.and_then(|e| e.headline(role))
                    .map_or("–".to_string(), |p| fmt_fixed(p.value, 2))
            };
            let _ = writeln!(
                out,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | **{}** |",
                cell(&t.machine.id),
                cell(&t.axis),
                cell(t.file.as_deref().unwrap_or("–")),
                t.standard().map_or("–", |s| s.key()),
                t.judgement
                    .as_ref()
                    .map_or("–".to_string(), |j| cell(&j.limits.describe())),
                e.map_or("–".to_string(), |e| e.n.to_string()),
                v(Role::Accuracy),
                v(Role::Systematic),
                v(Role::MeanRange),
                v(Role::Repeatability),
                v(Role::Reversal),
                t.kind().map_or("–", |k| k.deviation_symbol()),
                t.verdict
            );
        }
        let problems: Vec<String> = result
            .tests
            .iter()
            .filter(|t| t.verdict != Verdict::Pass || t.findings.iter().any(|_| true))
            .flat_map(|t| {
                let mut lines = Vec::new();
                if let Some(e) = &t.error {
                    lines.push(format!("- **{}**: error: {}", cell(&t.label()), cell(e)));
                }
                if let Some(j) = &t.judgement {
                    for c in j.failed() {
                        lines.push(format!(
                            "- **{}**: {} = {} over its limit {} (margin {})",
                            cell(&t.label()),
                            c.key,
                            fmt_fixed(c.value, 2),
                            fmt_fixed(c.limit, 2),
                            fmt_fixed(c.margin, 2)
                        ));
                    }
                }
                for f in &t.findings {
                    lines.push(format!(
                        "- **{}**: {} `{}` ({}): {}",
                        cell(&t.label()),
                        match f.severity {
                            crate::rules::Severity::Error => "rule",
                            crate::rules::Severity::Warning => "warning",
                        },
                        f.id,
                        f.clause,
                        cell(&f.message)
                    ));
                }
                lines
            })
            .collect();
        if !problems.is_empty() {
            let _ = writeln!(out, "\n## Findings\n");
            for p in problems {
                let _ = writeln!(out, "{p}");
            }
        }
        Ok(vec![OutputFile {
            path: "summary.md".into(),
            bytes: out.into_bytes(),
        }])
    }
}
