//! The text layer: bytes decoded (UTF-8, else Windows-1252), split into numbered lines
//! (CRLF or LF) and grouped into sections (`NAME::` lines), and `Key : value` lines split.

use super::MAX_LINES;
use crate::measurement::MAX_LINE_BYTES;
use crate::measurement::error::{Location, ReadError, ReadErrorKind};
use std::borrow::Cow;

/// The text of the file and whether it had to be read as Windows-1252.
///
/// The laser PC writes the Windows ANSI code page, not UTF-8; Windows-1252 decodes every
/// byte, so only user text can come out wrong (a file from a Czech or Chinese PC).
pub(super) fn decode(bytes: &[u8]) -> (Cow<'_, str>, bool) {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(text) => (Cow::Borrowed(text), false),
        Err(_) => (
            encoding_rs::WINDOWS_1252
                .decode_without_bom_handling(bytes)
                .0,
            true,
        ),
    }
}

/// One non-blank line of a section.
#[derive(Debug, Clone, Copy)]
pub(super) struct Line<'a> {
    /// 1-based line number in the file.
    pub number: usize,
    /// The line without its line end, untrimmed (columns count from its start).
    pub raw: &'a str,
}

impl<'a> Line<'a> {
    pub fn text(&self) -> &'a str {
        self.raw.trim()
    }

    /// 1-based character column of `part`, a slice of this line.
    pub fn column_of(&self, part: &str) -> usize {
        let offset = (part.as_ptr() as usize).saturating_sub(self.raw.as_ptr() as usize);
        self.raw
            .get(..offset.min(self.raw.len()))
            .map_or(1, |before| before.chars().count() + 1)
    }

    /// The line split at its first colon, when it has one.
    pub(crate) fn key_value(&self) -> Option<KeyValue<'a>> {
        let raw = self.raw;
        let colon = raw.find(':')?;
        let key = raw[..colon].trim();
        Some(KeyValue {
            key,
            normal: normal_key(key),
            value: raw[colon + 1..].trim(),
        })
    }
}

/// A `Key : value` line split at its first colon (values hold colons: times).
#[derive(Debug, Clone)]
pub(super) struct KeyValue<'a> {
    /// The key as written, trimmed.
    pub key: &'a str,
    /// The key compared: lower case without spaces, `-` and `_` (`Target-count`,
    /// `Target count` and `target_count` are one key; spacing differs between files).
    pub normal: String,
    pub value: &'a str,
}

/// The compared spelling of a key: lower case without spaces, tabs, `-` and `_`; empty
/// for a key too long to be one (a line of text that happens to hold a colon).
fn normal_key(key: &str) -> String {
    const LONGEST_KEY: usize = 40;
    if key.len() > LONGEST_KEY {
        return String::new();
    }
    key.chars()
        .filter(|c| !matches!(c, ' ' | '\t' | '-' | '_'))
        .map(|c| c.to_ascii_lowercase())
        .collect()
}

/// One section: its `NAME::` line and the non-blank lines up to the next.
#[derive(Debug, Clone)]
pub(super) struct Section<'a> {
    /// The name as written, without `::`.
    pub name: &'a str,
    /// The name compared: upper case, inner spaces single (`TARGET DATA`).
    pub key: String,
    pub line: usize,
    pub lines: Vec<Line<'a>>,
}

/// The file's sections in order, up to `EOF::`.
#[derive(Debug)]
pub(super) struct Sections<'a> {
    pub list: Vec<Section<'a>>,
    /// Non-blank lines after `EOF::`, ignored.
    pub(crate) after_eof: usize,
}

impl<'a> Sections<'a> {
    pub fn get(&self, key: &str) -> Option<&Section<'a>> {
        self.list.iter().find(|s| s.key == key)
    }

    /// The section `key`, or an error that says what it holds.
    pub fn require(
        &self,
        key: &str,
        expected: &str,
        file: &str,
    ) -> Result<&Section<'a>, ReadError> {
        self.get(key).ok_or_else(|| {
            ReadError::new(
                Location::file(file),
                ReadErrorKind::RenishawMissingSection {
                    section: format!("{key}::"),
                    expected: expected.into(),
                },
            )
        })
    }
}

/// The name of a section line (`TARGET DATA::` → `TARGET DATA`): an upper-case name of
/// letters, digits, spaces and `-`, followed by `::` and nothing else.
pub(super) fn section_name(trimmed: &str) -> Option<&str> {
    let name = trimmed.strip_suffix("::")?.trim_end();
    let first = name.chars().next()?;
    let allowed = |c: char| c.is_ascii_uppercase() || c.is_ascii_digit() || " -_".contains(c);
    (first.is_ascii_uppercase() && name.chars().all(allowed)).then_some(name)
}

