//! Compensation tables: from a measured axis to the correction its controller adds,
//! interpolated along the axis, and the parameters predicted after compensation.
//!
//! The pipeline: the controller's grid ([`grid`]), the table that cancels the mean
//! deviations on it ([`build`]), the table as the controller holds it (its unit, its
//! limits: [`controllers::Controller::hold`]), its file, and the readings evaluated again
//! with the held table applied as the controller would ([`table::apply`]). The floor is the
//! repeatability, which no table removes; [`warnings`] says when a static table will not
//! achieve the prediction at all.

pub mod build;
pub mod controllers;
pub mod grid;
pub mod table;
#[cfg(test)]
pub(crate) mod testing;
pub mod warnings;

pub use table::{Interpolation, Table, apply, linear};
pub use warnings::Warning;

use crate::diagnose::Diagnosis;
use crate::evaluate::{self, Evaluation, StandardId};
use crate::measurement::AxisData;
use controllers::{Controller, Refused};

/// What the user chose about the table (`--interval`, `--reference`).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    /// Spacing of an equidistant grid, mm or deg; `None`: the controller's default (the
    /// measured targets, or their mean spacing).
    pub interval: Option<f64>,
    /// The reference point, mm or deg: the grid passes through it and the correction is
    /// zero there. `None`: the first grid point, corrections as measured (−x̄).
    pub reference: Option<f64>,
    /// The declared lead-screw or encoder pitch, mm or deg: a periodic error of that period
    /// that the table's points cannot follow is warned of, found by the diagnosis or not.
    pub pitch: Option<f64>,
    /// The axis's name on the controller, for formats that name it (HEIDENHAIN's column,
    /// Siemens' machine axis `X1`): `--axis`, `compensation.axis` in campaigns; `None`: the
    /// file carries a placeholder to replace (a campaign's axis name need not be the
    /// controller's).
    pub axis: Option<String>,
}

/// The table as `controller` holds it for `data`, or why it cannot hold it.
pub fn held_table(
    controller: &dyn Controller,
    data: &AxisData,
    settings: &Settings,
) -> Result<Table, Refused> {
    let format = controller.format();
    let positions = grid::grid(data, &format, settings)?;
    let mut table = build::table(data, positions, &format, settings);
    table.interpolation = controller.interpolation();
    controller.hold(table)
}

/// A compensation that the controller can hold: its table, file and prediction.
#[derive(Debug, Clone)]
pub struct Compensated {
    /// The table as the controller holds it (rounded to its unit).
    pub table: Table,
    /// The file as the controller loads it.
    pub file: String,
    /// The parameters with the table active.
    pub predicted: Evaluation,
}

/// A test's compensation by its machine's controller.
#[derive(Debug, Clone)]
pub struct Compensation {
    pub controller: &'static str,
    /// The file's extension.
    pub extension: &'static str,
    /// The table, or why the controller cannot hold it (`controller: reason`).
    pub outcome: Result<Compensated, String>,
    /// Why the table may not achieve the prediction on the machine.
    pub warnings: Vec<Warning>,
}

/// The compensation of `data` by `controller`, with the warnings of its `diagnosis`.
pub fn compensation(
    controller: &dyn Controller,
    data: &AxisData,
    standard: StandardId,
    settings: &Settings,
    diagnosis: &Diagnosis,
) -> Compensation {
    let outcome = held_table(controller, data, settings)
        .and_then(|table| {
            let file = controller.write(&table)?;
            Ok(Compensated {
                predicted: evaluate::evaluate(&apply(&table, data), standard),
                table,
                file,
            })
        })
        .map_err(|e| format!("{}: {e}", controller.name()));
    let warnings = match &outcome {
        Ok(c) => warnings::warnings(data, diagnosis, &c.table, settings.pitch),
        Err(_) => Vec::new(),
    };
    Compensation {
        controller: controller.name(),
        extension: controller.extension(),
        outcome,
        warnings,
    }
}
