//! A straightness test's cross tables as the campaign and the commands state them: a
//! table file in a controller's cross format, read with the files beside it that the
//! format keeps apart (HEIDENHAIN's `.CMA` beside its `.COM`), under the same path rules
//! as the pitch tables ([`super::compensate::TableFile`]).

use super::compensate::{StatedTableError, TableFile};
use crate::compensate::cross::{CrossFormat, CrossTable};
use std::path::{Path, PathBuf};

/// The file of the format's `k`-th part beside `first` (the same name, its extension).
fn beside(first: &Path, k: usize, format: &dyn CrossFormat) -> PathBuf {
    match (k, format.extensions().get(k)) {
        (0, _) | (_, None) => first.to_path_buf(),
        (_, Some(ext)) => first.with_extension(ext),
    }
}

/// One part's path and text.
fn part(
    at: TableFile,
    k: usize,
    format: &dyn CrossFormat,
) -> Result<(PathBuf, String), StatedTableError> {
    let (path, text) = match at {
        TableFile::Stated { files, file, key } => {
            let name = beside(Path::new(file), k, format);
            let path = files
                .resolve(&name.to_string_lossy())
                .map_err(|refused| StatedTableError::Path { key, refused })?;
            let text = files.read_to_string(&path);
            (path, text)
        }
        TableFile::Given { path, .. } => {
            let path = beside(path, k, format);
            let text = crate::files::read_to_string(&path);
            (path, text)
        }
    };
    let text = text.map_err(|e| StatedTableError::Unreadable {
        path: path.clone(),
        reason: e.to_string(),
    })?;
    Ok((path, text))
}

/// The cross table at `at` as `format` reads it (with its other parts beside it).
pub fn read_cross_table(
    at: TableFile,
    format: &dyn CrossFormat,
) -> Result<CrossTable, StatedTableError> {
    let parts = (0..format.extensions().len())
        .map(|k| part(at, k, format))
        .collect::<Result<Vec<_>, _>>()?;
    let texts: Vec<&str> = parts.iter().map(|(_, t)| t.as_str()).collect();
    let key = match at {
        TableFile::Stated { key, .. } | TableFile::Given { key, .. } => key,
    };
    format
        .read(&texts)
        .map_err(|e| StatedTableError::NotATable {
            path: parts.first().map(|(p, _)| p.clone()).unwrap_or_default(),
            reason: e.to_string(),
            controller: format.name(),
            key,
        })
}
