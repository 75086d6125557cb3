//! Campaign outputs: one [`Exporter`] trait, one file per format (as hyperfine's export/).
//! Each output is serialised in memory, then written atomically.

pub mod csv;
pub mod json;
pub mod junit;
pub mod markdown;
#[cfg(feature = "parquet")]
pub mod parquet;
#[cfg(feature = "pdf")]
pub mod pdf;
pub mod table;

use crate::batch::CampaignResult;
use std::path::{Path, PathBuf};

/// An output that could not be produced or written.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("{format}: {message}")]
    Format {
        format: &'static str,
        message: String,
    },
    #[error("cannot write {path}: {source}")]
    Write {
        path: PathBuf,
        source: std::io::Error,
    },
}

/// One file an exporter produces, its path relative to the output folder.
#[derive(Debug, Clone, PartialEq)]
pub struct OutputFile {
    pub path: PathBuf,
    pub bytes: Vec<u8>,
}

/// A format of campaign output.
pub trait Exporter: Sync {
    /// Name of the format, for messages.
    fn name(&self) -> &'static str;
    /// The files of this format for `result`.
    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError>;
}

/// The table and data outputs every `run` writes.
pub fn table_exporters() -> Vec<Box<dyn Exporter>> {
    vec![
        Box::new(json::Json),
        Box::new(csv::Csv),
        #[cfg(feature = "parquet")]
        Box::new(parquet::Parquet),
        Box::new(markdown::Markdown),
        Box::new(junit::Junit),
    ]
}

/// Produces and writes the outputs of `exporters` into `dir`; returns the written paths.
pub fn write_all(
    result: &CampaignResult,
    exporters: &[Box<dyn Exporter>],
    dir: &Path,
) -> Result<Vec<PathBuf>, ExportError> {
    let mut written = Vec::new();
    for exporter in exporters {
        for file in exporter.export(result)? {
            let path = dir.join(&file.path);
            crate::atomic::write(&path, &file.bytes).map_err(|source| ExportError::Write {
                path: path.clone(),
                source,
            })?;
            written.push(path);
        }
    }
    Ok(written)
}
