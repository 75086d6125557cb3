//! The evaluation core: pure functions from an [`AxisData`] to the parameters of a
//! standard. No file I/O, no knowledge of campaigns, reports or the CLI.
//!
//! One module per standard, each behind the [`Standard`] trait; ISO 230-2 and GOST 27843
//! share the coverage-band arithmetic in [`band`].

pub mod band;
pub mod catalogue;
pub mod gost27843;
pub mod iso230_2;
pub mod json;
pub mod nmtba;
pub mod stats;
pub mod vdi3441;

pub use crate::param_key::ParamKey;
pub use catalogue::{Approach, ParameterDef, Role};

use crate::measurement::AxisData;
use crate::units::{AxisKind, Direction};
use serde::{Deserialize, Serialize};
use std::fmt;

/// The standards axcheck evaluates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum StandardId {
    /// ISO 230-2:1997.
    #[serde(rename = "iso230-2:1997")]
    Iso230_2,
    /// GB/T 17421.2-2000, equivalent to ISO 230-2:1997, with national amendment No. 1.
    #[serde(rename = "gbt17421.2-2000")]
    Gbt17421_2,
    /// GOST 27843-88 (ST SEV 6052-87).
    #[serde(rename = "gost27843-88")]
    Gost27843,
    /// VDI 3441 as described by Hemingray, Cowley and Burdekin (1971).
    #[serde(rename = "vdi3441")]
    Vdi3441,
    /// NMTBA accuracy definition as described by Hemingray, Cowley and Burdekin (1971).
    #[serde(rename = "nmtba")]
    Nmtba,
}

impl StandardId {
    pub const ALL: [StandardId; 5] = [
        StandardId::Iso230_2,
        StandardId::Gbt17421_2,
        StandardId::Gost27843,
        StandardId::Vdi3441,
        StandardId::Nmtba,
    ];

    /// Stable key used in JSON and campaign files.
    pub fn key(self) -> &'static str {
        match self {
            StandardId::Iso230_2 => "iso230-2:1997",
            StandardId::Gbt17421_2 => "gbt17421.2-2000",
            StandardId::Gost27843 => "gost27843-88",
            StandardId::Vdi3441 => "vdi3441",
            StandardId::Nmtba => "nmtba",
        }
    }

    /// Title for reports.
    pub fn title(self) -> &'static str {
        match self {
            StandardId::Iso230_2 => "ISO 230-2:1997",
            StandardId::Gbt17421_2 => "GB/T 17421.2-2000 (eqv ISO 230-2:1997, amendment No. 1)",
            StandardId::Gost27843 => "GOST 27843-88",
            StandardId::Vdi3441 => "VDI 3441",
            StandardId::Nmtba => "NMTBA",
        }
    }

    /// Accepts the usual spellings: `iso230-2`, `iso230-2:1997`, `iso`, `gbt17421.2`,
    /// `gb/t17421.2-2000`, `gost27843`, `gost27843-88`, `gost`, `vdi3441`, `vdi`, `nmtba`.
    pub fn parse(text: &str) -> Option<StandardId> {
        let t: String = text
            .trim()
            .to_ascii_lowercase()
            .chars()
            .filter(|c| !c.is_whitespace() && *c != '_')
            .collect();
        let t = t.replace("gb/t", "gbt");
        match t.as_str() {
            "iso230-2" | "iso230-2:1997" | "iso" | "iso230" | "iso230-2-1997" => {
                Some(StandardId::Iso230_2)
            }
            "gbt17421.2" | "gbt17421.2-2000" | "gbt" | "gb17421.2" => Some(StandardId::Gbt17421_2),
            "gost27843" | "gost27843-88" | "gost" => Some(StandardId::Gost27843),
            "vdi3441" | "vdi" => Some(StandardId::Vdi3441),
            "nmtba" => Some(StandardId::Nmtba),
            _ => None,
        }
    }

    /// The coverage factor k of the limit band X̄ ± kS.
    pub fn coverage_factor(self) -> f64 {
        match self {
            StandardId::Iso230_2 | StandardId::Gbt17421_2 => 2.0,
            StandardId::Gost27843 | StandardId::Vdi3441 | StandardId::Nmtba => 3.0,
        }
    }

    /// The evaluator with default options.
    pub fn evaluator(self) -> Box<dyn Standard> {
        match self {
            StandardId::Iso230_2 | StandardId::Gbt17421_2 => {
                Box::new(iso230_2::Iso230_2 { id: self })
            }
            StandardId::Gost27843 => Box::new(gost27843::Gost27843::default()),
            StandardId::Vdi3441 => Box::new(vdi3441::Vdi3441),
            StandardId::Nmtba => Box::new(nmtba::Nmtba),
        }
    }
}

impl fmt::Display for StandardId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.key())
    }
}

/// One way of evaluating a positioning test.
pub trait Standard: Send + Sync {
    fn id(&self) -> StandardId;
    /// Evaluates a validated test. Parameters that do not apply (e.g. S, R and A for
    /// n = 1, ISO 230-2 clause 5.2) are left out of the result, never set to 0.
    fn evaluate(&self, data: &AxisData) -> Evaluation;
}

/// Evaluates `data` by `standard` with default options.
pub fn evaluate(data: &AxisData, standard: StandardId) -> Evaluation {
    standard.evaluator().evaluate(data)
}

/// The parameters by `standard`, S of GOST 27843 by `s_method` (formula (5), or (6) from
/// the ranges; the other standards have one way): the one choice of evaluator that `eval`
/// and a campaign's axes share.
pub fn evaluate_by(
    data: &AxisData,
    standard: StandardId,
    s_method: gost27843::SMethod,
) -> Evaluation {
    match standard {
        StandardId::Gost27843 => gost27843::Gost27843 { s_method }.evaluate(data),
        _ => evaluate(data, standard),
    }
}

