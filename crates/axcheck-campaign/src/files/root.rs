//! A folder whose files axcheck reads, with its rules in one place: a campaign's folder
//! (data files, specs, tables, the history's path), a templates folder, a history folder.
//!
//! - the written rule: a path a campaign names is relative to its folder; absolute paths
//!   and `..` that climbs out are refused unless the campaign sets `allow_outside_paths`;
//! - the real-path rule ([`super::real`]): followed through its links, the path stays in
//!   the folder's real path, resolved once;
//! - the file is opened only if it is a regular file, and what the system opened is
//!   checked against the folder's real path again ([`super::open_within`]): a link
//!   swapped after the check is refused before a byte is read. On Linux a handle on the
//!   folder does both checks in the kernel ([`super::beneath`]), and the portable rules
//!   decide only what it refuses.

use super::beneath::Handle;
use super::digest::{Recorder, relative_to, sha256_hex, sha256_of};
use super::real::{OutsidePath, check_real, folder, real_path};
use super::{FileError, Opened};
use std::fs::File;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// What to tell the user when a campaign path leads outside.
const CAMPAIGN_HINT: &str = "set campaign.allow_outside_paths: true to allow it";

/// A path a campaign names that its folder's rules refuse.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum PathRefused {
    #[error("path `{}` contains a NUL byte", .0.escape_debug())]
    Nul(String),
    #[error("path `{0}` is absolute; paths in a campaign are relative to its folder ({hint})", hint = CAMPAIGN_HINT)]
    Absolute(String),
    /// Windows: `C:data\x.csv` is relative to drive C's current folder, not this one.
    #[error("path `{0}` names a drive; paths in a campaign are relative to its folder ({hint})", hint = CAMPAIGN_HINT)]
    Drive(String),
    #[error("path `{0}` leaves the campaign's folder; {hint}", hint = CAMPAIGN_HINT)]
    Leaves(String),
    /// Followed through its links, the path leaves the folder's real path.
    #[error("{0}; {hint}", hint = CAMPAIGN_HINT)]
    Outside(Box<OutsidePath>),
}

/// A folder and its rules.
#[derive(Debug, Clone)]
pub struct Root {
    dir: PathBuf,
    /// The folder's real path: every file opened must lie in it. `None` when paths
    /// outside are allowed, or when the folder cannot be resolved (nothing can be read
    /// from it then).
    real: Option<PathBuf>,
    allow_outside: bool,
    /// For messages: `campaign folder`, `templates folder`, `history folder`.
    name: &'static str,
    /// A handle on the folder at its real path, that files are opened beneath (Linux).
    handle: Option<Arc<Handle>>,
    /// Where each file read is noted with its SHA-256 ([`Root::recording`]).
    recorder: Option<Arc<Recorder>>,
}

impl Root {
    /// A campaign's folder (`allow_outside`: its `allow_outside_paths`).
    pub fn campaign(dir: &Path, allow_outside: bool) -> Root {
        let real = (!allow_outside)
            .then(|| real_path(folder(dir)).ok())
            .flatten();
        Root {
            dir: dir.to_path_buf(),
            handle: real.as_deref().and_then(Handle::open).map(Arc::new),
            real,
            allow_outside,
            name: "campaign folder",
            recorder: None,
        }
    }

    /// This folder, noting every file read through it (and its clones) with its SHA-256:
    /// [`Root::recorded`].
    pub fn recording(self) -> Root {
        Root {
            recorder: Some(Arc::default()),
            ..self
        }
    }

    /// The files read so far with their SHA-256, sorted by path (relative to the folder);
    /// empty unless [`Root::recording`].
    pub fn recorded(&self) -> Vec<super::InputFile> {
        self.recorder.as_ref().map_or_else(Vec::new, |r| r.files())
    }

    /// Another folder (`name` for messages): nothing outside it is ever read.
    pub fn folder(dir: &Path, name: &'static str) -> Root {
        Root {
            name,
            ..Root::campaign(dir, false)
        }
    }

    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// The folder's real path every file opened must lie in (`None`: no such check).
    pub fn real(&self) -> Option<&Path> {
        self.real.as_deref()
    }

    /// `dir/relative` under the written rule and, unless outside paths are allowed, the
    /// real-path rule (the rule for data files, specs, tables and the history).
    pub fn resolve(&self, relative: &str) -> Result<PathBuf, PathRefused> {
        let path = self.written(relative)?;
        if !self.allow_outside {
            self.check(Path::new(relative))
                .map_err(PathRefused::Outside)?;
        }
        Ok(path)
    }

