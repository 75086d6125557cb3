//! The files of the ecmc ISO 230 app (`ecmc_iso230_qt.py` in the ecmc configuration tools,
//! anderssandstrom/ecmc_cfg_tool, 2026), the Qt tool with which ESS and PSI measure EPICS
//! motion axes: its Markdown report ([`markdown`]) and its raw-points CSV ([`raw_csv`]).
//!
//! What both hold, as the app writes them:
//! - one row per measured point: cycle (1-based), direction `forward` (approached in the
//!   positive direction, ISO 230-2 ↑) or `reverse` (↓), the commanded target, and for up to
//!   five position references and the motor's readback (RBV) the mean and the standard
//!   deviation of the samples taken at the point (`Samples per point`, 150 ms apart) and
//!   the error: mean − target (ISO 230-2 2.5's x_ij). The app evaluates the selected
//!   reference; the readback and the other references are there to compare.
//! - no unit anywhere: the values are in the motor record's unit. The app's target rule
//!   ("five random target positions per metre") treats them as millimetres, and so does
//!   axcheck (said in the notes).
//! - reference values before the gain and offset the app applies (`Reference gain`,
//!   `Reference offset`; the raw values are written, the corrected ones evaluated): axcheck
//!   applies them as the app does, x = gain · raw + offset − target.
//!
//! Each point is the mean of several samples: its standard deviation is kept as a note,
//! not as readings (ISO 230-2 takes one reading per approach, 4.3).

pub mod markdown;
pub mod raw_csv;
pub mod reported;

use super::error::{Location, ReadError, ReadErrorKind};
use super::{MAX_DEVIATION, RawReading};
use crate::units::Direction;
use chrono::NaiveDateTime;
use serde::Serialize;

/// The app's name, as the notes and comparisons give it.
pub(crate) const APP: &str = "ecmc ISO 230 app";

/// Micrometres per unit of the file (taken as mm).
const UM_PER_UNIT: f64 = 1000.0;

/// Which of a file's position sources gives the deviations X_ij.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    /// The reference the app evaluated (its "selected" reference).
    #[default]
    Selected,
    /// Reference N (1 to 5, as the file numbers them: `Ref N`, `refN_*`).
    Reference(u8),
    /// The motor's readback (RBV): what the controller believes, not what was measured.
    Readback,
}

/// A `--reference` that names no reference of the app's files.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("expected a reference number 1 to 5, `rbv` (the readback) or `selected`, got `{0}`")]
pub struct UnknownSource(pub String);

impl Source {
    /// `1` … `5` for a reference, `rbv` or `readback` for the readback, `selected`.
    pub fn parse(text: &str) -> Result<Source, UnknownSource> {
        let t = text.trim().to_ascii_lowercase();
        match t.as_str() {
            "selected" => return Ok(Source::Selected),
            "rbv" | "readback" => return Ok(Source::Readback),
            _ => {}
        }
        match t.parse::<u8>() {
            Ok(n @ 1..=5) => Ok(Source::Reference(n)),
            _ => Err(UnknownSource(text.trim().to_string())),
        }
    }

    /// For notes: `the selected reference`, `reference 2`, `the readback (RBV)`.
    pub fn describe(self) -> String {
        match self {
            Source::Selected => "the selected reference".into(),
            Source::Reference(n) => format!("reference {n}"),
            Source::Readback => "the readback (RBV)".into(),
        }
    }
}

/// One measured point: a cycle's approach to a target (lengths in the file's unit).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Point {
    pub cycle: u32,
    pub direction: Direction,
    pub target: f64,
    /// Mean of the samples − target, gain and offset applied.
    pub error: f64,
    /// Standard deviation of the samples at the point.
    pub std: Option<f64>,
    pub time: Option<NaiveDateTime>,
    pub line: usize,
}

/// A reference's gain and offset, applied as the app applies them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Transform {
    pub gain: f64,
    pub offset: f64,
}

impl Transform {
    pub const NONE: Transform = Transform {
        gain: 1.0,
        offset: 0.0,
    };

    pub fn is_none(self) -> bool {
        self == Transform::NONE
    }

    /// The error of a raw mean at `target`: gain · raw + offset − target.
    pub(crate) fn error(self, raw_mean: f64, target: f64) -> f64 {
        self.gain * raw_mean + self.offset - target
    }
}

/// A direction as the app writes it (`forward`, `reverse`; other spellings refused).
pub(crate) fn direction(text: &str) -> Option<Direction> {
    match text.trim() {
        "forward" => Some(Direction::Up),
        "reverse" => Some(Direction::Down),
        _ => None,
    }
}

/// A time stamp as either file writes it: `2026-03-19 10:01:56` (report) or
/// `2026-03-19T10:01:56.123456` (CSV, local time).
pub(crate) fn timestamp(text: &str) -> Option<NaiveDateTime> {
    let t = text.trim();
    ["%Y-%m-%d %H:%M:%S", "%Y-%m-%dT%H:%M:%S%.f"]
        .iter()
        .find_map(|f| NaiveDateTime::parse_from_str(t, f).ok())
}

