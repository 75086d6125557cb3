//! Safe file output.
//!
//! [`write()`] is atomic: the bytes go to a temporary file beside the target
//! (`.NAME.axcheck-tmp-PID`), are synced, then renamed over it, so a reader (or a run
//! killed part-way) sees the old complete file or the new complete one, never a part.
//!
//! [`OutputDir`] is an output folder axcheck shares with its user. It records what axcheck
//! wrote in a manifest ([`MANIFEST`], one relative path per line, written atomically) and
//! replaces or removes only what that lists: an existing file at an output path that is not
//! listed is refused before anything is written. The protocol keeps the manifest a
//! superset of axcheck's files on disk at every moment, so a kill anywhere never turns
//! axcheck's own file into a "foreign" one:
//!
//! 1. [`OutputDir::open`] reads the manifest of the previous run;
//! 2. [`OutputDir::check`] refuses any path in the way (foreign file, folder, link);
//! 3. [`OutputDir::prepare`] removes stale temporary files of killed runs and writes the
//!    manifest as previous ∪ new, before any output;
//! 4. [`OutputDir::write`] writes each file atomically;
//! 5. [`OutputDir::finish`] removes the previous run's outputs this run no longer produces
//!    (an axis taken out of the campaign, PDFs after `--no-pdf`), then writes the manifest
//!    with exactly this run's outputs and `# complete: true`; after a failed write
//!    [`OutputDir::finish_incomplete`] does the same without the outputs it could not
//!    write (their older copies removed too) and records `# complete: false` and each
//!    `# missing: PATH`. Until then the manifest says `# complete: false`, so a folder
//!    whose run was stopped while writing says so as well.
//!
//! Each manifest write is followed by a sync of the folder ([`sync_dir`]), so a power loss
//! keeps the old manifest or the new one, and never a removal the manifest has forgotten.
//! One run at a time per folder is the caller's part ([`crate::lock`] is above this layer;
//! `run` takes it before [`OutputDir::open`]).

use std::collections::BTreeSet;
use std::io::Write;
use std::path::{Component, Path, PathBuf};

/// Writes `bytes` to `path` atomically, creating parent folders.
pub fn write(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    write_with(path, &|file| file.write_all(bytes))
}

/// Writes what `make` writes to `path` atomically (through a buffer), creating parent
/// folders: an output made as it is written, never held whole.
pub fn write_with(
    path: &Path,
    make: &dyn Fn(&mut dyn Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "output".into());
    let tmp = dir.join(temp_name(&name, std::process::id()));
    let result = (|| {
        let mut file = std::io::BufWriter::with_capacity(1 << 16, std::fs::File::create(&tmp)?);
        make(&mut file)?;
        let file = file.into_inner().map_err(|e| e.into_error())?;
        file.sync_all()?;
        std::fs::rename(&tmp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Makes the renames and removals in `dir` durable: after a power loss the folder holds
/// the old names or the new ones (a rename is atomic, but stays in memory until its
/// folder is synced). A no-op where folders cannot be opened (Windows).
pub fn sync_dir(dir: &Path) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        std::fs::File::open(dir)?.sync_all()
    }
    #[cfg(not(unix))]
    {
        let _ = dir;
        Ok(())
    }
}

const TEMP_MARK: &str = ".axcheck-tmp-";

/// The temporary name [`write()`] uses for `name` in process `pid`.
fn temp_name(name: &str, pid: u32) -> String {
    format!(".{name}{TEMP_MARK}{pid}")
}

/// The output name and process id of a temporary file name of [`write()`].
fn parse_temp_name(file_name: &str) -> Option<(&str, u32)> {
    let rest = file_name.strip_prefix('.')?;
    let at = rest.rfind(TEMP_MARK)?;
    let pid = &rest[at + TEMP_MARK.len()..];
    if pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    Some((&rest[..at], pid.parse().ok()?))
}

/// True when process `pid` still runs (Linux: `/proc/PID`); elsewhere assumed gone.
fn process_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        // Our own writes have not started: a file with our id is from an earlier process.
        return false;
    }
    cfg!(target_os = "linux") && Path::new("/proc").join(pid.to_string()).exists()
}

