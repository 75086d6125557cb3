//! Where an axis's measurement files are: one file, a list, or a folder and a glob.
//!
//! Paths are relative to the campaign file's folder. A path that is absolute or climbs out
//! of that folder with `..` is refused unless the campaign sets `allow_outside_paths:
//! true`: a campaign copied between machines should not silently read other files.

use crate::files::{PathRefused, Root};
use crate::yaml::describe;
use std::path::PathBuf;

/// The `data:` of an axis.
#[derive(Debug, Clone, PartialEq)]
pub enum DataSource {
    /// One file or a list of files: several files are several tests of the axis.
    Files(Vec<String>),
    /// Every file under `dir` whose path relative to `dir` matches `glob`.
    Glob { dir: String, glob: String },
    /// One file and what to read of it: the sheet of a workbook (the first when `None`),
    /// the reference of an ecmc ISO 230 app file (the one it evaluated when `None`).
    Book {
        file: String,
        sheet: Option<String>,
        reference: Option<crate::measurement::Source>,
    },
}

/// A `data:` that is none of its forms: where in it (`""`, `[1]`, `.dir`), whether the
/// key or its value is wrong, and what was expected.
#[derive(Debug, Clone, PartialEq)]
pub struct BadData {
    /// Path below `data`.
    pub path: String,
    /// The key at `path` is wrong (unknown), not its value.
    pub(crate) at_key: bool,
    pub message: String,
}

impl BadData {
    fn value(path: impl Into<String>, message: String) -> BadData {
        BadData {
            path: path.into(),
            at_key: false,
            message,
        }
    }
}

/// What `data:` may be, for messages.
const FORMS: &str = "a file path, a list of paths, {dir: FOLDER, glob: PATTERN} or {file: BOOK, sheet: NAME} ({file: REPORT, reference: N} for an ecmc ISO 230 app file)";

impl DataSource {
    pub fn from_value(value: &serde_norway::Value) -> Result<DataSource, BadData> {
        use serde_norway::Value;
        match value {
            Value::String(s) if !s.trim().is_empty() => Ok(DataSource::Files(vec![s.clone()])),
            Value::Sequence(items) if !items.is_empty() => items
                .iter()
                .enumerate()
                .map(|(k, v)| match v {
                    Value::String(s) if !s.trim().is_empty() => Ok(s.clone()),
                    other => Err(BadData::value(
                        format!("[{k}]"),
                        format!("expected a file path, got {}", describe(other)),
                    )),
                })
                .collect::<Result<Vec<_>, _>>()
                .map(DataSource::Files),
            Value::Mapping(map) => from_map(map),
            other => Err(BadData::value(
                "",
                format!("expected {FORMS}, got {}", describe(other)),
            )),
        }
    }

    /// The sheet to read in every file (`{file, sheet}`); `None`: the first of a workbook.
    pub fn sheet(&self) -> Option<&str> {
        match self {
            DataSource::Book { sheet, .. } => sheet.as_deref(),
            _ => None,
        }
    }

    /// What to read of every file: the sheet, the reference (`{file, sheet, reference}`).
    pub(crate) fn read_options(&self) -> crate::measurement::ReadOptions<'_> {
        match self {
            DataSource::Book {
                sheet, reference, ..
            } => crate::measurement::ReadOptions {
                sheet: sheet.as_deref(),
                source: *reference,
                ..Default::default()
            },
            _ => crate::measurement::ReadOptions::default(),
        }
    }

    /// The files, resolved in the campaign's folder `root` and sorted (a glob's matches by
    /// path).
    pub fn resolve(&self, root: &Root) -> Result<Vec<PathBuf>, DataFilesError> {
        match self {
            DataSource::Book { file, .. } => Ok(vec![root.written(file)?]),
            DataSource::Files(files) => Ok(files
                .iter()
                .map(|f| root.resolve(f))
                .collect::<Result<_, _>>()?),
            DataSource::Glob { dir, glob } => glob_files(root, dir, glob),
        }
    }
}

