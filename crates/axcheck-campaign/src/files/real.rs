//! Real paths: a path must stay in its folder after its symbolic links are followed, not
//! only as written. `data/x.csv` may be a link to `/etc/passwd`, or `data` a link to
//! another folder; so a path is resolved to its real path (links followed, as the system
//! will follow them when the file is opened) and compared with the real path of the
//! folder ([`super::Root`] applies the rule).

use std::path::{Component, Path, PathBuf};

/// The folder `base` as the system names it: `.` for the empty path of a campaign file
/// named without a folder.
pub(super) fn folder(base: &Path) -> &Path {
    if base.as_os_str().is_empty() {
        Path::new(".")
    } else {
        base
    }
}

/// `path` made absolute through its real folders: its nearest existing ancestor's real
/// path and the rest of it as written (the folders a run creates).
pub fn resolved(path: &Path) -> Option<PathBuf> {
    let mut rest = Vec::new();
    let mut existing = path;
    loop {
        if let Ok(real) = std::fs::canonicalize(folder(existing)) {
            return Some(
                rest.iter()
                    .rev()
                    .fold(real, |p: PathBuf, name| p.join(name)),
            );
        }
        rest.push(existing.file_name()?);
        existing = existing.parent()?;
    }
}

/// A path whose real path leaves its folder.
#[derive(Debug, Clone, PartialEq)]
pub struct OutsidePath {
    /// The path as written (relative to the folder).
    pub path: PathBuf,
    /// The link on the way that leads out, when it is not the path itself.
    pub through: Option<PathBuf>,
    /// Where it leads: the link's real path.
    pub real: PathBuf,
    /// The folder's real path.
    pub root: PathBuf,
    /// What the folder is: `campaign folder`, `templates folder`.
    pub folder: &'static str,
}

impl std::fmt::Display for OutsidePath {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (path, real, root) = (
            self.path.display(),
            dunce::simplified(&self.real).display(),
            dunce::simplified(&self.root).display(),
        );
        let folder = self.folder;
        match &self.through {
            None => write!(f, "{path} is a link to {real}, outside the {folder} {root}"),
            Some(link) => write!(
                f,
                "{path} lies in {}, a link to {real}, outside the {folder} {root}",
                link.display()
            ),
        }
    }
}

/// Refuses `base/relative` when its real path is not inside the real path of `base`.
/// A path that does not exist resolves as far as it does (a history folder a run will
/// create); one that cannot be resolved at all (a link loop) is left to the read, which
/// fails on it without reading anything.
/// `root`: the folder's real path when it is already known.
pub(crate) fn check_real(
    base: &Path,
    root: Option<&Path>,
    relative: &Path,
    folder_name: &'static str,
) -> Result<(), Box<OutsidePath>> {
    let base = folder(base);
    // Most paths are plain: no link on the way, no `..`; then they stay inside, whatever
    // the folder's real path (nothing is resolved or copied for them).
    if plain_below(base, relative) {
        return Ok(());
    }
    let root = match root {
        Some(root) => Ok(root.to_path_buf()),
        None => real_path(base),
    };
    let Ok(root) = root else {
        return Ok(());
    };
    let Ok(real) = real_path(&base.join(relative)) else {
        return Ok(());
    };
    if real.starts_with(&root) {
        return Ok(());
    }
    // Name the first link on the way that leads out (the path itself, or a folder).
    let mut prefix = PathBuf::new();
    for part in relative.components() {
        prefix.push(part);
        let full = base.join(&prefix);
        let is_link = std::fs::symlink_metadata(&full).is_ok_and(|m| m.file_type().is_symlink());
        if let (true, Ok(link_real)) = (is_link, real_path(&full))
            && !link_real.starts_with(&root)
        {
            let through = (prefix.as_path() != relative).then_some(prefix);
            return Err(Box::new(OutsidePath {
                path: relative.to_path_buf(),
                through,
                real: link_real,
                root,
                folder: folder_name,
            }));
        }
    }
    Err(Box::new(OutsidePath {
        path: relative.to_path_buf(),
        through: None,
        real,
        root,
        folder: folder_name,
    }))
}

