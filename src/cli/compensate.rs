//! `axcheck compensate`: the controller's correction table for a measured axis, and the
//! parameters predicted with it.

use super::text::{left, right};
use anyhow::{Context, Result, anyhow};
use axcheck::campaign::stages::compensate as stages;
use axcheck::compensate::controllers::{self, Controller};
use axcheck::compensate::json::TableJson;
use axcheck::compensate::{self, Mode, Table};
use axcheck::evaluate::Evaluation;
use axcheck::evaluate::StandardId;
use axcheck::measurement::AxisData;
use axcheck::units::{AxisKind, fmt_fixed};
use std::fmt::Write;
use std::path::Path;

/// The table's grid and naming (`--interval`, `--reference`, `--pitch`, `--axis`).
#[derive(Debug, clap::Args)]
pub struct TableArgs {
    /// Grid step (mm or deg) of an equidistant table; default: the measured targets where
    /// the controller takes any points, else their mean spacing.
    #[arg(long)]
    pub interval: Option<f64>,
    /// Reference point (mm or deg): the grid passes through it and the correction is zero
    /// there; default: the first grid point, corrections as measured.
    #[arg(long, value_name = "POS", allow_negative_numbers = true)]
    pub reference: Option<f64>,
    /// Lead-screw or encoder pitch (mm or deg), for the warning on periodic error.
    #[arg(long, allow_negative_numbers = true, value_parser = super::parse_pitch)]
    pub pitch: Option<f64>,
    /// The axis's name on the controller, for formats that name it (HEIDENHAIN `X`,
    /// Siemens `X1`, TwinCAT its logical number `2`) and to pick its table from an active
    /// file of several; default: the active table's, else a placeholder in the file that
    /// the control cannot load, to replace.
    #[arg(long)]
    pub axis: Option<String>,
    /// Siemens: the measuring system, 0 (the first encoder) or 1 (a direct measuring
    /// system the axis is closed on); default: the active table's, else 0.
    #[arg(long, value_parser = clap::value_parser!(u8).range(0..=1))]
    pub measuring_system: Option<u8>,
    /// The table active during the measurement, in the controller's format, or `none`:
    /// the table written is then the active one plus this measurement's correction.
    /// Without it the state is unknown, and a warning says to add the values to whatever
    /// was active.
    #[arg(long, value_name = "TABLE|none")]
    pub active: Option<String>,
    /// The backlash parameter active during the measurement, µm or arcsec (Siemens
    /// MD32450, LinuxCNC BACKLASH without a table, …).
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub active_backlash: Option<f64>,
}

impl TableArgs {
    /// The settings, with the active table read as `controller` reads it for an axis of
    /// `kind`.
    pub fn settings(
        self,
        controller: &dyn Controller,
        kind: AxisKind,
    ) -> Result<compensate::Settings> {
        let place = compensate::TableSlot {
            axis: self.axis,
            measuring_system: self.measuring_system,
            number: None,
        };
        let active = active_state(
            self.active.as_deref(),
            self.active_backlash,
            controller,
            kind,
            place.axis.as_deref(),
        )?;
        Ok(compensate::Settings {
            interval: self.interval,
            reference: self.reference,
            pitch: self.pitch,
            place,
            active,
            conditions: None,
        })
    }
}

/// The active state given on the command line: `None` when neither `--active` nor
/// `--active-backlash` says anything; `--active none` is a backlash without a table.
pub fn active_state(
    table: Option<&str>,
    backlash: Option<f64>,
    controller: &dyn Controller,
    kind: AxisKind,
    axis: Option<&str>,
) -> Result<Option<compensate::Active>> {
    if let Some(b) = backlash
        && !b.is_finite()
    {
        return Err(anyhow!("--active-backlash: expected a number, got {b}"));
    }
    let given = stages::given_active_state(table, backlash, "--active", controller, kind, axis);
    Ok(given?)
}

