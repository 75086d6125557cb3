//! The JSON form of an [`Evaluation`] (`axcheck eval --json`): a stable interface for
//! scripts, derived by serde from the view types below.
//!
//! ```json
//! {"standard": "iso230-2:1997", "kind": "linear", "unit": "um", "position_unit": "mm",
//!  "n": 5, "m": 11, "coverage_factor": 2.0,
//!  "parameters": {"A": 9.586, "A_up": 6.138, …},
//!  "at_target": {"R": 9, "R_up": 10, "R_down": 10, "B": 2},
//!  "details": [{"key": "A", "label": "A", "name": …, "clause": …, "value": …, "span": [hi, lo]}],
//!  "targets": [{"i": 1, "position": 6.711, "mean": …, "reversal": …, "repeatability": …,
//!               "up": {"deviations": […], "mean": …, "s": …, "range": …, "upper": …,
//!                      "lower": …, "repeatability": …}, "down": {…}}],
//!  "notes": []}
//! ```
//! A parameter or value that does not apply is absent. Target indices `i` are 1-based
//! as in the standards.

use super::{DirectionResult, Evaluation, Parameter, TargetResult};
use crate::units::AxisKind;
use serde::Serialize;
use serde::ser::{SerializeMap, Serializer};

/// The whole evaluation.
#[derive(Serialize)]
pub struct EvaluationJson<'a> {
    standard: &'static str,
    title: &'static str,
    kind: AxisKind,
    unit: &'static str,
    position_unit: &'static str,
    n: usize,
    m: usize,
    coverage_factor: f64,
    parameters: ParameterValues<'a>,
    at_target: TargetIndices<'a>,
    details: Vec<Detail>,
    targets: Vec<TargetJson<'a>>,
    notes: &'a [String],
}

/// Parameter values keyed by their stable key, in the standard's order.
#[derive(Clone, Copy)]
pub struct ParameterValues<'a>(pub &'a [Parameter]);

impl Serialize for ParameterValues<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for p in self.0 {
            map.serialize_entry(p.key(), &p.value)?;
        }
        map.end()
    }
}

/// An evaluation's parameters as `{"parameters": {KEY: value}}`: the measured, predicted
/// and achieved sets of compensations and their verification.
#[derive(Clone, Copy, Serialize)]
pub struct ParameterSet<'a> {
    pub parameters: ParameterValues<'a>,
}

impl<'a> ParameterSet<'a> {
    pub fn of(e: &'a Evaluation) -> ParameterSet<'a> {
        ParameterSet {
            parameters: ParameterValues(&e.parameters),
        }
    }
}

/// For the maxima over targets: the 1-based index of the target where each occurs.
#[derive(Clone, Copy)]
pub struct TargetIndices<'a>(pub &'a [Parameter]);

impl Serialize for TargetIndices<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(None)?;
        for p in self.0 {
            if let Some(i) = p.at_target {
                map.serialize_entry(p.key(), &(i + 1))?;
            }
        }
        map.end()
    }
}

/// A parameter with its definition and where it occurs.
#[derive(Serialize)]
struct Detail {
    key: &'static str,
    label: &'static str,
    name: &'static str,
    clause: &'static str,
    value: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    target_index: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    target_position: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    span: Option<[f64; 2]>,
}

/// One target's results.
#[derive(Serialize)]
struct TargetJson<'a> {
    i: usize,
    position: f64,
    mean: f64,
    reversal: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    repeatability: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    lost_motion: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    sigma_bi: Option<f64>,
    up: &'a DirectionResult,
    down: &'a DirectionResult,
}

impl Evaluation {
    /// The stable JSON view of the evaluation.
    pub fn json(&self) -> EvaluationJson<'_> {
        let details = self
            .parameters
            .iter()
            .map(|p| Detail {
                key: p.key(),
                label: p.symbol(),
                name: p.name(),
                clause: p.clause(),
                value: p.value,
                target_index: p.at_target.map(|i| i + 1),
                target_position: p.at_target.map(|i| self.targets[i].position),
                span: p.span.map(|(hi, lo)| [hi, lo]),
            })
            .collect();
        EvaluationJson {
            standard: self.standard.key(),
            title: self.standard.title(),
            kind: self.kind,
            unit: self.unit(),
            position_unit: self.kind.position_unit(),
            n: self.n,
            m: self.targets.len(),
            coverage_factor: self.coverage_factor,
            parameters: ParameterValues(&self.parameters),
            at_target: TargetIndices(&self.parameters),
            details,
            targets: self
                .targets
                .iter()
                .enumerate()
                .map(|(i, t)| target_json(i, t))
                .collect(),
            notes: &self.notes,
        }
    }
}

fn target_json(i: usize, t: &TargetResult) -> TargetJson<'_> {
    TargetJson {
        i: i + 1,
        position: t.position,
        mean: t.mean,
        reversal: t.reversal,
        repeatability: t.repeatability,
        lost_motion: t.nmtba.map(|x| x.lost_motion),
        sigma_bi: t.nmtba.and_then(|x| x.sigma_bi),
        up: &t.up,
        down: &t.down,
    }
}
