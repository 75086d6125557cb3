//! The other laser tests judged against their tolerances, by the same decision rules as
//! positioning ([`crate::judge`]: simple, or ISO 14253-1 with U).
//!
//! Which value each form of tolerance limits:
//! - a straightness test: a length (`0.015`) or a length per measuring length (`0.020
//!   per 1000`, taken in proportion to the measured travel, [`super::tolerance`]) limits
//!   the straightness; a length over any stretch (`0.010 over any 300`) limits the local
//!   straightness over that stretch;
//! - an angular test: an angle (`30″`), or a length per length as its slope (`0.040 per
//!   1000`, as ISO 230-1's acceptance standards write angular tolerances), limits the
//!   angular deviation;
//! - a squareness: an angle, or a slope (`0.020 per 1000`, arctan(2·10⁻⁵)), limits it.
//!
//! Any other pairing is refused with the reason: an angle cannot limit a straightness.

use super::TestKind;
use super::tolerance::Tolerance;
use crate::judge::{Check, Decision, Judgement, LimitSource, Limits};
use crate::param_key::ParamKey;
use std::collections::BTreeMap;

/// A value of a test to judge, in its unit, with its expanded uncertainty U (k = 2)
/// when it was computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Value {
    pub key: ParamKey,
    pub value: f64,
    pub expanded: Option<f64>,
}

/// A tolerance that cannot limit the test it is written for.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LimitError {
    #[error("tolerance `{written}` cannot limit a {test} test: {why}")]
    Form {
        written: String,
        test: &'static str,
        why: &'static str,
    },
    #[error("two tolerances limit the {key} (`{first}` and `{second}`); write one")]
    Twice {
        key: ParamKey,
        first: String,
        second: String,
    },
}

/// The limit each tolerance sets for a `test` over a measured travel of `length_mm`
/// (µm or arcsec, by key), with the tolerance as written beside it.
pub fn limits(
    test: TestKind,
    tolerances: &[(String, Tolerance)],
    length_mm: f64,
) -> Result<BTreeMap<ParamKey, (f64, String)>, LimitError> {
    let mut limits: BTreeMap<ParamKey, (f64, String)> = BTreeMap::new();
    for (written, tolerance) in tolerances {
        let (key, limit) =
            limit_of(test, *tolerance, length_mm).map_err(|why| LimitError::Form {
                written: written.clone(),
                test: test.key(),
                why,
            })?;
        if let Some((_, first)) = limits.get(&key) {
            return Err(LimitError::Twice {
                key,
                first: first.clone(),
                second: written.clone(),
            });
        }
        limits.insert(key, (limit, written.clone()));
    }
    Ok(limits)
}

/// The key a tolerance limits in `test` and its limit, or why it cannot.
fn limit_of(
    test: TestKind,
    tolerance: Tolerance,
    length_mm: f64,
) -> Result<(ParamKey, f64), &'static str> {
    let t = tolerance;
    match test {
        TestKind::Straightness => match (t.straightness_um(length_mm), t.local()) {
            (Some(um), _) => Ok((ParamKey::Straightness, um)),
            (_, Some((um, _))) => Ok((ParamKey::StraightnessLocal, um)),
            _ => Err("a straightness is a length across the axis; write e.g. `0.020 per 1000`"),
        },
        TestKind::Angular => match t.angle_arcsec() {
            Some(arcsec) => Ok((ParamKey::Angular, arcsec)),
            None => Err("an angular deviation is an angle; write e.g. `30″` or `0.040 per 1000`"),
        },
        TestKind::Squareness => match t.angle_arcsec() {
            Some(arcsec) => Ok((ParamKey::Squareness, arcsec)),
            None => Err("a squareness is an angle or a slope; write e.g. `0.020 per 1000` or `4″`"),
        },
        TestKind::Positioning => Err("its tolerances are written otherwise"),
    }
}

