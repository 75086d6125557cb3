//! What `run` prints of the compensation tables: how many were written and on what state,
//! those refused, those written over a state that is unknown or contradicted, those whose
//! file names no axis (what to replace), what the controllers must be told to load them,
//! and each verification's verdict.

use super::text::MAX_PROBLEM_LINES;
use axcheck::compensate::{Compensation, Mode};
use axcheck::results::{AxisTest, CampaignResult};

/// Warnings that concern the state a table builds on, shown on the console once for all
/// the tests they concern (the others, from the diagnosis, are in the reports and
/// `results.json`).
const STATE_WARNINGS: &[(&str, &str)] = &[
    (
        "active_compensation_unknown",
        "the compensation active during the test is not stated: each table is that measurement's correction alone, to be added to whatever the controller held (state compensation: {active: TABLE or none})",
    ),
    (
        "active_compensation_contradiction",
        "the test conditions and the stated active compensation disagree: check which was active before loading",
    ),
    (
        "active_backlash_unknown",
        "the backlash active during the test is not stated: the backlash written is the measured reversal alone",
    ),
];

/// Tests named on one line at most.
const MAX_NAMED: usize = 8;

/// The lines, none when no machine names a controller.
pub fn lines(result: &CampaignResult) -> Vec<String> {
    let compensated: Vec<&AxisTest> = result
        .tests
        .iter()
        .filter(|t| t.evaluated().is_some_and(|e| e.compensation.is_some()))
        .collect();
    if compensated.is_empty() {
        return Vec::new();
    }
    let written = compensated
        .iter()
        .filter(|t| {
            t.evaluated()
                .and_then(|e| e.compensation.as_deref())
                .is_some_and(|c| c.outcome.is_ok())
        })
        .count();
    let incremental = compensated
        .iter()
        .filter(|t| {
            t.evaluated()
                .and_then(|e| e.compensation.as_deref())
                .is_some_and(|c| c.outcome.is_ok() && c.mode == Mode::Incremental)
        })
        .count();
    let mut lines = vec![format!(
        "Compensation tables: {written} written ({incremental} incremental on the active tables), {} not written",
        compensated.len() - written
    )];
    let mut refused: Vec<String> = compensated.iter().filter_map(|t| refusal(t)).collect();
    let more = refused.len().saturating_sub(MAX_PROBLEM_LINES);
    refused.truncate(MAX_PROBLEM_LINES);
    lines.extend(refused);
    if more > 0 {
        lines.push(format!(
            "  … and {more} more not written (results.json, compensation)"
        ));
    }
    for (key, words) in STATE_WARNINGS {
        let named: Vec<String> = compensated
            .iter()
            .filter(|t| {
                let c = t.evaluated().and_then(|e| e.compensation.as_deref());
                c.is_some_and(|c| c.outcome.is_ok() && c.warnings.iter().any(|w| w.key == *key))
            })
            .map(|t| t.label())
            .collect();
        if !named.is_empty() {
            lines.push(format!("  {} ({key}): {words}", listed(&named)));
        }
    }
    lines.extend(placeholders(&compensated));
    lines.extend(loading_lines(&compensated));
    lines.extend(result.tests.iter().filter_map(verification));
    lines
}

/// `  VMC-07 X, VMC-07 Y (axis_placeholder): the file names no machine axis: replace …`:
/// the tables written with a placeholder for the axis, by what to replace (one controller's
/// words).
fn placeholders(compensated: &[&AxisTest]) -> Vec<String> {
    grouped(compensated, |c| {
        c.warnings
            .iter()
            .filter(|w| w.key == "axis_placeholder")
            .map(|w| w.message.clone())
            .collect()
    })
    .into_iter()
    .map(|(message, named)| format!("  {} (axis_placeholder): {message}", listed(&named)))
    .collect()
}

/// What the controllers must be told to load the tables written (LinuxCNC's INI lines),
/// each once with the tests it is for: `  M X, M Y: COMP_FILE_TYPE = 0: …`.
fn loading_lines(compensated: &[&AxisTest]) -> Vec<String> {
    grouped(compensated, |c| {
        let path = format!("compensation/MACHINE/AXIS.{}", c.extension);
        c.loading
            .iter()
            .map(|l| l.replace("<file>", &path))
            .collect()
    })
    .into_iter()
    .map(|(line, named)| format!("  {}: {line}", listed(&named)))
    .collect()
}

/// The lines `lines` gives for each written table, each once in the order first met,
/// with the labels of the tests it came from.
fn grouped(
    compensated: &[&AxisTest],
    lines: impl Fn(&Compensation) -> Vec<String>,
) -> Vec<(String, Vec<String>)> {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    for t in compensated {
        let c = t.evaluated().and_then(|e| e.compensation.as_deref());
        let Some(c) = c.filter(|c| c.outcome.is_ok()) else {
            continue;
        };
        for line in lines(c) {
            match groups.iter_mut().find(|(l, _)| *l == line) {
                Some((_, named)) => named.push(t.label()),
                None => groups.push((line, vec![t.label()])),
            }
        }
    }
    groups
}

/// `  VMC-07 Z  not written: …`.
fn refusal(t: &AxisTest) -> Option<String> {
    let e = t
        .evaluated()
        .and_then(|e| e.compensation.as_deref())?
        .outcome
        .as_ref()
        .err()?;
    Some(format!("  {}  not written: {e}", t.label()))
}

/// `VMC-07 X, VMC-07 Y` or, beyond [`MAX_NAMED`], `… and 12 more`.
fn listed(labels: &[String]) -> String {
    let shown = labels[..labels.len().min(MAX_NAMED)].join(", ");
    match labels.len().saturating_sub(MAX_NAMED) {
        0 => shown,
        more => format!("{shown} and {more} more"),
    }
}

/// `Verification of MILL-3 X: effective: E 21.90 µm before, 1.20 predicted, 1.41 achieved`.
fn verification(t: &AxisTest) -> Option<String> {
    let v = t.evaluated().and_then(|e| e.verification.as_deref())?;
    let unit = t.deviation_symbol();
    Some(match v {
        Err(e) => format!("Verification of {}: not made: {e}", t.label()),
        Ok(v) => format!("Verification of {}: {}", t.label(), v.summary(unit)),
    })
}
