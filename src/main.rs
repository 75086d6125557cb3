//! The `axcheck` command.

mod cli;

use anyhow::{Context, Result, bail};
use axcheck::evaluate::{Standard, StandardId, gost27843};
use axcheck::measurement;
use clap::{Parser, Subcommand};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

/// Positioning accuracy and repeatability of NC machine-tool axes (ISO 230-2 / GB/T
/// 17421.2, GOST 27843, VDI 3441, NMTBA).
#[derive(Parser)]
#[command(name = "axcheck", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate one measurement file: the axis parameters and the per-target table.
    Eval {
        /// Measurement file (long or wide CSV, XLSX workbook, or ecmc key=value; the
        /// layout is recognised from the content).
        file: PathBuf,
        #[command(flatten)]
        sheet: cli::SheetArg,
        /// Standard: iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba.
        #[arg(long, short, default_value = "iso230-2", value_parser = parse_standard)]
        standard: StandardId,
        /// GOST 27843 only: estimate S from the ranges, formula (6), instead of formula (5).
        #[arg(long)]
        s_from_ranges: bool,
        /// Print JSON (a stable interface) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Evaluate a whole campaign and write its outputs (exit 0: all pass, 1: any axis
    /// fails, is noncompliant or has an error, 2: the campaign cannot be read).
    Run {
        /// Campaign file (YAML).
        campaign: PathBuf,
        /// Output folder.
        #[arg(long, short, default_value = "out")]
        out: PathBuf,
        /// Worker threads (default: all cores).
        #[arg(long, short, default_value_t = 0)]
        jobs: usize,
        /// Write no PDF reports.
        #[arg(long)]
        no_pdf: bool,
        /// Write no summary.html.
        #[arg(long)]
        no_html: bool,
        /// Skip the model check and diagnosis of each axis.
        #[arg(long)]
        no_diagnose: bool,
        /// Folder with a customised copy of the report templates (templates/).
        #[arg(long)]
        templates: Option<PathBuf>,
        /// A progress line for every finished test on stderr (without a terminal the
        /// default is a line at every tenth of the campaign).
        #[arg(long)]
        progress: bool,
        /// Append the run's results to the inspection history in this folder (default:
        /// `campaign.history`, relative to the campaign file).
        #[arg(long)]
        history: Option<PathBuf>,
        /// Years after the latest inspection within which a forecast crossing of a limit
        /// is flagged (default: `campaign.trend_horizon_years`, else 2).
        #[arg(long = "horizon")]
        horizon_years: Option<f64>,
        /// When another run is writing to the output (or history) folder, wait for it to
        /// finish instead of stopping at once.
        #[arg(long)]
        wait: bool,
    },
    /// The CI gate: evaluate a campaign and write nothing (exit 0: every axis passes,
    /// 1: any axis fails, is noncompliant or has an error, 2: the campaign cannot be read).
    Check {
        /// Campaign file (YAML).
        campaign: PathBuf,
        /// Worker threads (default: all cores).
        #[arg(long, short, default_value_t = 0)]
        jobs: usize,
        /// Also run the model check and diagnosis (slower; `run` does it by default).
        #[arg(long)]
        diagnose: bool,
        /// A progress line for every finished test on stderr (without a terminal the
        /// default is a line at every tenth of the campaign).
        #[arg(long)]
        progress: bool,
    },
    /// Model check and diagnosis of one measurement file: what the standard's model of the
    /// axis gets wrong (drift, warm-up, thermal growth, run offsets, periodic error, reversal or
    /// scatter varying along the axis, outliers), with evidence and the held-out gain.
    Diagnose {
        /// Measurement file (long or wide CSV, XLSX workbook, or ecmc key=value).
        file: PathBuf,
        #[command(flatten)]
        sheet: cli::SheetArg,
        /// Standard for the parameters shown as measured and with effects removed.
        #[arg(long, short, default_value = "iso230-2", value_parser = parse_standard)]
        standard: StandardId,
        /// Lead-screw or encoder pitch (mm or deg), tested as a candidate period.
        #[arg(long)]
        pitch: Option<f64>,
        /// Tests simulated from the fitted base model for the model check.
        #[arg(long, default_value_t = 200)]
        simulations: usize,
        /// Seed of the simulations.
        #[arg(long, default_value_t = 0)]
        seed: u64,
        /// Write the extended model as a simulation file that `axcheck simulate` accepts.
        #[arg(long)]
        write_model: Option<PathBuf>,
        /// Print JSON (a stable interface) instead of text.
        #[arg(long)]
        json: bool,
    },
    /// Follow every machine, axis and parameter across the inspections of a history
    /// (`run --history DIR`): slope per year (Theil–Sen), the date it reaches its limit,
    /// and the series that will cross within the horizon or are worsening.
    #[cfg(feature = "parquet")]
    Trend(cli::trend::Args),
    /// The controller's compensation table for a measured axis (the correction it adds:
    /// minus the mean deviation at each point and direction) and the parameters predicted
    /// with it. Without --out the table goes to standard output.
    Compensate {
        /// Measurement file (long or wide CSV, XLSX workbook, or ecmc key=value).
        file: PathBuf,
        #[command(flatten)]
        sheet: cli::SheetArg,
        /// Controller whose table format to write: csv, linuxcnc, siemens-840d, fanuc,
        /// heidenhain, twincat, ecmc (10.0.0 and later), ecmc-9.6.
        #[arg(long, short)]
        controller: String,
        /// Table file to write (then a summary of measured and predicted parameters is
        /// printed).
        #[arg(long, short)]
        out: Option<PathBuf>,
        #[command(flatten)]
        table: cli::compensate::TableArgs,
        /// Standard for the parameters measured and predicted.
        #[arg(long, short, default_value = "iso230-2", value_parser = parse_standard)]
        standard: StandardId,
        /// Print JSON: the table and the parameters measured and predicted.
        #[arg(long)]
        json: bool,
    },
    /// The test plan of an axis before the laser is set up: the targets the standard asks
    /// for, checked by the test-plan rules; with --program the part program that runs it,
    /// and the target list for the laser software.
    Plan(Box<cli::plan::Args>),
    /// Compare the re-measurement after a table was loaded with the prediction from the
    /// measurement before and the table: effective, partly effective, not effective or
    /// made worse, and what went wrong (exit 0: effective, 1: not, 2: an input cannot be
    /// read).
    Verify(cli::verify::Args),
    /// Simulate a positioning test from an error model and a test plan (YAML), or with
    /// --fleet a whole synthetic campaign for benchmarks.
    Simulate(cli::simulate::Args),
}

