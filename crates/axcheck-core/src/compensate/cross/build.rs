//! A straightness test's cross table for a controller, built on the cross table active
//! during the test as the pitch tables are (`compensate::active`): the deviations measured
//! with a table active are what that table left, so the table to load is the active one
//! plus this measurement's correction, and the prediction applies only their difference.
//! Unstated, it is said, not guessed.

use super::verify::{change, predicted};
use super::{CrossFormat, CrossTable, Part, from_straightness};
use crate::compensate::Mode;
use crate::compensate::controllers::Refused;
use crate::geometry::line::ReferenceLine;
use crate::geometry::straightness::{self, Options};
use crate::measurement::AxisData;
use serde::Serialize;

/// The cross table active during the test.
#[derive(Debug, Clone, PartialEq, Default)]
pub enum CrossActive {
    /// Not stated: the table written is this measurement's alone (a warning says so).
    #[default]
    Unstated,
    /// No cross table was active.
    None,
    /// This table was, read from the file named.
    Table { table: CrossTable, file: String },
}

impl CrossActive {
    /// The table, when one was active.
    pub fn table(&self) -> Option<&CrossTable> {
        match self {
            CrossActive::Table { table, .. } => Some(table),
            _ => None,
        }
    }
}

/// What a cross table is built with.
#[derive(Debug, Clone, Default)]
pub struct CrossRequest {
    /// The input (measured along) and output (corrected) axes' names on the controller;
    /// default: the active table's.
    pub input: Option<String>,
    pub output: Option<String>,
    /// An equidistant grid's step, mm; default: the measured targets (their mean spacing
    /// where the format takes only equidistant points).
    pub interval_mm: Option<f64>,
    pub line: ReferenceLine,
    pub active: CrossActive,
    /// The files' name without extension (see [`CrossFormat::write`]); empty: the
    /// format's default.
    pub stem: String,
}

/// A cross table written, with what it is and what it predicts.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CrossCompensation {
    /// The format's name.
    pub format: &'static str,
    pub mode: Mode,
    /// The active table's file, as named.
    pub active_file: Option<String>,
    /// The table written (the active one plus this measurement's correction).
    pub table: CrossTable,
    /// The straightness measured and predicted with the table loaded, µm.
    pub measured_um: f64,
    pub predicted_um: f64,
    pub warnings: Vec<String>,
    /// The files, in the format's order.
    #[serde(skip)]
    pub parts: Vec<Part>,
}

/// The cross table of the straightness test `data` in `format`, or why it cannot be.
pub fn compensate(
    format: &dyn CrossFormat,
    data: &AxisData,
    request: &CrossRequest,
) -> Result<CrossCompensation, Refused> {
    let options = Options {
        line: request.line,
        local_length_mm: None,
    };
    let s = straightness::evaluate(data, &options)
        .ok_or_else(|| Refused::Grid("a cross table needs two targets or more".into()))?;
    let active = request.active.table();
    let (input, output) = names(request, active)?;
    let measured = from_straightness(&s, &data.targets, &input, &output);
    let grid = grid(format, &measured, request.interval_mm)?;
    let mut warnings = Vec::new();
    let table = match active {
        Some(a) => {
            warnings.extend(beyond(a, &grid));
            with_active(grid, a)
        }
        None => grid,
    };
    if request.active == CrossActive::Unstated {
        warnings.push(
            "the cross table active during the test is not stated: this table is this measurement's correction alone; add it to whatever table was active, or state it (`active: none` or its file)"
                .into(),
        );
    }
    let (measured_um, predicted_um) =
        predicted(data, &change(&table, active, &data.targets), request.line)
            .ok_or_else(|| Refused::Grid("a cross table needs two targets or more".into()))?;
    let parts = format.write(&table, &request.stem)?;
    Ok(CrossCompensation {
        format: format.name(),
        mode: if active.is_some() {
            Mode::Incremental
        } else {
            Mode::Absolute
        },
        active_file: match &request.active {
            CrossActive::Table { file, .. } => Some(file.clone()),
            _ => None,
        },
        table,
        measured_um,
        predicted_um,
        warnings,
        parts,
    })
}

impl CrossCompensation {
    /// `absolute` or `incremental`, as the JSON writes the mode.
    pub fn mode_key(&self) -> &'static str {
        match self.mode {
            Mode::Absolute => "absolute",
            Mode::Incremental => "incremental",
        }
    }
}

/// The axes named, else the active table's; a stated name that contradicts the active
/// table is refused (the table would build on another axis's correction).
fn names(request: &CrossRequest, active: Option<&CrossTable>) -> Result<(String, String), Refused> {
    let pick = |given: &Option<String>, held: Option<&String>, what: &str| match (given, held) {
        (Some(g), Some(h)) if g != h => Err(Refused::Active(format!(
            "the active table's {what} axis is `{h}`, not `{g}`: it corrects another pair of axes"
        ))),
        (Some(g), _) => Ok(g.clone()),
        (None, Some(h)) => Ok(h.clone()),
        (None, None) => Err(Refused::Grid(format!(
            "name the {what} axis as the controller names it"
        ))),
    };
    Ok((
        pick(&request.input, active.map(|a| &a.input), "input")?,
        pick(&request.output, active.map(|a| &a.output), "output")?,
    ))
}

/// The measured correction on the table's grid: the targets, or an equidistant grid of
/// the step asked for (the mean spacing where the format takes only equidistant points).
fn grid(
    format: &dyn CrossFormat,
    measured: &CrossTable,
    interval_mm: Option<f64>,
) -> Result<CrossTable, Refused> {
    let p = &measured.positions_mm;
    let step = match interval_mm {
        Some(s) if !(s > 0.0 && s.is_finite()) => {
            return Err(Refused::Grid(format!("the interval must be > 0, not {s}")));
        }
        Some(s) => Some(s),
        None if format.equidistant() && measured.step_mm().is_none() => {
            let n = p.len().max(2) - 1;
            Some((p[p.len() - 1] - p[0]) / n as f64)
        }
        None => None,
    };
    Ok(step.map_or_else(|| measured.clone(), |s| measured.resampled(s)))
}

/// The active table's correction added at each of `grid`'s points.
fn with_active(grid: CrossTable, active: &CrossTable) -> CrossTable {
    let corrections_um = (grid.positions_mm.iter().zip(&grid.corrections_um))
        .map(|(p, c)| c + active.at(*p))
        .collect();
    CrossTable {
        corrections_um,
        ..grid
    }
}

/// A warning when the active table reaches beyond the new one, whose end values the
/// controller holds there instead of the active table's.
fn beyond(active: &CrossTable, grid: &CrossTable) -> Option<String> {
    let (a, g) = (&active.positions_mm, &grid.positions_mm);
    let (Some(a0), Some(a1), Some(g0), Some(g1)) = (a.first(), a.last(), g.first(), g.last())
    else {
        return None;
    };
    (a0 < &(g0 - 1e-6) || a1 > &(g1 + 1e-6)).then(|| {
        format!(
            "the active table spans {a0} to {a1} mm, the new one the measured {g0} to {g1} mm: beyond it the controller holds the new table's end values, not the active table's"
        )
    })
}
