//! Reading the files a user names (measurements, campaigns, specs, templates): only
//! regular files.
//!
//! A named pipe given as a data file would block the run forever, and a device such as
//! `/dev/zero` never ends, so the file type is checked before opening (`stat`, which
//! never blocks). The file is then opened without blocking (`O_NONBLOCK` on unix, in case
//! it was swapped for a pipe in between), and the opened handle is checked again: still a
//! regular file (one renamed over the path in between, as an atomic write does, is read
//! whole: the history on shared storage is replaced that way). After the read the handle's
//! size and modification time are compared with those at opening, so a file that is
//! written while axcheck reads it is noticed instead of giving half a measurement.

mod beneath;
mod digest;
mod real;
mod root;
#[cfg(windows)]
pub mod windows;

pub use digest::{InputFile, path_from, relative_to, sha256_hex, sha256_of};
pub use real::{OutsidePath, real_path, resolved};
pub use root::{PathRefused, Root, may_match};

use std::fs::{File, Metadata};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// Why a file the user named is not read.
#[derive(Debug, thiserror::Error)]
pub enum FileError {
    #[error(
        "it is {0}, not a regular file; axcheck reads only regular files (a pipe, socket or device may block or never end)"
    )]
    NotRegular(&'static str),
    #[error(
        "the file changed while axcheck read it (its size or modification time differ before and after the read); run again once it is complete"
    )]
    Changed,
    #[error(
        "it was opened as {}, outside the folder {} (a link on its way was changed after the path was checked); nothing was read from it",
        dunce::simplified(real).display(),
        dunce::simplified(root).display()
    )]
    Outside { real: PathBuf, root: PathBuf },
    #[error(
        "it is {0} text; axcheck reads UTF-8: save it as UTF-8 (an editor's Save as, Encoding UTF-8) or convert it with `iconv -f UTF-16 -t UTF-8`"
    )]
    Utf16(&'static str),
    #[error(
        "line {line}, column {column}: byte 0x{byte:02X} is not UTF-8 (a Windows editor's \"ANSI\" text, Windows-1252 or Latin-1, writes `ü` so); axcheck reads UTF-8: save it as UTF-8 (Save as, Encoding UTF-8) or convert it with `iconv -f WINDOWS-1252 -t UTF-8`"
    )]
    NotUtf8 {
        line: usize,
        column: usize,
        byte: u8,
    },
    #[error("{0}")]
    Io(#[from] std::io::Error),
}

impl From<FileError> for std::io::Error {
    fn from(e: FileError) -> std::io::Error {
        match e {
            FileError::Io(e) => e,
            other => std::io::Error::other(other.to_string()),
        }
    }
}

/// What a file that is not regular is, for messages (`None`: a regular file).
pub(crate) fn special_kind(metadata: &Metadata) -> Option<&'static str> {
    let kind = metadata.file_type();
    if kind.is_file() {
        return None;
    }
    if kind.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return Some("a named pipe (FIFO)");
        }
        if kind.is_socket() {
            return Some("a socket");
        }
        if kind.is_char_device() {
            return Some("a character device");
        }
        if kind.is_block_device() {
            return Some("a block device");
        }
    }
    Some("a special file")
}

fn regular(metadata: &Metadata) -> Result<(), FileError> {
    match special_kind(metadata) {
        None => Ok(()),
        Some(kind) => Err(FileError::NotRegular(kind)),
    }
}

/// An opened regular file with its size and modification time at opening.
#[derive(Debug)]
pub struct Opened {
    pub file: File,
    size: u64,
    modified: Option<SystemTime>,
}

impl Opened {
    /// Refuses the file when its size or modification time changed since it was opened.
    pub(crate) fn check_unchanged(&self) -> Result<(), FileError> {
        let now = self.file.metadata()?;
        if now.len() != self.size || now.modified().ok() != self.modified {
            return Err(FileError::Changed);
        }
        Ok(())
    }
}

/// Opens `path` (links followed) for reading if it is a regular file, refusing pipes,
/// sockets, devices and folders without opening them; and when `root` (a folder's real
/// path) is given, refuses the opened file unless it lies inside it. The caller checked
/// the path's real path before; this checks what the system actually opened, so a link
/// changed in between (a race with whoever can write the folder) is caught before a byte
/// is read.
pub(crate) fn open_within(path: &Path, root: Option<&Path>) -> Result<Opened, FileError> {
    let opened = open_regular(path)?;
    if let Some(root) = root {
        let real = opened_real_path(&opened.file, path)?;
        if !real.starts_with(root) {
            return Err(FileError::Outside {
                real,
                root: root.to_path_buf(),
            });
        }
    }
    Ok(opened)
}

/// The real path of the file behind `file`: what the system opened (Linux:
/// `/proc/self/fd`; Windows: `GetFinalPathNameByHandleW`); elsewhere `path` resolved
/// again, a narrower window than none.
fn opened_real_path(file: &File, path: &Path) -> std::io::Result<PathBuf> {
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        if let Ok(real) = std::fs::read_link(format!("/proc/self/fd/{}", file.as_raw_fd())) {
            return Ok(real);
        }
    }
    #[cfg(windows)]
    if let Ok(real) = windows::final_path(file) {
        return Ok(real);
    }
    let _ = file;
    std::fs::canonicalize(path)
}

