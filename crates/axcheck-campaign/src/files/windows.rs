//! The Windows calls the standard library does not offer: a lock on one byte of a file,
//! the path of what a handle opened, and whether a handle is a file on a disk.

use std::fs::File;
use std::io::{Error, ErrorKind, Result};
use std::os::windows::ffi::OsStringExt;
use std::os::windows::io::AsRawHandle;
use std::path::PathBuf;
use windows_sys::Win32::Foundation::ERROR_LOCK_VIOLATION;
use windows_sys::Win32::Storage::FileSystem as fs;
use windows_sys::Win32::System::IO::{OVERLAPPED, OVERLAPPED_0_0};

/// Where the lock byte lies: past any text a lock file holds. Windows' locks are
/// mandatory, so a lock on the text (the standard library's `File::lock` locks the whole
/// file) would keep a waiting run from reading who holds the folder.
const LOCK_OFFSET: u64 = 1 << 32;

fn lock_byte_at() -> OVERLAPPED {
    let mut overlapped = OVERLAPPED::default();
    overlapped.Anonymous.Anonymous = OVERLAPPED_0_0 {
        Offset: LOCK_OFFSET as u32,
        OffsetHigh: (LOCK_OFFSET >> 32) as u32,
    };
    overlapped
}

/// Locks the lock byte of `file` for this process: waits while another holds it when
/// `wait`, else fails at once with [`ErrorKind::WouldBlock`]. The system releases it when
/// the handle is closed, however the process ends.
pub(crate) fn lock_byte(file: &File, wait: bool) -> Result<()> {
    let mut flags = fs::LOCKFILE_EXCLUSIVE_LOCK;
    if !wait {
        flags |= fs::LOCKFILE_FAIL_IMMEDIATELY;
    }
    let mut overlapped = lock_byte_at();
    // SAFETY: the handle is `file`'s, open for the call; the file is not opened for
    // overlapped I/O, so the call is done with `overlapped` when it returns.
    let ok = unsafe { fs::LockFileEx(file.as_raw_handle(), flags, 0, 1, 0, &mut overlapped) };
    if ok != 0 {
        return Ok(());
    }
    let e = Error::last_os_error();
    if e.raw_os_error() == Some(ERROR_LOCK_VIOLATION as i32) {
        return Err(Error::from(ErrorKind::WouldBlock));
    }
    Err(e)
}

/// Releases the lock byte of `file` ([`lock_byte`]).
pub(crate) fn unlock_byte(file: &File) -> Result<()> {
    let mut overlapped = lock_byte_at();
    // SAFETY: as in `lock_byte`.
    let ok = unsafe { fs::UnlockFileEx(file.as_raw_handle(), 0, 1, 0, &mut overlapped) };
    if ok != 0 {
        Ok(())
    } else {
        Err(Error::last_os_error())
    }
}

/// The path of the file `file` opened, links and junctions resolved (`\\?\C:\…`, as
/// `std::fs::canonicalize` gives it): what was opened, not what the path names now.
pub(crate) fn final_path(file: &File) -> Result<PathBuf> {
    let mut buffer = vec![0u16; 512];
    loop {
        // SAFETY: the buffer holds `len` units; the call writes at most that many.
        let n = unsafe {
            fs::GetFinalPathNameByHandleW(
                file.as_raw_handle(),
                buffer.as_mut_ptr(),
                buffer.len() as u32,
                fs::FILE_NAME_NORMALIZED | fs::VOLUME_NAME_DOS,
            )
        } as usize;
        if n == 0 {
            return Err(Error::last_os_error());
        }
        if n < buffer.len() {
            buffer.truncate(n);
            return Ok(PathBuf::from(std::ffi::OsString::from_wide(&buffer)));
        }
        // Too small: `n` is the length it needs, with the final NUL.
        buffer.resize(n, 0);
    }
}

/// Whether `file` is a file on a disk, not a console, printer port, `NUL` or a pipe
/// (Windows opens a device for the names `CON`, `NUL`, `COM1` … in any folder).
pub(crate) fn on_disk(file: &File) -> bool {
    // SAFETY: the handle is `file`'s, open for the call.
    unsafe { fs::GetFileType(file.as_raw_handle()) == fs::FILE_TYPE_DISK }
}
