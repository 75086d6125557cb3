//! A re-run's outputs compared with the run's, file by file and byte for byte; PDFs of
//! another axcheck version by their text (`pdftotext`) when it is there, else reported
//! as not comparable, never as identical.

use super::reproduce::{Manifest, manifest};
use std::path::Path;

/// How one output of the re-run compares with the run's.
#[derive(Debug, Clone, PartialEq)]
pub enum Difference {
    /// Both have it; the bytes differ.
    Differs(String),
    /// The re-run writes it; the run's folder lacks it.
    Missing(String),
    /// The run's manifest lists it; the re-run does not write it.
    Extra(String),
    /// A PDF of another version whose bytes differ and whose text could not be compared
    /// (no `pdftotext`).
    NotComparable(String),
}

impl Difference {
    pub fn path(&self) -> &str {
        match self {
            Difference::Differs(p)
            | Difference::Missing(p)
            | Difference::Extra(p)
            | Difference::NotComparable(p) => p,
        }
    }
}

/// The comparison of two output folders.
#[derive(Debug, Clone, Default)]
pub struct Comparison {
    /// Outputs compared (every file the re-run wrote).
    pub compared: usize,
    /// PDFs of another version whose bytes differ but whose text is the same.
    pub same_text: Vec<String>,
    pub differences: Vec<Difference>,
    /// The run's folder has no manifest: outputs it has beyond the re-run's are not known.
    pub no_manifest: bool,
    /// The run's manifest says it is incomplete (`complete: false`).
    pub incomplete: bool,
}

impl Comparison {
    pub fn identical(&self) -> bool {
        self.differences.is_empty() && self.same_text.is_empty()
    }
}

/// Every output of the re-run in `rerun` compared with the run's in `out`; `same_version`:
/// the re-run's axcheck is the run's (PDFs then compare by their bytes alone).
pub fn compare(out: &Path, rerun: &Path, same_version: bool) -> Comparison {
    let produced = manifest(rerun).unwrap_or_default();
    let original = manifest(out);
    let mut comparison = Comparison {
        no_manifest: original.is_none(),
        incomplete: original.as_ref().is_some_and(|m| !m.complete),
        compared: produced.files.len(),
        ..Comparison::default()
    };
    for path in &produced.files {
        let (mine, theirs) = (
            std::fs::read(rerun.join(path)),
            std::fs::read(out.join(path)),
        );
        let theirs = match theirs {
            Ok(bytes) => bytes,
            Err(_) => {
                comparison
                    .differences
                    .push(Difference::Missing(path.clone()));
                continue;
            }
        };
        if mine.as_deref().ok() == Some(theirs.as_slice()) {
            continue;
        }
        let pdf = path.to_ascii_lowercase().ends_with(".pdf");
        match (pdf && !same_version).then(|| same_text(&rerun.join(path), &out.join(path))) {
            Some(Some(true)) => comparison.same_text.push(path.clone()),
            Some(None) => comparison
                .differences
                .push(Difference::NotComparable(path.clone())),
            _ => comparison
                .differences
                .push(Difference::Differs(path.clone())),
        }
    }
    let Manifest { files, .. } = original.unwrap_or_default();
    for path in files {
        if !produced.files.contains(&path) {
            comparison.differences.push(Difference::Extra(path));
        }
    }
    comparison
}

/// Whether two PDFs give the same text (`pdftotext -layout`); `None` when pdftotext is not
/// there or fails.
fn same_text(a: &Path, b: &Path) -> Option<bool> {
    let text = |path: &Path| {
        let output = std::process::Command::new("pdftotext")
            .arg("-layout")
            .arg(path)
            .arg("-")
            .stderr(std::process::Stdio::null())
            .output()
            .ok()?;
        output.status.success().then_some(output.stdout)
    };
    Some(text(a)? == text(b)?)
}
