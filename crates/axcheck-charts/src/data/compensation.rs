//! The compensation part of an axis report: the table the machine's controller holds and
//! what it builds on (the compensation active during the test), the parameters measured
//! beside those predicted with the table active, the data of the chart of the mean
//! deviations before and after, when not to compensate, and the verification of a
//! re-measurement (before, predicted and achieved).

use super::conditions::Row;
use super::{key_words, num, pos};
use crate::charts::compensation::CompensationChart;
use crate::charts::verification::VerificationChart;
use crate::compensate::{Compensated, Compensation, Interpolation, Mode, Table};
use crate::evaluate::Evaluation;
use crate::results::StatedTableError;
use crate::units::{AxisKind, Direction};
use crate::verify::Verification;
use serde::Serialize;

/// The compensation section, as the template reads it.
#[derive(Serialize)]
pub(crate) struct CompensationSection<'a> {
    controller: &'static str,
    /// Why the controller cannot hold the table: shown instead of the rest.
    refusal: Option<String>,
    /// Controller, points, interval, reference point, range of the corrections.
    facts: Vec<Row>,
    unit: &'static str,
    parameters: Vec<PredictedRow>,
    /// Why the repeatability is the floor, with the clause of the parameters that stay.
    floor: String,
    /// How the controller applies the table between its points, for the prediction's note.
    applied: &'static str,
    /// What the state the table builds on leaves unsure (not stated, contradicted), and
    /// what the file leaves to fill in before it loads (the axis): beside the facts.
    state_warnings: Vec<&'a str>,
    warnings: Vec<&'a str>,
    /// The verification, when this test re-measures a table it verifies.
    verification: Option<VerificationSection<'a>>,
}

/// A verification as the template reads it.
#[derive(Serialize)]
struct VerificationSection<'a> {
    /// Why it could not be made: shown instead of the rest.
    error: Option<String>,
    /// `effective`, … and its words.
    verdict: &'static str,
    verdict_words: &'static str,
    /// E before, predicted, achieved, the uncertainty, the offset.
    facts: Vec<Row>,
    findings: Vec<FindingRow<'a>>,
    notes: &'a [String],
}

/// What went wrong, with its evidence.
#[derive(Serialize)]
struct FindingRow<'a> {
    /// The effect in words (`sign inverted`).
    effect: String,
    evidence: &'a str,
}

/// A parameter as measured and as predicted with the table active.
#[derive(Serialize)]
struct PredictedRow {
    key: &'static str,
    symbol: &'static str,
    name: &'static str,
    unit: &'static str,
    measured: String,
    predicted: String,
}

/// The section of a test evaluated as `measured` and compensated by `c`, with the
/// verification of the table it re-measures.
pub(super) fn compensation_section<'a>(
    c: &'a Compensation,
    measured: &Evaluation,
    verification: Option<&'a Result<Verification, StatedTableError>>,
) -> CompensationSection<'a> {
    let unit = measured.kind.deviation_symbol();
    let (state, other): (Vec<_>, Vec<_>) = c
        .warnings
        .iter()
        .partition(|w| w.key.starts_with("active_") || w.key == "axis_placeholder");
    let message = |w: &&'a crate::compensate::Warning| w.message.as_str();
    let state_warnings = state.iter().map(message).collect();
    let warnings = other.iter().map(message).collect();
    let (refusal, facts, parameters, floor) = match &c.outcome {
        Err(refusal) => {
            // The reason without the controller the outcome names.
            (
                Some(keys_in_words(&refusal.reason, verification)),
                Vec::new(),
                Vec::new(),
                String::new(),
            )
        }
        Ok(done) => (
            None,
            table_facts(c, &done.table, measured),
            predicted_rows(measured, &done.predicted),
            floor(measured),
        ),
    };
    let applied = match c.outcome.as_ref().map(|d| d.table.interpolation) {
        Ok(Interpolation::Steps) => "each point's value held up to the next point",
        _ => "interpolated linearly between its points",
    };
    CompensationSection {
        controller: c.controller,
        refusal,
        facts,
        unit,
        parameters,
        floor,
        applied,
        state_warnings,
        warnings,
        verification: verification.map(|v| verification_section(v, measured.kind)),
    }
}

