//! Judging an axis against tolerance limits: the limits that apply (an acceptance spec's
//! band, read above this crate, overridden per axis), the check of each parameter under
//! its decision rule, and the axis verdict.

use crate::evaluate::{Evaluation, ParamKey};
use crate::units::fmt_fixed;
use serde::{Deserialize, Serialize};

use std::collections::BTreeMap;

/// Limits per parameter, µm (linear) or arcsec (rotary), as checked: keyed by the
/// parameter, walked in the order of the written keys ([`ParamKey`]'s order).
pub type Tolerances = BTreeMap<ParamKey, f64>;

/// What the summary says of a test judged against no limit.
pub(crate) const NO_TOLERANCE: &str = "no tolerance applied";

/// What every line built on an example spec's limits says (`example: true`).
pub const EXAMPLE_LIMITS: &str = "example limits, not from a standard";

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
pub enum Conformance {
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
    pub fn outcome(&self, value: f64, limit: f64, u: f64) -> Conformance {
        let v = value.abs();
        match self.rule {
            DecisionRule::Simple if v <= limit + 1e-12 => Conformance::Pass,
            DecisionRule::Simple => Conformance::Fail,
            DecisionRule::Iso14253_1 if v <= limit - u + 1e-12 => Conformance::Pass,
            DecisionRule::Iso14253_1 if v > limit + u + 1e-12 => Conformance::Fail,
            DecisionRule::Iso14253_1 => Conformance::Inconclusive,
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
    /// A limit from a spec marked `example: true` applies: the verdict rests on example
    /// values, quoted from no standard.
    pub example: bool,
}

impl Limits {
    /// [`Self::describe`] followed by ` — example limits, not from a standard` when an
    /// example spec's limit applies: what reports and summaries print.
    pub fn describe_labelled(&self) -> String {
        match self.example {
            true => format!("{} — {EXAMPLE_LIMITS}", self.describe()),
            false => self.describe(),
        }
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
    pub key: ParamKey,
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
    pub outcome: Conformance,
}

impl Check {
    /// `value` of `key` against `limit` under `decision`: with ISO 14253-1 the value's U
    /// (`expanded`; a value without one is judged with U = 0), with the simple rule none.
    pub fn decide(
        key: ParamKey,
        value: f64,
        (limit, source): (f64, LimitSource),
        decision: &Decision,
        expanded: Option<f64>,
    ) -> Check {
        let expanded = match decision.rule {
            DecisionRule::Simple => None,
            DecisionRule::Iso14253_1 => Some(expanded.unwrap_or(0.0)),
        };
        let outcome = decision.outcome(value, limit, expanded.unwrap_or(0.0));
        Check {
            key,
            value,
            limit,
            margin: limit - value.abs(),
            pass: outcome == Conformance::Pass,
            source,
            expanded_uncertainty: expanded,
            outcome,
        }
    }

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
    /// result does not follow it, whatever the values), else not judged when no limit
    /// applied to any of its parameters (no spec, no tolerances, or only limits of
    /// parameters the test does not have: nothing was compared, so nothing passed), else
    /// fail when a nonconformance is proven, inconclusive when one lies within its
    /// uncertainty zone (ISO 14253-1), pass.
    pub fn verdict(&self, plan_broken: bool) -> Verdict {
        if plan_broken {
            Verdict::Noncompliant
        } else if self.checks.is_empty() {
            Verdict::NotJudged
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
        self.checks
            .iter()
            .filter(|c| c.outcome == Conformance::Fail)
    }

    /// The checks inside the uncertainty zone (ISO 14253-1).
    pub fn inconclusive(&self) -> impl Iterator<Item = &Check> {
        self.checks
            .iter()
            .filter(|c| c.outcome == Conformance::Inconclusive)
    }

    /// The check using the largest share of its tolerance.
    pub fn worst(&self) -> Option<&Check> {
        self.checks
            .iter()
            .max_by(|a, b| a.ratio().total_cmp(&b.ratio()))
    }
}

/// A check whose expanded uncertainty is too large for its verdict to carry weight: U
/// over half its limit, where ISO 14253-1's conformance zone (|value| ≤ limit − U) is
/// narrower than the zone of doubt around the limit, or U over the value itself, which
/// the measurement then cannot tell from zero. Flagged beside the verdict; the verdict
/// stands as the decision rule made it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LargeUncertainty {
    pub key: ParamKey,
    pub value: f64,
    #[serde(rename = "U")]
    pub expanded: f64,
    pub limit: f64,
    pub(crate) over_half_limit: bool,
    pub over_value: bool,
}

impl LargeUncertainty {
    /// Whether U is over half the limit.
    pub fn over_half_limit(&self) -> bool {
        self.over_half_limit
    }

    /// `A = 11.55 ± 45.58 µm against its limit 20.00 µm: U over half its limit and over
    /// the value`; `unit` may be empty.
    pub fn text(&self, decimals: usize, unit: &str) -> String {
        let why = match (self.over_half_limit, self.over_value) {
            (true, true) => "U over half its limit and over the value",
            (true, false) => "U over half its limit",
            _ => "U over the value",
        };
        format!(
            "{} = {} ± {} against its limit {}: {why}",
            self.key,
            fmt_fixed(self.value.abs(), decimals),
            with_unit(self.expanded, decimals, unit),
            with_unit(self.limit, decimals, unit)
        )
    }
}

impl Judgement {
    /// The checks whose U (from `expanded`, by parameter key) is over half the limit or
    /// over the value ([`LargeUncertainty`]).
    pub fn large_uncertainty(&self, expanded: &BTreeMap<String, f64>) -> Vec<LargeUncertainty> {
        (self.checks.iter())
            .filter_map(|c| {
                let u = *expanded.get(c.key.as_str())?;
                let over_half_limit = u > c.limit / 2.0;
                let over_value = u > c.value.abs();
                (over_half_limit || over_value).then_some(LargeUncertainty {
                    key: c.key,
                    value: c.value,
                    expanded: u,
                    limit: c.limit,
                    over_half_limit,
                    over_value,
                })
            })
            .collect()
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
        if let Some(&limit) = limits.values.get(&p.def.key) {
            let u = decision.expanded.and_then(|m| m.get(p.key())).copied();
            checks.push(Check::decide(p.def.key, p.value, limit, decision, u));
        }
    }
    // Alphabetically by key, as `ParamKey` orders.
    for key in limits.values.keys() {
        if evaluation.parameter(*key).is_none() {
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
    /// No limit was applied (no spec, no tolerances): evaluated and rule-checked, but
    /// nothing was compared with a limit, so nothing is proven either way. Never a pass:
    /// `check` and `run` exit 1 on it unless the campaign says `unjudged: allowed`.
    #[serde(rename = "not_judged")]
    NotJudged,
}

impl Verdict {
    /// Order for lists that put what needs attention first: fail, noncompliant,
    /// inconclusive, error, not judged, pass.
    pub fn attention_rank(self) -> u8 {
        match self {
            Verdict::Fail => 0,
            Verdict::Noncompliant => 1,
            Verdict::Inconclusive => 2,
            Verdict::Error => 3,
            Verdict::NotJudged => 4,
            Verdict::Pass => 5,
        }
    }

    /// Whether the verdict fails a CI gate as a failure (an error and a test not judged
    /// are counted apart).
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
            Verdict::NotJudged => "not_judged",
        }
    }

    /// The verdict in words for counts and badges: `not judged` (the others as named).
    pub fn words(self) -> &'static str {
        match self {
            Verdict::NotJudged => "not judged",
            other => other.name(),
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

    fn outcome(rule: DecisionRule, value: f64, limit: f64, u: f64) -> Conformance {
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
        use Conformance::{Fail, Inconclusive, Pass};
        use DecisionRule::{Iso14253_1 as Iso, Simple};
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

    fn check(key: &str, value: f64, limit: f64) -> Check {
        Check {
            key: ParamKey::parse(key).unwrap(),
            value,
            limit,
            margin: limit - value.abs(),
            pass: value.abs() <= limit,
            source: LimitSource::Spec,
            expanded_uncertainty: None,
            outcome: if value.abs() <= limit {
                Conformance::Pass
            } else {
                Conformance::Fail
            },
        }
    }

    /// Issue 42: a test no limit was applied to is `not_judged`, never `pass`: without
    /// limits, and with only limits of parameters the test does not have (A with n = 1).
    #[test]
    fn a_test_without_an_applied_limit_is_not_judged() {
        let none = Judgement::default();
        assert_eq!(none.verdict(false), Verdict::NotJudged);
        assert_eq!(none.verdict(true), Verdict::Noncompliant);
        let inapplicable = Judgement {
            not_applicable: vec!["A".to_string()],
            ..Judgement::default()
        };
        assert_eq!(inapplicable.verdict(false), Verdict::NotJudged);
        let judged = Judgement {
            checks: vec![check("E", 3.0, 6.0)],
            ..Judgement::default()
        };
        assert_eq!(judged.verdict(false), Verdict::Pass);
        assert_eq!(
            serde_json::to_value(Verdict::NotJudged).unwrap(),
            "not_judged"
        );
        assert_eq!(Verdict::NotJudged.name(), "not_judged");
        assert_eq!(Verdict::NotJudged.words(), "not judged");
        assert!(!Verdict::NotJudged.is_failure());
        let back: Verdict = serde_json::from_value("not_judged".into()).unwrap();
        assert_eq!(back, Verdict::NotJudged);
    }

    /// Issue 42: HMC-02 Y's A = 11.55 ± 45.58 µm against 28 µm is flagged on both counts;
    /// U over half the limit alone, over the value alone, and neither.
    #[test]
    fn a_large_uncertainty_is_flagged() {
        let j = Judgement {
            checks: vec![
                check("A", 11.55, 28.0),
                check("E", 10.0, 20.0),
                check("M", 1.0, 14.0),
                check("B", 2.0, 8.0),
            ],
            ..Judgement::default()
        };
        let u = BTreeMap::from([
            ("A".to_string(), 45.58),
            ("E".to_string(), 10.5),
            ("M".to_string(), 1.5),
            ("B".to_string(), 1.0),
        ]);
        let large = j.large_uncertainty(&u);
        let flags: Vec<(&str, bool, bool)> = (large.iter())
            .map(|l| (l.key.as_str(), l.over_half_limit, l.over_value))
            .collect();
        assert_eq!(
            flags,
            vec![("A", true, true), ("E", true, true), ("M", false, true)]
        );
        assert_eq!(
            large[0].text(2, "µm"),
            "A = 11.55 ± 45.58 µm against its limit 28.00 µm: U over half its limit and over the value"
        );
        let half_only = j.large_uncertainty(&BTreeMap::from([("E".to_string(), 10.01)]));
        assert_eq!(
            half_only[0].text(1, ""),
            "E = 10.0 ± 10.0 against its limit 20.0: U over half its limit and over the value"
        );
        let half = Judgement {
            checks: vec![check("E", 12.0, 20.0)],
            ..Judgement::default()
        };
        let half_only = half.large_uncertainty(&BTreeMap::from([("E".to_string(), 10.5)]));
        assert_eq!(
            half_only[0].text(1, ""),
            "E = 12.0 ± 10.5 against its limit 20.0: U over half its limit"
        );
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