/// The regular-file part of [`open_within`].
fn open_regular(path: &Path) -> Result<Opened, FileError> {
    regular(&std::fs::metadata(path)?)?;
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // A pipe swapped in after the check opens at once instead of waiting for a writer.
        options.custom_flags(rustix::fs::OFlags::NONBLOCK.bits() as i32);
    }
    opened(options.open(path)?)
}

/// The handle is what is read: a regular file, whichever. Another regular file renamed
/// over the path between the check and the open (an atomic write) is read whole.
fn opened(file: File) -> Result<Opened, FileError> {
    // `CON`, `NUL`, `COM1` name devices in any folder on Windows, which a file's type
    // does not show: the handle says what it is.
    #[cfg(windows)]
    if !windows::on_disk(&file) {
        return Err(FileError::NotRegular("a device or a pipe"));
    }
    let after = file.metadata()?;
    regular(&after)?;
    Ok(Opened {
        file,
        size: after.len(),
        modified: after.modified().ok(),
    })
}

/// [`open_within`] by a handle on the folder whose real path is `root`: `path` is the
/// folder's `relative`, opened beneath the handle in one system call ([`beneath`]); when
/// the kernel refuses it, [`open_within`] decides and says why.
fn open_beneath(
    handle: &beneath::Handle,
    relative: &Path,
    path: &Path,
    root: Option<&Path>,
) -> Result<Opened, FileError> {
    if !handle.is_regular(relative) {
        // Not a regular file, or not found from the folder: the portable check says which.
        regular(&std::fs::metadata(path)?)?;
    }
    match handle.open_file(relative) {
        Some(file) => opened(file),
        None => open_within(path, root),
    }
}

/// Opens `path` as [`open_within`] does, gives the file to `read`, and refuses the result
/// when the file changed while `read` ran (whatever `read` returned).
pub fn read_with<T>(
    path: &Path,
    root: Option<&Path>,
    read: impl FnOnce(&mut File) -> T,
) -> Result<T, FileError> {
    read_opened(open_within(path, root)?, read)
}

/// Gives the opened file to `read` and refuses the result when the file changed meanwhile.
fn read_opened<T>(mut opened: Opened, read: impl FnOnce(&mut File) -> T) -> Result<T, FileError> {
    let value = read(&mut opened.file);
    opened.check_unchanged()?;
    Ok(value)
}

/// The bytes of the regular file `path`.
pub fn read(path: &Path) -> Result<Vec<u8>, FileError> {
    read_with(path, None, bytes)?.map_err(FileError::Io)
}

fn bytes(file: &mut File) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    file.read_to_end(&mut bytes).map(|_| bytes)
}

/// The text of the regular file `path` (UTF-8, with or without a byte-order mark).
pub fn read_to_string(path: &Path) -> Result<String, FileError> {
    utf8(read(path)?)
}

/// The text of the regular file `path` (as [`read_to_string`]) and the SHA-256 of its
/// bytes: the campaign file, recorded with the files read beneath its folder.
pub fn read_to_string_hashed(path: &Path) -> Result<(String, String), FileError> {
    let bytes = read(path)?;
    let sha256 = sha256_hex(&bytes);
    Ok((utf8(bytes)?, sha256))
}

/// The bytes as UTF-8 text without its byte-order mark (Windows' "UTF-8 with BOM"); UTF-16
/// text is named as such, for the user to save it as UTF-8.
fn utf8(mut bytes: Vec<u8>) -> Result<String, FileError> {
    if let Some(kind) = utf16_kind(&bytes) {
        return Err(FileError::Utf16(kind));
    }
    if bytes.starts_with(UTF8_BOM) {
        bytes.drain(..UTF8_BOM.len());
    }
    String::from_utf8(bytes).map_err(|e| not_utf8(e.as_bytes(), e.utf8_error().valid_up_to()))
}

/// Where the first byte that is not UTF-8 stands (1-based line and column in characters).
fn not_utf8(bytes: &[u8], at: usize) -> FileError {
    let before = String::from_utf8_lossy(&bytes[..at]);
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    FileError::NotUtf8 {
        line: before.matches('\n').count() + 1,
        column: before[line_start..].chars().count() + 1,
        byte: bytes[at],
    }
}

/// The byte-order mark of UTF-8 text.
pub(crate) const UTF8_BOM: &[u8] = b"\xEF\xBB\xBF";

