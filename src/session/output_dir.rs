//! The output folder a run may write: a folder (or none yet) that holds no measurement.

use crate::campaign::Campaign;
use crate::campaign::data::DataSource;
use crate::files::resolved;
use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum OutputDirError {
    #[error("the output folder {} is a file; choose a folder with --out", out.display())]
    IsAFile { out: PathBuf },
    #[error(
        "the output folder {} is inside the data folder {} of machine `{machine}` axis `{axis}`; choose another --out",
        out.display(),
        data.display()
    )]
    InsideData {
        out: PathBuf,
        data: PathBuf,
        machine: String,
        axis: String,
    },
    #[error(
        "the history folder {} {how} the output folder {}: the outputs (summary.parquet among them) would be read as inspections and break the history; keep the history in a folder of its own (--history or campaign.history)",
        history.display(),
        out.display()
    )]
    HistoryOverlaps {
        history: PathBuf,
        out: PathBuf,
        how: &'static str,
    },
}

/// Refuses a history folder that is the output folder, lies inside it or holds it.
pub(crate) fn check_history_dir(out: &Path, history: &Path) -> Result<(), OutputDirError> {
    let (Some(out_abs), Some(history_abs)) = (resolved(out), resolved(history)) else {
        return Ok(());
    };
    let how = match () {
        _ if out_abs == history_abs => "is",
        _ if history_abs.starts_with(&out_abs) => "is inside",
        _ if out_abs.starts_with(&history_abs) => "holds",
        _ => return Ok(()),
    };
    Err(OutputDirError::HistoryOverlaps {
        history: history.into(),
        out: out.into(),
        how,
    })
}

/// Refuses an output folder that is a file, or is (or lies inside) a folder holding the
/// campaign's data, so outputs never mix with or overwrite measurements.
pub fn check_output_dir(campaign: &Campaign, out: &Path) -> Result<(), OutputDirError> {
    if out.exists() && !out.is_dir() {
        return Err(OutputDirError::IsAFile { out: out.into() });
    }
    let canonical = |p: &Path| std::fs::canonicalize(p).ok();
    let Some(out_abs) = resolved(out) else {
        return Ok(());
    };
    for (machine, entry) in campaign.axes() {
        let Ok(axis) = &entry.spec else { continue };
        for folder in data_folders(campaign, &axis.data) {
            if let Some(data) = canonical(&folder)
                && out_abs.starts_with(&data)
            {
                return Err(OutputDirError::InsideData {
                    out: out.into(),
                    data: folder,
                    machine: machine.info.id.clone(),
                    axis: axis.raw.name.clone(),
                });
            }
        }
    }
    Ok(())
}

/// The folders an axis's data files are in.
fn data_folders(campaign: &Campaign, data: &DataSource) -> Vec<PathBuf> {
    let parent = |f: &str| campaign.dir.join(f).parent().map(Path::to_path_buf);
    match data {
        DataSource::Files(files) => files.iter().filter_map(|f| parent(f)).collect(),
        DataSource::Glob { dir, .. } => vec![campaign.dir.join(dir)],
        DataSource::Book { file, .. } => parent(file).into_iter().collect(),
    }
}
