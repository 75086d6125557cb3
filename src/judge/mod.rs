//! Judging an axis against tolerance limits: acceptance specs (`specs/*.yaml`), per-axis
//! overrides, the check of each parameter, and the axis verdict.

use crate::evaluate::Evaluation;
use crate::units::{AxisKind, fmt_fixed};
use serde::{Deserialize, Serialize};

mod spec;
pub use spec::{BUILTIN_SPECS, Band, Spec};
use std::collections::BTreeMap;

/// What the summary says of a test judged against no limit.
pub const NO_TOLERANCE: &str = "no tolerance applied";

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

    /// What the test was judged by, as the summary says it: `general (linear ≤ 1000 mm)`,
    /// `… + axis tolerances`, `axis tolerances`, or [`NO_TOLERANCE`].
    pub fn describe(&self) -> String {
        match (&self.spec, self.is_empty()) {
            (_, true) => NO_TOLERANCE.to_string(),
            (Some(spec), false) => {
                if self.values.values().any(|(_, s)| *s == LimitSource::Axis) {
                    format!("{spec} + axis tolerances")
                } else {
                    spec.clone()
                }
            }
            (None, false) => "axis tolerances".to_string(),
        }
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

    /// "E = 8.930 µm over its limit 6.000 µm (margin -2.930)": a failed check in the words of
    /// the findings lists (Markdown summary, JUnit); `unit` may be empty.
    pub fn over_limit(&self, decimals: usize, unit: &str) -> String {
        let with_unit = |v: f64| match unit {
            "" => fmt_fixed(v, decimals),
            _ => format!("{} {unit}", fmt_fixed(v, decimals)),
        };
        format!(
            "{} = {} over its limit {} (margin {})",
            self.key,
            with_unit(self.value),
            with_unit(self.limit),
            fmt_fixed(self.margin, decimals)
        )
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
        if let Some(&(limit, source)) = limits.values.get(p.key()) {
            let margin = limit - p.value.abs();
            checks.push(Check {
                key: p.key().to_string(),
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