/// Whether `base/relative` exists with no link among the components of `relative` and
/// no `..`: then its real path is the folder's real path joined with `relative` (one
/// `lstat` a component instead of resolving the folder's own path again for each file).
fn plain_below(base: &Path, relative: &Path) -> bool {
    let mut written = base.to_path_buf();
    for part in relative.components() {
        match part {
            Component::Normal(name) => written.push(name),
            Component::CurDir => continue,
            _ => return false,
        }
        match std::fs::symlink_metadata(&written) {
            Ok(m) if !m.file_type().is_symlink() => {}
            _ => return false,
        }
    }
    true
}

/// Links followed before a dangling chain is given up (the system's own limit is 40).
const MAX_LINKS: usize = 40;

/// The real path of `path`: every link followed. When the end does not exist, the part
/// that exists is resolved and the rest appended; a dangling link is followed to where
/// it points.
pub fn real_path(path: &Path) -> std::io::Result<PathBuf> {
    real_path_within(path, MAX_LINKS)
}

fn real_path_within(path: &Path, links: usize) -> std::io::Result<PathBuf> {
    let error = match std::fs::canonicalize(path) {
        Ok(real) => return Ok(real),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound && links > 0 => e,
        Err(e) => return Err(e),
    };
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if let Ok(target) = std::fs::read_link(path) {
        return real_path_within(&parent.join(target), links - 1);
    }
    match path.file_name() {
        Some(name) => Ok(real_path_within(parent, links - 1)?.join(name)),
        None => Err(error),
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::super::Root;
    use std::os::unix::fs::symlink;
    use std::path::Path;

    fn contained(
        base: &Path,
        relative: &str,
        allow_outside: bool,
    ) -> Result<std::path::PathBuf, String> {
        Root::campaign(base, allow_outside)
            .resolve(relative)
            .map_err(|refused| refused.to_string())
    }

    #[test]
    fn links_out_are_named_and_links_in_pass() {
        let top = std::env::temp_dir().join(format!("axcheck-paths-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&top);
        let (camp, away) = (top.join("camp"), top.join("away"));
        std::fs::create_dir_all(camp.join("data/sub")).unwrap();
        std::fs::create_dir_all(away.join("d")).unwrap();
        std::fs::write(camp.join("data/sub/a.csv"), "a").unwrap();
        std::fs::write(away.join("secret.csv"), "s").unwrap();
        symlink(away.join("secret.csv"), camp.join("data/out.csv")).unwrap();
        symlink("../../away/d", camp.join("data/outdir")).unwrap();
        symlink("sub/a.csv", camp.join("data/in.csv")).unwrap();
        symlink(away.join("later"), camp.join("history")).unwrap();
        let real = |p: &Path| std::fs::canonicalize(p).unwrap();

        assert!(contained(&camp, "data/in.csv", false).is_ok());
        assert!(contained(&camp, "data/sub/new/x.csv", false).is_ok());
        assert_eq!(
            contained(&camp, "data/out.csv", false).unwrap_err(),
            format!(
                "data/out.csv is a link to {}, outside the campaign folder {}; set campaign.allow_outside_paths: true to allow it",
                real(&away.join("secret.csv")).display(),
                real(&camp).display()
            )
        );
        let e = contained(&camp, "data/outdir/x.csv", false).unwrap_err();
        assert!(
            e.starts_with(&format!(
                "data/outdir/x.csv lies in data/outdir, a link to {},",
                real(&away.join("d")).display()
            )),
            "{e}"
        );
        // `..` after a link climbs from where the link points, not from where it is.
        let e = contained(&camp, "data/outdir/../secret.csv", false).unwrap_err();
        assert!(e.contains("lies in data/outdir, a link to"), "{e}");
        // A dangling link out (a history folder not created yet) is refused too.
        let e = contained(&camp, "history", false).unwrap_err();
        assert!(e.contains("history is a link to"), "{e}");
        assert!(e.contains("away/later"), "{e}");
        assert!(contained(&camp, "data/out.csv", true).is_ok());
        std::fs::remove_dir_all(top).unwrap();
    }
}