/// A refusal with the verification's verdict and findings (`made_worse (sign_inverted)`,
/// as the console names them) in words.
fn keys_in_words(
    refusal: &str,
    verification: Option<&Result<Verification, StatedTableError>>,
) -> String {
    let Some(Ok(v)) = verification else {
        return refusal.to_string();
    };
    let keys = std::iter::once(v.verdict.name()).chain(v.findings.iter().map(|f| f.effect.name()));
    keys.fold(refusal.to_string(), |text, key| {
        text.replace(key, &key_words(key))
    })
}

/// The verification's verdict, E at each stage and what went wrong.
fn verification_section(
    v: &Result<Verification, StatedTableError>,
    kind: AxisKind,
) -> VerificationSection<'_> {
    let v = match v {
        Ok(v) => v,
        Err(e) => {
            return VerificationSection {
                error: Some(e.to_string()),
                verdict: "",
                verdict_words: "",
                facts: Vec::new(),
                findings: Vec::new(),
                notes: &[],
            };
        }
    };
    let unit = kind.deviation_symbol();
    let value = |x: f64| Some(format!("{} {unit}", num(x)));
    VerificationSection {
        error: None,
        verdict: v.verdict.name(),
        verdict_words: v.verdict.words(),
        facts: Row::present([
            ("E before the table", value(v.e.before)),
            ("E predicted", value(v.e.predicted)),
            ("E achieved", value(v.e.achieved)),
            ("Uncertainty of a difference (95 %)", value(v.e.uncertainty)),
            ("Offset between the measurements", value(v.offset)),
        ]),
        findings: v
            .findings
            .iter()
            .map(|f| FindingRow {
                effect: key_words(f.effect.name()),
                evidence: &f.evidence,
            })
            .collect(),
        notes: &v.notes,
    }
}

/// What the table is: its controller and file, its points, interval, reference point
/// and the range of its corrections.
fn table_facts(c: &Compensation, table: &Table, e: &Evaluation) -> Vec<Row> {
    let kind = table.kind;
    let unit = kind.deviation_symbol();
    let range = |values: &[f64]| {
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (lo <= hi).then(|| format!("{} … {} {unit}", num(lo), num(hi)))
    };
    let corrections = if table.up == table.down {
        range(&table.up).map(|r| format!("{r} (both directions)"))
    } else {
        range(&table.up)
            .zip(range(&table.down))
            .map(|(u, d)| format!("↑ {u}, ↓ {d}"))
    };
    Row::present([
        (
            "Controller",
            Some(format!("{} (file .{})", c.controller, c.extension)),
        ),
        ("Built on", Some(built_on(c))),
        ("Table points", Some(points(table))),
        ("Interval", interval(table, e)),
        ("Reference point", Some(pos(kind, table.reference))),
        ("Corrections added", corrections),
        (
            "Modulo",
            table
                .modulo_deg
                .map(|r| format!("one revolution, {}", pos(AxisKind::Rotary, r))),
        ),
        ("Loading", loading(c)),
    ])
}

/// What the controller must be told to load the file (LinuxCNC's type and INI lines).
fn loading(c: &Compensation) -> Option<String> {
    let path = format!("compensation/MACHINE/AXIS.{}", c.extension);
    let lines: Vec<String> = c
        .loading
        .iter()
        .map(|l| l.replace("<file>", &path))
        .collect();
    (!lines.is_empty()).then(|| lines.join(" "))
}

/// What the table builds on: the active table, nothing, or an unknown state.
fn built_on(c: &Compensation) -> String {
    let unknown = c
        .warnings
        .iter()
        .any(|w| w.key == "active_compensation_unknown");
    match (c.mode, c.active_file.as_deref()) {
        (Mode::Incremental, Some(file)) => {
            format!("the active table {file} (incremental: it plus this test's correction)")
        }
        (Mode::Incremental, None) => "the active backlash (incremental)".into(),
        (Mode::Absolute, _) if unknown => {
            "not stated (absolute: this test's correction alone)".into()
        }
        (Mode::Absolute, _) => "nothing active, as stated (absolute)".into(),
    }
}

/// The number of points, and whether the table holds one correction per direction.
fn points(table: &Table) -> String {
    let n = table.positions.len();
    if table.up == table.down {
        format!("{n}, one table for both directions")
    } else {
        format!("{n}, a correction per direction (↑ and ↓)")
    }
}

