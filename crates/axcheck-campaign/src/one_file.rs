//! The JSON of the commands that take one measurement file (`eval --json` and its other
//! tests, `diagnose --json`, `verify --json`), composed once for the command line and the
//! Python package so that both print the same keys in the same order.

use crate::crosscheck::OtherTool;
use crate::evaluate::json::EvaluationJson;
use crate::geometry::angular::{self, Angular};
use crate::geometry::line::ReferenceLine;
use crate::geometry::optics::Optics;
use crate::geometry::squareness::{Convention, Squareness};
use crate::geometry::straightness::{self, Straightness, Trace};
use crate::geometry::uncertainty::{self as geometry_u, Uncertain};
use crate::geometry::{self, TestKind};
use crate::measurement::{AxisData, Layout, ReadError, ReadOptions, ReadTest, Recognised};
use crate::nde::NdeCorrection;
use crate::uncertainty::Uncertainty;
use crate::units::AxisKind;
use serde::Serialize;
use std::path::Path;

/// What `eval` applied to the readings and what it did not (`applied`): a result printed
/// without a campaign's corrections must say so.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Applied {
    /// The correction to 20 °C (ISO 230-2 3.1), when asked.
    pub nde: Option<NdeCorrection>,
    /// Always empty: one file's evaluation applies no tolerance and no decision rule.
    pub tolerance: Option<()>,
    pub decision_rule: Option<()>,
}

/// `eval --json`: the evaluation, what was applied, the file's name, what it was read as
/// (`recognised`), the comparison with the results of the tool that wrote it
/// (`other_tool`, when it printed any) and, from Python, U per parameter (`uncertainty`).
#[derive(Serialize)]
pub struct EvalJson<'a> {
    #[serde(flatten)]
    pub evaluation: EvaluationJson<'a>,
    pub applied: &'a Applied,
    pub file: &'a str,
    pub recognised: &'a Recognised,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_tool: Option<&'a OtherTool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<&'a Uncertainty>,
}

/// `value`'s JSON with the measurement's `file` after it, as `diagnose --json` and
/// `verify --json` print it.
#[derive(Serialize)]
pub struct WithFile<'a, T> {
    #[serde(flatten)]
    pub value: T,
    pub file: &'a str,
}

/// `eval --test straightness|angular --json`: which test, its result (flattened: the
/// straightness's or the angular deviation's keys), the targets and the file.
#[derive(Serialize)]
pub struct GeometryJson<'a, T> {
    pub test: TestKind,
    /// The axis the straightness deviation is along (`X`, `Y`, `Z`) or the angular one is
    /// about (`A`, `B`, `C`), when given: ISO 230-1's EYX is `Y` on an X axis.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub direction: Option<char>,
    /// Runs per direction.
    pub n: usize,
    pub targets_mm: &'a [f64],
    #[serde(flatten)]
    pub result: T,
    /// U (k = 2) of the result (the bidirectional straightness, the angular deviation)
    /// with its budget and what it leaves out.
    pub uncertainty: &'a Uncertain,
    pub file: &'a str,
    pub recognised: &'a Recognised,
}

/// `eval --test squareness --json`: the squareness (flattened) and each straightness test
/// it comes from.
#[derive(Serialize)]
pub struct SquarenessJson<'a> {
    pub test: TestKind,
    pub line: ReferenceLine,
    #[serde(flatten)]
    pub squareness: &'a Squareness,
    pub uncertainty: &'a Uncertain,
    pub first: SquarenessSide<'a>,
    pub second: SquarenessSide<'a>,
}

/// One of the two straightness tests of a squareness.
#[derive(Serialize)]
pub struct SquarenessSide<'a> {
    pub file: &'a str,
    pub recognised: &'a Recognised,
    /// Its bidirectional straightness and reference line.
    pub straightness: &'a Trace,
}

/// A straightness or angular test evaluated (its keys, untagged).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum OtherResult {
    Straightness(Straightness),
    Angular(Angular),
    /// A campaign's squareness pair (its U is the test's `uncertainty`).
    Squareness(Box<SquarenessResult>),
}

impl OtherResult {
    /// The value a tolerance may limit (`straightness`, `straightness_local`, `angular`).
    pub fn value(&self, key: crate::param_key::ParamKey) -> Option<f64> {
        use crate::param_key::ParamKey as K;
        match (self, key) {
            (OtherResult::Straightness(s), K::Straightness) => Some(s.bidirectional.deviation_um),
            (OtherResult::Straightness(s), K::StraightnessLocal) => {
                s.local.as_ref().map(|l| l.deviation_um)
            }
            (OtherResult::Angular(a), K::Angular) => Some(a.deviation_arcsec),
            (OtherResult::Squareness(s), K::Squareness) => Some(s.squareness.error_arcsec),
            _ => None,
        }
    }
}

/// How to evaluate a straightness or angular test.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct OtherOptions {
    pub straightness: straightness::Options,
    /// The optics' accuracy, in the result's unit (µm or arcsec).
    pub optics: Option<Optics>,
}

