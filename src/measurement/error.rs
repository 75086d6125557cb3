//! Errors from reading a measurement file: each names the file, the line and column
//! where there is one, what was found and what was expected.

use std::fmt;

/// Where in a measurement file something went wrong (1-based line and column).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    pub file: String,
    pub line: Option<usize>,
    pub column: Option<usize>,
}

impl Location {
    pub fn file(file: &str) -> Location {
        Location {
            file: file.to_string(),
            line: None,
            column: None,
        }
    }

    pub fn line(file: &str, line: usize) -> Location {
        Location {
            file: file.to_string(),
            line: Some(line),
            column: None,
        }
    }

    pub fn at(file: &str, line: usize, column: usize) -> Location {
        Location {
            file: file.to_string(),
            line: Some(line),
            column: Some(column),
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
            if let Some(column) = self.column {
                write!(f, ":{column}")?;
            }
        }
        Ok(())
    }
}

/// A measurement file that could not be read.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{location}: {kind}")]
pub struct ReadError {
    pub location: Location,
    /// Boxed: errors are rare and `Result<AxisData, ReadError>` stays small.
    pub kind: Box<ReadErrorKind>,
}

impl ReadError {
    pub fn new(location: Location, kind: ReadErrorKind) -> ReadError {
        ReadError {
            location,
            kind: Box::new(kind),
        }
    }
}

/// What was wrong, and what to change.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ReadErrorKind {
    #[error("could not read the file: {0}")]
    Io(String),
    #[error(
        "the file is empty or holds only comments; expected a header line such as `target_mm,direction,run,deviation_um`"
    )]
    Empty,
    #[error("the file has a header but no readings; expected one row per reading after the header")]
    NoReadings,
    #[error("the line is not valid UTF-8 text; save the file as UTF-8")]
    InvalidUtf8,
    #[error(
        "the line is longer than {limit} bytes; a measurement file has short lines (is this the right file?)"
    )]
    LineTooLong { limit: usize },
    #[error("the file holds more than {limit} readings; split it into one file per test")]
    TooManyReadings { limit: usize },
    #[error(
        "unknown column `{name}`{}; expected target_mm|target_deg, deviation_um|deviation_mm|deviation_arcsec|deviation_deg or actual_mm|actual_deg, direction, run, and optionally time_s and temp_<name>_c",
        suggestion_text(suggestion)
    )]
    UnknownColumn {
        name: String,
        suggestion: Option<String>,
    },
    #[error("column `{name}` has no unit; write {expected}")]
    MissingUnit { name: String, expected: String },
    #[error(
        "more than {limit} temperature columns (temp_<name>_c); keep the sensors of this test, at most {limit}"
    )]
    TooManyTemperatures { limit: usize },
    #[error("column `{name}` appears twice; keep one")]
    DuplicateColumn { name: String },
    #[error("missing column {expected}")]
    MissingColumn { expected: String },
    #[error("columns `{first}` and `{second}` both give the {what}; keep one")]
    ConflictingColumns {
        first: String,
        second: String,
        what: String,
    },
    #[error(
        "column `{deviation}` is {deviation_kind} but `{target}` is {target_kind}; use units of one kind (mm with µm for linear axes, deg with arcsec for rotary axes)"
    )]
    MixedUnits {
        target: String,
        target_kind: String,
        deviation: String,
        deviation_kind: String,
    },
    #[error("expected {expected} fields as in the header, found {found}")]
    FieldCount { expected: usize, found: usize },
    #[error("column `{column}`: expected a number, found `{found}`")]
    NotANumber { column: String, found: String },
    #[error("column `{column}`: expected a finite number, found `{found}`")]
    NonFinite { column: String, found: String },
    #[error(
        "column `direction`: unknown direction `{found}`{}; expected up/down (or +/-, ↑/↓, fwd/bwd, forward/reverse)",
        suggestion_text(suggestion)
    )]
    UnknownDirection {
        found: String,
        suggestion: Option<String>,
    },
    #[error(
        "column `{column}`: {value} is not a plausible deviation (more than {limit} {unit}); check the column's unit"
    )]
    Implausible {
        column: String,
        value: String,
        limit: String,
        unit: String,
    },
    #[error("column `run`: expected a run number 1, 2, 3 …, found `{found}`")]
    InvalidRun { found: String },
    #[error(
        "duplicate reading: target {target}, direction {direction}, run {run} was already given on line {first_line}"
    )]
    DuplicateReading {
        target: String,
        direction: String,
        run: u32,
        first_line: usize,
    },
    #[error(
        "target {target} has readings in direction {present} only; every target must be approached from both directions (ISO 230-2 clause 2.2, 4.3)"
    )]
    OneDirection { target: String, present: String },
    #[error(
        "ragged runs: target {target} direction {direction} has runs {has}, but the test has runs {expected}; every target needs the same runs in both directions"
    )]
    RaggedRuns {
        target: String,
        direction: String,
        has: String,
        expected: String,
    },
    #[error("{0}")]
    KeyValue(String),
}

fn suggestion_text(suggestion: &Option<String>) -> String {
    match suggestion {
        Some(s) => format!(" (did you mean `{s}`?)"),
        None => String::new(),
    }
}

/// The closest of `candidates` to `word` when it is close enough to be a likely typo.
pub fn did_you_mean<'a>(word: &str, candidates: &[&'a str]) -> Option<&'a str> {
    let word = word.to_ascii_lowercase();
    candidates
        .iter()
        .map(|c| (levenshtein(&word, c), *c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 4))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// Edit distance between two strings (characters, not bytes).
pub fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.chars().enumerate() {
        cur[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn location_display() {
        assert_eq!(Location::at("a.csv", 3, 7).to_string(), "a.csv:3:7");
        assert_eq!(Location::line("a.csv", 3).to_string(), "a.csv:3");
        assert_eq!(Location::file("a.csv").to_string(), "a.csv");
    }

    #[test]
    fn suggests_close_names() {
        let c = ["deviation_um", "direction", "run"];
        assert_eq!(did_you_mean("deviaton_um", &c), Some("deviation_um"));
        assert_eq!(did_you_mean("dir", &c), None);
        assert_eq!(levenshtein("kitten", "sitting"), 3);
    }
}