/// The spacing of the points: one interval, or the measured targets' uneven one.
fn interval(table: &Table, e: &Evaluation) -> Option<String> {
    let steps: Vec<f64> = table.positions.windows(2).map(|w| w[1] - w[0]).collect();
    let lo = steps.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = steps.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if lo > hi {
        return None;
    }
    let kind = table.kind;
    let on_targets = table.positions.len() == e.targets.len()
        && table
            .positions
            .iter()
            .zip(&e.targets)
            .all(|(p, t)| (p - t.position).abs() <= 1e-9 * p.abs().max(1.0));
    let source = if on_targets {
        ", the measured targets"
    } else {
        ""
    };
    if hi - lo <= 1e-6 * hi.abs().max(1e-9) {
        Some(format!("{}{source}", pos(kind, lo)))
    } else {
        Some(format!(
            "uneven, {} … {}{source}",
            pos(kind, lo),
            pos(kind, hi)
        ))
    }
}

/// The parameters measured, each beside its value with the table active.
fn predicted_rows(measured: &Evaluation, predicted: &Evaluation) -> Vec<PredictedRow> {
    let unit = measured.kind.deviation_symbol();
    measured
        .parameters
        .iter()
        .map(|p| PredictedRow {
            key: p.key(),
            symbol: p.symbol(),
            name: p.name(),
            unit,
            measured: num(p.value),
            predicted: predicted.value(p.def.key).map_or("–".into(), num),
        })
        .collect()
}

/// Why the repeatability is the floor, naming the parameters of the test's standard that
/// stay: those the catalogue calls scatter ([`crate::evaluate::ParameterDef::is_scatter`]),
/// with their clause.
fn floor(e: &Evaluation) -> String {
    let base = "The floor is the repeatability: a table corrects the mean positional deviations x̄↑ and x̄↓ at each target, not the scatter of the readings about them.";
    let stay: Vec<_> = e.parameters.iter().filter(|p| p.def.is_scatter()).collect();
    let Some(first) = stay.first() else {
        return base.to_string();
    };
    let symbols: Vec<&str> = stay.iter().map(|p| p.symbol()).collect();
    let verb = if stay.len() == 1 { "stays" } else { "stay" };
    format!(
        "{base} {} ({}) {verb} as measured, whatever the table.",
        symbols.join(" and "),
        first.clause()
    )
}

/// The chart data: the means as measured and with the table, the readings with it.
pub fn compensation_chart(measured: &Evaluation, done: &Compensated) -> CompensationChart {
    let means = |e: &Evaluation, d: Direction| -> Vec<f64> {
        e.targets.iter().map(|t| t.direction(d).mean).collect()
    };
    let readings = |d: Direction| -> Vec<Vec<f64>> {
        let targets = done.predicted.targets.iter();
        targets.map(|t| t.direction(d).deviations.clone()).collect()
    };
    let (pos_unit, dev_unit) = match measured.kind {
        AxisKind::Linear => ("mm", "µm"),
        AxisKind::Rotary => ("°", "arcsec"),
    };
    CompensationChart {
        positions: measured.targets.iter().map(|t| t.position).collect(),
        position_label: format!("Target position Pi / {pos_unit}"),
        deviation_label: format!("Positional deviation / {dev_unit}"),
        measured_up: means(measured, Direction::Up),
        measured_down: means(measured, Direction::Down),
        compensated_up: means(&done.predicted, Direction::Up),
        compensated_down: means(&done.predicted, Direction::Down),
        readings_up: readings(Direction::Up),
        readings_down: readings(Direction::Down),
        table_points: done.table.positions.clone(),
    }
}

/// The verification chart: the means before, predicted and achieved at the
/// re-measurement's targets.
pub fn verification_chart(v: &Verification, kind: AxisKind) -> VerificationChart {
    let (pos_unit, dev_unit) = match kind {
        AxisKind::Linear => ("mm", "µm"),
        AxisKind::Rotary => ("°", "arcsec"),
    };
    let of = |d: Direction, f: fn(&crate::verify::ComparedTarget) -> f64| -> Vec<f64> {
        v.per_target
            .iter()
            .filter(|r| r.direction == d)
            .map(f)
            .collect()
    };
    VerificationChart {
        positions: of(Direction::Up, |r| r.position),
        position_label: format!("Target position Pi / {pos_unit}"),
        deviation_label: format!("Mean positional deviation / {dev_unit}"),
        before_up: of(Direction::Up, |r| r.before),
        before_down: of(Direction::Down, |r| r.before),
        predicted_up: of(Direction::Up, |r| r.predicted),
        predicted_down: of(Direction::Down, |r| r.predicted),
        achieved_up: of(Direction::Up, |r| r.achieved),
        achieved_down: of(Direction::Down, |r| r.achieved),
    }
}
