//! YAML helpers for the campaign, spec and simulation files: a path → location index (so
//! that errors found after parsing still name line and column), typed deserialization
//! whose errors say in the user's words what was expected and found, and did-you-mean for
//! unknown keys.

mod depth;
mod fields;
mod index;
mod pieces;
mod words;

pub use depth::MAX_DEPTH;
pub use fields::field_names;
pub use index::{LocationIndex, join};
pub use words::{describe, keyword, names_of, not_a_name, optional_keyword, or_list};

use serde_norway::Value;

/// An error in a YAML file: `file:line:column: message`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{file}:{line}:{column}: {message}")]
pub struct YamlError {
    pub file: String,
    /// 1-based.
    pub line: usize,
    /// 1-based, in characters.
    pub column: usize,
    pub message: String,
}

/// A message with its (line, column) when known, before the file is named.
#[derive(Debug, Clone, PartialEq)]
pub struct Located {
    pub at: Option<(usize, usize)>,
    pub message: String,
}

impl Located {
    pub fn new(at: Option<(usize, usize)>, message: impl Into<String>) -> Located {
        Located {
            at,
            message: message.into(),
        }
    }

    /// The error in `file`; without a known place, at the start of the document.
    pub(crate) fn in_file(self, file: &str) -> YamlError {
        let (line, column) = self.at.unwrap_or((1, 1));
        YamlError {
            file: file.to_string(),
            line,
            column,
            message: self.message,
        }
    }
}

/// A serde path as `a.b[0].c`.
pub(crate) fn path_string(path: &serde_path_to_error::Path) -> String {
    use serde_path_to_error::Segment;
    let mut out = String::new();
    for segment in path {
        match segment {
            Segment::Seq { index } => out.push_str(&format!("[{index}]")),
            Segment::Map { key } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(key);
            }
            Segment::Enum { variant } => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(variant);
            }
            // A key that is not text: the error is the mapping's.
            Segment::Unknown => {}
        }
    }
    out
}

/// The value at a serde path inside `root`, when the path leads to one.
fn value_at<'v>(root: &'v Value, path: &serde_path_to_error::Path) -> Option<&'v Value> {
    use serde_path_to_error::Segment;
    let mut value = root;
    for segment in path {
        value = match segment {
            Segment::Seq { index } => value.get(index)?,
            Segment::Map { key } => value.get(key.as_str())?,
            Segment::Enum { .. } | Segment::Unknown => return None,
        };
    }
    Some(value)
}

/// Rewrites serde's "unknown field `x`, expected one of `a`, `b`" into a shorter message
/// with a suggestion; returns the unknown key when there is one.
pub fn explain(message: &str) -> (String, Option<String>) {
    let Some(rest) = message.strip_prefix("unknown field `") else {
        return (message.to_string(), None);
    };
    let Some(end) = rest.find('`') else {
        return (message.to_string(), None);
    };
    let field = rest[..end].to_string();
    let expected: Vec<&str> = rest[end + 1..]
        .split('`')
        .enumerate()
        .filter(|(k, _)| k % 2 == 1)
        .map(|(_, s)| s)
        .collect();
    let hint = crate::suggest::hint(&field, &expected);
    let list = if expected.is_empty() {
        String::new()
    } else {
        format!("; expected one of {}", expected.join(", "))
    };
    (format!("unknown key `{field}`{hint}{list}"), Some(field))
}

/// `base` and a path inside it as one path.
fn full_path(base: &str, inner: &str) -> String {
    match (base.is_empty(), inner.is_empty() || inner == ".") {
        (_, true) => base.to_string(),
        (true, false) => inner.to_string(),
        (false, false) if inner.starts_with('[') => format!("{base}{inner}"),
        (false, false) => format!("{base}.{inner}"),
    }
}

/// The last key of a path (`kind` of `machines[0].axes[1].kind`), or `value` when the
/// path ends in a list index.
fn last_key(path: &str) -> &str {
    match path.rsplit('.').next() {
        Some(key) if !key.is_empty() && !key.ends_with(']') => key,
        _ => "value",
    }
}

/// Deserializes `value` (found at `base` in the document) and turns a failure into a
/// message in the user's words with the location of the offending key or value.
pub(crate) fn deserialize_at<T: serde::de::DeserializeOwned>(
    value: &Value,
    base: &str,
    index: &LocationIndex,
) -> Result<T, Located> {
    deserialize_spelled(value, base, index, &|_, field| field.to_string())
}

