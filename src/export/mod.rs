//! Campaign outputs: one [`Exporter`] trait, one file per format (as hyperfine's export/).
//! Each output is serialised in memory, then written atomically; an output that grows with
//! the data (`results.json`: about 58 kB an axis) is written as it is made ([`Body::Streamed`]),
//! so a plant's run never holds it whole.

pub mod compensation;
pub mod csv;
pub mod html;
pub mod json;
pub mod junit;
pub mod markdown;
pub mod overview;
#[cfg(feature = "parquet")]
pub mod parquet;
pub mod paths;
#[cfg(feature = "pdf")]
pub mod pdf;
mod workers;
pub mod xlsx;

use crate::results::CampaignResult;
/// The summary table (`axcheck-campaign`'s): the rows of `summary.csv`, the parquet file,
/// the workbook and Python's `check`.
pub use axcheck_campaign::table;
use std::path::{Path, PathBuf};

/// An output that could not be produced or written.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    #[error("{format}: {message}")]
    Format {
        format: &'static str,
        message: String,
    },
    #[error("cannot write {path}: {cause}")]
    Write {
        path: PathBuf,
        cause: std::io::Error,
    },
    /// The output folder cannot take the outputs (a file axcheck did not write is in the
    /// way), or writing it failed.
    #[error(transparent)]
    Output(#[from] crate::atomic::OutputError),
    /// Some outputs could not be written (a full disk): the others are, and the manifest
    /// says the folder is incomplete and what it misses.
    #[error("{}", incomplete_message(.written, .missing, .manifest))]
    Incomplete {
        written: usize,
        missing: Vec<PathBuf>,
        manifest: PathBuf,
        /// Why the first missing output could not be written.
        #[source]
        first: Box<crate::atomic::OutputError>,
    },
}

/// Missing outputs named in the message; the manifest lists them all.
const MISSING_NAMED: usize = 20;

/// `wrote 33 of 36 outputs; missing: …; …`.
fn incomplete_message(written: &usize, missing: &[PathBuf], manifest: &Path) -> String {
    let mut names: Vec<String> = (missing.iter().take(MISSING_NAMED))
        .map(|p| p.display().to_string())
        .collect();
    if missing.len() > MISSING_NAMED {
        names.push(format!("… and {} more", missing.len() - MISSING_NAMED));
    }
    format!(
        "the outputs are incomplete: {written} of {} written; missing: {} (listed in {}, which says complete: false); free space or fix the cause below and run again",
        written + missing.len(),
        names.join(", "),
        manifest.display()
    )
}

/// One file an exporter produces, its path relative to the output folder.
pub struct OutputFile<'a> {
    pub path: PathBuf,
    pub body: Body<'a>,
}

/// Writes an output's bytes into its (buffered) file, the same bytes at each call.
pub type StreamFn<'a> = dyn Fn(&mut dyn std::io::Write) -> std::io::Result<()> + Send + Sync + 'a;

/// What an output holds.
pub enum Body<'a> {
    /// Its bytes, made before anything is written.
    Bytes(Vec<u8>),
    /// Made while it is written: an output too large to hold (100 000 axes' `results.json`
    /// is 5.8 GB).
    Streamed(Box<StreamFn<'a>>),
}

impl OutputFile<'_> {
    /// An output made in memory.
    pub fn new(path: impl Into<PathBuf>, bytes: Vec<u8>) -> OutputFile<'static> {
        OutputFile {
            path: path.into(),
            body: Body::Bytes(bytes),
        }
    }
}

impl std::fmt::Debug for OutputFile<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let body = match &self.body {
            Body::Bytes(b) => format!("{} bytes", b.len()),
            Body::Streamed(_) => "streamed".to_string(),
        };
        write!(f, "{} ({body})", self.path.display())
    }
}

/// A format of campaign output.
pub trait Exporter: Sync {
    /// Name of the format, for messages.
    fn name(&self) -> &'static str;
    /// The files of this format for `result`.
    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError>;
}