/// The manifest of an output folder: what axcheck wrote there.
pub const MANIFEST: &str = ".axcheck-outputs";
const MANIFEST_HEADER: &str = "# axcheck output manifest: the files (and folders, ending in /) that `axcheck run` wrote in this folder.\n# axcheck replaces or removes only what is listed here; do not edit.\n";
const MANIFEST_MAGIC: &str = "# axcheck output manifest";

/// Why an output folder cannot take this run's outputs.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    #[error(
        "{path} already exists and was not written by axcheck (it is not listed in {manifest}); axcheck never replaces a file it did not create: remove or move it, or choose another --out"
    )]
    Foreign { path: PathBuf, manifest: PathBuf },
    #[error(
        "{path} is in the way of the output {output}: it is {what}, and axcheck writes only files into real folders; remove or move it, or choose another --out"
    )]
    InTheWay {
        path: PathBuf,
        output: PathBuf,
        what: &'static str,
    },
    #[error(
        "{path} is not a valid axcheck output manifest (line {line}: {problem}); remove it only if every file it lists may be replaced, or choose another --out"
    )]
    BadManifest {
        path: PathBuf,
        line: usize,
        problem: String,
    },
    // `cause`, not `source`: a source is printed again after the message (`{e:#}`).
    #[error("cannot write {path}: {cause}")]
    Io {
        path: PathBuf,
        cause: std::io::Error,
    },
    #[error(
        "cannot replace {path}: {cause}; another program has it open (a PDF viewer, Excel): close it there and run again"
    )]
    InUse {
        path: PathBuf,
        cause: std::io::Error,
    },
}

fn io_error(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
    move |cause| OutputError::Io {
        path: path.to_path_buf(),
        cause,
    }
}

/// An output folder and what axcheck wrote there before (see the module notes).
#[derive(Debug)]
pub struct OutputDir {
    root: PathBuf,
    /// Files listed in the manifest of the previous run.
    owned_files: BTreeSet<PathBuf>,
    /// Folders axcheck created, from the same manifest.
    owned_dirs: BTreeSet<PathBuf>,
    /// This run's outputs, once [`OutputDir::prepare`]d.
    new_files: BTreeSet<PathBuf>,
    new_dirs: BTreeSet<PathBuf>,
    /// The outputs this run could not write.
    missing: BTreeSet<PathBuf>,
}