/// Why a test's data files cannot be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DataFilesError {
    #[error(transparent)]
    Refused(#[from] PathRefused),
    #[error("data folder {} does not exist", .0.display())]
    NoFolder(PathBuf),
    #[error("bad glob `{glob}`: {reason}")]
    BadGlob { glob: String, reason: String },
    #[error("cannot list {}: {reason}", folder.display())]
    CannotList { folder: PathBuf, reason: String },
    #[error("no file in {} matches `{glob}`", folder.display())]
    NoMatch { folder: PathBuf, glob: String },
}

/// Every file under `root/dir` whose path relative to it matches `glob`, sorted.
fn glob_files(root: &Root, dir: &str, glob: &str) -> Result<Vec<PathBuf>, DataFilesError> {
    let folder = root.resolve(dir)?;
    if !folder.is_dir() {
        return Err(DataFilesError::NoFolder(folder));
    }
    let matcher = globset::Glob::new(glob)
        .map_err(|e| DataFilesError::BadGlob {
            glob: glob.to_string(),
            reason: e.to_string(),
        })?
        .compile_matcher();
    let hidden_ok = glob.starts_with('.');
    let mut found = Vec::new();
    // Links to folders are not followed (a link loop cannot hang the walk); a link to a
    // file, or a special file, is a match, checked like any other.
    for entry in walkdir::WalkDir::new(&folder)
        .follow_links(false)
        .sort_by_file_name()
    {
        let entry = entry.map_err(|e| DataFilesError::CannotList {
            folder: folder.clone(),
            reason: e.to_string(),
        })?;
        if !crate::files::may_match(&entry) {
            continue;
        }
        let rel = entry.path().strip_prefix(&folder).unwrap_or(entry.path());
        let hidden = rel
            .components()
            .any(|c| c.as_os_str().to_string_lossy().starts_with('.'));
        if (hidden_ok || !hidden) && matcher.is_match(rel) {
            found.push(entry.path().to_path_buf());
        }
    }
    if found.is_empty() {
        return Err(DataFilesError::NoMatch {
            folder,
            glob: glob.to_string(),
        });
    }
    found.sort();
    root.check_found(&found)?;
    Ok(found)
}

/// The keys of `data:` as a mapping.
const MAP_KEYS: &[&str] = &["dir", "glob", "file", "sheet", "reference"];

