//! Judging an axis against tolerance limits: acceptance specs (`specs/*.yaml`), per-axis
//! overrides, the check of each parameter, and the axis verdict.

use crate::evaluate::{Evaluation, ParamKey};
use crate::units::{AxisKind, fmt_fixed};
use serde::{Deserialize, Serialize};

mod spec;
pub use spec::{BUILTIN_SPECS, Band, Spec, Tolerances, check_tolerances};
use std::collections::BTreeMap;

/// What the summary says of a test judged against no limit.
pub const NO_TOLERANCE: &str = "no tolerance applied";

/// How a measured value is compared with its limit.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum DecisionRule {
    /// The value as if it were exact: conformance when |value| ≤ limit.
    #[default]
    #[serde(rename = "simple")]
    Simple,
    /// ISO 14253-1: conformance proven when |value| ≤ limit − U, nonconformance proven
    /// when |value| > limit + U, inconclusive in between (U: the expanded uncertainty).
    #[serde(rename = "iso14253-1")]
    Iso14253_1,
}

impl DecisionRule {
    /// The name as campaigns, specs and outputs write it.
    pub fn key(self) -> &'static str {
        match self {
            DecisionRule::Simple => "simple",
            DecisionRule::Iso14253_1 => "iso14253-1",
        }
    }
}

/// What one check proves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Outcome {
    Pass,
    Fail,
    /// Within the uncertainty zone around the limit: neither proven (ISO 14253-1).
    Inconclusive,
}

/// The decision rule of a test and the expanded uncertainty U of its parameters.
#[derive(Debug, Clone, Copy, Default)]
pub struct Decision<'a> {
    pub rule: DecisionRule,
    /// U (k = 2) by parameter key, in the parameter's unit; a parameter without one is
    /// judged with U = 0.
    pub expanded: Option<&'a BTreeMap<String, f64>>,
}

impl Decision<'_> {
    /// The outcome of |value| against `limit` with expanded uncertainty `u`; a rounding
    /// tolerance of 1e-12 keeps a value printed equal to the bound on its side.
    pub fn outcome(&self, value: f64, limit: f64, u: f64) -> Outcome {
        let v = value.abs();
        match self.rule {
            DecisionRule::Simple if v <= limit + 1e-12 => Outcome::Pass,
            DecisionRule::Simple => Outcome::Fail,
            DecisionRule::Iso14253_1 if v <= limit - u + 1e-12 => Outcome::Pass,
            DecisionRule::Iso14253_1 if v > limit + u + 1e-12 => Outcome::Fail,
            DecisionRule::Iso14253_1 => Outcome::Inconclusive,
        }
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
    pub values: BTreeMap<ParamKey, (f64, LimitSource)>,
}

impl Limits {
    /// Limits from a spec band (if any) overridden by the axis's own tolerances.
    pub fn new(
        spec: Option<&Spec>,
        overrides: &Tolerances,
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
                limits.values.insert(*k, (*v, LimitSource::Spec));
            }
        }
        for (k, v) in overrides {
            limits.values.insert(*k, (*v, LimitSource::Axis));
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
    /// Conformance proven under the decision rule (`outcome` is `pass`).
    pub pass: bool,
    pub source: LimitSource,
    /// The expanded uncertainty the rule used (k = 2), when it used one.
    #[serde(rename = "U", skip_serializing_if = "Option::is_none")]
    pub expanded_uncertainty: Option<f64>,
    pub outcome: Outcome,
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

    /// "E = 7.900 µm within U = 1.500 µm of its limit 8.000 µm (ISO 14253-1: neither
    /// conformance nor nonconformance proven)": an inconclusive check; `unit` may be empty.
    pub fn within_uncertainty(&self, decimals: usize, unit: &str) -> String {
        let with_unit = |v: f64| with_unit(v, decimals, unit);
        format!(
            "{} = {} within U = {} of its limit {} (ISO 14253-1: neither conformance nor nonconformance proven)",
            self.key,
            with_unit(self.value),
            with_unit(self.expanded_uncertainty.unwrap_or(0.0)),
            with_unit(self.limit)
        )
    }

    /// "E = 8.930 µm over its limit 6.000 µm (margin -2.930)": a failed check in the words of
    /// the findings lists (Markdown summary, JUnit); `unit` may be empty.
    pub fn over_limit(&self, decimals: usize, unit: &str) -> String {
        let with_unit = |v: f64| with_unit(v, decimals, unit);
        format!(
            "{} = {} over its limit {} (margin {})",
            self.key,
            with_unit(self.value),
            with_unit(self.limit),
            fmt_fixed(self.margin, decimals)
        )
    }
}

/// `8.930 µm` (`8.930` when `unit` is empty): a value in the findings' words.
fn with_unit(value: f64, decimals: usize, unit: &str) -> String {
    match unit {
        "" => fmt_fixed(value, decimals),
        _ => format!("{} {unit}", fmt_fixed(value, decimals)),
    }
}

/// The checks of one evaluation against its limits.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Judgement {
    pub limits: Limits,
    /// The decision rule the checks were made by.
    pub rule: DecisionRule,
    pub checks: Vec<Check>,
    /// Limits whose parameter does not apply to this test (e.g. A with n = 1).
    pub not_applicable: Vec<String>,
}