/// What is at a path, without following a final symbolic link.
enum Entry {
    Missing,
    File,
    Dir,
    Other(&'static str),
}

/// `path`, an output itself, is taken by `what` (a folder, a link …).
fn in_the_way(path: PathBuf, what: &'static str) -> OutputError {
    OutputError::InTheWay {
        output: path.clone(),
        path,
        what,
    }
}

fn entry(path: &Path) -> Result<Entry, OutputError> {
    match std::fs::symlink_metadata(path) {
        Ok(m) if m.file_type().is_symlink() => Ok(Entry::Other("a symbolic link")),
        Ok(m) if m.is_file() => Ok(Entry::File),
        Ok(m) if m.is_dir() => Ok(Entry::Dir),
        Ok(_) => Ok(Entry::Other("not a regular file")),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(Entry::Missing),
        Err(e) => Err(io_error(path)(e)),
    }
}

/// A manifest entry: `/`-separated plain names ([`plain_name`]), the same text on every
/// platform (a manifest written on Windows reads on Linux and back).
fn clean_relative(text: &str) -> Option<PathBuf> {
    if text.is_empty() {
        return None;
    }
    let mut path = PathBuf::new();
    for name in text.split('/') {
        path.push(plain_name(name)?);
    }
    Some(path)
}

/// An output path as the exporters make it (with the platform's separator: `\` on
/// Windows): plain names only, no root, drive, `.` or `..`.
fn clean_output(path: &Path) -> Option<PathBuf> {
    let mut clean = PathBuf::new();
    for part in path.components() {
        match part {
            Component::Normal(name) => clean.push(plain_name(name.to_str()?)?),
            _ => return None,
        }
    }
    (!clean.as_os_str().is_empty()).then_some(clean)
}

/// A file or folder name that means itself on every platform: not empty, `.` or `..`; no
/// separator (`/`, `\`), NUL, or `:` (a drive or an NTFS stream); no trailing dot or space
/// (Windows drops them, so `a.` would be `a`).
fn plain_name(name: &str) -> Option<&str> {
    let plain = !matches!(name, "" | "." | "..")
        && !name.contains(['/', '\\', '\0', ':'])
        && !name.ends_with(['.', ' ']);
    plain.then_some(name)
}

/// `path` as a manifest line: `/`-separated whatever the platform.
fn manifest_line(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

/// The folders between the root and `path` (exclusive of both), outermost first.
fn ancestors(path: &Path) -> Vec<PathBuf> {
    let mut dirs: Vec<PathBuf> = path
        .ancestors()
        .skip(1)
        .filter(|p| !p.as_os_str().is_empty())
        .map(Path::to_path_buf)
        .collect();
    dirs.reverse();
    dirs
}

impl OutputDir {
    /// Reads the manifest of `root` (none when the folder or the manifest does not
    /// exist yet); writes nothing.
    pub fn open(root: &Path) -> Result<OutputDir, OutputError> {
        let mut dir = OutputDir {
            root: root.to_path_buf(),
            owned_files: BTreeSet::new(),
            owned_dirs: BTreeSet::new(),
            new_files: BTreeSet::new(),
            new_dirs: BTreeSet::new(),
            missing: BTreeSet::new(),
        };
        let path = dir.manifest_path();
        match entry(&path)? {
            Entry::Missing => return Ok(dir),
            Entry::File => {}
            Entry::Dir => return Err(in_the_way(path, "a folder")),
            Entry::Other(what) => return Err(in_the_way(path, what)),
        }
        let bad = |line: usize, problem: &str| OutputError::BadManifest {
            path: path.clone(),
            line,
            problem: problem.to_string(),
        };
        // A regular file now, but read as one even if swapped for a pipe since the check.
        let bytes = crate::files::read(&path).map_err(|e| io_error(&path)(e.into()))?;
        let text = String::from_utf8(bytes).map_err(|_| bad(1, "not UTF-8 text"))?;
        if !text.starts_with(MANIFEST_MAGIC) {
            return Err(bad(1, "it does not start with `# axcheck output manifest`"));
        }
        for (k, line) in text.lines().enumerate() {
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let (text, is_dir) = match line.strip_suffix('/') {
                Some(d) => (d, true),
                None => (line, false),
            };
            let entry = clean_relative(text).ok_or_else(|| {
                bad(
                    k + 1,
                    &format!("`{line}` is not a relative path inside the folder"),
                )
            })?;
            if is_dir {
                dir.owned_dirs.insert(entry);
            } else {
                dir.owned_files.insert(entry);
            }
        }
        Ok(dir)
    }

    fn manifest_path(&self) -> PathBuf {
        self.root.join(MANIFEST)
    }

    /// Refuses the first of `outputs` (relative paths) that would replace a file axcheck
    /// did not write, or whose place is taken by a folder, a link or something else.
    pub fn check<'a>(
        &self,
        outputs: impl IntoIterator<Item = &'a Path>,
    ) -> Result<(), OutputError> {
        for output in outputs {
            let Some(relative) = clean_output(output) else {
                return Err(OutputError::Io {
                    path: self.root.join(output),
                    cause: std::io::Error::other("not a relative path inside the output folder"),
                });
            };
            for dir in ancestors(&relative) {
                let path = self.root.join(&dir);
                match entry(&path)? {
                    Entry::Missing => break,
                    Entry::Dir => {}
                    Entry::File => {
                        return Err(OutputError::InTheWay {
                            path,
                            output: self.root.join(&relative),
                            what: "a file",
                        });
                    }
                    Entry::Other(what) => {
                        return Err(OutputError::InTheWay {
                            path,
                            output: self.root.join(&relative),
                            what,
                        });
                    }
                }
            }
            let path = self.root.join(&relative);
            match entry(&path)? {
                Entry::Missing => {}
                Entry::File if self.owned_files.contains(&relative) => {}
                Entry::File => {
                    return Err(OutputError::Foreign {
                        path,
                        manifest: self.manifest_path(),
                    });
                }
                Entry::Dir => return Err(in_the_way(path, "a folder")),
                Entry::Other(what) => return Err(in_the_way(path, what)),
            }
        }
        Ok(())
    }

    /// Before writing `outputs` (already [`check`](OutputDir::check)ed): removes the
    /// temporary files that killed runs left beside axcheck's outputs, and records the
    /// previous and the new outputs in the manifest.
    pub fn prepare<'a>(
        &mut self,
        outputs: impl IntoIterator<Item = &'a Path>,
    ) -> Result<(), OutputError> {
        self.new_files = outputs.into_iter().map(Path::to_path_buf).collect();
        self.new_dirs = self
            .new_files
            .iter()
            .flat_map(|p| ancestors(p))
            .filter(|d| {
                // Folders this run creates, and those an earlier run created.
                self.owned_dirs.contains(d) || !self.root.join(d).exists()
            })
            .collect();
        std::fs::create_dir_all(&self.root).map_err(io_error(&self.root))?;
        self.remove_stale_temporaries()?;
        let files: BTreeSet<&PathBuf> = self.owned_files.iter().chain(&self.new_files).collect();
        let dirs: BTreeSet<&PathBuf> = self.owned_dirs.iter().chain(&self.new_dirs).collect();
        self.write_manifest(&files, &dirs, false)
    }