/// The table and data outputs every `run` writes.
pub(crate) fn table_exporters() -> Vec<Box<dyn Exporter>> {
    vec![
        Box::new(json::JsonExporter),
        Box::new(csv::CsvExporter),
        #[cfg(feature = "parquet")]
        Box::new(parquet::ParquetExporter),
        Box::new(markdown::MarkdownExporter),
        Box::new(junit::JunitExporter),
        Box::new(compensation::CompensationExporter),
    ]
}

/// Produces and writes the outputs of `exporters` into `dir`; returns the written paths.
///
/// Nothing is written until every output is produced (a [`Body::Streamed`] one is made as
/// it is written) and every output path is checked:
/// a file at an output path that axcheck did not write (not in the folder's manifest,
/// [`crate::atomic::MANIFEST`]) is refused. Each exporter's paths are checked as soon as it
/// has produced them, so a refused table output fails before the PDFs are typeset. Then
/// stale temporary files of killed runs are removed, each file is written atomically, and
/// outputs of the previous run that this run no longer produces are removed (see
/// [`crate::atomic::OutputDir`]).
pub fn write_all(
    result: &CampaignResult,
    exporters: &[Box<dyn Exporter>],
    dir: &Path,
) -> Result<Vec<PathBuf>, ExportError> {
    let out = crate::atomic::OutputDir::open(dir)?;
    let mut files = Vec::new();
    for exporter in exporters {
        let produced = exporter.export(result)?;
        out.check(produced.iter().map(|f| f.path.as_path()))?;
        files.extend(produced);
    }
    write_checked(out, &files, dir)
}

/// Writes `files` into `dir` as [`write_all`] writes a campaign's outputs (the folder's
/// manifest, atomic files, a full disk reported): the one way an output folder is written,
/// for `trend --out` too.
pub fn write_into(dir: &Path, files: &[OutputFile<'_>]) -> Result<Vec<PathBuf>, ExportError> {
    let out = crate::atomic::OutputDir::open(dir)?;
    out.check(files.iter().map(|f| f.path.as_path()))?;
    write_checked(out, files, dir)
}

/// Writes `files`, each path already checked in `out`.
fn write_checked(
    mut out: crate::atomic::OutputDir,
    files: &[OutputFile<'_>],
    dir: &Path,
) -> Result<Vec<PathBuf>, ExportError> {
    out.prepare(files.iter().map(|f| f.path.as_path()))?;
    let mut failed = write_files(&out, files)?.into_iter();
    let Some((path, first)) = failed.next() else {
        out.finish()?;
        return Ok(files.iter().map(|f| dir.join(&f.path)).collect());
    };
    let missing: Vec<PathBuf> = std::iter::once(path)
        .chain(failed.map(|(p, _)| p))
        .collect();
    // The manifest records what is missing; if even it cannot be written, the message
    // still names the missing outputs.
    let _ = out.finish_incomplete(missing.iter().cloned().collect());
    Err(ExportError::Incomplete {
        written: files.len() - missing.len(),
        missing,
        manifest: dir.join(crate::atomic::MANIFEST),
        first: Box::new(first),
    })
}

/// Writers working at once: each file is synced to disk before its rename, and a sync waits
/// on the disk (about 3 ms here), so a thousand reports written one after the other spent
/// seconds waiting; several writers overlap the waits (0.75 ms per file with two).
const WRITERS: usize = 8;

/// Writes `files` with up to [`WRITERS`] threads, each of them whatever becomes of the
/// others (so which outputs a full disk leaves out depends on their sizes, not on timing);
/// returns those that could not be written, in order, with why.
fn write_files(
    out: &crate::atomic::OutputDir,
    files: &[OutputFile<'_>],
) -> Result<Vec<(PathBuf, crate::atomic::OutputError)>, ExportError> {
    let here = |_thread: usize, work: &(dyn Fn() + Sync)| {
        work();
        Ok::<(), crate::atomic::OutputError>(())
    };
    let written = workers::map_in_order(files, WRITERS, here, |file| {
        let written = match &file.body {
            Body::Bytes(bytes) => out.write(&file.path, bytes),
            Body::Streamed(stream) => out.write_with(&file.path, stream),
        };
        Ok(written.err())
    })?;
    Ok((files.iter().zip(written))
        .filter_map(|(file, error)| error.map(|e| (file.path.clone(), e)))
        .collect())
}
