//! Compensation tables: from a measured axis to the correction its controller adds,
//! interpolated along the axis, and the parameters predicted after compensation.
//!
//! The pipeline: the controller's grid ([`grid`], or the active table's), the table that
//! cancels the mean deviations on it ([`build`]) added to what was active during the test
//! ([`active`]), the table as the controller holds it (its unit, its limits:
//! [`controllers::Controller::hold`]), its file, and the readings evaluated again with the
//! difference between the held table and the active one applied as the controller would
//! ([`table::apply_change`]). The floor is the repeatability, which no table removes;
//! [`warnings`] says when a static table will not achieve the prediction at all. Each
//! controller also reads its files back ([`controllers::Controller::read`]): the active
//! table is one of them.

pub mod active;
pub mod build;
pub mod controllers;
pub mod cross;
pub mod grid;
pub mod json;
pub mod table;
#[cfg(test)]
pub(crate) mod testing;
pub mod warnings;

pub use active::{Active, Mode};
pub use table::{Interpolation, Table, TableSlot, apply, apply_change, linear};
pub use warnings::Warning;

use crate::diagnose::Diagnosis;
use crate::evaluate::{self, Evaluation, StandardId};
use crate::measurement::AxisData;
use controllers::{Controller, Refused};

/// What the user chose about the table (`--interval`, `--reference`, `--axis`, `--active`)
/// and what the campaign says of the test.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    /// Spacing of an equidistant grid, mm or deg; `None`: the controller's default (the
    /// measured targets, or their mean spacing). An active table's grid comes first.
    pub interval: Option<f64>,
    /// The reference point, mm or deg: the grid passes through it and the correction is
    /// zero there. `None`: the first grid point (or the active table's reference),
    /// corrections as measured (−x̄).
    pub reference: Option<f64>,
    /// The declared lead-screw or encoder pitch, mm or deg: a periodic error of that period
    /// that the table's points cannot follow is warned of, found by the diagnosis or not.
    pub pitch: Option<f64>,
    /// Where the table goes on the controller (`--axis`, `--measuring-system`,
    /// `compensation.axis` in campaigns): what is given here, else the active table's.
    pub place: TableSlot,
    /// The compensation active during the test; `None`: not stated (a warning says so).
    pub active: Option<Active>,
    /// The test conditions' text on compensation (ISO 230-2 3.2), to check against `active`.
    pub conditions: Option<String>,
}

/// The table `controller` must hold for `data`'s mean deviations to vanish, as it holds it,
/// or why it cannot: on the active table's grid (else the controller's), this
/// measurement's correction plus `total`, the correction active during the test, rounded
/// once to the controller's unit.
fn held_on(
    controller: &dyn Controller,
    data: &AxisData,
    settings: &Settings,
    total: Option<&Table>,
) -> Result<Table, Refused> {
    let format = controller.format();
    let base = settings.active.as_ref().and_then(|a| a.table.as_ref());
    let (positions, wraps) = match base {
        Some(t) => (t.positions.clone(), t.modulo_deg.is_some()),
        None => (
            grid::grid(data, &format, settings)?,
            grid::modulo(data, &format),
        ),
    };
    let mut table = build::measured(data, positions, &format, wraps);
    if let Some(total) = total {
        build::add(&mut table, total);
    }
    table.reference = base.map_or(table.positions[0], |t| t.reference);
    if let Some(reference) = settings.reference {
        build::zero_at_reference(&mut table, reference, &format);
    }
    table.place = place(&settings.place, base);
    table.interpolation = controller.interpolation();
    let held = controller.hold(table)?;
    controllers::finite(&held)?;
    Ok(held)
}

/// The place given, completed by the active table's.
fn place(given: &TableSlot, base: Option<&Table>) -> TableSlot {
    let active = base.map(|t| t.place.clone()).unwrap_or_default();
    TableSlot {
        axis: given.axis.clone().or(active.axis),
        measuring_system: given.measuring_system.or(active.measuring_system),
        number: given.number.or(active.number),
    }
}

/// The correction active during the test as the controller added it (its table and the
/// backlash that acted), or why the stated state does not fit the controller.
fn active_total(
    controller: &dyn Controller,
    data: &AxisData,
    settings: &Settings,
) -> Result<Option<Table>, Refused> {
    let Some(active) = &settings.active else {
        return Ok(None);
    };
    if let Some(why) = active::refusal(controller, active, data.kind) {
        return Err(Refused::Active(why));
    }
    Ok(active.total(controller.backlash(), data.kind))
}

/// The table as `controller` holds it for `data`, or why it cannot hold it.
pub fn held_table(
    controller: &dyn Controller,
    data: &AxisData,
    settings: &Settings,
) -> Result<Table, Refused> {
    let total = active_total(controller, data, settings)?;
    held_on(controller, data, settings, total.as_ref())
}

/// A compensation that the controller can hold: its table, file and prediction.
#[derive(Debug, Clone)]
pub struct Compensated {
    /// The table as the controller holds it (rounded to its unit).
    pub table: Table,
    /// The file as the controller loads it.
    pub file: String,
    /// The parameters with the table active in place of the one active during the test.
    pub predicted: Evaluation,
}

