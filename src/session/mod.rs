//! One campaign run, in the pipeline's order: the output folder checked, the folders
//! locked, the manifest and the templates read before anything is evaluated (so that a
//! run that cannot write stops at once), every axis evaluated ([`crate::batch`]), the run
//! appended to its inspection history and its trends fitted, then every output written
//! ([`crate::export`]). The command line only prints what [`run`] returns.

pub mod compare;
mod history;
mod inputs;
mod locks;
mod output_dir;
pub mod reproduce;

pub use history::{AppendError, Appended};
pub use locks::lock_folders;
pub use output_dir::{OutputDirError, check_output_dir};

use crate::batch;
use crate::campaign::Campaign;
use crate::export;
use crate::history::AxisTrends;
use crate::results::{AxisTest, CampaignResult};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What one run of a campaign does: the one options type of `run` and `check`, built by
/// the command line from its flags and the campaign's own `output` settings.
#[derive(Debug, Clone, Default)]
pub struct RunOptions<'a> {
    /// The output folder; `None`: the CI gate (`check`), which writes nothing, keeps no
    /// history and drops each test's readings once it is judged.
    pub out: Option<&'a Path>,
    /// The axis reports and the summary PDF.
    pub pdf: bool,
    /// `summary.html`.
    pub html: bool,
    /// The model check and diagnosis of every axis.
    pub diagnose: bool,
    /// A customised copy of `templates/`.
    pub templates: Option<&'a Path>,
    /// The inspection history to append to.
    pub history: Option<PathBuf>,
    pub horizon: crate::trend::fit::TrendOptions,
    /// Wait for another run that holds the output or history folder.
    pub wait: bool,
    /// The command-line options as given, recorded in `results.json` (`inputs`) so that
    /// `reproduce` runs the campaign the same way.
    pub flags: crate::inputs::RunFlags,
}

/// What a run hears of while it runs: a lock it waits for or takes over, each test done.
pub trait Observer: Sync {
    /// A message for the user about the folders' locks.
    fn lock(&self, message: &str);
    fn test_done(&self, test: &AxisTest);
}

/// What a run did.
pub struct RunOutcome {
    pub result: CampaignResult,
    /// Every output file written.
    pub written: Vec<PathBuf>,
    /// The history appended to (when the run keeps one), or why it could not be.
    pub appended: Option<Result<Appended, AppendError>>,
    /// The trends of the run's axes over the history, when it could be read.
    pub trends: Option<Arc<AxisTrends>>,
}

/// Why a run stopped before its outputs were written.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    #[error(transparent)]
    OutputDir(#[from] OutputDirError),
    #[error(transparent)]
    History(#[from] crate::history::HistoryError),
    #[error(transparent)]
    Lock(#[from] crate::lock::LockError),
    #[error(transparent)]
    Manifest(#[from] crate::atomic::OutputError),
    #[error(transparent)]
    Templates(#[from] crate::report::ReportError),
    #[error("writing the outputs to {out}")]
    Write {
        out: PathBuf,
        #[source]
        source: export::ExportError,
    },
}

/// Runs `campaign` as `options` say: the CI gate, or a run that writes its outputs.
pub fn run(
    campaign: &Campaign,
    options: &RunOptions,
    observer: &dyn Observer,
) -> Result<RunOutcome, SessionError> {
    match options.out {
        None => Ok(gate(campaign, options, observer)),
        Some(out) => write_run(campaign, options, out, observer),
    }
}

/// The CI gate: every axis evaluated and judged, nothing written. Without compensation
/// tables (the gate writes none) and with U only where ISO 14253-1 decides.
fn gate(campaign: &Campaign, options: &RunOptions, observer: &dyn Observer) -> RunOutcome {
    let batch_options = batch::BatchOptions {
        diagnose: options.diagnose,
        drop_data: true,
        compensate: false,
        record_inputs: false,
    };
    let result = batch::run(campaign, batch_options, &|t| observer.test_done(t));
    RunOutcome {
        result,
        written: Vec::new(),
        appended: None,
        trends: None,
    }
}

/// A run that writes its outputs to `out`.
fn write_run(
    campaign: &Campaign,
    plan: &RunOptions,
    out: &Path,
    observer: &dyn Observer,
) -> Result<RunOutcome, SessionError> {
    check_output_dir(campaign, out)?;
    if let Some(history) = plan.history.as_deref() {
        // Before the evaluation: a history needs the run's date and a file name the file
        // system takes, in a folder of its own.
        crate::history::run_date(&campaign.info, &campaign.file.display().to_string())?;
        output_dir::check_history_dir(out, history)?;
    }
    // One writer per folder, from before the manifest is read until the history is
    // appended: a second run on the folder stops here (or waits), not half-way.
    let _locks = lock_folders(out, plan.history.as_deref(), plan.wait, &|m| {
        observer.lock(m)
    })?;
    // A broken manifest is refused before the evaluation; the output paths themselves are
    // checked by `write_all` before anything is written.
    crate::atomic::OutputDir::open(out)?;
    // Built before the evaluation, so bad templates stop the run at once.
    let reports = match plan.pdf {
        true => Some(crate::report::Reports::new(plan.templates)?.with_lang(plan.flags.lang)),
        false => None,
    };
    let options = batch::BatchOptions {
        diagnose: plan.diagnose,
        drop_data: false,
        compensate: true,
        record_inputs: true,
    };
    let mut result = batch::run(campaign, options, &|t| observer.test_done(t));
    // The history first: the reports show each axis over it, this run included. A history
    // that cannot be appended to or read costs the reports their history, not the outputs.
    let appended = (plan.history.as_deref()).map(|dir| history::append(&result, dir, plan.horizon));
    let trends = match &appended {
        Some(Ok(appended)) => appended.trends.clone(),
        _ => None,
    };
    let read = std::mem::take(&mut result.inputs);
    let done = appended.as_ref().and_then(|a| a.as_ref().ok());
    let named = result.info.history.clone();
    result.inputs = inputs::complete(read, plan, reports.as_ref(), done, named.as_deref());
    let exporters = exporters(plan, reports, trends.as_ref());
    let written =
        export::write_all(&result, &exporters, out).map_err(|source| SessionError::Write {
            out: out.to_path_buf(),
            source,
        })?;
    Ok(RunOutcome {
        result,
        written,
        appended,
        trends,
    })
}

/// The run's exporters: the tables, the workbook, then the page and the PDFs when asked.
fn exporters(
    plan: &RunOptions,
    reports: Option<crate::report::Reports>,
    trends: Option<&Arc<AxisTrends>>,
) -> Vec<Box<dyn export::Exporter>> {
    let mut exporters = export::table_exporters();
    exporters.push(Box::new(export::xlsx::XlsxExporter {
        trends: trends.cloned(),
    }));
    if plan.html {
        exporters.push(Box::new(export::html::HtmlExporter {
            reports: reports.is_some(),
            trends: trends.cloned(),
            lang: plan.flags.lang,
        }));
    }
    if let Some(reports) = reports {
        exporters.push(Box::new(export::pdf::PdfExporter {
            reports,
            trends: trends.cloned(),
        }));
    }
    exporters
}