/// `{dir: FOLDER, glob: PATTERN}` or `{file: BOOK, sheet: NAME, reference: N}` (sheet and
/// reference optional).
fn from_map(map: &serde_norway::Mapping) -> Result<DataSource, BadData> {
    let (mut dir, mut glob, mut file, mut sheet, mut reference) = (None, None, None, None, None);
    for (k, v) in map {
        let Some(key) = k.as_str() else {
            return Err(BadData::value("", format!("expected {FORMS}")));
        };
        let (slot, what) = match key {
            "dir" => (&mut dir, "a folder"),
            "glob" => (&mut glob, "a pattern such as \"*.csv\""),
            "file" => (&mut file, "a file path"),
            "sheet" => (&mut sheet, "a sheet's name"),
            "reference" => (&mut reference, "a reference 1 to 5 or `rbv`"),
            other => {
                return Err(BadData {
                    path: format!(".{other}"),
                    at_key: true,
                    message: format!(
                        "unknown key `{other}`{}; expected {{dir: FOLDER, glob: PATTERN}} or {{file: BOOK, sheet: NAME}}",
                        crate::suggest::hint(other, MAP_KEYS)
                    ),
                });
            }
        };
        // A sheet named `2024` is written unquoted: a whole number is its name (and a
        // reference's number is a number).
        let number_name = v
            .as_u64()
            .map(|n| n.to_string())
            .filter(|_| key == "sheet" || key == "reference");
        match v.as_str().map(str::to_string).or(number_name) {
            Some(text) if !text.trim().is_empty() => *slot = Some(text),
            _ => {
                let message = format!("expected {what}, got {}", describe(v));
                return Err(BadData::value(format!(".{key}"), message));
            }
        }
    }
    let reference = match reference {
        None => None,
        Some(text) => Some(
            crate::measurement::Source::parse(&text)
                .map_err(|unknown| BadData::value(".reference", unknown.to_string()))?,
        ),
    };
    match (dir, glob, file, sheet, reference) {
        (Some(dir), Some(glob), None, None, None) => Ok(DataSource::Glob { dir, glob }),
        (None, None, Some(file), sheet, reference) => Ok(DataSource::Book {
            file,
            sheet,
            reference,
        }),
        (None, None, None, Some(_), _) => Err(BadData::value(
            "",
            "`sheet` needs its `file`, e.g. {file: data/x.xlsx, sheet: X axis}".into(),
        )),
        (None, None, None, None, Some(_)) => Err(BadData::value(
            "",
            "`reference` needs its `file`, e.g. {file: data/x-report.md, reference: 2}".into(),
        )),
        (_, _, None, None, None) => Err(BadData::value(
            "",
            "expected both `dir` and `glob`, e.g. {dir: data/vmc07, glob: \"x-*.csv\"}".into(),
        )),
        _ => Err(BadData::value(
            "",
            "give either {dir, glob} or {file, sheet}, not keys of both".into(),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_forms() {
        let v: serde_norway::Value = serde_norway::from_str("{dir: d, glob: \"*.csv\"}").unwrap();
        assert_eq!(
            DataSource::from_value(&v).unwrap(),
            DataSource::Glob {
                dir: "d".into(),
                glob: "*.csv".into()
            }
        );
        let v: serde_norway::Value = serde_norway::from_str("{dir: d}").unwrap();
        assert!(
            DataSource::from_value(&v)
                .unwrap_err()
                .message
                .contains("both")
        );
        let v: serde_norway::Value = serde_norway::from_str("[a.csv, b.csv]").unwrap();
        assert_eq!(
            DataSource::from_value(&v).unwrap(),
            DataSource::Files(vec!["a.csv".into(), "b.csv".into()])
        );
        let v: serde_norway::Value = serde_norway::from_str("12").unwrap();
        assert_eq!(
            DataSource::from_value(&v).unwrap_err().message,
            "expected a file path, a list of paths, {dir: FOLDER, glob: PATTERN} or {file: BOOK, sheet: NAME} ({file: REPORT, reference: N} for an ecmc ISO 230 app file), got the number 12"
        );
        let v: serde_norway::Value = serde_norway::from_str("[a.csv, 2]").unwrap();
        let e = DataSource::from_value(&v).unwrap_err();
        assert_eq!(
            (e.path.as_str(), e.message.as_str()),
            ("[1]", "expected a file path, got the number 2")
        );
        let v: serde_norway::Value = serde_norway::from_str("{dir: [d], glob: x}").unwrap();
        let e = DataSource::from_value(&v).unwrap_err();
        assert_eq!(
            (e.path.as_str(), e.message.as_str()),
            (".dir", "expected a folder, got a list of 1 item")
        );
    }

    #[test]
    fn book_and_sheet() {
        let parse = |text: &str| {
            let v: serde_norway::Value = serde_norway::from_str(text).unwrap();
            DataSource::from_value(&v)
        };
        let book = parse("{file: b.xlsx, sheet: X axis}").unwrap();
        assert_eq!(book.sheet(), Some("X axis"));
        assert_eq!(
            book.resolve(&Root::campaign(std::path::Path::new("camp"), false))
                .unwrap(),
            vec![std::path::Path::new("camp/b.xlsx")]
        );
        assert_eq!(parse("{file: b.xlsx}").unwrap().sheet(), None);
        let e = parse("{file: b.xlsx, shet: X}").unwrap_err();
        assert_eq!(e.path, ".shet");
        assert!(
            e.at_key && e.message.contains("did you mean `sheet`"),
            "{}",
            e.message
        );
        assert!(
            parse("{sheet: X}")
                .unwrap_err()
                .message
                .contains("needs its `file`")
        );
        assert!(
            parse("{dir: d, file: b.xlsx}")
                .unwrap_err()
                .message
                .contains("not keys of both")
        );
        assert_eq!(
            parse("{file: b.xlsx, sheet: 2024}").unwrap().sheet(),
            Some("2024")
        );
        let e = parse("{file: b.xlsx, sheet: [X]}").unwrap_err();
        assert_eq!(
            (e.path.as_str(), e.message.as_str()),
            (".sheet", "expected a sheet's name, got a list of 1 item")
        );
        assert!(
            parse("{file: ../b.xlsx}")
                .unwrap()
                .resolve(&Root::campaign(std::path::Path::new("c"), false))
                .is_err()
        );
    }
}