/// The points as readings of a linear axis in µm, times from the first point's, with the
/// notes on what the points are.
pub(crate) fn readings(points: &[Point], file: &str) -> Result<Vec<RawReading>, ReadError> {
    let start = points.iter().filter_map(|p| p.time).min();
    let timed = points.iter().all(|p| p.time.is_some());
    points
        .iter()
        .map(|p| {
            let deviation = p.error * UM_PER_UNIT;
            if !deviation.is_finite() || deviation.abs() > MAX_DEVIATION {
                let kind = ReadErrorKind::Implausible {
                    column: "error".into(),
                    value: format!("{} mm", p.error),
                    limit: format!("{} mm", MAX_DEVIATION / UM_PER_UNIT),
                    unit: "mm".into(),
                };
                return Err(ReadError::new(Location::line(file, p.line), kind));
            }
            let time_s = match (timed, p.time, start) {
                (true, Some(t), Some(t0)) => Some(seconds_between(t0, t)),
                _ => None,
            };
            Ok(RawReading {
                target: p.target,
                direction: p.direction,
                run: p.cycle,
                deviation,
                time_s,
                temps_c: Vec::new(),
                line: p.line,
            })
        })
        .collect()
}

fn seconds_between(t0: NaiveDateTime, t: NaiveDateTime) -> f64 {
    (t - t0)
        .num_microseconds()
        .map_or(0.0, |us| us as f64 / 1e6)
}

/// The notes every reading of an app file carries: the unit taken, the source read, what
/// a point is.
pub(crate) fn notes(source_name: &str, transform: Transform, points: &[Point]) -> Vec<String> {
    let mut notes = vec![
        format!("written by the {APP}; no unit in the file: positions and errors taken as mm"),
        format!("deviations from {source_name}: the mean at each point − the commanded target"),
    ];
    if !transform.is_none() {
        notes.push(format!(
            "the reference's gain {} and offset {} mm applied as the app applies them (gain · raw + offset), the file's values being raw",
            transform.gain, transform.offset
        ));
    }
    let stds: Vec<f64> = points.iter().filter_map(|p| p.std).collect();
    if let Some(largest) = stds.iter().copied().reduce(f64::max) {
        notes.push(format!(
            "each point is the mean of several samples; their standard deviation, up to {:.2} µm, is not part of the ISO 230-2 evaluation (one reading per approach, 4.3)",
            largest * UM_PER_UNIT
        ));
    }
    if points.iter().any(|p| p.time.is_none()) {
        notes.push("no time stamp on every point: the readings carry no time".into());
    }
    notes
}

/// A finite number written in column `column` at `line`.
pub(crate) fn number(text: &str, column: &str, file: &str, line: usize) -> Result<f64, ReadError> {
    let text = text.trim();
    let value = text.parse::<f64>().ok().filter(|x| x.is_finite());
    value.ok_or_else(|| {
        let message = format!("column `{column}`: expected a number, found `{text}`");
        error(file, line, message)
    })
}

/// A cycle (run) number 1, 2, 3 … written in column `column` at `line`.
pub(crate) fn cycle(text: &str, column: &str, file: &str, line: usize) -> Result<u32, ReadError> {
    let text = text.trim();
    text.parse::<u32>().ok().filter(|&c| c > 0).ok_or_else(|| {
        let message =
            format!("column `{column}`: expected a cycle number 1, 2, 3 …, found `{text}`");
        error(file, line, message)
    })
}

/// A direction as written in column `column` at `line` (`forward` or `reverse`).
pub(crate) fn direction_at(
    text: &str,
    column: &str,
    file: &str,
    line: usize,
) -> Result<Direction, ReadError> {
    direction(text).ok_or_else(|| {
        let message = format!(
            "column `{column}`: expected `forward` or `reverse`, found `{}`",
            text.trim()
        );
        error(file, line, message)
    })
}

/// An error of an app file at `line` (0: the whole file).
pub(crate) fn error(file: &str, line: usize, message: String) -> ReadError {
    let location = match line {
        0 => Location::file(file),
        n => Location::line(file, n),
    };
    ReadError::new(location, ReadErrorKind::EcmcApp(message))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sources_and_times() {
        assert_eq!(Source::parse(" 2 "), Ok(Source::Reference(2)));
        assert_eq!(Source::parse("RBV"), Ok(Source::Readback));
        assert!(
            Source::parse("6")
                .unwrap_err()
                .to_string()
                .contains("1 to 5")
        );
        let a = timestamp("2026-03-19 10:01:56").unwrap();
        let b = timestamp("2026-03-19T10:02:00.250000").unwrap();
        assert_eq!(seconds_between(a, b), 4.25);
        assert_eq!(direction("reverse"), Some(Direction::Down));
        assert_eq!(direction("up"), None);
        let t = Transform {
            gain: 1.0002,
            offset: -0.001,
        };
        assert!((t.error(100.0, 100.0) - 0.019).abs() < 1e-12);
    }
}
