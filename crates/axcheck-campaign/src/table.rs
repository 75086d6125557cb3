//! The summary table shared by the CSV, parquet, Markdown and workbook outputs and the
//! Python package's `check`: one row per axis test, a fixed set of columns (a stable
//! interface, README "Outputs").

use crate::evaluate::catalogue;
use crate::param_key::ParamKey;
use crate::results::{AxisTest, CampaignResult};

/// A cell of the table.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    Text(String),
    Int(i64),
    Number(f64),
    Bool(bool),
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
    Bool,
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
    // The ISO 230-2 and GOST 27843 parameters (empty when not applicable).
    cols.extend(
        catalogue::summary_keys()
            .iter()
            .map(|p| (p.to_string(), Number)),
    );
    cols.extend(
        [
            ("worst", Text),
            ("worst_ratio", Number),
            ("failed", Text),
            ("rules", Text),
            ("diagnosis", Text),
            ("error", Text),
            // Added in issue 42: the verdict rests on a spec marked `example: true`.
            ("example_limits", Bool),
            // Added in issue 46: the laser test (`positioning`, `straightness`, `angular`),
            // ISO 230-1's symbol (`EYX`) and the other tests' values (µm, µm, arcsec,
            // arcsec).
            ("test_kind", Text),
            ("symbol", Text),
            ("straightness", Number),
            ("straightness_local", Number),
            ("angular", Number),
            ("squareness", Number),
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
    let ev = t.evaluated();
    let e = ev.map(|e| &e.evaluation);
    let other = t.other();
    let data = (ev.and_then(|e| e.data.as_ref())).or_else(|| other.and_then(|o| o.data.as_ref()));
    // Rounded to 1e-6: positions carry at most 6 decimals, their difference no more.
    let travel = data.map(|d| {
        let (a, b) = d.measurement_travel();
        ((b - a) * 1e6).round() / 1e6
    });
    let worst = t.judgement().and_then(|j| j.worst());
    let (n, m) = match (e, data) {
        (Some(e), _) => (Some(e.n), Some(e.targets.len())),
        (None, Some(d)) => (Some(d.runs()), Some(d.targets.len())),
        _ => (None, None),
    };
    let mut cells = vec![
        Cell::text(&t.machine.id),
        Cell::text(&t.axis),
        Cell::Int(t.test as i64),
        Cell::opt_text(t.file.clone()),
        Cell::opt_text(t.kind().map(|k| k.to_string())),
        Cell::opt_text(t.positioning_standard().map(|s| s.key())),
        Cell::opt_text(t.judgement().map(|j| j.limits.describe())),
        Cell::opt_text(t.deviation_unit()),
        n.map_or(Cell::Empty, |n| Cell::Int(n as i64)),
        m.map_or(Cell::Empty, |m| Cell::Int(m as i64)),
        Cell::opt_number(travel),
        Cell::text(t.verdict().name()),
    ];
    for p in catalogue::summary_keys() {
        cells.push(Cell::opt_number(e.and_then(|e| e.value(*p))));
    }
    cells.push(Cell::opt_text(worst.map(|c| c.key.to_string())));
    cells.push(Cell::opt_number(worst.map(|c| c.ratio())));
    let failed: Vec<String> = (t.judgement().into_iter())
        .flat_map(|j| j.failed().map(|c| c.key.to_string()))
        .collect();
    cells.push(Cell::text(failed.join(" ")));
    let rules: Vec<&str> = t.findings().iter().map(|f| f.id).collect();
    cells.push(Cell::text(rules.join(" ")));
    cells.push(match ev.and_then(|e| e.diagnosis.as_deref()) {
        Some(d) => Cell::text(d.effects_label()),
        None => Cell::Empty,
    });
    cells.push(Cell::opt_text(t.error()));
    // Empty where no limit applied: there is no verdict to qualify.
    cells.push(
        (t.judgement().filter(|j| !j.limits.is_empty()))
            .map_or(Cell::Empty, |j| Cell::Bool(j.limits.example)),
    );
    cells.push(Cell::text(t.test_kind().key()));
    cells.push(Cell::opt_text(
        other.map(|o| o.symbol.clone()).filter(|s| !s.is_empty()),
    ));
    let value = |key| {
        let result = other.map(|o| &o.result);
        Cell::opt_number(result.and_then(|r| r.value(key)))
    };
    cells.extend(ParamKey::GEOMETRY.map(value));
    cells
}
