//! `junit.xml`: one test case per axis test, so CI servers show the campaign as tests.
//! A failing parameter or a broken rule is a `<failure>` naming parameter, value, limit
//! and rule ids; an axis that could not be evaluated is an `<error>`.

use super::{ExportError, Exporter, OutputFile};
use crate::batch::CampaignResult;
use crate::judge::Verdict;
use std::fmt::Write;

pub struct Junit;

/// Text for XML attributes and content: markup as entities, the characters XML 1.0
/// forbids and those that hide or reorder text shown visibly ([`crate::safe_text`]).
pub fn escape(s: &str) -> String {
    crate::safe_text::xml_text(s)
}

impl Exporter for Junit {
    fn name(&self) -> &'static str {
        "junit"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        let counts = result.counts();
        let failures: usize = (counts.iter())
            .filter(|(v, _)| v.is_failure())
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
            let f = tests.iter().filter(|t| t.verdict().is_failure()).count();
            let e = tests
                .iter()
                .filter(|t| t.verdict() == Verdict::Error)
                .count();
            let _ = writeln!(
                out,
                "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{f}\" errors=\"{e}\" skipped=\"0\">",
                escape(machine),
                tests.len()
            );
            for t in tests {
                let name = match &t.file {
                    Some(file) if t.tests > 1 => format!("{} [{file}]", t.axis),
                    _ => t.axis.clone(),
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
                let unit = t.kind().map_or("", |k| k.deviation_symbol());
                let mut body = Vec::new();
                if let Some(j) = t.evaluated().and_then(|e| e.judgement.as_ref()) {
                    for c in j.failed() {
                        body.push(c.over_limit(3, unit));
                    }
                    for c in j.inconclusive() {
                        body.push(c.within_uncertainty(3, unit));
                    }
                }
                for finding in t.broken_rules() {
                    body.push(format!(
                        "rule {} ({}): {}",
                        finding.id, finding.clause, finding.message
                    ));
                }
                match t.verdict() {
                    Verdict::Pass => out.push_str("/>\n"),
                    Verdict::Fail | Verdict::Noncompliant | Verdict::Inconclusive => {
                        let message = body.first().cloned().unwrap_or_default();
                        let _ = write!(
                            out,
                            ">\n      <failure type=\"{}\" message=\"{}\">{}</failure>\n    </testcase>\n",
                            t.verdict(),
                            escape(&message),
                            escape(&body.join("\n"))
                        );
                    }
                    Verdict::Error => {
                        let message = t.error().unwrap_or_default().to_string();
                        let _ = write!(
                            out,
                            ">\n      <error type=\"error\" message=\"{}\">{}</error>\n    </testcase>\n",
                            escape(&message),
                            escape(&message)
                        );
                    }
                }
            }
            out.push_str("  </testsuite>\n");
        }
        out.push_str("</testsuites>\n");
        Ok(vec![OutputFile {
            path: "junit.xml".into(),
            bytes: out.into_bytes(),
        }])
    }
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
