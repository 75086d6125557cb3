//! The compensation part of an axis report: the table the machine's controller holds, the
//! parameters measured beside those predicted with the table active, the data of the
//! chart of the mean deviations before and after, and when not to compensate.

use super::conditions::Row;
use super::{num, pos};
use crate::compensate::{Compensated, Compensation, Interpolation, Table};
use crate::evaluate::Evaluation;
use crate::report::compensation_chart::CompensationChart;
use crate::units::{AxisKind, Direction};
use serde::Serialize;

/// The compensation section, as the template reads it.
#[derive(Serialize)]
pub struct CompensationSection<'a> {
    controller: &'static str,
    /// Why the controller cannot hold the table: shown instead of the rest.
    refusal: Option<&'a str>,
    /// Controller, points, interval, reference point, range of the corrections.
    facts: Vec<Row>,
    unit: &'static str,
    parameters: Vec<PredictedRow>,
    /// Why the repeatability is the floor, with the clause of the parameters that stay.
    floor: String,
    /// How the controller applies the table between its points, for the prediction's note.
    applied: &'static str,
    warnings: Vec<&'a str>,
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

/// The section of a test evaluated as `measured` and compensated by `c`.
pub(super) fn compensation_section<'a>(
    c: &'a Compensation,
    measured: &Evaluation,
) -> CompensationSection<'a> {
    let unit = measured.kind.deviation_symbol();
    let warnings = c.warnings.iter().map(|w| w.message.as_str()).collect();
    let (refusal, facts, parameters, floor) = match &c.outcome {
        Err(refusal) => {
            // The reason without the `controller: ` the outcome starts with.
            let reason = refusal
                .strip_prefix(c.controller)
                .and_then(|r| r.strip_prefix(": "));
            (
                Some(reason.unwrap_or(refusal)),
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
        warnings,
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
    ])
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
            predicted: predicted.value(p.key()).map_or("–".into(), num),
        })
        .collect()
}

/// Keys of the parameters that measure the scatter about the means (unidirectional
/// repeatability or spread), which a table leaves as measured.
const SCATTER: &[&str] = &["R_up", "R_down", "sigma_mean", "spread_up", "spread_down"];

/// Why the repeatability is the floor, naming the parameters of the test's standard that
/// stay (their clause from the catalogue).
fn floor(e: &Evaluation) -> String {
    let base = "The floor is the repeatability: a table corrects the mean positional deviations x̄↑ and x̄↓ at each target, not the scatter of the readings about them.";
    let stay: Vec<_> = e
        .parameters
        .iter()
        .filter(|p| SCATTER.contains(&p.key()))
        .collect();
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
