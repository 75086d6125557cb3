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
        "cannot find the campaign file {campaign} (the path `run` was given, taken from the folder it ran in); run reproduce from that folder, or give the campaign with --campaign FILE"
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
/// templates and the history.
#[derive(Debug, Clone)]
pub struct Places {
    pub campaign: PathBuf,
    pub templates: Option<PathBuf>,
    pub history: Option<PathBuf>,
}

impl Places {
    /// The campaign at `campaign` (else the path `run` was given, from the current
    /// folder), the templates and the history as recorded: `--templates` and `--history`
    /// as given, else the campaign's `history:` beside it.
    pub fn of(inputs: &Inputs, campaign: Option<&Path>) -> Result<Places, ReproduceError> {
        let campaign = campaign.map_or_else(|| PathBuf::from(&inputs.campaign), Path::to_path_buf);
        if std::fs::symlink_metadata(&campaign).is_err() {
            return Err(ReproduceError::NoCampaign {
                campaign: campaign.display().to_string(),
            });
        }
        let dir = campaign.parent().map(Path::to_path_buf).unwrap_or_default();
        let history = (inputs.history.as_ref()).map(|h| match &inputs.options.history {
            Some(given) => PathBuf::from(given),
            None => dir.join(&h.folder),
        });
        Ok(Places {
            templates: (inputs.templates.as_ref()).map(|t| PathBuf::from(&t.folder)),
            campaign,
            history,
        })
    }
}

/// Each recorded input read again and its SHA-256 compared: what changed, in the order
/// recorded (the campaign's files, the templates, the history's). An input that exists
/// but cannot be read stops the check (exit 2).
pub fn check_inputs(inputs: &Inputs, places: &Places) -> Result<Vec<InputChange>, ReproduceError> {
    let dir = places.campaign.parent().unwrap_or(Path::new(""));
    let campaign_name = crate::files::relative_to(&places.campaign, dir);
    let mut changes = Vec::new();
    for f in &inputs.files {
        // The campaign file is where it was found, whatever its name.
        let path = match f.path == inputs_campaign_name(inputs) {
            true => places.campaign.clone(),
            false => dir.join(&f.path),
        };
        let shown = match f.path == inputs_campaign_name(inputs) {
            true => campaign_name.clone(),
            false => f.path.clone(),
        };
        check_one(&path, &shown, f, &mut changes)?;
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

/// The campaign file's entry among the recorded files: the name of the path `run` was
/// given.
fn inputs_campaign_name(inputs: &Inputs) -> String {
    let given = Path::new(&inputs.campaign);
    let dir = given.parent().unwrap_or(Path::new(""));
    crate::files::relative_to(given, dir)
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
