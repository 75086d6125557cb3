//! Judging an axis against tolerance limits: acceptance specs (`specs/*.yaml`), per-axis
//! overrides, the check of each parameter, and the axis verdict.

use crate::evaluate::Evaluation;
use crate::measurement::error::did_you_mean;
use crate::units::AxisKind;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Every parameter key a limit may name (ISO 230-2, GOST 27843, VDI 3441, NMTBA).
const PARAMETERS: &[&str] = &[
    "A",
    "A_up",
    "A_down",
    "E",
    "E_up",
    "E_down",
    "M",
    "R",
    "R_up",
    "R_down",
    "B",
    "B_mean",
    "R_max",
    "R_mean",
    "B_max",
    "T",
    "R_p",
    "sigma_mean",
    "spread",
    "spread_up",
    "spread_down",
    "L_max",
    "L_mean",
];

pub fn is_known_parameter(key: &str) -> bool {
    PARAMETERS.contains(&key)
}

pub fn known_parameters() -> Vec<&'static str> {
    PARAMETERS.to_vec()
}

/// The specs that ship inside the binary (`specs/*.yaml` of the source tree).
pub const BUILTIN_SPECS: &[(&str, &str)] = &[
    ("general", include_str!("../specs/general.yaml")),
    ("precision", include_str!("../specs/precision.yaml")),
];

/// One band of a spec: limits for axes whose measurement travel is up to `up_to`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Band {
    /// Upper end of the band's measurement travel, mm or deg; absent: no upper end.
    #[serde(
        default,
        alias = "up_to_mm",
        alias = "up_to_deg",
        skip_serializing_if = "Option::is_none"
    )]
    pub up_to: Option<f64>,
    /// Limits per parameter, µm (linear) or arcsec (rotary).
    pub tolerances: BTreeMap<String, f64>,
}

/// An acceptance spec.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub name: String,
    #[serde(default)]
    pub title: String,
    #[serde(default)]
    pub note: String,
    /// The standard whose parameters the limits name.
    #[serde(default)]
    pub standard: Option<String>,
    #[serde(default)]
    pub linear: Vec<Band>,
    #[serde(default)]
    pub rotary: Vec<Band>,
}

impl Spec {
    /// Parses a spec; `file` names it in errors.
    pub fn from_yaml(text: &str, file: &str) -> Result<Spec, String> {
        let index = crate::campaign::yaml::LocationIndex::new(text);
        let value: serde_norway::Value = serde_norway::from_str(text)
            .map_err(|e| crate::campaign::yaml::syntax_error(&e, file, text))?;
        let spec: Spec = crate::campaign::yaml::deserialize_at(value, "", &index)
            .map_err(|e| e.in_file(file))?;
        for (group, bands) in [("linear", &spec.linear), ("rotary", &spec.rotary)] {
            let mut last = f64::NEG_INFINITY;
            for (k, band) in bands.iter().enumerate() {
                let here = format!("{group}[{k}]");
                let at = |p: &str| {
                    crate::campaign::yaml::Located {
                        at: index.value(p),
                        message: String::new(),
                    }
                    .in_file(file)
                };
                match band.up_to {
                    Some(u) if u > last => last = u,
                    Some(_) => {
                        return Err(format!(
                            "{}{here}: bands must have increasing up_to",
                            at(&here)
                        ));
                    }
                    None if k + 1 == bands.len() => last = f64::INFINITY,
                    None => {
                        return Err(format!(
                            "{}{here}: only the last band may omit up_to",
                            at(&here)
                        ));
                    }
                }
                for (key, limit) in &band.tolerances {
                    if !is_known_parameter(key) {
                        let hint = did_you_mean(key, PARAMETERS)
                            .map(|s| format!(" (did you mean `{s}`?)"))
                            .unwrap_or_default();
                        return Err(format!(
                            "{}{here}.tolerances: unknown parameter `{key}`{hint}",
                            at(&format!("{here}.tolerances.{key}"))
                        ));
                    }
                    if !(*limit >= 0.0 && limit.is_finite()) {
                        return Err(format!(
                            "{}{here}.tolerances.{key}: expected a limit ≥ 0",
                            at(&format!("{here}.tolerances.{key}"))
                        ));
                    }
                }
            }
        }
        Ok(spec)
    }

    /// The band for an axis of `kind` whose measurement travel is `travel`.
    pub fn band(&self, kind: AxisKind, travel: f64) -> Option<&Band> {
        let bands = match kind {
            AxisKind::Linear => &self.linear,
            AxisKind::Rotary => &self.rotary,
        };
        bands
            .iter()
            .find(|b| b.up_to.is_none_or(|u| travel <= u + 1e-9))
    }
}

/// Where a limit comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LimitSource {
    Spec,
    Axis,
}

/// The limits that apply to one axis test.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Limits {
    /// Spec name and band, e.g. `general (linear ≤ 1000 mm)`.
    pub spec: Option<String>,
    pub values: BTreeMap<String, (f64, LimitSource)>,
}

