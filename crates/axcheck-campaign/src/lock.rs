//! One writer per folder: `axcheck run` locks its output folder (and the history folder)
//! before it writes anything, so two runs on one shared folder never mix their files.
//!
//! The lock is an advisory lock of the operating system on [`LOCK_FILE`] in the folder
//! (`flock` on unix; `LockFileEx` on one byte past the text on Windows, whose locks are
//! mandatory and would otherwise hide the text): the system releases it when the process
//! ends, however it ends, so the lock of a killed run is never stale; the next run finds
//! the file unlocked and takes it over. The file holds the pid, host and start time of
//! the run that holds it, for the message of a run that finds it locked. A run removes
//! the file when it is done (unix), still holding the lock; a run that waited on the
//! removed file sees that it is no longer in the folder and locks the new one. On Windows
//! a file open in another process cannot be removed at once everywhere (FAT, network
//! shares, Wine), so the file stays and a run that ends empties it instead: only a
//! killed run leaves its holder in it.

use std::fs::File;
use std::io::{Read, Seek, Write};
use std::path::{Path, PathBuf};

/// The lock file's name in a locked folder.
pub const LOCK_FILE: &str = ".axcheck.lock";

/// The run that holds (or held) a lock, as its lock file says.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Holder {
    pub pid: Option<u32>,
    pub host: Option<String>,
    pub started: Option<String>,
}

impl Holder {
    fn this_process() -> Holder {
        Holder {
            pid: Some(std::process::id()),
            host: host_name(),
            started: Some(chrono::Local::now().format("%Y-%m-%d %H:%M:%S").to_string()),
        }
    }

    fn parse(text: &str) -> Holder {
        let mut holder = Holder::default();
        for line in text.lines() {
            match line.split_once(' ') {
                Some(("pid", pid)) => holder.pid = pid.trim().parse().ok(),
                Some(("host", host)) => holder.host = Some(host.trim().to_string()),
                Some(("started", at)) => holder.started = Some(at.trim().to_string()),
                _ => {}
            }
        }
        holder
    }

    fn text(&self) -> String {
        let mut text = String::from("# axcheck lock: the run that writes to this folder\n");
        if let Some(pid) = self.pid {
            text.push_str(&format!("pid {pid}\n"));
        }
        if let Some(host) = &self.host {
            text.push_str(&format!("host {host}\n"));
        }
        if let Some(at) = &self.started {
            text.push_str(&format!("started {at}\n"));
        }
        text
    }

    fn is_empty(&self) -> bool {
        *self == Holder::default()
    }

    /// `pid 4711, started 2026-11-23 10:42:05` (the host when it is not this one).
    pub fn describe(&self) -> String {
        let mut parts = Vec::new();
        if let Some(pid) = self.pid {
            match &self.host {
                Some(host) if Some(host) != host_name().as_ref() => {
                    parts.push(format!("pid {pid} on {host}"));
                }
                _ => parts.push(format!("pid {pid}")),
            }
        }
        if let Some(at) = &self.started {
            parts.push(format!("started {at}"));
        }
        parts.join(", ")
    }
}

/// This machine's name, when the system tells it cheaply (a shared network folder can be
/// locked from another machine, where the pid means nothing here).
fn host_name() -> Option<String> {
    let name = std::fs::read_to_string("/proc/sys/kernel/hostname")
        .ok()
        .or_else(|| std::env::var("COMPUTERNAME").ok())
        .or_else(|| std::env::var("HOSTNAME").ok())?;
    let name = name.trim();
    (!name.is_empty()).then(|| name.to_string())
}

/// A folder another run holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Locked {
    pub dir: PathBuf,
    pub holder: Holder,
}

impl std::fmt::Display for Locked {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let who = self.holder.describe();
        if who.is_empty() {
            write!(
                f,
                "another axcheck run is writing to {}",
                self.dir.display()
            )
        } else {
            write!(
                f,
                "another axcheck run ({who}) is writing to {}",
                self.dir.display()
            )
        }
    }
}