impl Judgement {
    /// The test's verdict: noncompliant when its plan breaks a rule of the standard (the
    /// result does not follow it, whatever the values), else fail when a nonconformance is
    /// proven, inconclusive when one lies within its uncertainty zone (ISO 14253-1), pass.
    pub fn verdict(&self, plan_broken: bool) -> Verdict {
        if plan_broken {
            Verdict::Noncompliant
        } else if self.failed().next().is_some() {
            Verdict::Fail
        } else if self.inconclusive().next().is_some() {
            Verdict::Inconclusive
        } else {
            Verdict::Pass
        }
    }

    /// The checks whose nonconformance is proven.
    pub fn failed(&self) -> impl Iterator<Item = &Check> {
        self.checks.iter().filter(|c| c.outcome == Outcome::Fail)
    }

    /// The checks inside the uncertainty zone (ISO 14253-1).
    pub fn inconclusive(&self) -> impl Iterator<Item = &Check> {
        self.checks
            .iter()
            .filter(|c| c.outcome == Outcome::Inconclusive)
    }

    /// The check using the largest share of its tolerance.
    pub fn worst(&self) -> Option<&Check> {
        self.checks
            .iter()
            .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
    }
}

/// Checks every limited parameter under the `decision` rule: with `simple`, |value| ≤
/// limit passes; with ISO 14253-1 the expanded uncertainty decides a zone around the limit.
/// Signed parameters (B̄) are compared by magnitude. The judgement keeps `limits` (taken,
/// not copied: a fleet judges 10 000 tests).
pub fn judge(evaluation: &Evaluation, limits: Limits, decision: &Decision) -> Judgement {
    let mut checks = Vec::with_capacity(limits.values.len());
    let mut not_applicable = Vec::new();
    // In the standard's order of parameters, then any others.
    for p in &evaluation.parameters {
        if let Some(&(limit, source)) = limits.values.get(&p.def.key) {
            let expanded = match decision.rule {
                DecisionRule::Simple => None,
                DecisionRule::Iso14253_1 => {
                    let u = decision.expanded.and_then(|m| m.get(p.key()));
                    Some(u.copied().unwrap_or(0.0))
                }
            };
            let outcome = decision.outcome(p.value, limit, expanded.unwrap_or(0.0));
            checks.push(Check {
                key: p.key().to_string(),
                value: p.value,
                limit,
                margin: limit - p.value.abs(),
                pass: outcome == Outcome::Pass,
                source,
                expanded_uncertainty: expanded,
                outcome,
            });
        }
    }
    // Alphabetically by key, as `ParamKey` orders.
    for key in limits.values.keys() {
        if evaluation.parameter(key.as_str()).is_none() {
            not_applicable.push(key.to_string());
        }
    }
    Judgement {
        limits,
        rule: decision.rule,
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
    /// No parameter is proven over its limit, but one lies within its uncertainty zone
    /// (ISO 14253-1): neither conformance nor nonconformance is proven.
    Inconclusive,
}

impl Verdict {
    /// Order for lists that put what needs attention first: fail, noncompliant,
    /// inconclusive, error, pass.
    pub fn attention_rank(self) -> u8 {
        match self {
            Verdict::Fail => 0,
            Verdict::Noncompliant => 1,
            Verdict::Inconclusive => 2,
            Verdict::Error => 3,
            Verdict::Pass => 4,
        }
    }

    /// Whether the verdict fails a CI gate as a failure (an error is counted apart).
    pub fn is_failure(self) -> bool {
        matches!(
            self,
            Verdict::Fail | Verdict::Noncompliant | Verdict::Inconclusive
        )
    }

    pub fn name(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "fail",
            Verdict::Noncompliant => "noncompliant",
            Verdict::Error => "error",
            Verdict::Inconclusive => "inconclusive",
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

    fn outcome(rule: DecisionRule, value: f64, limit: f64, u: f64) -> Outcome {
        Decision {
            rule,
            expanded: None,
        }
        .outcome(value, limit, u)
    }

    /// Every boundary of both rules with limit 8 and U = 1.5 (exact in binary): 6.5 is
    /// limit − U, 9.5 is limit + U.
    #[test]
    fn decision_rule_boundaries() {
        use DecisionRule::{Iso14253_1 as Iso, Simple};
        use Outcome::{Fail, Inconclusive, Pass};
        let cases = [
            (6.5, Pass, Pass),
            (6.5 + 1e-9, Pass, Inconclusive),
            (8.0, Pass, Inconclusive),
            (8.0 + 1e-9, Fail, Inconclusive),
            (9.5, Fail, Inconclusive),
            (9.5 + 1e-9, Fail, Fail),
            // Signed values by magnitude (B̄).
            (-6.5, Pass, Pass),
            (-9.6, Fail, Fail),
        ];
        for (value, simple, iso) in cases {
            assert_eq!(outcome(Simple, value, 8.0, 1.5), simple, "simple {value}");
            assert_eq!(outcome(Iso, value, 8.0, 1.5), iso, "iso {value}");
        }
        // With U = 0 ISO 14253-1 decides as the simple rule.
        for value in [7.9, 8.0, 8.0 + 1e-9] {
            assert_eq!(
                outcome(Iso, value, 8.0, 0.0),
                outcome(Simple, value, 8.0, 0.0)
            );
        }
    }

    #[test]
    fn rule_names_are_the_serialised_names() {
        for rule in [DecisionRule::Simple, DecisionRule::Iso14253_1] {
            assert_eq!(serde_json::to_value(rule).unwrap(), rule.key());
            let back: DecisionRule = serde_json::from_value(rule.key().into()).unwrap();
            assert_eq!(back, rule);
        }
    }
}