    /// Writes one output (a relative path given to [`prepare`](OutputDir::prepare)).
    pub fn write(&self, output: &Path, bytes: &[u8]) -> Result<(), OutputError> {
        self.write_with(output, &|file| file.write_all(bytes))
    }

    /// Writes one output as [`write_with`] does.
    pub fn write_with(
        &self,
        output: &Path,
        make: &dyn Fn(&mut dyn Write) -> std::io::Result<()>,
    ) -> Result<(), OutputError> {
        let path = self.root.join(output);
        write_with(&path, make).map_err(|cause| {
            // Windows refuses to replace a file another program holds open (without
            // allowing its deletion, or at all before Windows 10 1809 and on FAT and
            // network shares); elsewhere the same error means a folder not writable.
            let in_use = cfg!(windows)
                && cause.kind() == std::io::ErrorKind::PermissionDenied
                && path.is_file();
            match in_use {
                true => OutputError::InUse { path, cause },
                false => OutputError::Io { path, cause },
            }
        })
    }

    /// After some outputs could not be written (`missing`): finishes as [`finish`] would
    /// with the outputs that were written, so an older copy of a missing output is removed
    /// too (the folder never mixes two runs), and records the run as incomplete with what
    /// is missing.
    ///
    /// [`finish`]: OutputDir::finish
    pub fn finish_incomplete(mut self, missing: BTreeSet<PathBuf>) -> Result<(), OutputError> {
        self.new_files.retain(|p| !missing.contains(p));
        self.missing = missing;
        self.finish()
    }

    /// After every output is written: removes the previous run's outputs this run did not
    /// produce (and the folders axcheck created for them, when empty), and records exactly
    /// this run's outputs.
    pub fn finish(self) -> Result<(), OutputError> {
        let mut emptied = BTreeSet::new();
        for stale in self.owned_files.difference(&self.new_files) {
            let path = self.root.join(stale);
            // Only a regular file inside real folders: never through a link.
            let inside = ancestors(stale)
                .iter()
                .all(|d| matches!(entry(&self.root.join(d)), Ok(Entry::Dir)));
            if inside && matches!(entry(&path)?, Entry::File) {
                std::fs::remove_file(&path).map_err(io_error(&path))?;
                emptied.insert(path.parent().map(Path::to_path_buf).unwrap_or_default());
            }
        }
        // The removals reach the disk before the manifest that no longer lists them: a
        // power loss must not bring back a file the manifest has forgotten.
        for dir in &emptied {
            sync_dir(dir).map_err(io_error(dir))?;
        }
        // Deepest first; a folder that is not empty (a user's file in it) stays.
        let unused: Vec<&PathBuf> = self.owned_dirs.difference(&self.new_dirs).collect();
        for dir in unused.into_iter().rev() {
            let path = self.root.join(dir);
            if matches!(entry(&path)?, Entry::Dir) {
                let _ = std::fs::remove_dir(&path);
            }
        }
        let files: BTreeSet<&PathBuf> = self.new_files.iter().collect();
        let dirs: BTreeSet<&PathBuf> = self.new_dirs.iter().collect();
        self.write_manifest(&files, &dirs, self.missing.is_empty())
    }