    /// `dir/relative` under the written rule only: absolute paths and paths that leave the
    /// folder are refused unless outside paths are allowed.
    pub fn written(&self, relative: &str) -> Result<PathBuf, PathRefused> {
        if relative.contains('\0') {
            return Err(PathRefused::Nul(relative.to_string()));
        }
        let rel = Path::new(relative);
        if !self.allow_outside {
            if rel.is_absolute() || rel.has_root() {
                return Err(PathRefused::Absolute(relative.to_string()));
            }
            // Windows: `C:data\x.csv` is relative to drive C's current folder, not this one.
            if let Some(Component::Prefix(_)) = rel.components().next() {
                return Err(PathRefused::Drive(relative.to_string()));
            }
            let mut depth: i64 = 0;
            for c in rel.components() {
                match c {
                    Component::ParentDir => depth -= 1,
                    Component::Normal(_) => depth += 1,
                    _ => {}
                }
                if depth < 0 {
                    return Err(PathRefused::Leaves(relative.to_string()));
                }
            }
        }
        Ok(self.dir.join(rel))
    }

    /// The real-path rule for `relative` (a path inside the folder as written).
    /// Boxed: the message's four paths are large (144 bytes on Windows).
    pub fn check(&self, relative: &Path) -> Result<(), Box<OutsidePath>> {
        // A path beneath the folder with no link on its way stays inside: one system call.
        if self.handle.as_ref().is_some_and(|h| h.plain(relative)) {
            return Ok(());
        }
        check_real(&self.dir, self.real(), relative, self.name)
    }

    /// The real-path rule for each file a walk found under the folder (unless outside
    /// paths are allowed).
    pub(crate) fn check_found(&self, found: &[PathBuf]) -> Result<(), PathRefused> {
        if self.allow_outside {
            return Ok(());
        }
        for path in found {
            let relative = path.strip_prefix(&self.dir).unwrap_or(path);
            self.check(relative).map_err(PathRefused::Outside)?;
        }
        Ok(())
    }

    /// Opens `path` ([`super::open_within`] this folder's real path).
    pub fn open(&self, path: &Path) -> Result<Opened, FileError> {
        let relative = path.strip_prefix(&self.dir).ok();
        match (&self.handle, relative) {
            (Some(handle), Some(relative)) => {
                super::open_beneath(handle, relative, path, self.real())
            }
            _ => super::open_within(path, self.real()),
        }
    }

    /// Opens `path`, gives it to `read`, and refuses the result when the file changed.
    /// When recording, the file is hashed from its start once `read` is done, through the
    /// same handle (before the check that it did not change).
    pub fn read_with<T>(
        &self,
        path: &Path,
        read: impl FnOnce(&mut File) -> T,
    ) -> Result<T, FileError> {
        let Some(recorder) = &self.recorder else {
            return super::read_opened(self.open(path)?, read);
        };
        let mut opened = self.open(path)?;
        let value = read(&mut opened.file);
        use std::io::{Seek, SeekFrom};
        opened.file.seek(SeekFrom::Start(0))?;
        let sha256 = sha256_of(&mut opened.file)?;
        opened.check_unchanged()?;
        recorder.note(relative_to(path, &self.dir), sha256);
        Ok(value)
    }

    /// The bytes of `path` (hashed as they are, when recording).
    pub fn read(&self, path: &Path) -> Result<Vec<u8>, FileError> {
        let bytes = super::read_opened(self.open(path)?, super::bytes)?.map_err(FileError::Io)?;
        if let Some(recorder) = &self.recorder {
            recorder.note(relative_to(path, &self.dir), sha256_hex(&bytes));
        }
        Ok(bytes)
    }

    /// The text of `path` (UTF-8).
    pub fn read_to_string(&self, path: &Path) -> Result<String, FileError> {
        super::utf8(self.read(path)?)
    }
}

/// A walked entry a glob may match: anything but a folder or a link to one. Links to
/// files and special files are matches, so that they are checked and refused by name
/// instead of silently left out.
pub fn may_match(entry: &walkdir::DirEntry) -> bool {
    let kind = entry.file_type();
    if kind.is_symlink() {
        return !std::fs::metadata(entry.path()).is_ok_and(|m| m.is_dir());
    }
    !kind.is_dir()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_stay_inside_unless_allowed() {
        let root = Root::campaign(Path::new("camp"), false);
        assert_eq!(
            root.written("data/x.csv").unwrap(),
            Path::new("camp/data/x.csv")
        );
        assert!(
            root.written("/etc/passwd")
                .unwrap_err()
                .to_string()
                .contains("absolute")
        );
        assert!(
            root.written("../x.csv")
                .unwrap_err()
                .to_string()
                .contains("leaves the campaign's folder")
        );
        assert!(root.written("a/../../x").is_err());
        assert!(root.written("a/../b").is_ok());
        assert!(
            root.written("x\0y")
                .unwrap_err()
                .to_string()
                .contains("NUL")
        );
        let open = Root::campaign(Path::new("camp"), true);
        assert_eq!(
            open.written("/data/x.csv").unwrap(),
            Path::new("/data/x.csv")
        );
        assert!(open.real().is_none());
    }
}
