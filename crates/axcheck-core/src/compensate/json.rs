//! A compensation as JSON, built once for every output that gives it: `results.json`'s
//! `compensation` and `compensate --json` (the command line's and the Python package's)
//! begin with the same [`CompensationHead`]; [`TableJson`] is the command's whole object.

use super::{Compensated, Compensation, Mode, Table, Warning};
use crate::evaluate::Evaluation;
use crate::evaluate::json::ParameterSet;
use serde::Serialize;

/// What every compensation's JSON begins with: the controller, whether the table builds
/// on the active one, and the active table.
#[derive(Serialize)]
pub struct CompensationHead<'a> {
    controller: &'static str,
    /// `absolute` or `incremental` (the active table plus this measurement's correction).
    mode: Mode,
    /// The active table's file, when one was given.
    #[serde(skip_serializing_if = "Option::is_none")]
    active_file: Option<&'a str>,
}

impl<'a> CompensationHead<'a> {
    pub fn of(c: &'a Compensation) -> CompensationHead<'a> {
        CompensationHead {
            controller: c.controller,
            mode: c.mode,
            active_file: c.active_file.as_deref(),
        }
    }
}

/// `compensate --json`: the table, and the parameters as measured and predicted.
#[derive(Serialize)]
pub struct TableJson<'a> {
    #[serde(flatten)]
    head: CompensationHead<'a>,
    /// Deviation unit of the corrections and parameters: `um` or `arcsec`.
    unit: &'static str,
    table: &'a Table,
    measured: ParameterSet<'a>,
    predicted: ParameterSet<'a>,
    /// Why the table may not achieve the prediction on the machine.
    warnings: &'a [Warning],
    /// What the controller must be told to load the file (LinuxCNC's INI lines).
    #[serde(skip_serializing_if = "<[String]>::is_empty")]
    loading: &'a [String],
    /// The table file written, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<String>,
}

impl<'a> TableJson<'a> {
    /// The JSON of `c`'s table `done` with the parameters `measured`; `file` the path it
    /// was written to.
    pub fn new(
        c: &'a Compensation,
        done: &'a Compensated,
        measured: &'a Evaluation,
        unit: &'static str,
        file: Option<String>,
    ) -> TableJson<'a> {
        TableJson {
            head: CompensationHead::of(c),
            unit,
            table: &done.table,
            measured: ParameterSet::of(measured),
            predicted: ParameterSet::of(&done.predicted),
            warnings: &c.warnings,
            loading: &c.loading,
            file,
        }
    }
}
