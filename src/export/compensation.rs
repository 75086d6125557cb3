//! `compensation/<machine>/<axis>.<ext>`: the compensation table of each evaluated axis
//! whose machine names a `controller`, in that controller's format.

use super::paths::test_stems;
use super::{ExportError, Exporter, OutputFile};
use crate::results::CampaignResult;
use std::path::PathBuf;

pub(crate) struct CompensationExporter;

/// Where each test's table goes (None: no controller, or it refused the table).
pub(crate) fn table_paths(result: &CampaignResult) -> Vec<Option<PathBuf>> {
    result
        .tests
        .iter()
        .zip(test_stems(result, "compensation"))
        .map(|(t, stem)| {
            let c = t
                .evaluated()
                .and_then(|e| e.compensation.as_deref())
                .filter(|c| c.outcome.is_ok())?;
            Some(PathBuf::from(format!("{}.{}", stem.display(), c.extension)))
        })
        .collect()
}

impl Exporter for CompensationExporter {
    fn name(&self) -> &'static str {
        "compensation"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        Ok(result
            .tests
            .iter()
            .zip(table_paths(result))
            .filter_map(|(t, path)| {
                let file = &t
                    .evaluated()
                    .and_then(|e| e.compensation.as_deref())?
                    .outcome
                    .as_ref()
                    .ok()?
                    .file;
                Some(OutputFile {
                    path: path?,
                    bytes: file.as_bytes().to_vec(),
                })
            })
            .collect())
    }
}