pub(crate) fn parse_standard(text: &str) -> Result<StandardId, String> {
    StandardId::parse(text).ok_or_else(|| {
        format!(
            "unknown standard `{text}`; expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba"
        )
    })
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    axcheck::panics::install_quiet_hook();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("axcheck: error: {e:#}");
            ExitCode::from(2)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode> {
    // One pool for the whole process: --jobs workers evaluate the axes (0: one per core);
    // reports are typeset by as many workers of their own (export::pdf), so --jobs bounds
    // both. Large stacks, as Typst's layout recurses deeply.
    if let Command::Run { jobs, .. } | Command::Check { jobs, .. } = &cli.command {
        rayon::ThreadPoolBuilder::new()
            .num_threads(*jobs)
            .stack_size(64 << 20)
            .build_global()
            .context("cannot start the worker threads")?;
    }
    match cli.command {
        Command::Eval {
            file,
            sheet,
            standard,
            s_from_ranges,
            json,
        } => eval(&file, &sheet, standard, s_from_ranges, json)?,
        Command::Run {
            campaign,
            out,
            jobs,
            no_pdf,
            no_html,
            no_diagnose,
            templates,
            progress,
            history,
            horizon_years,
            wait,
        } => {
            let options = cli::campaign::RunOptions {
                out: &out,
                jobs,
                no_pdf,
                no_html,
                no_diagnose,
                templates: templates.as_deref(),
                progress: progress_of(progress),
                history: history.as_deref(),
                horizon_years,
                wait,
            };
            return Ok(ExitCode::from(cli::campaign::run(&campaign, &options)?));
        }
        Command::Check {
            campaign,
            jobs,
            diagnose,
            progress,
        } => {
            return Ok(ExitCode::from(cli::campaign::check(
                &campaign,
                jobs,
                diagnose,
                progress_of(progress),
            )?));
        }
        Command::Diagnose {
            file,
            sheet,
            standard,
            pitch,
            simulations,
            seed,
            write_model,
            json,
        } => {
            let data = measurement::read_file_with(&file, &sheet.options())?.data;
            let options = axcheck::diagnose::Options {
                pitch,
                simulations,
                seed,
                standard,
            };
            let diagnosis = axcheck::diagnose::diagnose(&data, &options);
            let written = write_model
                .as_deref()
                .map(|path| write_extended_model(path, &diagnosis.extended_model));
            let name = file.display().to_string();
            let text = if json {
                cli::json_with_file(&diagnosis, &name)?
            } else {
                cli::diagnose::render(&name, &diagnosis)
            };
            // The diagnosis is printed even when its model could not be written.
            print(&text)?;
            written.transpose()?;
        }
        #[cfg(feature = "parquet")]
        Command::Trend(args) => print(&cli::trend::run(&args)?)?,
        Command::Compensate {
            file,
            sheet,
            controller,
            out,
            table,
            standard,
            json,
        } => {
            let controller = cli::compensate::controller(&controller)?;
            let data = measurement::read_file_with(&file, &sheet.options())?.data;
            let request = cli::compensate::Request {
                controller,
                out: out.as_deref(),
                settings: table.settings(controller, data.kind)?,
                standard,
                json,
            };
            print(&cli::compensate::run(&data, &request)?)?;
        }
        Command::Plan(args) => print(&cli::plan::run(&args)?)?,
        Command::Verify(args) => {
            let (text, effective) = cli::verify::run(&args)?;
            print(&text)?;
            return Ok(ExitCode::from(if effective { 0 } else { 1 }));
        }
        Command::Simulate(args) => {
            if let Some(csv) = cli::simulate::command(&args)? {
                print(&csv)?;
            }
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// `axcheck eval`: the parameters of one file, and what it was read as.
fn eval(
    file: &std::path::Path,
    sheet: &cli::SheetArg,
    standard: StandardId,
    s_from_ranges: bool,
    json: bool,
) -> Result<()> {
    if s_from_ranges && standard != StandardId::Gost27843 {
        bail!("--s-from-ranges applies to --standard gost27843 only");
    }
    let measurement::ReadTest { data, recognised } =
        measurement::read_file_with(file, &sheet.options())?;
    let evaluation = if s_from_ranges {
        gost27843::Gost27843 {
            s_method: gost27843::SMethod::Ranges,
        }
        .evaluate(&data)
    } else {
        axcheck::evaluate::evaluate(&data, standard)
    };
    let name = file.display().to_string();
    let other = (recognised.reported.as_ref()).map(|r| axcheck::crosscheck::compare(r, &data));
    let text = if json {
        cli::json_with_read(&evaluation.json(), &name, &recognised, other.as_ref())?
    } else {
        cli::eval::render(&name, &recognised, &evaluation, other.as_ref())
    };
    print(&text)
}

fn progress_of(every_test: bool) -> cli::campaign::Progress {
    if every_test {
        cli::campaign::Progress::EveryTest
    } else {
        cli::campaign::Progress::Auto
    }
}

/// Writes `diagnose --write-model`'s file, only if `axcheck simulate` would accept it: a
/// model whose plan the simulator refuses (targets closer than the 0.001 it records) is
/// not written, and the error says why.
fn write_extended_model(
    path: &std::path::Path,
    model: &axcheck::simulate::Simulation,
) -> Result<()> {
    if let Err(why) = model.validate_as_written() {
        anyhow::bail!(
            "did not write the extended model to {}: `axcheck simulate` would refuse it: {why}",
            path.display()
        );
    }
    axcheck::atomic::write(path, model.to_yaml().as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))?;
    eprintln!("axcheck: wrote the extended model to {}", path.display());
    Ok(())
}

/// Prints to stdout; a closed pipe (`| head`) is not an error.
fn print(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => Ok(other?),
    }
}
