//! The inspection history: every run's axis results appended to a dataset of Parquet files
//! (one per campaign run, identified by campaign name and date: a rerun replaces its file),
//! read back as trend series. The rows, series and trends are `axcheck-campaign`'s
//! (re-exported here); this module is the store, at the edge, and a test's history as its
//! report and page show it ([`history_of`]).
//!
//! Layout: `DIR/year=YYYY/<campaign-slug>_<YYYY-MM-DD>.parquet` (Hive-style partitions, so
//! DuckDB and polars add a `year` column when asked). Each file is written atomically
//! ([`crate::atomic::write`]: `.NAME.axcheck-tmp-PID`, then a rename), so a reader sees a
//! complete file or none, and temporary files never match `*.parquet`.

pub use axcheck_campaign::history::*;

mod charts;
#[cfg(feature = "parquet")]
mod footer;
#[cfg(feature = "parquet")]
mod pages;
#[cfg(feature = "parquet")]
mod store;

pub use charts::{History, HistoryChart, history_of};
#[cfg(feature = "parquet")]
pub use store::{append, file_path, history_files, read, read_bytes, visit};

/// The trends of the run's axes (`run`'s records) over the history in `dir`, read file by
/// file: only the run's axes' series are kept, never the whole history.
#[cfg(feature = "parquet")]
pub(crate) fn trends_of_history(
    dir: &std::path::Path,
    run: &[Record],
    options: crate::trend::TrendOptions,
) -> Result<AxisTrends, HistoryError> {
    AxisTrends::of_run(run, options, |add| visit(dir, add))
}
