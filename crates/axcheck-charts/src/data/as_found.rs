//! The axis as found and as left (ISO/IEC 17025:2017 7.8.4.1 d): where a test verifies a
//! table loaded since a measurement before, both measurements' parameters side by side,
//! each with its U and its check against the same limits.

use super::{num, symbol_of};
use crate::evaluate::{Evaluation, ParamKey};
use crate::judge::{Conformance, Judgement};
use crate::results::AxisTest;
use crate::uncertainty::Uncertainty;
use crate::words::Words;
use serde::Serialize;

/// The two measurements of an adjusted axis.
#[derive(Serialize)]
pub struct AsFoundSection<'a> {
    found_file: &'a str,
    left_file: &'a str,
    /// The verdicts in the report's words.
    found_verdict: String,
    left_verdict: String,
    rows: Vec<StateRow>,
}

/// One parameter before and after.
#[derive(Serialize)]
struct StateRow {
    symbol: String,
    name: String,
    limit: String,
    found: String,
    found_u: String,
    /// `pass`, `fail`, `inconclusive`, or "" where no limit applies.
    found_status: &'static str,
    left: String,
    left_u: String,
    left_status: &'static str,
}

/// A measurement's value, U and check of `key`.
struct State<'a> {
    evaluation: &'a Evaluation,
    uncertainty: Option<&'a Uncertainty>,
    judgement: Option<&'a Judgement>,
}

impl State<'_> {
    fn value(&self, key: ParamKey) -> String {
        self.evaluation
            .parameter(key)
            .map_or("–".into(), |p| num(p.value))
    }

    fn u(&self, key: ParamKey) -> String {
        (self.uncertainty.and_then(|u| u.expanded_of(key)))
            .map_or("–".into(), |u| format!("±{}", num(u)))
    }

    fn check(&self, key: ParamKey) -> Option<&crate::judge::Check> {
        self.judgement?.checks.iter().find(|c| c.key == key)
    }

    fn status(&self, key: ParamKey) -> &'static str {
        self.check(key).map_or("", |c| match c.outcome {
            Conformance::Pass => "pass",
            Conformance::Fail => "fail",
            Conformance::Inconclusive => "inconclusive",
        })
    }
}

/// The section of a test that verifies a table, or `None`; in `words`' language.
pub fn as_found_section<'a>(t: &'a AxisTest, words: &Words) -> Option<AsFoundSection<'a>> {
    let e = t.evaluated()?;
    let found = e.as_found.as_deref()?;
    let before = State {
        evaluation: &found.evaluation,
        uncertainty: found.uncertainty.as_ref(),
        judgement: found.judgement.as_ref(),
    };
    let after = State {
        evaluation: &e.evaluation,
        uncertainty: e.uncertainty.as_ref(),
        judgement: e.judgement.as_ref(),
    };
    let rows = (e.evaluation.parameters.iter())
        .map(|p| {
            let key = p.def.key;
            let limit = (after.check(key).or_else(|| before.check(key))).map(|c| c.limit);
            StateRow {
                symbol: symbol_of(t, key),
                name: words.parameter(e.evaluation.standard, key, p.name()),
                limit: limit.map_or("–".into(), num),
                found: before.value(key),
                found_u: before.u(key),
                found_status: before.status(key),
                left: after.value(key),
                left_u: after.u(key),
                left_status: after.status(key),
            }
        })
        .collect();
    Some(AsFoundSection {
        found_file: &found.file,
        left_file: t.file.as_deref().unwrap_or_default(),
        found_verdict: words.verdict(found.verdict.name()),
        left_verdict: words.verdict(e.verdict.name()),
        rows,
    })
}
