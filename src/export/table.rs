//! The summary table shared by the CSV, parquet and Markdown outputs: one row per axis
//! test, a fixed set of columns.

use crate::batch::{AxisTest, CampaignResult};

/// Parameter columns: the ISO 230-2 and GOST 27843 parameters (empty when not applicable).
pub const PARAMETER_COLUMNS: &[&str] = &[
    "A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean",
    "R_max", "R_mean", "B_max",
];

/// A cell of the table.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    Text(String),
    Int(i64),
    Number(f64),
    Empty,
}

impl Cell {
    fn text(s: impl Into<String>) -> Cell {
        Cell::Text(s.into())
    }

    fn opt_text(s: Option<impl Into<String>>) -> Cell {
        s.map_or(Cell::Empty, |s| Cell::Text(s.into()))
    }

    fn opt_number(x: Option<f64>) -> Cell {
        x.map_or(Cell::Empty, Cell::Number)
    }
}

/// Kind of a column, for typed formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnKind {
    Text,
    Int,
    Number,
}

/// The column names and kinds, in order.
pub fn columns() -> Vec<(String, ColumnKind)> {
    use ColumnKind::*;
    let mut cols: Vec<(String, ColumnKind)> = [
        ("machine", Text),
        ("axis", Text),
        ("test", Int),
        ("file", Text),
        ("kind", Text),
        ("standard", Text),
        ("spec", Text),
        ("unit", Text),
        ("n", Int),
        ("m", Int),
        ("travel", Number),
        ("verdict", Text),
    ]
    .iter()
    .map(|(n, k)| (n.to_string(), *k))
    .collect();
    cols.extend(PARAMETER_COLUMNS.iter().map(|p| (p.to_string(), Number)));
    cols.extend(
        [
            ("worst", Text),
            ("worst_ratio", Number),
            ("failed", Text),
            ("rules", Text),
            ("diagnosis", Text),
            ("error", Text),
        ]
        .iter()
        .map(|(n, k)| (n.to_string(), *k)),
    );
    cols
}

/// One row per test, in campaign order.
pub fn rows(result: &CampaignResult) -> Vec<Vec<Cell>> {
    result.tests.iter().map(row).collect()
}

fn row(t: &AxisTest) -> Vec<Cell> {
    let e = t.evaluation.as_ref();
    // Rounded to 1e-6: positions carry at most 6 decimals, their difference no more.
    let travel = t.data.as_ref().map(|d| {
        let (a, b) = d.measurement_travel();
        ((b - a) * 1e6).round() / 1e6
    });
    let worst = t.judgement.as_ref().and_then(|j| j.worst());
    let mut cells = vec![
        Cell::text(&t.machine.id),
        Cell::text(&t.axis),
        Cell::Int(t.test as i64),
        Cell::opt_text(t.file.clone()),
        Cell::opt_text(t.kind().map(|k| k.to_string())),
        Cell::opt_text(t.standard().map(|s| s.key())),
        Cell::opt_text(t.judgement.as_ref().map(|j| spec_label(&j.limits))),
        Cell::opt_text(t.kind().map(|k| k.deviation_unit())),
        e.map_or(Cell::Empty, |e| Cell::Int(e.n as i64)),
        e.map_or(Cell::Empty, |e| Cell::Int(e.targets.len() as i64)),
        Cell::opt_number(travel),
        Cell::text(t.verdict.name()),
    ];
    for p in PARAMETER_COLUMNS {
        cells.push(Cell::opt_number(e.and_then(|e| e.value(p))));
    }
    cells.push(Cell::opt_text(worst.map(|c| c.key.clone())));
    cells.push(Cell::opt_number(worst.map(|c| c.ratio())));
    let failed: Vec<String> = t
        .judgement
        .iter()
        .flat_map(|j| j.failed().map(|c| c.key.clone()))
        .collect();
    cells.push(Cell::text(failed.join(" ")));
    let rules: Vec<&str> = t.findings.iter().map(|f| f.id).collect();
    cells.push(Cell::text(rules.join(" ")));
    cells.push(match &t.diagnosis {
        Some(d) => Cell::text(diagnosis_label(d)),
        None => Cell::Empty,
    });
    cells.push(Cell::opt_text(t.error.clone()));
    cells
}

/// The spec a test was judged by, or that no tolerance applied.
pub fn spec_label(limits: &crate::judge::Limits) -> String {
    match (&limits.spec, limits.is_empty()) {
        (_, true) => NO_TOLERANCE.to_string(),
        (Some(spec), false) => {
            if limits
                .values
                .values()
                .any(|(_, s)| *s == crate::judge::LimitSource::Axis)
            {
                format!("{spec} + axis tolerances")
            } else {
                spec.clone()
            }
        }
        (None, false) => "axis tolerances".to_string(),
    }
}

/// What the summary says of a test judged against no limit.
pub const NO_TOLERANCE: &str = "no tolerance applied";

/// The effects a diagnosis names, e.g. `drift outlier`, or `none`.
pub fn diagnosis_label(d: &crate::diagnose::Diagnosis) -> String {
    let mut effects: Vec<&str> = d.findings.iter().map(|f| f.effect.name()).collect();
    effects.dedup();
    if effects.is_empty() {
        "none".to_string()
    } else {
        effects.join(" ")
    }
}
