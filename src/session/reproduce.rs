//! `axcheck reproduce`: a run's recorded inputs (`results.json` `inputs`) found, checked
//! against their SHA-256, and the history copied for the re-run; [`super::compare`]
//! compares its outputs with the run's. The command line runs the campaign between.

use crate::files::{FileError, sha256_hex};
use crate::inputs::{InputFile, Inputs};
use std::path::{Path, PathBuf};

/// Why a run cannot be reproduced at all (exit 2, as other input errors).
#[derive(Debug, thiserror::Error)]
pub enum ReproduceError {
    #[error("{}: {reason}", path.display())]
    Unreadable { path: PathBuf, reason: String },
    #[error(
        "{}: the PDF does not carry the inputs of its run, and no results.json that lists it was found in its folder or above; give the results.json of its run (or the folder the run wrote)",
        .0.display()
    )]
    PdfAlone(PathBuf),
    #[error("{}: no results.json in this folder; give a results.json, the folder a run wrote, or one of its PDF reports", .0.display())]
    NoResults(PathBuf),
    #[error(
        "{}: no `inputs` block: it was written by an axcheck that did not record its inputs; run the campaign again with this one to record them",
        .0.display()
    )]
    NoInputs(PathBuf),
    #[error(
        "cannot find the campaign file {campaign} as the run read it (by its SHA-256) beside the output folder, above it or in the current folder; give it with --campaign FILE"
    )]
    NoCampaign { campaign: String },
    #[error("copying the history {} for the re-run: {cause}", from.display())]
    HistoryCopy { from: PathBuf, cause: String },
}

/// A run's outputs and what it recorded.
#[derive(Debug)]
pub struct Recorded {
    /// The output folder (the folder of `results.json`).
    pub out: PathBuf,
    pub results: PathBuf,
    pub inputs: Inputs,
}

/// The run behind `given`: a `results.json`, the folder a run wrote, or a PDF report of
/// one (found through the `results.json` of its folder or a folder above, whose manifest
/// lists it).
pub fn recorded(given: &Path) -> Result<Recorded, ReproduceError> {
    let results = results_of(given)?;
    let out = results.parent().map(Path::to_path_buf).unwrap_or_default();
    let bytes = crate::files::read(&results).map_err(|e| unreadable(&results, e))?;
    #[derive(serde::Deserialize)]
    struct Head {
        inputs: Option<Inputs>,
    }
    let head: Head = serde_json::from_slice(&bytes).map_err(|e| ReproduceError::Unreadable {
        path: results.clone(),
        reason: format!("not the results.json of a run: {e}"),
    })?;
    let inputs = head
        .inputs
        .ok_or_else(|| ReproduceError::NoInputs(results.clone()))?;
    Ok(Recorded {
        out,
        results,
        inputs,
    })
}

fn unreadable(path: &Path, e: FileError) -> ReproduceError {
    ReproduceError::Unreadable {
        path: path.to_path_buf(),
        reason: e.to_string(),
    }
}

/// The `results.json` that `given` stands for.
fn results_of(given: &Path) -> Result<PathBuf, ReproduceError> {
    if given.is_dir() {
        let results = given.join("results.json");
        return match results.exists() {
            true => Ok(results),
            false => Err(ReproduceError::NoResults(given.to_path_buf())),
        };
    }
    let is_pdf = given
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("pdf"));
    if !is_pdf {
        return Ok(given.to_path_buf());
    }
    // reports/MACHINE/AXIS.pdf lies two folders below its results.json.
    let mut folder = given.parent();
    for _ in 0..3 {
        let Some(dir) = folder else { break };
        let results = dir.join("results.json");
        let listed = given
            .strip_prefix(dir)
            .is_ok_and(|relative| manifest(dir).is_some_and(|m| m.lists(relative)));
        if results.is_file() && listed {
            return Ok(results);
        }
        folder = dir.parent().filter(|p| !p.as_os_str().is_empty());
    }
    Err(ReproduceError::PdfAlone(given.to_path_buf()))
}