/// [`deserialize_at`] for documents whose keys are spelled differently from the fields
/// they fill: `spell(path, field)` names the field of the mapping at `path` as the file
/// writes it (`pitch` as `pitch_mm`), for "missing key".
pub(crate) fn deserialize_spelled<T: serde::de::DeserializeOwned>(
    value: &Value,
    base: &str,
    index: &LocationIndex,
    spell: &dyn Fn(&str, &str) -> String,
) -> Result<T, Located> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let bad_key = e
            .path()
            .iter()
            .next_back()
            .is_some_and(|s| matches!(s, serde_path_to_error::Segment::Unknown));
        let found = value_at(value, e.path());
        let path = full_path(base, &path_string(e.path()));
        let raw = e.into_inner().to_string();
        let (message, unknown) = explain(&raw);
        if let Some(field) = unknown {
            // The path may or may not already end in the unknown key.
            let key_path = if path.ends_with(&format!(".{field}")) || path == field {
                path
            } else {
                join(&path, &field)
            };
            return Located::new(
                index.key_or_value(&key_path),
                format!("{key_path}: {message}"),
            );
        }
        let message = if bad_key {
            words::key_in_words(&message)
        } else {
            words::in_words(&message, last_key(&path), found, &|field| {
                spell(&path, field)
            })
        };
        let at = index.value(&path);
        Located::new(
            at,
            if path.is_empty() {
                message
            } else {
                format!("{path}: {message}")
            },
        )
    })
}

/// Parses `text` as YAML: the value and the location of every key and value. A syntax
/// error names its line and column, with a hint when a line is indented with a tab (YAML
/// allows only spaces).
pub fn parse(text: &str, file: &str) -> Result<(Value, LocationIndex), YamlError> {
    depth::check(text).map_err(|e| e.in_file(file))?;
    // The locations are indexed only when an error needs them.
    let (value, index) = (
        serde_norway::from_str::<Value>(text),
        LocationIndex::new(text),
    );
    let value = value.map_err(|e| syntax_error(&e, file, text, &index))?;
    Ok((value, index))
}

/// Pieces of a long list per thread: each piece's parser events are freed before the next
/// piece is parsed, so smaller pieces reuse their memory (the gate's peak on 10 000 axes:
/// 110 MB with one piece per thread, 91 MB with four, and 2 % faster).
const PIECES_PER_THREAD: usize = 4;

/// [`parse`] for a document whose top-level `key` holds a long block list (a campaign's
/// `machines:`): the list is parsed in pieces on the pool's threads when its text can be
/// cut plainly ([`pieces`]), else whole; the value is the same either way.
pub(crate) fn parse_long_list(
    text: &str,
    file: &str,
    key: &str,
) -> Result<(Value, LocationIndex), YamlError> {
    depth::check(text).map_err(|e| e.in_file(file))?;
    match pieces::parse_list_in_pieces(text, key, PIECES_PER_THREAD * rayon::current_num_threads())
    {
        Some(value) => Ok((value, LocationIndex::new(text))),
        None => parse(text, file),
    }
}

/// serde_norway's own errors carry a location; turn them into `file:line:col: message`,
/// with a hint when the line is indented with a tab (YAML allows only spaces). A key
/// given twice is placed at its second occurrence (serde_norway names the mapping).
fn syntax_error(
    e: &serde_norway::Error,
    file: &str,
    text: &str,
    index: &LocationIndex,
) -> YamlError {
    let raw = e.to_string();
    let message = words::syntax_in_words(&raw);
    if let Some(key) = words::duplicate_key(&raw)
        && let Some(at) = index.key(&key)
    {
        return Located::new(Some(at), message).in_file(file);
    }
    let Some(loc) = e.location() else {
        // An error about the document as a whole (a second document, aliases that expand
        // too far): at the second document's start when there is one, else the first's.
        let at = index.second_document().unwrap_or((1, 1));
        return Located::new(Some(at), message).in_file(file);
    };
    let line = text.lines().nth(loc.line().saturating_sub(1)).unwrap_or("");
    let hint = if line.trim_end().starts_with([' ', '\t']) && line.contains('\t')
        || line.starts_with('\t')
    {
        " (the line is indented with a tab; YAML indents with spaces only)"
    } else {
        ""
    };
    Located::new(Some((loc.line(), loc.column())), format!("{message}{hint}")).in_file(file)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn explains_unknown_fields() {
        let (m, f) = explain("unknown field `tolerence`, expected one of `name`, `tolerances`");
        assert_eq!(f.as_deref(), Some("tolerence"));
        assert!(m.contains("did you mean `tolerances`"), "{m}");
    }

    #[test]
    fn errors_name_the_place_in_the_users_words() {
        #[derive(Debug, serde::Deserialize)]
        #[serde(deny_unknown_fields)]
        #[allow(dead_code)]
        struct Axis {
            name: String,
            travel: Option<crate::units::Travel>,
            pitch: Option<f64>,
        }
        let text = "axes:\n  - {name: X, travel: [1, 2, 3, 4]}\n  - {name: Y, pitch: abc}\n";
        let (value, index) = parse(text, "f.yaml").unwrap();
        let e = deserialize_at::<Axis>(&value["axes"][0], "axes[0]", &index).unwrap_err();
        assert_eq!(
            e.in_file("f.yaml").to_string(),
            "f.yaml:2:23: axes[0].travel: expected a length (600) or its two ends ([0, 600]), got a list of 4 items"
        );
        let e = deserialize_at::<Axis>(&value["axes"][1], "axes[1]", &index).unwrap_err();
        assert_eq!(
            e.in_file("f.yaml").to_string(),
            "f.yaml:3:22: axes[1].pitch: expected a number, got the text `abc`"
        );
    }
}