impl Limits {
    /// Limits from a spec band (if any) overridden by the axis's own tolerances.
    pub fn new(
        spec: Option<&Spec>,
        overrides: &BTreeMap<String, f64>,
        kind: AxisKind,
        travel: f64,
    ) -> Result<Limits, String> {
        let mut limits = Limits::default();
        if let Some(spec) = spec {
            let band = spec.band(kind, travel).ok_or_else(|| {
                format!(
                    "spec `{}` has no {kind} band for a measurement travel of {travel} {}",
                    spec.name,
                    kind.position_unit()
                )
            })?;
            let range = match band.up_to {
                Some(u) => format!("≤ {u} {}", kind.position_unit()),
                None => "all travels".to_string(),
            };
            limits.spec = Some(format!("{} ({kind} {range})", spec.name));
            for (k, v) in &band.tolerances {
                limits.values.insert(k.clone(), (*v, LimitSource::Spec));
            }
        }
        for (k, v) in overrides {
            limits.values.insert(k.clone(), (*v, LimitSource::Axis));
        }
        Ok(limits)
    }

    pub fn is_empty(&self) -> bool {
        self.values.is_empty()
    }
}

/// One parameter against its limit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    pub key: String,
    pub value: f64,
    pub limit: f64,
    /// limit − |value|: negative when over the limit.
    pub margin: f64,
    pub pass: bool,
    pub source: LimitSource,
}

impl Check {
    /// |value| / limit: the share of the tolerance used.
    pub fn ratio(&self) -> f64 {
        if self.limit > 0.0 {
            self.value.abs() / self.limit
        } else if self.value == 0.0 {
            0.0
        } else {
            f64::INFINITY
        }
    }
}

/// The checks of one evaluation against its limits.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Judgement {
    pub limits: Limits,
    pub checks: Vec<Check>,
    /// Limits whose parameter does not apply to this test (e.g. A with n = 1).
    pub not_applicable: Vec<String>,
}

impl Judgement {
    pub fn failed(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| !c.pass)
    }

    /// The check using the largest share of its tolerance.
    pub fn worst(&self) -> Option<&Check> {
        self.checks
            .iter()
            .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
    }
}

/// Checks every limited parameter: |value| ≤ limit passes. Signed parameters (B̄) are
/// compared by magnitude.
pub fn judge(evaluation: &Evaluation, limits: &Limits) -> Judgement {
    let mut checks = Vec::new();
    let mut not_applicable = Vec::new();
    // In the standard's order of parameters, then any others.
    for p in &evaluation.parameters {
        if let Some(&(limit, source)) = limits.values.get(p.key) {
            let margin = limit - p.value.abs();
            checks.push(Check {
                key: p.key.to_string(),
                value: p.value,
                limit,
                margin,
                pass: margin >= -1e-12,
                source,
            });
        }
    }
    for key in limits.values.keys() {
        if evaluation.parameter(key).is_none() {
            not_applicable.push(key.clone());
        }
    }
    Judgement {
        limits: limits.clone(),
        checks,
        not_applicable,
    }
}

/// The outcome of one axis test.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Verdict {
    Pass,
    /// A parameter is over its limit.
    Fail,
    /// A test-plan rule of severity error is broken: the result does not follow the standard.
    Noncompliant,
    /// The axis could not be evaluated.
    Error,
}

impl Verdict {
    /// Order for lists that put what needs attention first: fail, noncompliant, error, pass.
    pub fn attention_rank(self) -> u8 {
        match self {
            Verdict::Fail => 0,
            Verdict::Noncompliant => 1,
            Verdict::Error => 2,
            Verdict::Pass => 3,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "fail",
            Verdict::Noncompliant => "noncompliant",
            Verdict::Error => "error",
        }
    }
}

impl std::fmt::Display for Verdict {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_specs_parse_and_say_they_are_examples() {
        for (name, text) in BUILTIN_SPECS {
            let spec = Spec::from_yaml(text, name).unwrap();
            assert_eq!(&spec.name, name);
            assert!(spec.note.to_lowercase().contains("example"), "{name}");
            assert!(spec.band(AxisKind::Linear, 1000.0).is_some());
            assert!(spec.band(AxisKind::Linear, 9000.0).is_some());
            assert!(spec.band(AxisKind::Rotary, 360.0).is_some());
        }
    }

    #[test]
    fn bands_and_overrides() {
        let spec = Spec::from_yaml(
            "name: t\nlinear:\n  - {up_to_mm: 1000, tolerances: {A: 10, R: 5}}\n  - {tolerances: {A: 20}}\n",
            "t.yaml",
        )
        .unwrap();
        let over = BTreeMap::from([("R".to_string(), 4.0)]);
        let l = Limits::new(Some(&spec), &over, AxisKind::Linear, 1000.0).unwrap();
        assert_eq!(l.values["A"], (10.0, LimitSource::Spec));
        assert_eq!(l.values["R"], (4.0, LimitSource::Axis));
        let l = Limits::new(Some(&spec), &BTreeMap::new(), AxisKind::Linear, 1000.5).unwrap();
        assert_eq!(l.values["A"].0, 20.0);
        assert!(Limits::new(Some(&spec), &BTreeMap::new(), AxisKind::Rotary, 90.0).is_err());
        let e = Spec::from_yaml(
            "name: t\nlinear:\n  - {up_to_mm: 1000, tolerances: {AA: 1}}\n",
            "t.yaml",
        )
        .unwrap_err();
        assert!(
            e.contains("t.yaml:3:") && e.contains("unknown parameter `AA`"),
            "{e}"
        );
    }
}
