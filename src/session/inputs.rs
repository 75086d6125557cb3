//! The run's `inputs` completed once everything is read: the version, the options as
//! given, the templates read and the history the trends were fitted on (the files beneath
//! the campaign's folder were noted by the batch).

use super::{Appended, RunOptions};
use crate::inputs::{Folder, History, InputFile, Inputs};
use std::path::Path;

/// `inputs` (the campaign's files, from the batch) with the rest of the run;
/// `campaign_history`: the campaign's `history:` as written.
pub(super) fn complete(
    inputs: Inputs,
    plan: &RunOptions,
    reports: Option<&crate::report::Reports>,
    appended: Option<&Appended>,
    campaign_history: Option<&str>,
) -> Inputs {
    let templates = match (&plan.flags.templates, reports) {
        (Some(dir), Some(reports)) => Some(Folder {
            folder: dir.clone(),
            files: reports.templates_read().to_vec(),
        }),
        _ => None,
    };
    // Named as given, never by where it lies: `reproduce` runs on a copy.
    let named = (plan.flags.history.clone()).or_else(|| campaign_history.map(str::to_string));
    let history = (plan.history.as_deref())
        .zip(appended)
        .map(|(dir, a)| History {
            folder: named.unwrap_or_default(),
            files: history_files(dir, a.path.as_deref()),
            written: (a.path.as_deref()).map(|p| crate::files::relative_to(p, dir)),
        });
    Inputs {
        axcheck: env!("CARGO_PKG_VERSION").to_string(),
        command: plan.flags.command(&inputs.campaign),
        options: plan.flags.clone(),
        templates,
        history,
        ..inputs
    }
}

/// The history's files the trends read but the one this run wrote, each with its SHA-256
/// (a file that cannot be read now is left out: the run said why it has no trends).
pub(crate) fn history_files(dir: &Path, written: Option<&Path>) -> Vec<InputFile> {
    let root = crate::files::Root::folder(dir, "history folder").recording();
    for path in crate::history::history_files(dir).unwrap_or_default() {
        if Some(path.as_path()) != written {
            let _ = root.read(&path);
        }
    }
    root.recorded()
}