/// A table file given as the option `key`, read as `controller` reads it.
pub fn read_table(
    path: &Path,
    key: &'static str,
    controller: &dyn Controller,
    kind: AxisKind,
    axis: Option<&str>,
) -> Result<Table> {
    let at = stages::TableFile::Given { path, key };
    Ok(stages::read_table(at, controller, kind, axis)?)
}

/// The controller called `name`, or the error that lists the known ones.
pub fn controller(name: &str) -> Result<&'static dyn Controller> {
    controllers::find(name).ok_or_else(|| {
        anyhow!(
            "unknown controller `{name}`; known: {}",
            controllers::names().join(", ")
        )
    })
}

/// `axcheck compensate`'s arguments.
#[derive(clap::Args)]
pub struct CompensateArgs {
    /// Measurement file (any layout `eval` reads).
    file: std::path::PathBuf,
    #[command(flatten)]
    sheet: super::SheetArg,
    /// Controller whose table format to write: csv, linuxcnc, siemens-840d, fanuc,
    /// heidenhain, twincat, ecmc (10.0.0 and later), ecmc-9.6.
    #[arg(long, short)]
    controller: String,
    /// LinuxCNC: the file's COMP_FILE_TYPE, 0 (nominal, forward and reverse actual
    /// position; LinuxCNC's default) or 1 (nominal and trims); the file's notes and the
    /// listing name the INI lines to set.
    #[arg(long, value_name = "0|1", value_parser = clap::value_parser!(u8).range(0..=1))]
    comp_file_type: Option<u8>,
    /// Table file to write (then a summary of measured and predicted parameters is
    /// printed).
    #[arg(long, short)]
    out: Option<std::path::PathBuf>,
    #[command(flatten)]
    table: TableArgs,
    #[command(flatten)]
    cross: super::cross::CrossArgs,
    /// Standard for the parameters measured and predicted.
    #[arg(long, short, default_value = "iso230-2", value_parser = super::parse_standard)]
    standard: StandardId,
    /// Print JSON: the table and the parameters measured and predicted.
    #[arg(long)]
    json: bool,
}

/// `axcheck compensate`: reads the file, writes the table; the text to print.
pub fn command(args: CompensateArgs) -> Result<String> {
    if args.cross.is_cross()? {
        return cross(&args);
    }
    let controller =
        controllers::with_comp_file_type(controller(&args.controller)?, args.comp_file_type)
            .map_err(|e| anyhow!("--comp-file-type: {e}"))?;
    let read = axcheck::measurement::read_file_with(&args.file, &args.sheet.options())?;
    if let Some(note) = reference_note(&read.recognised.layout, &args) {
        super::tell(&format!("axcheck: note: {note}"));
    }
    let data = read.data;
    let request = Request {
        controller,
        out: args.out.as_deref(),
        settings: args.table.settings(controller, data.kind)?,
        standard: args.standard,
        json: args.json,
    };
    run(&data, &request)
}

/// `compensate --test straightness`: a cross table; the pitch table's options refused.
fn cross(args: &CompensateArgs) -> Result<String> {
    let t = &args.table;
    let pitch_only = [
        ("--reference", t.reference.is_some()),
        ("--pitch", t.pitch.is_some()),
        ("--axis", t.axis.is_some()),
        ("--measuring-system", t.measuring_system.is_some()),
        ("--active-backlash", t.active_backlash.is_some()),
        ("--comp-file-type", args.comp_file_type.is_some()),
    ];
    if let Some((option, _)) = pitch_only.iter().find(|(_, given)| *given) {
        return Err(anyhow!(
            "{option} applies to a positioning test's table, not to a cross table (--test straightness names its axes with --input and --output)"
        ));
    }
    super::cross::compensate_command(super::cross::CompensateCross {
        file: &args.file,
        sheet: args.sheet.options(),
        controller: &args.controller,
        out: args.out.as_deref(),
        interval_mm: t.interval,
        active: t.active.as_deref(),
        json: args.json,
        cross: &args.cross,
    })
}

