//! `summary.pdf` and `reports/<machine>/<axis>.pdf`, typeset in parallel.

use super::{ExportError, Exporter, OutputFile};
use crate::history::AxisTrends;
use crate::report::{self, Reports};
use crate::results::CampaignResult;
use std::path::PathBuf;
use std::sync::Arc;

pub(crate) struct PdfExporter {
    pub reports: Reports,
    /// The trends of the run's axes over the inspection history, when the run keeps one:
    /// each axis report gets its history section, the summary the flagged series.
    pub trends: Option<Arc<AxisTrends>>,
}

/// Reports typeset between two evictions of Typst's caches.
const REPORTS_PER_EVICTION: usize = 32;

impl Exporter for PdfExporter {
    fn name(&self) -> &'static str {
        "pdf"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let paths = super::paths::test_paths(result, "reports", "pdf");
        // The summary first: it is the longest job (one table row per axis: 1.5 s for
        // 1 000 axes) and should not be left to the end.
        let jobs: Vec<Job> = std::iter::once(Job::Summary)
            .chain(result.tests.iter().zip(paths).map(|(t, p)| Job::Axis(t, p)))
            .collect();
        let mut files = typeset_all(&jobs, rayon::current_num_threads(), |job| match job {
            Job::Summary => Ok(OutputFile::new(
                "summary.pdf",
                (self.reports)
                    .summary_with_trends(result, self.trends.as_deref())?
                    .pdf,
            )),
            Job::Axis(test, path) => Ok(OutputFile::new(
                path.clone(),
                (self.reports)
                    .axis_with_history(result, test, self.trends.as_deref())?
                    .pdf,
            )),
        })
        .map_err(|e| ExportError::Format {
            format: "pdf",
            message: e.to_string(),
        })?;
        // Axis reports in campaign order, then the summary (the order of the listing).
        files.rotate_left(1);
        Ok(files)
    }
}

/// One document to typeset.
enum Job<'a> {
    Summary,
    Axis(&'a crate::results::AxisTest, PathBuf),
}

/// Typesets every job with `workers` threads of its own, each taking the next job as soon as
/// it is free, and returns the files in the jobs' order; the first error stops the others.
///
/// Why not one rayon pool for all reports: a rayon worker that waits inside Typst's own
/// parallel page layout takes up other queued work on the same stack, so reports nested on
/// one worker (stack overflow on 1 000 reports), and bounding that with chunks left cores
/// idle at every chunk's end (about a fifth of the run). Here each worker is the single
/// thread of a rayon pool of its own and runs a report from start to end, its page layout
/// included (no hand-off to a shared pool, no other report to take up while it waits),
/// with fonts of its own ([`report::typeset::world::on_font_lane`]).
/// Typst's caches are evicted after every [`REPORTS_PER_EVICTION`] finished reports,
/// which keeps memory bounded; comemo's caches are safe to evict while others compile.
fn typeset_all<'a>(
    jobs: &'a [Job<'a>],
    workers: usize,
    typeset: impl Fn(&Job<'a>) -> Result<OutputFile<'static>, report::ReportError> + Sync,
) -> Result<Vec<OutputFile<'static>>, report::ReportError> {
    use std::sync::atomic::{AtomicUsize, Ordering};
    let finished = AtomicUsize::new(0);
    let in_own_pool =
        |thread: usize, work: &(dyn Fn() + Sync)| match rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .stack_size(WORKER_STACK)
            .build()
        {
            Ok(pool) => {
                pool.install(|| report::typeset::world::on_font_lane(thread, work));
                Ok(())
            }
            Err(e) => Err(report::ReportError::Typeset {
                document: "reports".into(),
                message: format!("a typesetting thread could not be started: {e}"),
            }),
        };
    let files = super::workers::map_in_order(jobs, workers, in_own_pool, |job| {
        let file = typeset(job);
        if (finished.fetch_add(1, Ordering::Relaxed) + 1).is_multiple_of(REPORTS_PER_EVICTION) {
            report::evict_caches();
        }
        file
    });
    report::evict_caches();
    files
}

/// Stack of a typesetting thread: Typst's layout recurses deeply on nested content.
const WORKER_STACK: usize = 64 << 20;
