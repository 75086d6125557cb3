//! YAML helpers for campaign and spec files: a path → location index (so that errors found
//! after parsing still name line and column) and did-you-mean for unknown keys.

use saphyr_parser::{Event, Parser};
use std::collections::HashMap;

/// Line and column (both 1-based) of every key and value, by path (`machines[0].axes[1].kind`).
#[derive(Debug, Default, Clone)]
pub struct LocationIndex {
    keys: HashMap<String, (usize, usize)>,
    values: HashMap<String, (usize, usize)>,
}

enum Frame {
    Map { path: String, key: Option<String> },
    Seq { path: String, index: usize },
}

fn child(frame: &mut Frame) -> Option<String> {
    match frame {
        Frame::Map { path, key } => key.take().map(|k| join(path, &k)),
        Frame::Seq { path, index } => {
            let p = format!("{path}[{index}]");
            *index += 1;
            Some(p)
        }
    }
}

fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

impl LocationIndex {
    /// Indexes `text`; a syntax error leaves the index partial (the YAML parser that reads
    /// the values reports it).
    pub fn new(text: &str) -> LocationIndex {
        let mut index = LocationIndex::default();
        let mut stack: Vec<Frame> = Vec::new();
        for event in Parser::new_from_str(text) {
            let Ok((event, span)) = event else { break };
            let at = (span.start.line(), span.start.col() + 1);
            match event {
                Event::Scalar(value, ..) => match stack.last_mut() {
                    Some(Frame::Map { path, key }) if key.is_none() => {
                        let k = value.to_string();
                        index.keys.insert(join(path, &k), at);
                        *key = Some(k);
                    }
                    Some(frame) => {
                        if let Some(p) = child(frame) {
                            index.values.insert(p, at);
                        }
                    }
                    None => {}
                },
                Event::Alias(_) => {
                    if let Some(p) = stack.last_mut().and_then(child) {
                        index.values.insert(p, at);
                    }
                }
                Event::MappingStart(..) | Event::SequenceStart(..) => {
                    let path = stack.last_mut().and_then(child).unwrap_or_default();
                    index.values.insert(path.clone(), at);
                    stack.push(if matches!(event, Event::MappingStart(..)) {
                        Frame::Map { path, key: None }
                    } else {
                        Frame::Seq { path, index: 0 }
                    });
                }
                Event::MappingEnd | Event::SequenceEnd => {
                    stack.pop();
                }
                _ => {}
            }
        }
        index
    }

    /// Where the key at `path` is written.
    pub fn key(&self, path: &str) -> Option<(usize, usize)> {
        self.keys.get(path).copied()
    }

    /// Where the value at `path` is written, or failing that its key, or the nearest parent.
    pub fn value(&self, path: &str) -> Option<(usize, usize)> {
        let mut p = path.to_string();
        loop {
            if let Some(at) = self.values.get(&p).or_else(|| self.keys.get(&p)) {
                return Some(*at);
            }
            let cut = p.rfind(['.', '['])?;
            p.truncate(cut);
        }
    }
}

/// A serde path as `a.b[0].c`.
pub fn path_string(path: &serde_path_to_error::Path) -> String {
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
            Segment::Unknown => out.push_str(".?"),
        }
    }
    out
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

/// Deserializes `value` (found at `base` in the document) and turns a failure into a
/// message with the location of the offending key or value.
pub fn deserialize_at<T: serde::de::DeserializeOwned>(
    value: serde_norway::Value,
    base: &str,
    index: &LocationIndex,
) -> Result<T, Located> {
    serde_path_to_error::deserialize(value).map_err(|e| {
        let inner = path_string(e.path());
        let path = match (base.is_empty(), inner.is_empty() || inner == ".") {
            (_, true) => base.to_string(),
            (true, false) => inner,
            (false, false) if inner.starts_with('[') => format!("{base}{inner}"),
            (false, false) => format!("{base}.{inner}"),
        };
        let (message, unknown) = explain(&e.into_inner().to_string());
        // The path may or may not already end in the unknown key.
        let key_path = match &unknown {
            Some(field) if !path.ends_with(&format!(".{field}")) && path != *field => {
                join(&path, field)
            }
            _ => path,
        };
        let at = match unknown {
            Some(_) => index.key(&key_path).or_else(|| index.value(&key_path)),
            None => index.value(&key_path),
        };
        let shown = key_path;
        Located {
            at,
            message: if shown.is_empty() {
                message
            } else {
                format!("{shown}: {message}")
            },
        }
    })
}

/// A message with an optional (line, column).
#[derive(Debug, Clone, PartialEq)]
pub struct Located {
    pub at: Option<(usize, usize)>,
    pub message: String,
}

impl Located {
    /// `file:line:col: message`.
    pub fn in_file(&self, file: &str) -> String {
        match self.at {
            Some((l, c)) => format!("{file}:{l}:{c}: {}", self.message),
            None => format!("{file}: {}", self.message),
        }
    }
}

/// serde_norway's own errors carry a location; turn them into `file:line:col: message`,
/// with a hint when the line is indented with a tab (YAML allows only spaces).
pub fn syntax_error(e: &serde_norway::Error, file: &str, text: &str) -> String {
    match e.location() {
        Some(loc) => {
            let message = e.to_string();
            let message = message
                .rsplit_once(" at line ")
                .map_or(message.clone(), |(head, _)| head.to_string());
            let line = text.lines().nth(loc.line().saturating_sub(1)).unwrap_or("");
            let hint = if line.trim_end().starts_with([' ', '\t']) && line.contains('\t')
                || line.starts_with('\t')
            {
                " (the line is indented with a tab; YAML indents with spaces only)"
            } else {
                ""
            };
            format!("{file}:{}:{}: {message}{hint}", loc.line(), loc.column())
        }
        None => format!("{file}: {e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "campaign:\n  name: x\nmachines:\n  - id: M1\n    axes:\n      - name: X\n        kind: linear\n      - {name: Y, kind: rotary}\n";

    #[test]
    fn indexes_keys_and_values() {
        let i = LocationIndex::new(DOC);
        assert_eq!(i.key("campaign.name"), Some((2, 3)));
        assert_eq!(i.value("campaign.name"), Some((2, 9)));
        assert_eq!(i.key("machines[0].axes[0].kind"), Some((7, 9)));
        assert_eq!(i.value("machines[0].axes[1]"), Some((8, 9)));
        assert_eq!(i.key("machines[0].axes[1].kind"), Some((8, 19)));
        assert_eq!(i.value("machines[0].axes[1].missing"), Some((8, 9)));
    }

    #[test]
    fn explains_unknown_fields() {
        let (m, f) = explain("unknown field `tolerence`, expected one of `name`, `tolerances`");
        assert_eq!(f.as_deref(), Some("tolerence"));
        assert!(m.contains("did you mean `tolerances`"), "{m}");
    }
}