/// Why a folder could not be locked.
#[derive(Debug, thiserror::Error)]
pub enum LockError {
    #[error("{0}; wait for it to finish, run again with --wait, or choose another folder")]
    Locked(Locked),
    #[error(
        "{path} is {what}, not axcheck's lock file; remove it (axcheck creates its lock file itself)"
    )]
    InTheWay { path: PathBuf, what: &'static str },
    #[error(
        "cannot write in {}: {cause}; axcheck locks a folder before it writes there: choose a folder you may write in, or make this one writable",
        path.parent().unwrap_or(path).display()
    )]
    ReadOnly {
        path: PathBuf,
        cause: std::io::Error,
    },
    // `cause`, not `source`: a source is printed again after the message (`{e:#}`).
    #[error("cannot lock {path}: {cause}")]
    Io {
        path: PathBuf,
        cause: std::io::Error,
    },
}

impl LockError {
    /// An I/O error at the lock file `path`: a folder that cannot be written (a read-only
    /// file system, no permission) is said so, not "cannot lock".
    fn io(path: PathBuf, cause: std::io::Error) -> LockError {
        use std::io::ErrorKind::{PermissionDenied, ReadOnlyFilesystem};
        match cause.kind() {
            ReadOnlyFilesystem | PermissionDenied => LockError::ReadOnly { path, cause },
            _ => LockError::Io { path, cause },
        }
    }
}

/// A locked folder; dropping it releases the lock, removes the lock file (unix) and the
/// folders [`FolderLock::acquire`] created, when they are still empty.
#[derive(Debug)]
pub struct FolderLock {
    file: File,
    /// The lock file, removed when the lock is released (unix only).
    #[cfg_attr(not(unix), allow(dead_code))]
    path: PathBuf,
    created: Vec<PathBuf>,
    /// The holder written in a lock file nobody held any more: a run that was killed.
    pub taken_over: Option<Holder>,
}

impl FolderLock {
    /// Locks `dir` (creating it). When another run holds it: with `wait`, calls
    /// `waiting` once and waits until it is released; without, fails at once.
    pub fn acquire(
        dir: &Path,
        wait: bool,
        mut waiting: impl FnMut(&Locked),
    ) -> Result<FolderLock, LockError> {
        let path = dir.join(LOCK_FILE);
        let io = |cause| LockError::io(path.clone(), cause);
        let created = create_folders(dir).map_err(io)?;
        let mut announced = false;
        let mut attempts = 0;
        loop {
            // Again on every attempt: the run before may have removed the folder it created.
            std::fs::create_dir_all(dir).map_err(io)?;
            let mut file = match open_lock_file(&path) {
                Err(LockError::Io { cause, .. })
                    if cause.kind() == std::io::ErrorKind::NotFound && attempts < 100 =>
                {
                    attempts += 1;
                    continue;
                }
                other => other?,
            };
            match try_lock(&file) {
                Ok(()) => {}
                Err(std::fs::TryLockError::WouldBlock) => {
                    let locked = Locked {
                        dir: dir.to_path_buf(),
                        holder: read_written_holder(&mut file),
                    };
                    if !wait {
                        return Err(LockError::Locked(locked));
                    }
                    if !announced {
                        waiting(&locked);
                        announced = true;
                    }
                    lock(&file).map_err(io)?;
                }
                Err(std::fs::TryLockError::Error(e)) => return Err(io(e)),
            }
            // The run before removed its lock file while we waited on it: lock the new one.
            if !still_in_place(&file, &path) {
                continue;
            }
            let previous = read_holder(&mut file);
            let holder = Holder::this_process();
            // Written first, then cut to length: a reader never sees an empty lock file
            // that a previous holder had filled.
            (|| {
                let text = holder.text();
                file.rewind()?;
                file.write_all(text.as_bytes())?;
                file.set_len(text.len() as u64)
            })()
            .map_err(io)?;
            return Ok(FolderLock {
                file,
                path,
                created,
                taken_over: (!previous.is_empty()).then_some(previous),
            });
        }
    }
}

