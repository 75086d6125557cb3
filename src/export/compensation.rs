//! `compensation/<machine>/<axis>.<ext>`: the compensation table of each evaluated axis
//! whose machine names a `controller`, in that controller's format; a straightness test's
//! cross table beside it (`X-EYX.<ext>`, each of the format's files).

use super::paths::test_stems;
use super::{ExportError, Exporter, OutputFile};
use crate::compensate::cross::{self, build::CrossCompensation};
use crate::results::CampaignResult;
use std::path::{Path, PathBuf};

pub(crate) struct CompensationExporter;

/// Where each test's table goes (None: no controller, or it refused the table).
pub(crate) fn table_paths(result: &CampaignResult) -> Vec<Option<PathBuf>> {
    result
        .tests
        .iter()
        .zip(test_stems(result, "compensation"))
        .map(|(t, stem)| {
            if let Some(extension) = cross_extension(t) {
                return Some(PathBuf::from(format!("{}.{extension}", stem.display())));
            }
            let c = t
                .evaluated()
                .and_then(|e| e.compensation.as_deref())
                .filter(|c| c.outcome.is_ok())?;
            Some(PathBuf::from(format!("{}.{}", stem.display(), c.extension)))
        })
        .collect()
}

/// A straightness test's cross table, when one was written.
fn cross_table(t: &crate::results::AxisTest) -> Option<&CrossCompensation> {
    let cross = t.other()?.cross.as_deref()?;
    cross.table.as_ref()?.as_ref().ok()
}

/// The extension of a cross table's first file.
fn cross_extension(t: &crate::results::AxisTest) -> Option<&'static str> {
    cross_table(t)?.parts.first().map(|p| p.extension)
}

/// Each file of a test's cross table beside `first`, written again under that name (the
/// files of a format may name each other: HEIDENHAIN's `.CMA` enters its `.COM`).
fn cross_files(t: &crate::results::AxisTest, first: &Path) -> Vec<OutputFile<'static>> {
    let Some(c) = cross_table(t) else {
        return Vec::new();
    };
    let stem = first
        .file_stem()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let parts = (cross::find(c.format).and_then(|f| f.write(&c.table, &stem).ok()))
        .unwrap_or_else(|| c.parts.clone());
    parts
        .into_iter()
        .map(|p| OutputFile::new(first.with_extension(p.extension), p.text.into_bytes()))
        .collect()
}

impl Exporter for CompensationExporter {
    fn name(&self) -> &'static str {
        "compensation"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        Ok(result
            .tests
            .iter()
            .zip(table_paths(result))
            .flat_map(|(t, path)| {
                let path = path?;
                if t.other().is_some() {
                    return Some(cross_files(t, &path));
                }
                let file = &t
                    .evaluated()
                    .and_then(|e| e.compensation.as_deref())?
                    .outcome
                    .as_ref()
                    .ok()?
                    .file;
                Some(vec![OutputFile::new(path, file.as_bytes().to_vec())])
            })
            .flatten()
            .collect())
    }
}
