//! The judge's configuration as the campaign states it: the specs its axes name (read
//! beneath its folder, or built in), each test's limits, and its decision rule
//! (ISO 14253-1 or simple).

use crate::campaign::{AxisSpec, Campaign};
use crate::files::Root as Files;
use crate::judge::{self, DecisionRule, Limits, NoBand, Spec};
use crate::measurement::AxisData;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The decision rule: the axis's, else its spec's, else the campaign's, else simple.
pub fn decision_rule(
    axis: &AxisSpec,
    spec: Option<&Spec>,
    campaign_rule: Option<DecisionRule>,
) -> DecisionRule {
    (axis.raw.decision_rule)
        .or(spec.and_then(|s| s.decision_rule))
        .or(campaign_rule)
        .unwrap_or_default()
}

/// The limits a test of `axis` is judged against: its spec's band for the test's
/// measurement travel, with the axis's own tolerances over it.
pub fn limits(axis: &AxisSpec, spec: Option<&Spec>, data: &AxisData) -> Result<Limits, NoBand> {
    let (first, last) = data.measurement_travel();
    judge::limits(spec, &axis.raw.tolerances, axis.raw.kind, last - first)
}

/// Why a spec the campaign names cannot be had.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SpecError {
    /// The campaign's folder rules refuse the path.
    #[error("spec `{name}`: {refused}")]
    Path {
        name: String,
        refused: crate::files::PathRefused,
    },
    #[error("{}: cannot read the spec: {reason}", path.display())]
    Unreadable { path: PathBuf, reason: String },
    /// The file (or the built-in text) is no valid spec; the error names file and line.
    #[error(transparent)]
    Invalid(#[from] crate::yaml::YamlError),
    #[error(
        "spec `{name}` not found{hint}: no {} and no built-in spec of that name (built in: {builtin})",
        path.display()
    )]
    NotFound {
        name: String,
        /// Did you mean, with its leading words (or empty).
        hint: String,
        path: PathBuf,
        builtin: String,
    },
}

/// Every spec the campaign names, loaded once: `specs/NAME.yaml` beside the campaign, a
/// path to a `.yaml` file, or a spec built into axcheck.
pub fn load_specs(
    campaign: &Campaign,
    files: &Files,
) -> BTreeMap<String, Result<Arc<Spec>, SpecError>> {
    let mut specs = BTreeMap::new();
    for (_, entry) in campaign.axes() {
        if let Ok(axis) = &entry.spec
            && let Some(name) = &axis.spec
            && !specs.contains_key(name)
        {
            let spec = load_spec(files, name);
            specs.insert(name.clone(), spec.map(Arc::new));
        }
    }
    specs
}

/// A spec named by path, or `specs/NAME.yaml` beside the campaign, or a built-in one; the
/// path follows the campaign folder's rules ([`Files`]).
fn load_spec(files: &Files, name: &str) -> Result<Spec, SpecError> {
    let is_path = name.ends_with(".yaml") || name.ends_with(".yml");
    let relative = if is_path {
        name.to_string()
    } else {
        format!("specs/{name}.yaml")
    };
    let candidate = (files.resolve(&relative)).map_err(|refused| SpecError::Path {
        name: name.to_string(),
        refused,
    })?;
    // Anything at the path is the spec (a folder or a pipe there is an error, not a
    // reason to take the built-in spec of that name).
    if std::fs::symlink_metadata(&candidate).is_ok() {
        let text = (files.read_to_string(&candidate)).map_err(|e| SpecError::Unreadable {
            path: candidate.clone(),
            reason: e.to_string(),
        })?;
        return Ok(Spec::from_yaml(&text, &candidate.display().to_string())?);
    }
    if !is_path && let Some((_, text)) = judge::BUILTIN_SPECS.iter().find(|(n, _)| *n == name) {
        return Ok(Spec::from_yaml(text, &format!("built-in spec {name}"))?);
    }
    let builtin: Vec<&str> = judge::BUILTIN_SPECS.iter().map(|(n, _)| *n).collect();
    let beside = spec_files(&files.dir().join("specs"));
    let known: Vec<&str> = (builtin.iter().copied())
        .chain(beside.iter().map(String::as_str))
        .collect();
    let hint = match is_path {
        true => String::new(),
        false => crate::suggest::hint(name, &known),
    };
    Err(SpecError::NotFound {
        name: name.to_string(),
        hint,
        path: candidate,
        builtin: builtin.join(", "),
    })
}

/// The names of the spec files in `dir` (`NAME` of `NAME.yaml`), for did-you-mean.
fn spec_files(dir: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    entries
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|n| n.strip_suffix(".yaml").map(str::to_string))
        .collect()
}
