//! What a run read: each file's path (relative to the folder it was read from) and its
//! SHA-256, so that its outputs can be traced to their inputs and re-run from them
//! (`results.json` `inputs`, `axcheck reproduce`).

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Component, Path};
use std::sync::Mutex;

/// One file read: its path relative to its folder, with forward slashes, and the SHA-256
/// of its bytes in lower-case hex.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub struct InputFile {
    pub path: String,
    pub sha256: String,
}

/// The SHA-256 of `bytes` in lower-case hex (64 characters).
pub fn sha256_hex(bytes: &[u8]) -> String {
    hex(&Sha256::digest(bytes))
}

/// The SHA-256 of what `reader` gives until its end.
pub fn sha256_of(reader: &mut impl Read) -> std::io::Result<String> {
    let mut hasher = Sha256::new();
    let mut buf = vec![0u8; 64 * 1024];
    loop {
        match reader.read(&mut buf) {
            Ok(0) => return Ok(hex(&hasher.finalize())),
            Ok(n) => hasher.update(&buf[..n]),
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// `path` as recorded for the folder `dir`: relative to it when it lies beneath it as
/// written (`a/./b` and `a/../b` made plain), else as given; forward slashes either way.
/// No real path is taken: the record must not depend on where the folder lies.
pub fn relative_to(path: &Path, dir: &Path) -> String {
    let relative = path.strip_prefix(dir).unwrap_or(path);
    // The root (`/`, `C:\`) as the first part, then the names.
    let mut head = String::new();
    let mut names: Vec<String> = Vec::new();
    for c in relative.components() {
        match c {
            Component::Prefix(p) => head = p.as_os_str().to_string_lossy().into_owned(),
            Component::RootDir => head.push('/'),
            Component::CurDir => {}
            Component::ParentDir if names.last().is_some_and(|p| p != "..") => {
                names.pop();
            }
            Component::ParentDir => names.push("..".into()),
            Component::Normal(name) => names.push(name.to_string_lossy().into_owned()),
        }
    }
    format!("{head}{}", names.join("/"))
}

/// `path` as seen from the folder `dir`, both through their real paths (the parts that do
/// not exist yet, as a history folder a run creates, as written): `../templates`,
/// `history`, `.`; `/`-separated. Where no relative path leads (another drive) or a path
/// cannot be resolved, `path` as given.
pub fn path_from(dir: &Path, path: &Path) -> String {
    let given = || path.to_string_lossy().replace('\\', "/");
    let (Some(dir), Some(path)) = (resolved(dir), resolved(path)) else {
        return given();
    };
    let (d, p): (Vec<Component>, Vec<Component>) =
        (dir.components().collect(), path.components().collect());
    let common = d.iter().zip(&p).take_while(|(a, b)| a == b).count();
    if common == 0 {
        return given();
    }
    let ups = std::iter::repeat_n("..".to_string(), d.len() - common);
    let names = p[common..]
        .iter()
        .map(|c| c.as_os_str().to_string_lossy().into_owned());
    let parts: Vec<String> = ups.chain(names).collect();
    match parts.is_empty() {
        true => ".".to_string(),
        false => parts.join("/"),
    }
}

/// `path`'s real path (`super::real::resolved`), without Windows' `\\?\` prefix.
fn resolved(path: &Path) -> Option<std::path::PathBuf> {
    super::real::resolved(path).map(|p| dunce::simplified(&p).to_path_buf())
}

/// The files read through one folder ([`super::Root::recording`]), shared by its clones.
#[derive(Debug, Default)]
pub struct Recorder {
    files: Mutex<BTreeMap<String, String>>,
}

impl Recorder {
    /// Notes that `path` (relative to its folder) had the SHA-256 `sha256`.
    pub(crate) fn note(&self, path: String, sha256: String) {
        let mut files = self.files.lock().unwrap_or_else(|e| e.into_inner());
        files.insert(path, sha256);
    }

    /// Every file noted, sorted by path.
    pub fn files(&self) -> Vec<InputFile> {
        let files = self.files.lock().unwrap_or_else(|e| e.into_inner());
        (files.iter())
            .map(|(path, sha256)| InputFile {
                path: path.clone(),
                sha256: sha256.clone(),
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sha256_of_known_texts() {
        // FIPS 180-2, appendix B.1: "abc".
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
        let mut reader: &[u8] = b"abc";
        assert_eq!(sha256_of(&mut reader).unwrap(), sha256_hex(b"abc"));
    }

    #[test]
    fn paths_are_recorded_relative_with_forward_slashes() {
        let dir = Path::new("plant/camp");
        assert_eq!(
            relative_to(&dir.join("data/x.csv"), dir),
            "data/x.csv".to_string()
        );
        assert_eq!(relative_to(&dir.join("a/../b/./c.csv"), dir), "b/c.csv");
        assert_eq!(
            relative_to(&dir.join("../shared/s.yaml"), dir),
            "../shared/s.yaml"
        );
        assert_eq!(relative_to(Path::new("x.csv"), Path::new("")), "x.csv");
        #[cfg(unix)]
        assert_eq!(relative_to(Path::new("/data/x.csv"), dir), "/data/x.csv");
    }

    #[test]
    fn folders_are_named_from_the_campaigns_folder() {
        let base = std::env::temp_dir().join(format!("axcheck-path-from-{}", std::process::id()));
        std::fs::create_dir_all(base.join("plant/camp")).unwrap();
        std::fs::create_dir_all(base.join("plant/templates")).unwrap();
        let camp = base.join("plant/camp");
        assert_eq!(
            path_from(&camp, &base.join("plant/templates")),
            "../templates"
        );
        // A history a run will create.
        assert_eq!(path_from(&camp, &camp.join("history/new")), "history/new");
        assert_eq!(path_from(&camp, &camp), ".");
        std::fs::remove_dir_all(base).unwrap();
    }
}
