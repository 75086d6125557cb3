//! A handle on a folder that files are opened beneath (Linux `openat2` with
//! `RESOLVE_BENEATH`): the kernel keeps the path inside the folder in the very call that
//! opens it. The portable way walks the path before the open (an `lstat` a component) and
//! reads the opened file's path back after it (`/proc/self/fd`): four system calls of the
//! eleven a measurement file cost the CI gate. Where the kernel refuses (a link that leaves
//! the folder or is absolute, a kernel before 5.6, another system), the portable way
//! decides, so a refusal keeps its message naming the link.

/// An open handle on a folder (none on systems without `openat2`).
#[derive(Debug)]
pub(crate) struct Handle {
    #[cfg(target_os = "linux")]
    fd: std::os::fd::OwnedFd,
}

#[cfg(target_os = "linux")]
mod linux {
    use super::Handle;
    use rustix::fs::{AtFlags, CWD, FileType, Mode, OFlags, ResolveFlags, openat2, statat};
    use std::fs::File;
    use std::path::Path;

    impl Handle {
        /// The folder at its real path `real`, reached through no link (so it is the
        /// folder that path named when the rules resolved it).
        pub fn open(real: &Path) -> Option<Handle> {
            let flags = OFlags::PATH | OFlags::DIRECTORY | OFlags::CLOEXEC;
            let fd = openat2(CWD, real, flags, Mode::empty(), ResolveFlags::NO_SYMLINKS).ok()?;
            Some(Handle { fd })
        }

        /// Whether `relative` exists beneath the folder with no link on its way: then its
        /// real path lies inside the folder.
        pub fn plain(&self, relative: &Path) -> bool {
            let flags = OFlags::PATH | OFlags::CLOEXEC;
            let resolve = ResolveFlags::BENEATH | ResolveFlags::NO_SYMLINKS;
            openat2(&self.fd, relative, flags, Mode::empty(), resolve).is_ok()
        }

        /// Whether `relative` (links followed) is a regular file: the check before the
        /// open, by a walk from the folder instead of from the root of the file system.
        pub fn is_regular(&self, relative: &Path) -> bool {
            statat(&self.fd, relative, AtFlags::empty())
                .is_ok_and(|st| FileType::from_raw_mode(st.st_mode) == FileType::RegularFile)
        }

        /// `relative` opened for reading without blocking, its links followed only while
        /// they stay beneath the folder; `None` when the kernel refuses it.
        pub fn open_file(&self, relative: &Path) -> Option<File> {
            let flags = OFlags::RDONLY | OFlags::NONBLOCK | OFlags::CLOEXEC;
            let fd = openat2(
                &self.fd,
                relative,
                flags,
                Mode::empty(),
                ResolveFlags::BENEATH,
            );
            fd.ok().map(File::from)
        }
    }
}

#[cfg(not(target_os = "linux"))]
use std::{fs::File, path::Path};

#[cfg(not(target_os = "linux"))]
impl Handle {
    pub fn open(_real: &Path) -> Option<Handle> {
        None
    }

    pub fn plain(&self, _relative: &Path) -> bool {
        false
    }

    pub(crate) fn is_regular(&self, _relative: &Path) -> bool {
        false
    }

    pub(crate) fn open_file(&self, _relative: &Path) -> Option<File> {
        None
    }
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;
    use std::path::Path;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir =
            std::env::temp_dir().join(format!("axcheck-beneath-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("data")).unwrap();
        dir
    }

    /// Plain paths open beneath the folder; a link inside is followed when it stays
    /// inside; a link out, an absolute path and `..` out are refused (and left to the
    /// portable rules).
    #[test]
    fn files_open_beneath_the_folder_only() {
        let dir = scratch("open");
        let outside = scratch("outside");
        std::fs::write(dir.join("data/x.csv"), "x").unwrap();
        std::fs::write(outside.join("data/secret.csv"), "s").unwrap();
        std::os::unix::fs::symlink("x.csv", dir.join("data/in.csv")).unwrap();
        std::os::unix::fs::symlink(outside.join("data/secret.csv"), dir.join("data/out.csv"))
            .unwrap();
        let real = std::fs::canonicalize(&dir).unwrap();
        let handle = Handle::open(&real).expect("openat2 on this kernel");
        assert!(handle.plain(Path::new("data/x.csv")));
        assert!(handle.plain(Path::new("data/../data/x.csv")));
        assert!(
            !handle.plain(Path::new("data/in.csv")),
            "a link is not plain"
        );
        assert!(!handle.plain(Path::new("data/none.csv")));
        assert!(handle.is_regular(Path::new("data/in.csv")));
        assert!(!handle.is_regular(Path::new("data")));
        assert!(!handle.is_regular(Path::new("data/none.csv")));
        let read = |p: &str| {
            handle.open_file(Path::new(p)).map(|mut f| {
                let mut s = String::new();
                std::io::Read::read_to_string(&mut f, &mut s).unwrap();
                s
            })
        };
        assert_eq!(read("data/x.csv").as_deref(), Some("x"));
        assert_eq!(read("data/in.csv").as_deref(), Some("x"));
        assert_eq!(read("data/out.csv"), None);
        let name = outside.file_name().unwrap().to_str().unwrap();
        assert_eq!(read(&format!("../{name}/data/secret.csv")), None);
        let absolute = outside.join("data/secret.csv");
        assert_eq!(read(absolute.to_str().unwrap()), None);
        // A folder reached through a link is not opened as the folder.
        std::os::unix::fs::symlink(&real, outside.join("link")).unwrap();
        assert!(Handle::open(&outside.join("link")).is_none());
        std::fs::remove_dir_all(dir).unwrap();
        std::fs::remove_dir_all(outside).unwrap();
    }
}
