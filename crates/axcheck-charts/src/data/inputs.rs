//! The inputs of a run as the summaries list them (`summary.pdf`, `summary.md`): the
//! axcheck version, the command, and each file read with its SHA-256, whole or its start
//! (`results.json` `inputs` has every one whole).

use crate::inputs::{InputFile, Inputs};
use serde::Serialize;

/// Files listed in `summary.pdf` before "… and N more".
pub const PDF_LISTED: usize = 60;
/// Hex digits of each SHA-256 in `summary.pdf` (64 bits: enough to tell two files apart).
pub const PDF_DIGITS: usize = 16;

/// The run's inputs, the first files of them.
#[derive(Debug, Serialize)]
pub struct InputsList {
    /// The version of axcheck that ran.
    pub axcheck: String,
    /// `axcheck run …` as it was run (without the output folder).
    pub command: String,
    pub rows: Vec<InputRow>,
    /// Every file recorded (the rows are the first of them).
    pub total: usize,
    /// Files beyond the rows.
    pub more: usize,
}

/// One file: its path (relative to the campaign's folder; a template's and a history
/// file's after their folder as given) and its SHA-256 (or its first digits).
#[derive(Debug, Serialize)]
pub struct InputRow {
    pub path: String,
    pub sha256: String,
}

/// The first `listed` files of `inputs`, each SHA-256 cut to `digits` hex digits; `None`
/// when the run recorded none (a result that no run wrote, as Python's `check`).
pub fn inputs_list(inputs: &Inputs, listed: usize, digits: usize) -> Option<InputsList> {
    if inputs.axcheck.is_empty() {
        return None;
    }
    let beneath = |folder: &str, f: &InputFile| InputFile {
        path: format!("{}/{}", folder.trim_end_matches(['/', '\\']), f.path),
        sha256: f.sha256.clone(),
    };
    let templates =
        (inputs.templates.iter()).flat_map(|t| t.files.iter().map(|f| beneath(&t.folder, f)));
    let history =
        (inputs.history.iter()).flat_map(|h| h.files.iter().map(|f| beneath(&h.folder, f)));
    let all: Vec<InputFile> = (inputs.files.iter().cloned())
        .chain(templates)
        .chain(history)
        .collect();
    let rows: Vec<InputRow> = (all.iter().take(listed))
        .map(|f| InputRow {
            path: f.path.clone(),
            sha256: f.sha256.chars().take(digits).collect(),
        })
        .collect();
    Some(InputsList {
        axcheck: inputs.axcheck.clone(),
        command: inputs.command.clone(),
        more: all.len() - rows.len(),
        total: all.len(),
        rows,
    })
}

/// The first [`PDF_DIGITS`] hex digits of the SHA-256 of `file` (relative to the
/// campaign's folder), as the run recorded it, with an ellipsis: an axis report's
/// measurement file.
pub fn short_sha256(inputs: &Inputs, file: Option<&str>) -> Option<String> {
    let file = file?;
    let found = inputs.files.iter().find(|f| f.path == file)?;
    Some(format!(
        "{}…",
        &found.sha256[..PDF_DIGITS.min(found.sha256.len())]
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::inputs::Folder;

    #[test]
    fn the_list_is_cut_and_the_templates_follow_the_campaign_files() {
        let file = |path: &str| InputFile {
            path: path.into(),
            sha256: "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad".into(),
        };
        let inputs = Inputs {
            axcheck: "0.1.0".into(),
            files: vec![file("campaign.yaml"), file("data/x.csv")],
            templates: Some(Folder {
                folder: "my-templates/".into(),
                files: vec![file("summary.typ")],
            }),
            ..Inputs::default()
        };
        let list = inputs_list(&inputs, 2, 16).unwrap();
        assert_eq!(list.total, 3);
        assert_eq!(list.more, 1);
        assert_eq!(list.rows[1].path, "data/x.csv");
        assert_eq!(list.rows[1].sha256, "ba7816bf8f01cfea");
        let all = inputs_list(&inputs, 10, 64).unwrap();
        assert_eq!(all.rows[2].path, "my-templates/summary.typ");
        assert!(inputs_list(&Inputs::default(), 10, 64).is_none());
    }
}