/// Why no table is written: the controller cannot hold it, its active table cannot be
/// read, or the table it would be built on did not act as stated (`controller: reason`).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{controller}: {reason}")]
pub struct NoTable {
    pub controller: &'static str,
    pub reason: String,
}

/// A test's compensation by its machine's controller.
#[derive(Debug, Clone)]
pub struct Compensation {
    pub controller: &'static str,
    /// The file's extension.
    pub extension: &'static str,
    /// The whole correction, or the active one plus this measurement's.
    pub mode: Mode,
    /// The active table's file, as named.
    pub active_file: Option<String>,
    /// The table, or why the controller cannot hold it.
    pub outcome: Result<Compensated, NoTable>,
    /// What the active state leaves unsure, and why the table may not achieve the
    /// prediction on the machine.
    pub warnings: Vec<Warning>,
    /// What the controller must be told to load the file as written (LinuxCNC's INI
    /// lines), `<file>` standing for its path; empty when no table was written.
    pub loading: Vec<String>,
}

impl Compensation {
    /// No table from `controller`, for `reason` (an active table that cannot be read).
    pub fn refused(controller: &dyn Controller, reason: &str) -> Compensation {
        Compensation {
            controller: controller.name(),
            extension: controller.extension(),
            mode: Mode::Absolute,
            active_file: None,
            outcome: Err(NoTable {
                controller: controller.name(),
                reason: reason.to_string(),
            }),
            warnings: Vec::new(),
            loading: Vec::new(),
        }
    }
}

/// The compensation of one measurement outside a campaign (`axcheck compensate`, the
/// Python package's `compensate`): its diagnosis made for the warnings (with the lead
/// screw's pitch the settings give), and the parameters as measured.
pub fn of_measurement(
    controller: &dyn Controller,
    data: &AxisData,
    standard: StandardId,
    settings: &Settings,
) -> (Compensation, Evaluation) {
    let options = crate::diagnose::Options {
        pitch: settings.pitch,
        standard,
        ..Default::default()
    };
    let diagnosis = crate::diagnose::diagnose(data, &options);
    let c = compensation(controller, data, standard, settings, &diagnosis);
    (c, evaluate::evaluate(data, standard))
}

/// The compensation of `data` by `controller`, with the warnings of its `diagnosis`.
pub fn compensation(
    controller: &dyn Controller,
    data: &AxisData,
    standard: StandardId,
    settings: &Settings,
    diagnosis: &Diagnosis,
) -> Compensation {
    let active = settings.active.as_ref();
    let mode = active.map_or(Mode::Absolute, Active::mode);
    let mut warnings = active::warnings(
        controller,
        active,
        settings.conditions.as_deref(),
        data.kind,
    );
    if let (Some(step), Some(_)) = (settings.interval, active.and_then(|a| a.table.as_ref())) {
        warnings.push(Warning {
            key: "active_grid_kept",
            message: format!(
                "the interval {} {} given is not used: a table built on the active one keeps the active table's points",
                crate::units::fmt_position(step),
                data.kind.position_unit()
            ),
        });
    }
    let outcome = active_total(controller, data, settings)
        .and_then(|total| {
            let table = held_on(controller, data, settings, total.as_ref())?;
            let notes = file_notes(mode, active, &warnings);
            let file = controller.write(&table, &notes)?;
            let readings = apply_change(&table, total.as_ref(), data);
            Ok(Compensated {
                predicted: evaluate::evaluate(&readings, standard),
                table,
                file,
            })
        })
        .map_err(|e| NoTable {
            controller: controller.name(),
            reason: e.to_string(),
        });
    if let Ok(c) = &outcome {
        warnings.extend(controller.unnamed_axis(&c.table).map(|message| Warning {
            key: "axis_placeholder",
            message,
        }));
        warnings.extend(warnings::warnings(
            data,
            diagnosis,
            &c.table,
            settings.pitch,
        ));
    }
    let loading = match &outcome {
        Ok(_) => controller.loading(data.kind),
        Err(_) => Vec::new(),
    };
    Compensation {
        controller: controller.name(),
        extension: controller.extension(),
        mode,
        active_file: active.and_then(|a| a.file.clone()),
        outcome,
        warnings,
        loading,
    }
}

/// What the file itself says of the state it builds on: incremental on which file, or
/// what the active state's warnings say.
fn file_notes(mode: Mode, active: Option<&Active>, warnings: &[Warning]) -> Vec<String> {
    let mut notes = Vec::new();
    if let Some(a) = active {
        notes.push(match (mode, &a.file) {
            (Mode::Incremental, Some(file)) => format!(
                "Incremental: the table active during the measurement ({file}) plus this measurement's correction; load it in place of that table."
            ),
            (Mode::Incremental, None) => "Incremental: the backlash active during the measurement plus this measurement's correction.".to_string(),
            (Mode::Absolute, _) => "Absolute: measured with no compensation active (as stated); load it as the whole table.".to_string(),
        });
    }
    notes.extend(warnings.iter().map(|w| format!("Warning: {}", w.message)));
    notes
}