/// Which UTF-16 the text starting with `head` is: by its byte-order mark, or without one
/// by a NUL byte beside most of its first characters (Latin text as Notepad and Excel's
/// "Unicode text" write it); UTF-8 text has no NUL byte.
pub(crate) fn utf16_kind(head: &[u8]) -> Option<&'static str> {
    if head.starts_with(b"\xFF\xFE") {
        return Some("UTF-16 little-endian");
    }
    if head.starts_with(b"\xFE\xFF") {
        return Some("UTF-16 big-endian");
    }
    let pairs: Vec<&[u8]> = head.chunks_exact(2).take(64).collect();
    let most = |fits: fn(&[u8]) -> bool| {
        pairs.len() >= 4 && 4 * pairs.iter().filter(|p| fits(p)).count() >= 3 * pairs.len()
    };
    match () {
        _ if most(|p| p[0] != 0 && p[1] == 0) => Some("UTF-16 little-endian"),
        _ if most(|p| p[0] == 0 && p[1] != 0) => Some("UTF-16 big-endian"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;
    use std::path::PathBuf;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("axcheck-files-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Issue 49: a campaign saved as Windows-1252 ("ANSI") is named so, with the line and
    /// column of its first such byte, instead of "stream did not contain valid UTF-8".
    #[test]
    fn windows_1252_text_is_named_at_its_first_byte() {
        let e = utf8(b"campaign:\r\n  name: Pr\xFCfung\r\n".to_vec()).unwrap_err();
        let text = e.to_string();
        assert!(
            text.starts_with("line 2, column 11: byte 0xFC is not UTF-8"),
            "{text}"
        );
        assert!(text.contains("iconv -f WINDOWS-1252 -t UTF-8"), "{text}");
        assert_eq!(utf8(b"a: \xC3\xBC\r\n".to_vec()).unwrap(), "a: ü\r\n");
    }

    #[test]
    fn regular_files_are_read_and_folders_refused() {
        let dir = scratch("regular");
        std::fs::write(dir.join("a.txt"), "text").unwrap();
        assert_eq!(read_to_string(&dir.join("a.txt")).unwrap(), "text");
        let e = read(&dir).unwrap_err().to_string();
        assert!(e.starts_with("it is a folder, not a regular file"), "{e}");
        assert!(matches!(read(&dir.join("none")), Err(FileError::Io(_))));
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn pipes_and_devices_are_refused_without_blocking() {
        let dir = scratch("special");
        let pipe = dir.join("pipe.csv");
        rustix::fs::mkfifoat(
            rustix::fs::CWD,
            &pipe,
            rustix::fs::Mode::from_raw_mode(0o600),
        )
        .unwrap();
        // No writer ever opens the pipe: a plain open would wait forever.
        let e = read(&pipe).unwrap_err().to_string();
        assert!(
            e.starts_with("it is a named pipe (FIFO), not a regular file"),
            "{e}"
        );
        let e = read(Path::new("/dev/zero")).unwrap_err().to_string();
        assert!(e.starts_with("it is a character device"), "{e}");
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[cfg(unix)]
    #[test]
    fn what_was_opened_must_lie_inside_the_root() {
        let dir = scratch("within");
        let (inside, outside) = (dir.join("campaign"), dir.join("elsewhere"));
        std::fs::create_dir_all(inside.join("data")).unwrap();
        std::fs::create_dir_all(&outside).unwrap();
        std::fs::write(inside.join("data/a.csv"), "in").unwrap();
        std::fs::write(outside.join("secret.csv"), "root:x:0:0").unwrap();
        // As after a link was swapped in once the path had been checked.
        std::os::unix::fs::symlink(outside.join("secret.csv"), inside.join("data/b.csv")).unwrap();
        let root = std::fs::canonicalize(&inside).unwrap();
        let within = |path: &Path| read_with(path, Some(&root), bytes)?.map_err(FileError::Io);
        assert_eq!(within(&inside.join("data/a.csv")).unwrap(), b"in");
        let secret = std::fs::canonicalize(outside.join("secret.csv")).unwrap();
        let expected = format!(
            "it was opened as {}, outside the folder {} (a link on its way was changed \
             after the path was checked); nothing was read from it",
            secret.display(),
            root.display()
        );
        let e = within(&inside.join("data/b.csv")).unwrap_err();
        assert_eq!(e.to_string(), expected);
        // Through the folder's handle (Linux): the kernel refuses the link out, and the
        // portable open says why in the same words.
        let folder = Root::folder(&inside, "campaign folder");
        let e = folder
            .read_to_string(&inside.join("data/b.csv"))
            .unwrap_err();
        assert_eq!(e.to_string(), expected);
        assert_eq!(
            folder.read_to_string(&inside.join("data/a.csv")).unwrap(),
            "in"
        );
        // Without a root, links are followed as before.
        assert!(read_to_string(&inside.join("data/b.csv")).is_ok());
        std::fs::remove_dir_all(dir).unwrap();
    }

    #[test]
    fn a_file_written_during_the_read_is_refused() {
        let dir = scratch("changed");
        let path = dir.join("growing.csv");
        std::fs::write(&path, "first half\n").unwrap();
        let result = read_with(&path, None, |file| {
            let mut text = String::new();
            file.read_to_string(&mut text).unwrap();
            let mut writer = std::fs::OpenOptions::new()
                .append(true)
                .open(&path)
                .unwrap();
            writer.write_all(b"second half\n").unwrap();
            text
        });
        assert!(matches!(result, Err(FileError::Changed)), "{result:?}");
        assert!(read_with(&path, None, |_| ()).is_ok());
        std::fs::remove_dir_all(dir).unwrap();
    }
}