    /// The manifest: the header, whether the run is complete (and what it could not
    /// write), then the files and folders.
    fn write_manifest(
        &self,
        files: &BTreeSet<&PathBuf>,
        dirs: &BTreeSet<&PathBuf>,
        complete: bool,
    ) -> Result<(), OutputError> {
        let mut lines: Vec<String> = files
            .iter()
            .map(|p| manifest_line(p))
            .chain(dirs.iter().map(|d| format!("{}/", manifest_line(d))))
            .collect();
        lines.sort();
        let mut text = String::from(MANIFEST_HEADER);
        text.push_str(&format!("# complete: {complete}\n"));
        for missing in &self.missing {
            text.push_str(&format!("# missing: {}\n", manifest_line(missing)));
        }
        for line in lines {
            text.push_str(&line);
            text.push('\n');
        }
        let path = self.manifest_path();
        write(&path, text.as_bytes()).map_err(io_error(&path))?;
        // The manifest's rename reaches the disk before any output is written (prepare)
        // and before the run ends (finish): a power loss keeps the old or the new one.
        sync_dir(&self.root).map_err(io_error(&self.root))
    }

    /// Removes `.NAME.axcheck-tmp-PID` files of processes that no longer run, where NAME
    /// is one of axcheck's outputs (previous or new) in that folder, or the manifest.
    fn remove_stale_temporaries(&self) -> Result<(), OutputError> {
        let mut names: BTreeSet<(PathBuf, String)> = BTreeSet::new();
        names.insert((PathBuf::new(), MANIFEST.to_string()));
        for file in self.owned_files.iter().chain(&self.new_files) {
            if let Some(name) = file.file_name() {
                let dir = file.parent().map(Path::to_path_buf).unwrap_or_default();
                names.insert((dir, name.to_string_lossy().into_owned()));
            }
        }
        let dirs: BTreeSet<&PathBuf> = names.iter().map(|(d, _)| d).collect();
        for dir in dirs {
            let inside = ancestors(&dir.join("x"))
                .iter()
                .all(|d| matches!(entry(&self.root.join(d)), Ok(Entry::Dir)));
            let folder = self.root.join(dir);
            let Ok(list) = std::fs::read_dir(&folder) else {
                continue;
            };
            if !inside {
                continue;
            }
            for item in list.flatten() {
                let file_name = item.file_name();
                let Some((name, pid)) = file_name.to_str().and_then(parse_temp_name) else {
                    continue;
                };
                let path = item.path();
                if names.contains(&(dir.clone(), name.to_string()))
                    && matches!(entry(&path)?, Entry::File)
                    && !process_alive(pid)
                {
                    std::fs::remove_file(&path).map_err(io_error(&path))?;
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("axcheck-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn replaces_content() {
        let dir = scratch("atomic");
        let path = dir.join("sub/out.txt");
        write(&path, b"one").unwrap();
        write(&path, b"two").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        let leftovers = std::fs::read_dir(dir.join("sub")).unwrap().count();
        assert_eq!(leftovers, 1);
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn temporary_names() {
        assert_eq!(temp_name("a.pdf", 42), ".a.pdf.axcheck-tmp-42");
        assert_eq!(
            parse_temp_name(".a.pdf.axcheck-tmp-42"),
            Some(("a.pdf", 42))
        );
        assert_eq!(parse_temp_name("a.pdf.axcheck-tmp-42"), None);
        assert_eq!(parse_temp_name(".a.pdf.axcheck-tmp-"), None);
        assert_eq!(parse_temp_name(".a.pdf.axcheck-tmp-4x"), None);
    }

    #[test]
    fn manifest_entries_stay_inside_the_folder() {
        assert!(clean_relative("reports/M/X.pdf").is_some());
        for bad in [
            "",
            "/etc/passwd",
            "../x",
            "a/../../x",
            "./a",
            "a\\b",
            "a//b",
            "C:/x",
            "c:x",
            "x.pdf:stream",
            "a./b",
            "a /b",
            "\\\\server\\share\\x",
        ] {
            assert!(clean_relative(bad).is_none(), "{bad}");
        }
    }

    /// The exporters join output paths with the platform's separator; a check that took
    /// only `/` refused every output on Windows (`compensation\\VMC-07\\X.ini`).
    #[test]
    fn output_paths_take_the_platform_separator() {
        let joined = Path::new("compensation").join("VMC-07").join("X.ini");
        assert_eq!(
            clean_output(&joined),
            Some(PathBuf::from("compensation/VMC-07/X.ini"))
        );
        assert_eq!(manifest_line(&joined), "compensation/VMC-07/X.ini");
        for bad in ["", "../x", "a/../b", "/abs", "./a", "a/x:y", "a/x."] {
            assert_eq!(clean_output(Path::new(bad)), None, "{bad}");
        }
        #[cfg(windows)]
        for bad in [
            "C:\\x",
            "C:x",
            "\\x",
            "\\\\server\\share\\x",
            "a\\..\\..\\x",
            "x:y",
        ] {
            assert_eq!(clean_output(Path::new(bad)), None, "{bad}");
        }
    }

    fn run(root: &Path, outputs: &[(&str, &str)]) -> Result<(), OutputError> {
        let mut dir = OutputDir::open(root)?;
        let paths: Vec<&Path> = outputs.iter().map(|(p, _)| Path::new(*p)).collect();
        dir.check(paths.iter().copied())?;
        dir.prepare(paths.iter().copied())?;
        for (p, text) in outputs {
            dir.write(Path::new(p), text.as_bytes())?;
        }
        dir.finish()
    }

    #[test]
    fn owns_what_it_wrote_and_nothing_else() {
        let root = scratch("owned");
        run(
            &root,
            &[("a.txt", "1"), ("r/m/x.pdf", "1"), ("r/n/y.pdf", "1")],
        )
        .unwrap();
        let manifest = std::fs::read_to_string(root.join(MANIFEST)).unwrap();
        assert!(
            manifest.ends_with("a.txt\nr/\nr/m/\nr/m/x.pdf\nr/n/\nr/n/y.pdf\n"),
            "{manifest}"
        );
        // A user's files: one beside, one in a folder axcheck made.
        std::fs::write(root.join("notes.txt"), "mine").unwrap();
        std::fs::write(root.join("r/n/mine.txt"), "mine").unwrap();
        // Re-run without r/m and r/n outputs: they are removed, r/m with its folder; r/n
        // stays because it holds the user's file.
        run(&root, &[("a.txt", "2")]).unwrap();
        assert_eq!(std::fs::read_to_string(root.join("a.txt")).unwrap(), "2");
        assert!(!root.join("r/m").exists());
        assert!(!root.join("r/n/y.pdf").exists());
        assert!(root.join("r/n/mine.txt").exists());
        assert_eq!(
            std::fs::read_to_string(root.join("notes.txt")).unwrap(),
            "mine"
        );
        // A user's file at an output path is refused, untouched.
        let e = run(&root, &[("a.txt", "3"), ("notes.txt", "3")]).unwrap_err();
        assert!(matches!(e, OutputError::Foreign { .. }), "{e}");
        assert_eq!(
            std::fs::read_to_string(root.join("notes.txt")).unwrap(),
            "mine"
        );
        assert_eq!(std::fs::read_to_string(root.join("a.txt")).unwrap(), "2");
        std::fs::remove_dir_all(root).unwrap();
    }

    #[test]
    fn a_tampered_manifest_is_refused() {
        let root = scratch("tampered");
        std::fs::create_dir_all(&root).unwrap();
        std::fs::write(
            root.join(MANIFEST),
            "# axcheck output manifest\n../../etc/passwd\n",
        )
        .unwrap();
        let e = OutputDir::open(&root).unwrap_err();
        assert!(e.to_string().contains("line 2"), "{e}");
        std::fs::write(root.join(MANIFEST), "results.json\n").unwrap();
        assert!(OutputDir::open(&root).is_err());
        std::fs::remove_dir_all(root).unwrap();
    }
}
