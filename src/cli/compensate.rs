//! `axcheck compensate`: the controller's correction table for a measured axis, and the
//! parameters predicted with it.

use super::text::{left, right};
use anyhow::{Context, Result, anyhow};
use axcheck::compensate::{self, Table, Warning, controllers};
use axcheck::evaluate::Evaluation;
use axcheck::evaluate::StandardId;
use axcheck::evaluate::json::ParameterValues;
use axcheck::measurement::AxisData;
use axcheck::units::fmt_fixed;
use serde::Serialize;
use std::fmt::Write;
use std::path::Path;

/// The table's grid and naming (`--interval`, `--reference`, `--pitch`, `--axis`).
#[derive(Debug, clap::Args)]
pub struct TableArgs {
    /// Grid step (mm or deg) of an equidistant table; default: the measured targets where
    /// the controller takes any points, else their mean spacing.
    #[arg(long)]
    interval: Option<f64>,
    /// Reference point (mm or deg): the grid passes through it and the correction is zero
    /// there; default: the first grid point, corrections as measured.
    #[arg(long)]
    reference: Option<f64>,
    /// Lead-screw or encoder pitch (mm or deg), for the warning on periodic error.
    #[arg(long)]
    pitch: Option<f64>,
    /// The axis's name on the controller, for formats that name it (HEIDENHAIN `X`,
    /// Siemens `X1`); default: a placeholder in the file to replace.
    #[arg(long)]
    axis: Option<String>,
}

impl From<TableArgs> for compensate::Settings {
    fn from(a: TableArgs) -> compensate::Settings {
        compensate::Settings {
            interval: a.interval,
            reference: a.reference,
            pitch: a.pitch,
            axis: a.axis,
        }
    }
}

/// What `compensate` was asked for.
pub struct Request<'a> {
    pub controller: &'a str,
    pub out: Option<&'a Path>,
    pub settings: compensate::Settings,
    pub standard: StandardId,
    pub json: bool,
}

/// `--json`: the table, and the parameters as measured and predicted.
#[derive(Serialize)]
struct CompensationJson<'a> {
    controller: &'a str,
    /// Deviation unit of the corrections and parameters: `um` or `arcsec`.
    unit: &'static str,
    table: &'a Table,
    measured: Parameters<'a>,
    predicted: Parameters<'a>,
    /// Why the table may not achieve the prediction on the machine.
    warnings: &'a [Warning],
    /// The table file written, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<String>,
}

#[derive(Serialize)]
struct Parameters<'a> {
    parameters: ParameterValues<'a>,
}

/// Writes the table (to `out`, or standard output without it) and returns what to print;
/// the warnings go to standard error when the table goes to standard output.
pub fn run(data: &AxisData, request: &Request) -> Result<String> {
    let controller = controllers::find(request.controller).ok_or_else(|| {
        anyhow!(
            "unknown controller `{}`; known: {}",
            request.controller,
            controllers::names().join(", ")
        )
    })?;
    if let Some(step) = request.settings.interval
        && !(step > 0.0 && step.is_finite())
    {
        return Err(anyhow!("--interval: expected a step > 0, got {step}"));
    }
    let options = axcheck::diagnose::Options {
        pitch: request.settings.pitch,
        standard: request.standard,
        ..Default::default()
    };
    let diagnosis = axcheck::diagnose::diagnose(data, &options);
    let c = compensate::compensation(
        controller,
        data,
        request.standard,
        &request.settings,
        &diagnosis,
    );
    let done = c.outcome.map_err(|refused| anyhow!(refused))?;
    if let Some(out) = request.out {
        axcheck::atomic::write(out, done.file.as_bytes())
            .with_context(|| format!("cannot write {}", out.display()))?;
    }
    let measured = axcheck::evaluate::evaluate(data, request.standard);
    if request.json {
        let json = CompensationJson {
            controller: controller.name(),
            unit: data.kind.deviation_unit(),
            table: &done.table,
            measured: Parameters {
                parameters: ParameterValues(&measured.parameters),
            },
            predicted: Parameters {
                parameters: ParameterValues(&done.predicted.parameters),
            },
            warnings: &c.warnings,
            file: request.out.map(|p| p.display().to_string()),
        };
        return Ok(serde_json::to_string_pretty(&json)? + "\n");
    }
    Ok(match request.out {
        None => {
            for w in &c.warnings {
                eprintln!("axcheck: warning: {}", w.message);
            }
            done.file
        }
        Some(out) => {
            let mut text = summary(&measured, &done.predicted, data, out, controller.name());
            for w in &c.warnings {
                let _ = writeln!(text, "Warning: {}", w.message);
            }
            text
        }
    })
}

/// The parameters before and after, and where the table went.
fn summary(
    measured: &Evaluation,
    predicted: &Evaluation,
    data: &AxisData,
    out: &Path,
    controller: &str,
) -> String {
    let unit = data.kind.deviation_symbol();
    let mut text = format!("{controller} table written to {}\n\n", out.display());
    let _ = writeln!(
        text,
        "{}  {}  {}",
        left("Parameter", 10),
        right(&format!("measured ({unit})"), 16),
        right(&format!("predicted ({unit})"), 17)
    );
    for m in &measured.parameters {
        let after = predicted.parameter(m.key()).map_or(f64::NAN, |q| q.value);
        let _ = writeln!(
            text,
            "{}  {}  {}",
            left(m.symbol(), 10),
            right(&fmt_fixed(m.value, 2), 16),
            right(&fmt_fixed(after, 2), 17)
        );
    }
    text.push_str(
        "\nThe floor is the repeatability: a table corrects the mean deviations, not the scatter about them.\n",
    );
    text
}