/// A parameter's value for one axis test, with its definition from the [`catalogue`].
#[derive(Debug, Clone, PartialEq)]
pub struct Parameter {
    pub def: &'static ParameterDef,
    /// Value in µm (linear) or arcsec (rotary).
    pub value: f64,
    /// Index i (0-based) of the target where a maximum occurs, for R and B.
    pub at_target: Option<usize>,
    /// For range-type parameters (A, E, M): the upper and lower terms, `max − min`.
    pub span: Option<(f64, f64)>,
}

impl Parameter {
    /// A parameter with no location.
    pub fn plain(def: &'static ParameterDef, value: f64) -> Parameter {
        Parameter {
            def,
            value,
            at_target: None,
            span: None,
        }
    }

    /// A range-type parameter, `max − min`, from (value, upper term, lower term).
    pub fn spanned(def: &'static ParameterDef, (value, hi, lo): (f64, f64, f64)) -> Parameter {
        Parameter {
            span: Some((hi, lo)),
            ..Parameter::plain(def, value)
        }
    }

    /// A maximum over targets, from (target index, value).
    pub fn located(def: &'static ParameterDef, (i, value): (usize, f64)) -> Parameter {
        Parameter {
            at_target: Some(i),
            ..Parameter::plain(def, value)
        }
    }

    /// Stable key: `A`, `A_up`, `R_max` …
    pub fn key(&self) -> &'static str {
        self.def.key.as_str()
    }

    /// Symbol for people: `A↑`, `B̄` …
    pub fn symbol(&self) -> &'static str {
        self.def.symbol
    }

    pub fn name(&self) -> &'static str {
        self.def.name
    }

    pub fn clause(&self) -> &'static str {
        self.def.clause
    }
}

/// Per-target, per-direction results (serialised as they are in `eval --json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DirectionResult {
    /// X_ij for j = 1…n (µm or arcsec).
    pub deviations: Vec<f64>,
    /// X̄i↑ or X̄i↓ (ISO 2.10, GOST formula (2)).
    pub mean: f64,
    /// The scatter estimate used by the standard: ISO Si (2.15); GOST S by formula (5) or
    /// (6); VDI σi = Ri/d; NMTBA σ. `None` for n = 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub s: Option<f64>,
    /// Range W of the n deviations (GOST formula (4)); `None` for n = 1.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub range: Option<f64>,
    /// X̄ + kS (ISO 5.1, GOST 3.1.4).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub upper: Option<f64>,
    /// X̄ − kS.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lower: Option<f64>,
    /// Unidirectional repeatability at the target, 2kS (ISO 2.16: 4S; GOST (7): 6S).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub repeatability: Option<f64>,
}

/// Per-target results.
#[derive(Debug, Clone, PartialEq)]
pub struct TargetResult {
    /// Target position P_i, mm or deg.
    pub position: f64,
    pub up: DirectionResult,
    pub down: DirectionResult,
    /// Bidirectional mean X̄i = (X̄i↑ + X̄i↓)/2 (ISO 2.11).
    pub mean: f64,
    /// Reversal value Bi = X̄i↑ − X̄i↓ (ISO 2.12, GOST formula (3), NMTBA lost motion).
    pub reversal: f64,
    /// Bidirectional repeatability Ri (ISO 2.17, GOST formula (8)); `None` for n = 1 or a
    /// standard without it.
    pub repeatability: Option<f64>,
    /// NMTBA's values at the point (Hemingray et al. 1971, §3.1); `None` for the other
    /// standards.
    pub nmtba: Option<NmtbaTarget>,
}

/// NMTBA's values at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NmtbaTarget {
    /// Lost motion L_i = X̄i↑ − X̄i↓.
    pub lost_motion: f64,
    /// σ of both directions' readings pooled (`None` for n = 1).
    pub sigma_bi: Option<f64>,
}

impl TargetResult {
    pub fn direction(&self, d: Direction) -> &DirectionResult {
        match d {
            Direction::Up => &self.up,
            Direction::Down => &self.down,
        }
    }
}

/// The result of evaluating one axis test.
#[derive(Debug, Clone, PartialEq)]
pub struct Evaluation {
    pub standard: StandardId,
    pub kind: AxisKind,
    /// Approaches per direction and target.
    pub n: usize,
    /// Coverage factor k of the limit band.
    pub coverage_factor: f64,
    /// The parameters that apply, in the standard's order.
    pub parameters: Vec<Parameter>,
    pub targets: Vec<TargetResult>,
    /// Caveats about how the result was obtained.
    pub notes: Vec<String>,
}

impl Evaluation {
    /// The parameter with `key`, if it applies.
    pub fn parameter(&self, key: ParamKey) -> Option<&Parameter> {
        self.parameters.iter().find(|p| p.def.key == key)
    }

    /// The parameter filling `role` in this standard, if it applies.
    pub fn headline(&self, role: Role) -> Option<&Parameter> {
        self.parameters.iter().find(|p| p.def.role == Some(role))
    }

    /// The standard's parameters this result leaves out (those that need repeated
    /// approaches, with n = 1: ISO 230-2 clause 5.2), in the standard's order.
    pub fn not_applicable(&self) -> impl Iterator<Item = &'static ParameterDef> + '_ {
        catalogue::of(self.standard).filter(|d| !self.parameters.iter().any(|p| p.def == *d))
    }

    /// The value of parameter `key`, if it applies.
    pub fn value(&self, key: ParamKey) -> Option<f64> {
        self.parameter(key).map(|p| p.value)
    }

    /// Deviation unit: `um` or `arcsec`.
    pub fn unit(&self) -> &'static str {
        self.kind.deviation_unit()
    }
}