/// An output folder's manifest ([`crate::atomic::MANIFEST`]): the files the run wrote.
#[derive(Debug, Clone, Default)]
pub struct Manifest {
    /// The files listed, `/`-separated relative paths (folders left out).
    pub files: Vec<String>,
    /// `# complete: true`.
    pub complete: bool,
}

impl Manifest {
    fn lists(&self, relative: &Path) -> bool {
        let relative = crate::files::relative_to(relative, Path::new(""));
        self.files.contains(&relative)
    }
}

/// The manifest of the output folder `dir`, if it has one.
pub fn manifest(dir: &Path) -> Option<Manifest> {
    let text = crate::files::read_to_string(&dir.join(crate::atomic::MANIFEST)).ok()?;
    let mut manifest = Manifest::default();
    for line in text.lines() {
        if line.trim() == "# complete: true" {
            manifest.complete = true;
        }
        if !line.starts_with('#') && !line.ends_with('/') && !line.is_empty() {
            manifest.files.push(line.to_string());
        }
    }
    Some(manifest)
}

/// An input that is not as the run read it.
#[derive(Debug, Clone, PartialEq)]
pub enum InputChange {
    /// Its bytes differ: the SHA-256 recorded and the one now.
    Changed {
        path: String,
        recorded: String,
        now: String,
    },
    Missing {
        path: String,
    },
    /// A history file that the run did not read (an inspection added since): the trends
    /// would differ.
    Added {
        path: String,
    },
}

/// Where the recorded inputs are now: the campaign file found, and the folders of the
/// templates and the history (both recorded from the campaign's folder).
#[derive(Debug, Clone)]
pub struct Places {
    pub campaign: PathBuf,
    pub templates: Option<PathBuf>,
    pub history: Option<PathBuf>,
}

impl Places {
    /// The campaign at `campaign`, else the file of the campaign's name and SHA-256 beside
    /// the output folder `out` or above it, or in the current folder, or in a folder of
    /// one of these ([`find_campaign`]).
    pub fn of(
        inputs: &Inputs,
        out: &Path,
        campaign: Option<&Path>,
    ) -> Result<Places, ReproduceError> {
        let campaign = match campaign {
            Some(path) => path.to_path_buf(),
            None => find_campaign(inputs, out).ok_or_else(|| ReproduceError::NoCampaign {
                campaign: inputs.campaign.clone(),
            })?,
        };
        let dir = campaign.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok(Places {
            templates: (inputs.templates.as_ref()).map(|t| dir.join(&t.folder)),
            history: (inputs.history.as_ref()).map(|h| dir.join(&h.folder)),
            campaign,
        })
    }
}

/// The campaign file a run read, found by its name and SHA-256 in the output folder's
/// parent and grandparent and the current folder, or in a folder directly inside one of
/// them (`out` beside `example-campaign/`); the first in that order, folders by name.
pub fn find_campaign(inputs: &Inputs, out: &Path) -> Option<PathBuf> {
    let recorded = (inputs.files.iter()).find(|f| f.path == inputs.campaign)?;
    let parent = out.parent().unwrap_or(Path::new(""));
    let grandparent = match parent.as_os_str().is_empty() {
        true => Path::new(".."),
        false => parent.parent().unwrap_or(Path::new("")),
    };
    let mut seen = Vec::new();
    for base in [parent, grandparent, Path::new("")] {
        // `""` is the current folder, which paths joined to it keep relative.
        let here = match base.as_os_str().is_empty() {
            true => Path::new("."),
            false => base,
        };
        match std::fs::canonicalize(here) {
            Ok(real) if seen.contains(&real) => continue,
            Ok(real) => seen.push(real),
            Err(_) => continue,
        }
        let mut folders: Vec<PathBuf> = (std::fs::read_dir(here).into_iter().flatten())
            .filter_map(Result::ok)
            .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()))
            .map(|e| base.join(e.file_name()))
            .collect();
        folders.sort();
        let found = std::iter::once(base.join(&inputs.campaign))
            .chain(folders.iter().map(|f| f.join(&inputs.campaign)))
            .find(|candidate| {
                crate::files::read(candidate)
                    .is_ok_and(|bytes| sha256_hex(&bytes) == recorded.sha256)
            });
        if found.is_some() {
            return found;
        }
    }
    None
}