fn section_key(name: &str) -> String {
    name.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Splits the text into sections. The first non-blank line must be `HEADER::`; the file
/// must end with `EOF::` (a file without it was cut short); a section may not repeat.
pub(super) fn split<'a>(text: &'a str, file: &str) -> Result<Sections<'a>, ReadError> {
    let mut list: Vec<Section<'a>> = Vec::new();
    let mut stored = 0usize;
    let mut lines = text.split('\n').enumerate();
    for (k, raw) in lines.by_ref() {
        let line = Line {
            number: k + 1,
            raw: raw.strip_suffix('\r').unwrap_or(raw),
        };
        check_length(&line, file)?;
        let trimmed = line.text();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(name) = section_name(trimmed) {
            let key = section_key(name);
            if list.is_empty() && key != "HEADER" {
                return Err(not_renishaw(&line, file));
            }
            if key == "EOF" {
                let after_eof = lines.filter(|(_, l)| !l.trim().is_empty()).count();
                return Ok(Sections { list, after_eof });
            }
            if let Some(first) = list.iter().find(|s| s.key == key) {
                return Err(ReadError::new(
                    Location::line(file, line.number),
                    ReadErrorKind::RenishawDuplicateSection {
                        section: format!("{key}::"),
                        first_line: first.line,
                    },
                ));
            }
            list.push(Section {
                name,
                key,
                line: line.number,
                lines: Vec::new(),
            });
            continue;
        }
        let Some(section) = list.last_mut() else {
            return Err(not_renishaw(&line, file));
        };
        if section.key == "HEADER" && line.key_value().is_some_and(|kv| kv.normal == "data") {
            // A `.rtx` capture: binary samples follow, no positioning test.
            return Err(ReadError::new(
                Location::line(file, line.number),
                ReadErrorKind::RenishawDynamic,
            ));
        }
        stored += 1;
        if stored > MAX_LINES {
            return Err(ReadError::new(
                Location::line(file, line.number),
                ReadErrorKind::RenishawTooLarge {
                    limit: format!("{MAX_LINES} lines"),
                },
            ));
        }
        section.lines.push(line);
    }
    match list.last() {
        None => Err(ReadError::new(
            Location::file(file),
            ReadErrorKind::RenishawNotRenishaw {
                found: "the file is empty".into(),
            },
        )),
        Some(last) => Err(ReadError::new(
            Location::line(file, last.lines.last().map_or(last.line, |l| l.number)),
            ReadErrorKind::RenishawNoEof {
                section: format!("{}::", last.key),
            },
        )),
    }
}

fn check_length(line: &Line, file: &str) -> Result<(), ReadError> {
    if line.raw.len() > MAX_LINE_BYTES {
        return Err(ReadError::new(
            Location::line(file, line.number),
            ReadErrorKind::LineTooLong {
                limit: MAX_LINE_BYTES,
            },
        ));
    }
    Ok(())
}

fn not_renishaw(line: &Line, file: &str) -> ReadError {
    ReadError::new(
        Location::line(file, line.number),
        ReadErrorKind::RenishawNotRenishaw {
            found: format!("line {} is `{}`", line.number, shown(line.text())),
        },
    )
}

/// Text from the file for a message: at most 40 characters, control characters escaped
/// (binary junk must not garble a terminal).
pub(super) fn shown(text: &str) -> String {
    const MAX_CHARS: usize = 40;
    let mut out = String::new();
    for (k, c) in text.chars().enumerate() {
        if k == MAX_CHARS {
            out.push('…');
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decodes_utf8_or_windows_1252() {
        assert_eq!(decode(b"\xEF\xBB\xBFM\xC3\xBChle").0, "Mühle");
        let (text, ansi) = decode(b"M\xFChle 20\xB0C \x80");
        assert_eq!(text, "Mühle 20°C €");
        assert!(ansi);
    }

    #[test]
    fn keys_are_compared_without_spacing_or_case() {
        let line = Line {
            number: 1,
            raw: "Date Time  : \"10:46 Dec 12 2016\"",
        };
        let kv = line.key_value().unwrap();
        assert_eq!((kv.key, kv.normal.as_str()), ("Date Time", "datetime"));
        assert_eq!(kv.value, "\"10:46 Dec 12 2016\"");
        let line = Line {
            number: 1,
            raw: "Run-count:4",
        };
        assert_eq!(line.key_value().unwrap().normal, "runcount");
        assert_eq!(line.column_of(&line.raw[10..]), 11);
    }

    #[test]
    fn section_lines() {
        assert_eq!(section_name("TARGET DATA::"), Some("TARGET DATA"));
        assert_eq!(section_name("USER-TEXT::"), Some("USER-TEXT"));
        assert_eq!(section_name("Machine: A::"), None);
        assert_eq!(section_name("::"), None);
        assert_eq!(section_name("Title::"), None);
    }

    #[test]
    fn shown_escapes_junk() {
        assert_eq!(shown("a\u{0}b"), "a\\u{0}b");
        assert_eq!(shown(&"x".repeat(50)).chars().count(), 41);
    }
}
