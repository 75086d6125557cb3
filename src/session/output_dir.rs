//! The output folder a run may write: a folder (or none yet) that holds no measurement.

use crate::campaign::Campaign;
use crate::campaign::data::DataSource;
use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum OutputDirError {
    #[error("the output folder {} is a file; choose a folder with --out", out.display())]
    IsAFile { out: PathBuf },
    #[error(
        "the output folder {} is inside the data folder {} of {machine} {axis}; choose another --out",
        out.display(),
        data.display()
    )]
    InsideData {
        out: PathBuf,
        data: PathBuf,
        machine: String,
        axis: String,
    },
}

/// Refuses an output folder that is a file, or is (or lies inside) a folder holding the
/// campaign's data, so outputs never mix with or overwrite measurements.
pub fn check_output_dir(campaign: &Campaign, out: &Path) -> Result<(), OutputDirError> {
    if out.exists() && !out.is_dir() {
        return Err(OutputDirError::IsAFile { out: out.into() });
    }
    let canonical = |p: &Path| std::fs::canonicalize(p).ok();
    let Some(out_abs) = canonical(out).or_else(|| {
        let parent = (out.parent())
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        canonical(parent).map(|p| p.join(out.file_name().unwrap_or_default()))
    }) else {
        return Ok(());
    };
    for (_, entry) in campaign.axes() {
        let Ok(axis) = &entry.spec else { continue };
        for folder in data_folders(campaign, &axis.data) {
            if let Some(data) = canonical(&folder)
                && out_abs.starts_with(&data)
            {
                return Err(OutputDirError::InsideData {
                    out: out.into(),
                    data: folder,
                    machine: entry.name.to_string(),
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