/// Each recorded input read again and its SHA-256 compared: what changed, in the order
/// recorded (the campaign's files, the templates, the history's). An input that exists
/// but cannot be read stops the check (exit 2).
pub fn check_inputs(inputs: &Inputs, places: &Places) -> Result<Vec<InputChange>, ReproduceError> {
    let dir = places.campaign.parent().unwrap_or(Path::new(""));
    let mut changes = Vec::new();
    for f in &inputs.files {
        // The campaign file is the one found or given, whatever its name.
        let path = match f.path == inputs.campaign {
            true => places.campaign.clone(),
            false => dir.join(&f.path),
        };
        check_one(&path, &f.path, f, &mut changes)?;
    }
    if let (Some(t), Some(folder)) = (&inputs.templates, &places.templates) {
        for f in &t.files {
            let shown = format!("{}/{}", t.folder.trim_end_matches('/'), f.path);
            check_one(&folder.join(&f.path), &shown, f, &mut changes)?;
        }
    }
    if let (Some(h), Some(folder)) = (&inputs.history, &places.history) {
        let name = |path: &str| format!("{}/{path}", h.folder.trim_end_matches('/'));
        for f in &h.files {
            check_one(&folder.join(&f.path), &name(&f.path), f, &mut changes)?;
        }
        for path in crate::history::history_files(folder).unwrap_or_default() {
            let relative = crate::files::relative_to(&path, folder);
            let known = h.files.iter().any(|f| f.path == relative);
            if !known && h.written.as_deref() != Some(relative.as_str()) {
                changes.push(InputChange::Added {
                    path: name(&relative),
                });
            }
        }
    }
    Ok(changes)
}

/// `path` read and its SHA-256 compared with `recorded`'s (named `shown` when not).
fn check_one(
    path: &Path,
    shown: &str,
    recorded: &InputFile,
    changes: &mut Vec<InputChange>,
) -> Result<(), ReproduceError> {
    match crate::files::read(path) {
        Ok(bytes) => {
            let now = sha256_hex(&bytes);
            if now != recorded.sha256 {
                changes.push(InputChange::Changed {
                    path: shown.to_string(),
                    recorded: recorded.sha256.clone(),
                    now,
                });
            }
            Ok(())
        }
        Err(FileError::Io(e)) if e.kind() == std::io::ErrorKind::NotFound => {
            changes.push(InputChange::Missing {
                path: shown.to_string(),
            });
            Ok(())
        }
        Err(e) => Err(unreadable(path, e)),
    }
}

/// A temporary folder, removed with everything in it when dropped.
pub struct Scratch {
    pub dir: PathBuf,
}

impl Scratch {
    /// A new folder under the system's temporary folder.
    pub fn new() -> std::io::Result<Scratch> {
        let base = std::env::temp_dir();
        for k in 0..1000 {
            let dir = base.join(format!("axcheck-reproduce-{}-{k}", std::process::id()));
            match std::fs::create_dir(&dir) {
                Ok(()) => return Ok(Scratch { dir }),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(e) => return Err(e),
            }
        }
        Err(std::io::Error::other("no free name for a temporary folder"))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

/// Copies the history's files (`*.parquet`, in their folders) from `from` into `to`, for
/// a re-run that must not append to the user's history; the number of files copied.
pub fn copy_history(from: &Path, to: &Path) -> Result<usize, ReproduceError> {
    let fail = |cause: String| ReproduceError::HistoryCopy {
        from: from.to_path_buf(),
        cause,
    };
    std::fs::create_dir_all(to).map_err(|e| fail(e.to_string()))?;
    if !from.is_dir() {
        return Ok(0);
    }
    let files = crate::history::history_files(from).map_err(|e| fail(e.to_string()))?;
    for path in &files {
        let relative = path.strip_prefix(from).unwrap_or(path);
        let target = to.join(relative);
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(|e| fail(e.to_string()))?;
        }
        let bytes =
            crate::files::read(path).map_err(|e| fail(format!("{}: {e}", path.display())))?;
        std::fs::write(&target, bytes).map_err(|e| fail(format!("{}: {e}", target.display())))?;
    }
    Ok(files.len())
}