impl Drop for FolderLock {
    fn drop(&mut self) {
        // Removed while still locked, so no run can lock it after it is released.
        #[cfg(unix)]
        let _ = std::fs::remove_file(&self.path);
        // Emptied while still locked: the next run finds no holder to take over.
        #[cfg(not(unix))]
        let _ = self.file.set_len(0);
        let _ = unlock(&self.file);
        for dir in self.created.iter().rev() {
            // Only when empty: a run that wrote nothing leaves no folder behind.
            let _ = std::fs::remove_dir(dir);
        }
    }
}

/// Takes the lock of `file` if no other run holds it.
fn try_lock(file: &File) -> Result<(), std::fs::TryLockError> {
    #[cfg(windows)]
    {
        use std::fs::TryLockError;
        crate::files::windows::lock_byte(file, false).map_err(|e| match e.kind() {
            std::io::ErrorKind::WouldBlock => TryLockError::WouldBlock,
            _ => TryLockError::Error(e),
        })
    }
    #[cfg(not(windows))]
    {
        file.try_lock()
    }
}

/// Waits for the lock of `file` and takes it.
fn lock(file: &File) -> std::io::Result<()> {
    #[cfg(windows)]
    {
        crate::files::windows::lock_byte(file, true)
    }
    #[cfg(not(windows))]
    {
        file.lock()
    }
}

fn unlock(file: &File) -> std::io::Result<()> {
    #[cfg(windows)]
    {
        crate::files::windows::unlock_byte(file)
    }
    #[cfg(not(windows))]
    {
        file.unlock()
    }
}

/// Creates `dir` and its missing parents; returns those it created, outermost first.
fn create_folders(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut missing: Vec<PathBuf> = dir
        .ancestors()
        .filter(|p| !p.as_os_str().is_empty())
        .take_while(|p| std::fs::symlink_metadata(p).is_err())
        .map(Path::to_path_buf)
        .collect();
    missing.reverse();
    std::fs::create_dir_all(dir)?;
    Ok(missing)
}

/// Opens (creating) the lock file; never through a symbolic link, never a special file.
fn open_lock_file(path: &Path) -> Result<File, LockError> {
    let in_the_way = |what| LockError::InTheWay {
        path: path.to_path_buf(),
        what,
    };
    if let Ok(m) = std::fs::symlink_metadata(path) {
        if m.file_type().is_symlink() {
            return Err(in_the_way("a symbolic link"));
        }
        if let Some(what) = crate::files::special_kind(&m) {
            return Err(in_the_way(what));
        }
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true).write(true).create(true).truncate(false);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        let flags = rustix::fs::OFlags::NOFOLLOW | rustix::fs::OFlags::NONBLOCK;
        options.custom_flags(flags.bits() as i32).mode(0o644);
    }
    let file = options
        .open(path)
        .map_err(|cause| LockError::io(path.to_path_buf(), cause))?;
    match file
        .metadata()
        .ok()
        .as_ref()
        .and_then(crate::files::special_kind)
    {
        Some(what) => Err(in_the_way(what)),
        None => Ok(file),
    }
}

/// The lock file we hold is the one at `path` (not one its holder removed meanwhile).
fn still_in_place(file: &File, path: &Path) -> bool {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        match (file.metadata(), std::fs::symlink_metadata(path)) {
            (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
            _ => false,
        }
    }
    #[cfg(not(unix))]
    {
        let _ = (file, path);
        true
    }
}

