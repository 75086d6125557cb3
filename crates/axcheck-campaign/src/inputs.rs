//! What a campaign run read and how it was run (`results.json` `inputs`): the axcheck
//! version, every file read with its SHA-256, and the command-line options that change
//! the outputs, so that `axcheck reproduce` can check the inputs and run it again the same
//! way. No time, no real path: the same run gives the same block.

pub use crate::files::InputFile;
use serde::{Deserialize, Serialize};

/// The `inputs` block of `results.json`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Inputs {
    /// The version of axcheck that ran.
    pub axcheck: String,
    /// The campaign file's name (in its folder, which every other path starts from).
    pub campaign: String,
    /// Every file read from the campaign's folder, the campaign file too: its path
    /// relative to that folder (`/`-separated) and its SHA-256, sorted by path.
    pub files: Vec<InputFile>,
    /// The templates read from `--templates` (paths relative to its folder); `null` with
    /// the built-in templates or without PDFs.
    #[serde(default)]
    pub templates: Option<Folder>,
    /// The inspection history the run was appended to; `null` without one.
    #[serde(default)]
    pub history: Option<History>,
    /// The command-line options of `run` that change its outputs.
    pub options: RunFlags,
    /// `axcheck run CAMPAIGN …` with those options, as run from the campaign's folder
    /// (without `--out`, `--jobs` and the options that change nothing in the outputs).
    pub command: String,
}

/// A folder given on the command line and the files read from it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Folder {
    /// `--templates DIR` seen from the campaign's folder (`../templates`).
    pub folder: String,
    pub files: Vec<InputFile>,
}

/// The history a run was appended to, and what of it the trends read.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct History {
    /// `--history DIR` seen from the campaign's folder, else the campaign's `history:`
    /// as written.
    pub folder: String,
    /// The other runs' files the trends were fitted on (relative to the folder).
    pub files: Vec<InputFile>,
    /// The file this run wrote into it (an output of the run, not an input); `null` when
    /// no test was evaluated.
    #[serde(default)]
    pub written: Option<String>,
}

/// The options of `axcheck run` that change its outputs (each `false` or `null` when not
/// given; the campaign's own `output:` settings are in its file). The folders are seen
/// from the campaign's folder, so that the record names no place on one machine.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct RunFlags {
    #[serde(default)]
    pub no_pdf: bool,
    #[serde(default)]
    pub no_html: bool,
    #[serde(default)]
    pub no_diagnose: bool,
    /// `--templates DIR`, from the campaign's folder.
    #[serde(default)]
    pub templates: Option<String>,
    /// `--history DIR`, from the campaign's folder.
    #[serde(default)]
    pub history: Option<String>,
    /// `--horizon YEARS`.
    #[serde(default)]
    pub horizon: Option<f64>,
    /// `--lang`: the reports' language (recorded only when given, so that the record of a
    /// run without it stays as it was).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lang: Option<crate::lang::Lang>,
}

impl RunFlags {
    /// `axcheck run CAMPAIGN` and these options, each argument quoted for a POSIX shell
    /// when it needs it.
    pub fn command(&self, campaign: &str) -> String {
        let mut words = vec!["axcheck".to_string(), "run".to_string(), quoted(campaign)];
        let flags = [
            (self.no_pdf, "--no-pdf"),
            (self.no_html, "--no-html"),
            (self.no_diagnose, "--no-diagnose"),
        ];
        words.extend((flags.iter().filter(|(on, _)| *on)).map(|(_, f)| f.to_string()));
        if let Some(dir) = &self.templates {
            words.extend(["--templates".to_string(), quoted(dir)]);
        }
        if let Some(dir) = &self.history {
            words.extend(["--history".to_string(), quoted(dir)]);
        }
        if let Some(years) = self.horizon {
            words.extend(["--horizon".to_string(), years.to_string()]);
        }
        if let Some(lang) = self.lang {
            words.extend(["--lang".to_string(), lang.to_string()]);
        }
        words.join(" ")
    }
}

/// `word` as one word of a POSIX shell: as it is when it holds only safe characters, else
/// in single quotes.
fn quoted(word: &str) -> String {
    let safe = |c: char| c.is_alphanumeric() || "-_./=:@%+,".contains(c);
    match !word.is_empty() && word.chars().all(safe) {
        true => word.to_string(),
        false => format!("'{}'", word.replace('\'', r"'\''")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_command_names_the_options_given() {
        let flags = RunFlags {
            no_pdf: true,
            history: Some("plant history".into()),
            horizon: Some(1.5),
            lang: Some(crate::lang::Lang::Ru),
            ..RunFlags::default()
        };
        assert_eq!(
            flags.command("campaign.yaml"),
            "axcheck run campaign.yaml --no-pdf --history 'plant history' --horizon 1.5 --lang ru"
        );
        assert_eq!(
            RunFlags::default().command("it's.yaml"),
            r"axcheck run 'it'\''s.yaml'"
        );
    }
}
