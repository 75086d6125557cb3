//! Each machine's `squareness:` pairs, evaluated once their two straightness tests are
//! read (`one_file::evaluate_squareness`: HP 5528A User's Guide §21, U by
//! `geometry::uncertainty`) and judged against the pair's tolerance by the campaign's
//! decision rule. A pair whose test could not be read, or was read from several files,
//! is an error naming it; the rest of the campaign is unaffected.

use super::Tested;
use crate::campaign::squareness::{SquarenessEntry, SquarenessSpec};
use crate::campaign::{AxisSpec, Campaign, MachineInfo};
use crate::geometry::TestKind;
use crate::geometry::judge::{Value, judge, limits};
use crate::judge::Decision;
use crate::one_file::{OtherResult, SquarenessOptions, evaluate_squareness};
use crate::param_key::ParamKey;
use crate::results::{AxisTest, OtherTested, Outcome};
use std::sync::Arc;

/// A test per squareness pair of every machine, in campaign order.
pub(super) fn evaluate_all(campaign: &Campaign, tested: &[Tested]) -> Vec<AxisTest> {
    let rule = campaign.info.decision_rule.unwrap_or_default();
    let mut tests = Vec::new();
    for machine in &campaign.machines {
        let info = Arc::new(machine.info.clone());
        for entry in &machine.squareness {
            let outcome = match &entry.spec {
                Err(e) => Err(e.to_string()),
                Ok(spec) => evaluate(spec, tested, rule),
            };
            tests.push(test(&info, entry, outcome));
        }
    }
    tests
}

fn test(
    machine: &Arc<MachineInfo>,
    entry: &SquarenessEntry,
    outcome: Result<OtherTested, String>,
) -> AxisTest {
    AxisTest {
        machine: machine.clone(),
        axis: entry.axes.clone(),
        spec: None,
        file: None,
        test: 1,
        tests: 1,
        outcome: match outcome {
            Ok(o) => Outcome::Other(Box::new(o)),
            Err(error) => Outcome::Unread {
                error,
                recognised: None,
            },
        },
    }
}

/// The straightness test of `spec`'s entry: its readings, symbol and file.
fn straightness<'a>(
    tested: &'a [Tested],
    spec: &Arc<AxisSpec>,
    name: &str,
) -> Result<(&'a crate::measurement::AxisData, String, String), String> {
    let of_entry: Vec<&AxisTest> = (tested.iter().map(|(t, _)| t))
        .filter(|t| t.spec.as_ref().is_some_and(|s| Arc::ptr_eq(s, spec)))
        .collect();
    let symbol = crate::campaign::geometry::symbol(&spec.raw).unwrap_or_default();
    match of_entry[..] {
        [t] => match (t.other(), t.error()) {
            (Some(o), _) => {
                let data = o.data.as_ref().ok_or("its readings were not kept")?;
                Ok((data, symbol, t.file.clone().unwrap_or_default()))
            }
            (None, error) => Err(format!(
                "{name}'s straightness {symbol} could not be evaluated: {}",
                error.unwrap_or("not read")
            )),
        },
        _ => Err(format!(
            "{name}'s straightness {symbol} has {} files; a squareness takes one test of each axis",
            of_entry.len()
        )),
    }
}

fn evaluate(
    spec: &SquarenessSpec,
    tested: &[Tested],
    rule: crate::judge::DecisionRule,
) -> Result<OtherTested, String> {
    let raw = &spec.raw;
    let first = straightness(tested, &spec.tests[0], &raw.axes[0])?;
    let second = straightness(tested, &spec.tests[1], &raw.axes[1])?;
    let options = SquarenessOptions {
        line: raw.line.unwrap_or_default(),
        square_error_arcsec: raw.square_error_arcsec,
        square_u_arcsec: raw.square_u_arcsec,
        convention: raw.convention.unwrap_or_default(),
        optics: raw.optics,
    };
    let result = evaluate_squareness(first.0, second.0, &options)
        .map_err(|k| format!("straightness test {k} has fewer than two targets"))?;
    let limits = limits(TestKind::Squareness, &raw.tolerance, 0.0).map_err(|e| e.to_string())?;
    let value = Value {
        key: ParamKey::Squareness,
        value: result.squareness.error_arcsec,
        expanded: Some(result.uncertainty.expanded),
    };
    let decision = Decision {
        rule,
        expanded: None,
    };
    let judgement = judge(&[value], &limits, &decision);
    Ok(OtherTested {
        verdict: judgement.verdict(false),
        recognised: None,
        test: TestKind::Squareness,
        symbol: String::new(),
        data: None,
        uncertainty: result.uncertainty.clone(),
        result: OtherResult::Squareness(Box::new(result)),
        judgement,
        trace: None,
        sources: vec![(first.1, first.2), (second.1, second.2)],
        tolerance: raw.tolerance.iter().map(|(text, _)| text.clone()).collect(),
        cross: None,
        // Its straightness tests carry their instruments' findings.
        findings: Vec::new(),
    })
}
