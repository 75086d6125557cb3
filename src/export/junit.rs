//! `junit.xml`: one test case per axis test, so CI servers show the campaign as tests.
//! A failing parameter or a broken rule is a `<failure>` naming parameter, value, limit
//! and rule ids; an axis that could not be evaluated is an `<error>`.
//!
//! A test no limit was applied to (`not_judged`) is never a bare, green test case. Its
//! state follows the gate: where it fails the gate (the default) it is a `<failure
//! type="not_judged">`, which every CI server shows red, as the job's exit status is; with
//! `unjudged: allowed` it is `<skipped message="not judged: …">`, which Jenkins, GitLab
//! and Azure DevOps count apart from the passed tests (skipped, not executed), never as
//! passed, while the job stays green as the gate allows.

use super::{ExportError, Exporter, OutputFile};
use crate::judge::Verdict;
use crate::results::{AxisTest, CampaignResult};
use std::fmt::Write;

pub(crate) struct JunitExporter;

/// What JUnit says of a test no limit was applied to.
const NOT_JUDGED_MESSAGE: &str =
    "not judged: no limit applied (no spec, no tolerances), so nothing was compared";

/// Text for XML attributes and content: markup as entities, the characters XML 1.0
/// forbids and those that hide or reorder text shown visibly ([`crate::safe_text`]).
pub fn escape(s: &str) -> String {
    crate::safe_text::xml_text(s)
}

impl Exporter for JunitExporter {
    fn name(&self) -> &'static str {
        "junit"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let counts = result.counts();
        let allowed = result.info.unjudged_allowed();
        let failing = |v: Verdict| v.is_failure() || (v == Verdict::NotJudged && !allowed);
        let failures: usize = (counts.iter())
            .filter(|(v, _)| failing(**v))
            .map(|(_, n)| n)
            .sum();
        let errors = counts[&Verdict::Error];
        let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        let _ = writeln!(
            out,
            "<testsuites name=\"{}\" tests=\"{}\" failures=\"{failures}\" errors=\"{errors}\">",
            escape(&result.info.name),
            result.tests.len()
        );
        // One suite per machine, in campaign order.
        let mut machines: Vec<&str> = Vec::new();
        for t in &result.tests {
            if !machines.contains(&t.machine.id.as_str()) {
                machines.push(&t.machine.id);
            }
        }
        for machine in machines {
            let tests: Vec<_> = result
                .tests
                .iter()
                .filter(|t| t.machine.id == machine)
                .collect();
            let f = tests.iter().filter(|t| failing(t.verdict())).count();
            let count = |v: Verdict| tests.iter().filter(|t| t.verdict() == v).count();
            let e = count(Verdict::Error);
            let skipped = if allowed {
                count(Verdict::NotJudged)
            } else {
                0
            };
            let _ = writeln!(
                out,
                "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{f}\" errors=\"{e}\" skipped=\"{skipped}\">",
                escape(machine),
                tests.len()
            );
            for t in tests {
                let name = match &t.file {
                    Some(file) if t.tests > 1 => format!("{} [{file}]", t.axis_label()),
                    _ => t.axis_label(),
                };
                let _ = write!(
                    out,
                    "    <testcase classname=\"{}.{}\" name=\"{}\"",
                    escape(&result.info.name),
                    escape(machine),
                    escape(&name)
                );
                if let Some(file) = &t.file {
                    let _ = write!(out, " file=\"{}\"", escape(file));
                }
                let body = failure_lines(t);
                close_testcase(&mut out, t, &body, allowed);
            }
            out.push_str("  </testsuite>\n");
        }
        out.push_str("</testsuites>\n");
        Ok(vec![OutputFile::new("junit.xml", out.into_bytes())])
    }
}

/// What a test case's failure says: the parameters over their limits, those within their
/// uncertainty zone, the limits when they are examples, the broken rules.
fn failure_lines(t: &AxisTest) -> Vec<String> {
    let unit = t.deviation_symbol();
    let mut body = Vec::new();
    if let Some(j) = t.judgement() {
        body.extend(j.failed().map(|c| c.over_limit(3, unit)));
        body.extend(j.inconclusive().map(|c| c.within_uncertainty(3, unit)));
        if j.limits.example && !body.is_empty() {
            body.push(format!("limits: {}", j.limits.describe_labelled()));
        }
    }
    for finding in t.broken_rules() {
        body.push(format!(
            "rule {} ({}): {}",
            finding.id, finding.clause, finding.message
        ));
    }
    body
}

/// The end of a `<testcase` opened by the caller: `/>` for a pass, else the element of
/// its verdict (`allowed`: the campaign says `unjudged: allowed`).
fn close_testcase(out: &mut String, t: &AxisTest, body: &[String], allowed: bool) {
    let _ = match t.verdict() {
        Verdict::Pass => writeln!(out, "/>"),
        Verdict::Fail | Verdict::Noncompliant | Verdict::Inconclusive => writeln!(
            out,
            ">\n      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>",
            t.verdict(),
            escape(body.first().map_or("", String::as_str)),
            escape(&body.join("\n"))
        ),
        Verdict::NotJudged if allowed => writeln!(
            out,
            ">\n      <skipped message=\"{}\"/>\n    </testcase>",
            escape(NOT_JUDGED_MESSAGE)
        ),
        Verdict::NotJudged => writeln!(
            out,
            ">\n      <failure type=\"not_judged\" message=\"{m}\">{m}; the campaign does not allow tests without limits (unjudged: allowed)</failure>\n    </testcase>",
            m = escape(NOT_JUDGED_MESSAGE)
        ),
        Verdict::Error => {
            let message = escape(t.error().unwrap_or_default());
            writeln!(
                out,
                ">\n      <error type=\"error\" message=\"{message}\">{message}</error>\n    </testcase>"
            )
        }
    };
}

#[cfg(test)]
mod tests {
    #[test]
    fn escapes_markup_and_control_characters() {
        assert_eq!(
            super::escape("a<b>&\"c'\u{1}"),
            "a&lt;b&gt;&amp;&quot;c&apos;\\u0001"
        );
    }
}
