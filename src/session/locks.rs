//! One writer per folder: the output folder and the history folder locked for the run.

use crate::lock::{FolderLock, LockError};
use std::path::{Path, PathBuf};

/// Locks the output folder and the history folder (once when they are one), in the order
/// of their real paths so that two waiting runs never hold one each. Also the one folder
/// that `trend --out` and `simulate --fleet` write. `say` hears of a lock waited for or
/// taken over.
pub fn lock_folders(
    out: &Path,
    history: Option<&Path>,
    wait: bool,
    say: &dyn Fn(&str),
) -> Result<Vec<FolderLock>, LockError> {
    let real = |p: &Path| crate::files::real_path(p).unwrap_or_else(|_| p.into());
    let mut folders: Vec<(PathBuf, &Path)> = std::iter::once(out)
        .chain(history)
        .map(|p| (real(p), p))
        .collect();
    folders.sort();
    folders.dedup_by(|a, b| a.0 == b.0);
    let mut locks = Vec::new();
    for (_, dir) in folders {
        let lock = FolderLock::acquire(dir, wait, |locked| {
            say(&format!("{locked}; waiting for it to finish (--wait)"));
        })?;
        if let Some(ended) = &lock.taken_over {
            say(&format!(
                "{} holds the lock file of a run that ended without removing it ({}); taken over",
                dir.display(),
                ended.describe()
            ));
        }
        locks.push(lock);
    }
    Ok(locks)
}