/// `test` (straightness or angular) of `data` with U; `None` when it has too few targets.
pub fn evaluate_other(
    data: &AxisData,
    test: TestKind,
    options: &OtherOptions,
) -> Option<(OtherResult, Uncertain)> {
    let o = options;
    match test {
        TestKind::Straightness => Some((
            OtherResult::Straightness(straightness::evaluate(data, &o.straightness)?),
            geometry_u::straightness(data, o.straightness.line, None, o.optics)?,
        )),
        _ => Some((
            OtherResult::Angular(angular::evaluate(data)?),
            geometry_u::angular(data, o.optics)?,
        )),
    }
}

/// `eval --test straightness|angular --json`'s text.
pub fn geometry_json(
    test: TestKind,
    direction: Option<char>,
    data: &AxisData,
    (result, uncertainty): &(OtherResult, Uncertain),
    file: &str,
    recognised: &Recognised,
) -> serde_json::Result<String> {
    serde_json::to_string_pretty(&GeometryJson {
        test,
        direction,
        n: data.runs(),
        targets_mm: &data.targets,
        result,
        uncertainty,
        file,
        recognised,
    })
}

/// Why a file cannot be one of the other tests of a linear axis.
#[derive(Debug, thiserror::Error)]
pub enum GeometryReadError {
    #[error(transparent)]
    Read(#[from] ReadError),
    #[error(
        "{file}: a {test} test is of a linear axis (targets in mm); this file's targets are in degrees"
    )]
    NotLinear { file: String, test: &'static str },
}

/// A straightness (µm across the axis) or angular (arcsec) test of a linear axis read
/// from `path`, as `eval --test` and Python read it.
pub fn read_geometry(
    path: &Path,
    test: TestKind,
    options: ReadOptions,
) -> Result<ReadTest, GeometryReadError> {
    let options = ReadOptions {
        angular: test == TestKind::Angular,
        ..options
    };
    let mut read = crate::measurement::read_file_with(path, &options)?;
    note_test(&mut read, test);
    if read.data.kind != AxisKind::Linear {
        let file = path.display().to_string();
        return Err(GeometryReadError::NotLinear {
            file,
            test: test.key(),
        });
    }
    Ok(read)
}

/// Notes what a file read for `test` (another test of a linear axis than its
/// positioning) cannot say of itself. A Renishaw file records no test type (see
/// [`crate::measurement::renishaw`]): its µm at targets in mm are taken as the
/// straightness asked for, and the notes say so. The tables need no note: their units
/// are the test's. `eval --test` and a campaign's reading of a test both call it.
pub fn note_test(read: &mut ReadTest, test: TestKind) {
    // An `.rta` is a rotary axis's: refused as such by the other tests' readers.
    if read.recognised.layout == Layout::RenishawRtl && test != TestKind::Positioning {
        read.recognised.notes.push(format!(
            "a Renishaw file records no test type: its deviations (µm at targets in mm) are taken as the {} test asked for",
            test.key()
        ));
    }
}

/// How to evaluate a squareness.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SquarenessOptions {
    pub line: ReferenceLine,
    /// The optical square's error as printed on it, arcsec.
    pub square_error_arcsec: f64,
    /// The standard uncertainty of that error (its calibration), arcsec.
    pub square_u_arcsec: Option<f64>,
    pub convention: Convention,
    /// The optics' accuracy, arcsec.
    pub optics: Option<Optics>,
}

/// A squareness with U and the two lines it comes from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SquarenessResult {
    pub line: ReferenceLine,
    #[serde(flatten)]
    pub squareness: Squareness,
    #[serde(skip)]
    pub uncertainty: Uncertain,
    /// Each straightness test's bidirectional straightness and reference line.
    pub first: Trace,
    pub second: Trace,
}

/// The squareness of two straightness tests; `Err(k)` when test k (1 or 2) has fewer
/// than two targets.
pub fn evaluate_squareness(
    first: &AxisData,
    second: &AxisData,
    o: &SquarenessOptions,
) -> Result<SquarenessResult, usize> {
    let options = straightness::Options {
        line: o.line,
        local_length_mm: None,
    };
    let trace = |data, k: usize| {
        straightness::evaluate(data, &options)
            .map(|s| s.bidirectional)
            .ok_or(k)
    };
    let (a, b) = (trace(first, 1)?, trace(second, 2)?);
    let squareness =
        geometry::squareness::evaluate(&a.line, &b.line, o.square_error_arcsec, o.convention);
    let uncertainty = geometry_u::squareness(
        first,
        second,
        o.line,
        squareness.error_arcsec,
        o.square_u_arcsec,
        o.optics,
    );
    Ok(SquarenessResult {
        line: o.line,
        squareness,
        uncertainty,
        first: a,
        second: b,
    })
}

impl SquarenessResult {
    /// `eval --test squareness --json`'s text, with each straightness test's file and
    /// what it was read as.
    pub fn json(
        &self,
        first: (&str, &Recognised),
        second: (&str, &Recognised),
    ) -> serde_json::Result<String> {
        let side = |(file, recognised), straightness| SquarenessSide {
            file,
            recognised,
            straightness,
        };
        serde_json::to_string_pretty(&SquarenessJson {
            test: TestKind::Squareness,
            line: self.line,
            squareness: &self.squareness,
            uncertainty: &self.uncertainty,
            first: side(first, &self.first),
            second: side(second, &self.second),
        })
    }
}