/// On an ecmc ISO 230 app file, `--reference 1` to `5` without `--ecmc-reference` may be
/// meant as the file's reference (`--reference N` was that option's name): say what it is.
fn reference_note(layout: &axcheck::measurement::Layout, args: &CompensateArgs) -> Option<String> {
    use axcheck::measurement::Layout;
    let at = args.table.reference?;
    let ecmc = matches!(layout, Layout::EcmcAppReport | Layout::EcmcAppCsv);
    let like_source = at.fract() == 0.0 && (1.0..=5.0).contains(&at);
    (ecmc && like_source && !args.sheet.names_source()).then(|| {
        format!(
            "--reference {at} is the table's reference point ({at} on the axis); the file's reference {at} is read with --ecmc-reference {at}"
        )
    })
}

/// What `compensate` was asked for.
pub struct Request<'a> {
    pub controller: &'static dyn Controller,
    pub out: Option<&'a Path>,
    pub settings: compensate::Settings,
    pub standard: StandardId,
    pub json: bool,
}

/// Writes the table (to `out`, or standard output without it) and returns what to print;
/// the warnings go to standard error when the table goes to standard output.
pub fn run(data: &AxisData, request: &Request) -> Result<String> {
    let controller = request.controller;
    if let Some(step) = request.settings.interval
        && !(step > 0.0 && step.is_finite())
    {
        return Err(anyhow!("--interval: expected a step > 0, got {step}"));
    }
    let (c, measured) =
        compensate::of_measurement(controller, data, request.standard, &request.settings);
    let done = c
        .outcome
        .as_ref()
        .map_err(|refused| anyhow!(refused.clone()))?;
    if let Some(out) = request.out {
        axcheck::atomic::write(out, done.file.as_bytes())
            .with_context(|| format!("cannot write {}", out.display()))?;
    }
    if request.json {
        let unit = data.kind.deviation_unit();
        let file = request.out.map(|p| p.display().to_string());
        let json = TableJson::new(&c, done, &measured, unit, file);
        return Ok(serde_json::to_string_pretty(&json)? + "\n");
    }
    Ok(match request.out {
        None => {
            for w in &c.warnings {
                super::tell(&format!("axcheck: warning: {}", w.message));
            }
            done.file.clone()
        }
        Some(out) => {
            let mut text = format!(
                "{} table written to {} ({})\n",
                controller.name(),
                out.display(),
                mode_words(c.mode, c.active_file.as_deref())
            );
            for line in &c.loading {
                let _ = writeln!(
                    text,
                    "{}",
                    line.replace("<file>", &out.display().to_string())
                );
            }
            text.push('\n');
            text.push_str(&summary(&measured, &done.predicted, data));
            for w in &c.warnings {
                let _ = writeln!(text, "Warning: {}", w.message);
            }
            text
        }
    })
}

/// What the table is: the whole correction or the active one plus this measurement's.
fn mode_words(mode: Mode, active: Option<&str>) -> String {
    match (mode, active) {
        (Mode::Incremental, Some(file)) => {
            format!("incremental: the active table {file} plus this measurement's correction")
        }
        (Mode::Incremental, None) => {
            "incremental: the active backlash plus this measurement's correction".into()
        }
        (Mode::Absolute, _) => "absolute: this measurement's correction alone".into(),
    }
}

/// The parameters measured and predicted.
fn summary(measured: &Evaluation, predicted: &Evaluation, data: &AxisData) -> String {
    let unit = data.kind.deviation_symbol();
    let mut text = String::new();
    let _ = writeln!(
        text,
        "{}  {}  {}",
        left("Parameter", 10),
        right(&format!("measured ({unit})"), 16),
        right(&format!("predicted ({unit})"), 17)
    );
    for m in &measured.parameters {
        let after = predicted.parameter(m.def.key).map_or(f64::NAN, |q| q.value);
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