/// The checks of `values` against `limits` under `decision` (a value without U is judged
/// with U = 0 under ISO 14253-1, as positioning's parameters are). Every limit is the
/// axis's own (`LimitSource::Axis`): no acceptance spec holds these tests' limits yet.
pub fn judge(
    values: &[Value],
    limits: &BTreeMap<ParamKey, (f64, String)>,
    decision: &Decision,
) -> Judgement {
    let checks = (values.iter())
        .filter_map(|v| {
            let &(limit, _) = limits.get(&v.key)?;
            let limit = (limit, LimitSource::Axis);
            Some(Check::decide(v.key, v.value, limit, decision, v.expanded))
        })
        .collect();
    let not_applicable = (limits.keys())
        .filter(|k| !values.iter().any(|v| v.key == **k))
        .map(|k| k.to_string())
        .collect();
    Judgement {
        limits: Limits {
            spec: None,
            values: (limits.iter())
                .map(|(k, (l, _))| (*k, (*l, LimitSource::Axis)))
                .collect(),
            example: false,
        },
        rule: decision.rule,
        checks,
        not_applicable,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::judge::{DecisionRule, Verdict};

    fn written(texts: &[&str]) -> Vec<(String, Tolerance)> {
        (texts.iter())
            .map(|t| (t.to_string(), Tolerance::parse(t).unwrap()))
            .collect()
    }

    /// `0.020 per 1000` over 800 mm allows 16 µm; the local one limits the local value.
    #[test]
    fn straightness_limits_in_proportion_and_locally() {
        let tolerances = written(&["0.020 per 1000", "0.010 over any 300"]);
        let l = limits(TestKind::Straightness, &tolerances, 800.0).unwrap();
        assert!((l[&ParamKey::Straightness].0 - 16.0).abs() < 1e-12);
        assert!((l[&ParamKey::StraightnessLocal].0 - 10.0).abs() < 1e-12);
    }

    #[test]
    fn an_angle_cannot_limit_a_straightness_nor_a_length_an_angle() {
        let e = limits(TestKind::Straightness, &written(&["30″"]), 800.0).unwrap_err();
        assert!(
            e.to_string().contains("cannot limit a straightness test"),
            "{e}"
        );
        let e = limits(TestKind::Angular, &written(&["0.010"]), 800.0).unwrap_err();
        assert!(
            e.to_string().contains("an angular deviation is an angle"),
            "{e}"
        );
        let e = limits(TestKind::Straightness, &written(&["0.02", "20 µm"]), 800.0).unwrap_err();
        assert!(
            e.to_string()
                .contains("two tolerances limit the straightness"),
            "{e}"
        );
    }

    /// 14 µm ± 2.5 µm against 16 µm: simple passes, ISO 14253-1 is inconclusive
    /// (14 > 16 − 2.5); 12 µm passes both.
    #[test]
    fn judged_by_either_decision_rule() {
        let l = limits(TestKind::Straightness, &written(&["0.020 per 1000"]), 800.0).unwrap();
        let value = |v| Value {
            key: ParamKey::Straightness,
            value: v,
            expanded: Some(2.5),
        };
        let rule = |rule| Decision {
            rule,
            expanded: None,
        };
        let j = judge(&[value(14.0)], &l, &rule(DecisionRule::Simple));
        assert_eq!(j.verdict(false), Verdict::Pass);
        let j = judge(&[value(14.0)], &l, &rule(DecisionRule::Iso14253_1));
        assert_eq!(j.verdict(false), Verdict::Inconclusive);
        assert_eq!(j.checks[0].expanded_uncertainty, Some(2.5));
        let j = judge(&[value(12.0)], &l, &rule(DecisionRule::Iso14253_1));
        assert_eq!(j.verdict(false), Verdict::Pass);
        let j = judge(&[value(18.6)], &l, &rule(DecisionRule::Iso14253_1));
        assert_eq!(j.verdict(false), Verdict::Fail);
        assert!((j.checks[0].margin + 2.6).abs() < 1e-12);
    }

    /// A local tolerance on a test evaluated without a local length has nothing to judge.
    #[test]
    fn a_limit_without_its_value_is_not_applicable() {
        let l = limits(
            TestKind::Straightness,
            &written(&["0.010 over any 300"]),
            800.0,
        )
        .unwrap();
        let v = Value {
            key: ParamKey::Straightness,
            value: 5.0,
            expanded: None,
        };
        let j = judge(&[v], &l, &Decision::default());
        assert_eq!(j.not_applicable, ["straightness_local"]);
        assert_eq!(j.verdict(false), Verdict::NotJudged);
    }
}