/// The holder of a held lock. A run writes its holder text just after it locks, so an
/// empty text means it is about to: wait for it a little (at most 0.2 s) to name it.
fn read_written_holder(file: &mut File) -> Holder {
    for _ in 0..40 {
        let holder = read_holder(file);
        if !holder.is_empty() {
            return holder;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    read_holder(file)
}

fn read_holder(file: &mut File) -> Holder {
    let mut text = String::new();
    let _ = file.rewind();
    let _ = file.take(4096).read_to_string(&mut text);
    Holder::parse(&text)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A read-only file system is said so, and its OS error text is printed once (it was
    /// "cannot lock …: (os error 30): … (os error 30)").
    #[cfg(unix)]
    #[test]
    fn a_read_only_folder_is_said_so_once() {
        let path = PathBuf::from("/media/disk/out").join(LOCK_FILE);
        let e = LockError::io(path, std::io::Error::from_raw_os_error(30));
        let shown = format!("{:#}", anyhow::Error::from(e));
        assert!(
            shown.starts_with("cannot write in /media/disk/out: "),
            "{shown}"
        );
        assert_eq!(shown.matches("(os error 30)").count(), 1, "{shown}");
    }

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("axcheck-lock-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    #[test]
    fn a_second_lock_fails_at_once_and_names_the_holder() {
        let dir = scratch("second");
        let first = FolderLock::acquire(&dir, false, |_| {}).unwrap();
        assert!(first.taken_over.is_none());
        let text = std::fs::read_to_string(dir.join(LOCK_FILE)).unwrap();
        assert!(
            text.contains(&format!("pid {}\n", std::process::id())),
            "{text}"
        );
        let e = FolderLock::acquire(&dir, false, |_| {})
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with(&format!(
                "another axcheck run (pid {}, started ",
                std::process::id()
            )) && e.contains(&format!(") is writing to {}", dir.display())),
            "{e}"
        );
        drop(first);
        if cfg!(unix) {
            assert!(!dir.exists(), "the folder it created is removed when empty");
        } else {
            let left = std::fs::read(dir.join(LOCK_FILE)).unwrap();
            assert!(left.is_empty(), "emptied when released");
        }
        let again = FolderLock::acquire(&dir, false, |_| {}).unwrap();
        assert!(
            again.taken_over.is_none(),
            "a released lock is not taken over"
        );
        std::fs::write(dir.join("output.txt"), "x").unwrap();
        drop(again);
        assert!(dir.join("output.txt").exists());
        assert_eq!(dir.join(LOCK_FILE).exists(), cfg!(not(unix)));
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_waiting_lock_is_taken_when_released() {
        let dir = scratch("wait");
        let first = FolderLock::acquire(&dir, false, |_| {}).unwrap();
        let (tx, rx) = std::sync::mpsc::channel();
        let waiter = {
            let dir = dir.clone();
            std::thread::spawn(move || {
                FolderLock::acquire(&dir, true, |locked| tx.send(locked.clone()).unwrap())
                    .map(|_| ())
                    .map_err(|e| e.to_string())
            })
        };
        let locked = rx.recv().unwrap();
        assert_eq!(locked.holder.pid, Some(std::process::id()));
        drop(first);
        waiter.join().unwrap().unwrap();
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn a_lock_file_left_unlocked_is_taken_over() {
        let dir = scratch("stale");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join(LOCK_FILE),
            "pid 999999\nstarted 2026-11-23 10:42:05\n",
        )
        .unwrap();
        let lock = FolderLock::acquire(&dir, false, |_| {}).unwrap();
        let previous = lock.taken_over.clone().unwrap();
        assert_eq!(previous.pid, Some(999_999));
        assert_eq!(previous.started.as_deref(), Some("2026-11-23 10:42:05"));
        drop(lock);
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn a_link_in_place_of_the_lock_file_is_refused() {
        let dir = scratch("link");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("victim"), "keep").unwrap();
        std::os::unix::fs::symlink(dir.join("victim"), dir.join(LOCK_FILE)).unwrap();
        let e = FolderLock::acquire(&dir, false, |_| {})
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("is a symbolic link, not axcheck's lock file"),
            "{e}"
        );
        assert_eq!(std::fs::read_to_string(dir.join("victim")).unwrap(), "keep");
        std::fs::remove_dir_all(dir).unwrap();
    }
}
