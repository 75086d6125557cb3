//! `summary.pdf` and `reports/<machine>/<axis>.pdf`, typeset in parallel.

use super::{ExportError, Exporter, OutputFile};
use crate::batch::CampaignResult;
use crate::report::{self, Reports};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

pub struct Pdf {
    pub reports: Reports,
}

/// Reports typeset between two evictions of Typst's caches.
const REPORTS_PER_CHUNK: usize = 32;

/// A file-name part from user text: ASCII letters, digits, `-`, `_` and `.` kept, anything
/// else (`/`, `..`, NUL, spaces, non-ASCII) becomes `_`; no leading dot; Windows' reserved
/// device names get a trailing `_`; at most 64 characters.
pub fn safe_name(text: &str) -> String {
    let mut s: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '_'
            }
        })
        .take(64)
        .collect();
    while s.starts_with('.') {
        s.replace_range(0..1, "_");
    }
    if s.is_empty() {
        s.push('_');
    }
    let stem = s.split('.').next().unwrap_or("").to_ascii_uppercase();
    let reserved = matches!(stem.as_str(), "CON" | "PRN" | "AUX" | "NUL")
        || ((stem.starts_with("COM") || stem.starts_with("LPT"))
            && stem.len() == 4
            && stem.as_bytes()[3].is_ascii_digit());
    if reserved {
        s.push('_');
    }
    s
}

/// The report path of every test, unique even when names collide after sanitising.
pub fn report_paths(result: &CampaignResult) -> Vec<PathBuf> {
    let mut used: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut machine_dirs: BTreeMap<String, String> = BTreeMap::new();
    let mut taken_dirs: BTreeSet<String> = BTreeSet::new();
    result
        .tests
        .iter()
        .map(|t| {
            let dir = machine_dirs
                .entry(t.machine.id.clone())
                .or_insert_with(|| unique(&safe_name(&t.machine.id), &mut taken_dirs))
                .clone();
            let base = if t.tests > 1 {
                format!("{}-test{}", safe_name(&t.axis), t.test)
            } else {
                safe_name(&t.axis)
            };
            let name = unique(&base, used.entry(dir.clone()).or_default());
            PathBuf::from("reports")
                .join(dir)
                .join(format!("{name}.pdf"))
        })
        .collect()
}

fn unique(base: &str, taken: &mut BTreeSet<String>) -> String {
    let mut name = base.to_string();
    let mut k = 2;
    while !taken.insert(name.to_ascii_lowercase()) {
        name = format!("{base}-{k}");
        k += 1;
    }
    name
}

impl Exporter for Pdf {
    fn name(&self) -> &'static str {
        "pdf"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        let err = |e: report::ReportError| ExportError::Format {
            format: "pdf",
            message: e.to_string(),
        };
        let paths = report_paths(result);
        let work: Vec<_> = result.tests.iter().zip(paths).collect();
        // The summary (one table row per axis: 1.5 s for 1 000 axes) is typeset beside the
        // axis reports, not after them on one core while the others wait.
        let (summary, axis_reports) = rayon::join(
            || self.reports.summary(result).map_err(err),
            || -> Result<Vec<OutputFile>, ExportError> {
                let mut files: Vec<OutputFile> = Vec::with_capacity(work.len() + 1);
                // In chunks, evicting Typst's memo caches between them: memory stays
                // bounded however many reports a campaign has.
                for chunk in work.chunks(REPORTS_PER_CHUNK) {
                    let rendered = chunk
                        .par_iter()
                        .map(|(t, path)| {
                            Ok(OutputFile {
                                path: path.clone(),
                                bytes: self.reports.axis(result, t).map_err(err)?.pdf,
                            })
                        })
                        .collect::<Result<Vec<_>, ExportError>>()?;
                    files.extend(rendered);
                    report::evict_caches();
                }
                Ok(files)
            },
        );
        let mut files = axis_reports?;
        files.push(OutputFile {
            path: "summary.pdf".into(),
            bytes: summary?.pdf,
        });
        report::evict_caches();
        Ok(files)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_safe() {
        assert_eq!(safe_name("VMC-07"), "VMC-07");
        assert_eq!(safe_name("../etc/passwd"), "_._etc_passwd");
        assert_eq!(safe_name(".."), "_.");
        assert_eq!(safe_name("a\0b"), "a_b");
        assert_eq!(safe_name("slit 1"), "slit_1");
        assert_eq!(safe_name("CON"), "CON_");
        assert_eq!(safe_name("com1.txt"), "com1.txt_");
        assert_eq!(safe_name(""), "_");
        assert_eq!(safe_name("Ось X"), "____X");
    }
}
