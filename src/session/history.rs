//! The run appended to its inspection history, and the trends of its axes fitted over the
//! whole history (the reports show each axis over it, this run included).

use crate::history::{AxisTrends, HistoryError};
use crate::results::CampaignResult;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::Instant;

/// The run in its history.
pub struct Appended {
    /// Rows appended.
    pub rows: usize,
    /// The history file written; `None` when no test was evaluated (nothing appended).
    pub path: Option<PathBuf>,
    /// Seconds the append and the fit took.
    pub seconds: f64,
    /// Why the history could not be read back for the trends, when it could not.
    pub unread: Option<HistoryError>,
    /// The trends of the run's axes over the history.
    pub trends: Option<Arc<AxisTrends>>,
}

/// Why the run is not in its history.
#[derive(Debug, thiserror::Error)]
pub enum AppendError {
    #[error(transparent)]
    Records(HistoryError),
    #[error("appending the run to the history {}", dir.display())]
    Append {
        dir: PathBuf,
        #[source]
        source: HistoryError,
    },
}

/// Appends the run to the history in `dir` and fits the trends of the run's axes over it.
/// A history file that cannot be read (another run's, damaged) leaves the reports without
/// their history sections; it does not undo the append.
pub(super) fn append(
    result: &CampaignResult,
    dir: &Path,
    horizon: crate::trend::fit::TrendOptions,
) -> Result<Appended, AppendError> {
    let start = Instant::now();
    let records = crate::history::records(result).map_err(AppendError::Records)?;
    let path = crate::history::append(dir, &records).map_err(|source| AppendError::Append {
        dir: dir.to_path_buf(),
        source,
    })?;
    let mut appended = Appended {
        rows: records.len(),
        path,
        seconds: 0.0,
        unread: None,
        trends: None,
    };
    if appended.path.is_some() {
        match crate::history::trends_of_history(dir, &records, horizon) {
            Ok(trends) => appended.trends = Some(Arc::new(trends)),
            Err(e) => appended.unread = Some(e),
        }
    }
    appended.seconds = start.elapsed().as_secs_f64();
    Ok(appended)
}
