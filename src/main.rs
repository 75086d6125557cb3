//! The `axcheck` command.

mod cli;

use anyhow::{Context, Result};
use axcheck::evaluate::StandardId;
use axcheck::simulate::SimulationFile as _;
use clap::{Parser, Subcommand};
use cli::print;
use std::path::PathBuf;
use std::process::ExitCode;

/// mimalloc: a fleet's run allocates and frees millions of small blocks (fields, results)
/// across worker threads; glibc's malloc spent a fifth of `check`'s time on it and on
/// zeroing pages it did not reuse (measured in bench/fleet.sh).
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

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
    Eval(cli::eval::EvalArgs),
    /// Evaluate a whole campaign and write its outputs (exit 0: all pass, 1: any axis
    /// fails, is noncompliant or has an error, 2: the campaign cannot be read).
    Run(cli::campaign::RunArgs),
    /// The CI gate: evaluate a campaign and write nothing (exit 0: every axis passes,
    /// 1: any axis fails, is noncompliant or has an error, 2: the campaign cannot be read).
    Check(cli::campaign::CheckArgs),
    /// Check that a run's outputs follow from its inputs: every input recorded in its
    /// results.json checked by its SHA-256, then the campaign run again the same way into a
    /// temporary folder and every output compared byte for byte (exit 0: identical, 1: an
    /// input changed or an output differs, 2: the run or an input cannot be read).
    Reproduce(cli::reproduce::ReproduceArgs),
    /// Model check and diagnosis of a measurement file: what the standard's model of the
    /// axis gets wrong (drift, warm-up, thermal growth, run offsets, periodic error, reversal or
    /// scatter varying along the axis, outliers), with evidence and the held-out gain; several
    /// files of one axis are each also predicted from the others.
    #[command(mut_arg(cli::ECMC_REFERENCE, |a| a.visible_alias(cli::REFERENCE_ALIAS)))]
    Diagnose {
        /// Measurement files (long or wide CSV, XLSX workbook, or ecmc key=value): one
        /// test, or several tests of one axis, each then also predicted by the models
        /// fitted on each other test.
        #[arg(required = true, value_name = "FILE")]
        files: Vec<PathBuf>,
        #[command(flatten)]
        sheet: cli::SheetArg,
        /// Standard for the parameters shown as measured and with effects removed.
        #[arg(long, short, default_value = "iso230-2", value_parser = cli::parse_standard)]
        standard: StandardId,
        /// Lead-screw or encoder pitch (mm or deg), tested as a candidate period.
        #[arg(long, allow_negative_numbers = true, value_parser = cli::parse_pitch)]
        pitch: Option<f64>,
        /// Where a thermal growth holds still (mm or deg: the lead screw's fixed bearing or
        /// the scale's fixing point); tells a drift from a growth about another origin.
        #[arg(long, allow_negative_numbers = true, value_parser = cli::parse_position)]
        thermal_origin: Option<f64>,
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
    Trend(cli::trend::TrendArgs),
    /// The controller's compensation table for a measured axis (the correction it adds:
    /// minus the mean deviation at each point and direction) and the parameters predicted
    /// with it. Without --out the table goes to standard output.
    Compensate(cli::compensate::CompensateArgs),
    /// The test plan of an axis before the laser is set up: the targets the standard asks
    /// for, checked by the test-plan rules; with --program the part program that runs it,
    /// and the target list for the laser software.
    Plan(Box<cli::plan::PlanArgs>),
    /// Compare the re-measurement after a table was loaded with the prediction from the
    /// measurement before and the table: effective, partly effective, not effective or
    /// made worse, and what went wrong (exit 0: effective, 1: not, 2: an input cannot be
    /// read).
    Verify(cli::verify::VerifyArgs),
    /// Simulate a positioning test from an error model and a test plan (YAML), or with
    /// --fleet a whole synthetic campaign for benchmarks.
    Simulate(cli::simulate::SimulateArgs),
}

/// mimalloc's `mi_option_purge_delay` (mimalloc.h, v3: the 16th option).
const MI_OPTION_PURGE_DELAY: libmimalloc_sys::mi_option_t = 15;

/// How soon mimalloc gives freed memory back to the system, by command (its default
/// otherwise: after 10 ms). `run` keeps it: it builds a report after another, and pages
/// given back are zeroed by the kernel again when taken back (a tenth of its time on 200
/// axes). `check` keeps it too: on 10 000 axes it gave back 12–15 MB in 80–180 calls
/// (the campaign's parse tree, each file's text) only to take as much again, and its
/// system time fell from 0.16–0.22 s to 0.12–0.14 s. `trend` gives it back at once: it
/// reads a history file by file, and kept pages raised its peak from 0.16 to 0.24 GB on
/// ten inspections of 10 000 axes.
fn purge_delay_ms(command: &Command) -> Option<i64> {
    match command {
        Command::Run(_) | Command::Check(_) => Some(-1),
        Command::Trend(_) => Some(0),
        _ => None,
    }
}

/// Whether the command turns transparent huge pages off for the process. The gate and
/// the run touch their memory once: each huge page is 2 MB zeroed at its first touch,
/// and after another large process (the fleet bench's pandas peer, a CI job before) the
/// kernel compacts memory to find one, which made the gate's time on 10 000 axes range
/// from 0.22 to 0.36 s; with small pages it stayed at 0.23–0.25 s, and the run's system
/// time on 1 000 axes with reports fell from 1.5 to 0.6 s (bench/results.md).
#[cfg(target_os = "linux")]
fn small_pages_only(command: &Command) -> bool {
    matches!(command, Command::Check(_) | Command::Run(_))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(ms) = purge_delay_ms(&cli.command) {
        // SAFETY: sets a global option before any worker thread starts; any value is
        // valid (mimalloc reads it at each purge).
        unsafe { libmimalloc_sys::mi_option_set(MI_OPTION_PURGE_DELAY, ms as _) };
    }
    #[cfg(target_os = "linux")]
    if small_pages_only(&cli.command) {
        // Applies to the memory mapped already too; where the call is refused (an old
        // kernel, a sandbox) huge pages stay on, which is only slower.
        let _ = rustix::thread::disable_transparent_huge_pages(true);
    }
    axcheck::panics::install_quiet_hook();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            cli::tell(&format!("axcheck: error: {e:#}"));
            ExitCode::from(2)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode> {
    // One pool for the whole process: --jobs workers evaluate the axes (0: one per core);
    // reports are typeset by as many workers of their own (export::pdf), so --jobs bounds
    // both. Large stacks, as Typst's layout recurses deeply.
    let mut cli = cli;
    let jobs = match &mut cli.command {
        Command::Run(args) => Some(&mut args.jobs),
        Command::Check(args) => Some(&mut args.jobs),
        Command::Reproduce(args) => Some(&mut args.jobs),
        _ => None,
    };
    if let Some(jobs) = jobs {
        *jobs = cli::capped_jobs(*jobs);
        let jobs = *jobs;
        rayon::ThreadPoolBuilder::new()
            .num_threads(jobs)
            .stack_size(64 << 20)
            .build_global()
            .context("cannot start the worker threads")?;
    }
    match cli.command {
        Command::Eval(args) => print(&cli::eval::run(&args)?)?,
        Command::Run(args) => return Ok(ExitCode::from(cli::campaign::run_command(&args)?)),
        Command::Check(args) => return Ok(ExitCode::from(cli::campaign::check_command(&args)?)),
        Command::Reproduce(args) => return Ok(ExitCode::from(cli::reproduce::command(&args)?)),
        Command::Diagnose {
            files,
            sheet,
            standard,
            pitch,
            thermal_origin,
            simulations,
            seed,
            write_model,
            json,
        } => {
            let options = axcheck::diagnose::Options {
                pitch,
                thermal_origin,
                simulations,
                seed,
                standard,
            };
            let read = sheet.options();
            let outcome = cli::diagnose::run(&files, &read, &options, json, write_model.is_some())?;
            let written = (write_model.as_deref())
                .zip(outcome.extended_model.as_ref())
                .map(|(path, model)| write_extended_model(path, model));
            // The diagnosis is printed even when its model could not be written.
            print(&outcome.text)?;
            written.transpose()?;
        }
        #[cfg(feature = "parquet")]
        Command::Trend(args) => print(&cli::trend::run(&args)?)?,
        Command::Compensate(args) => print(&cli::compensate::command(args)?)?,
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
    cli::tell(&format!(
        "axcheck: wrote the extended model to {}",
        path.display()
    ));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::Cli;
    use clap::CommandFactory;

    /// clap's own checks of the whole tree: no long or short name, alias or id that two
    /// options of a command share, no conflict or requirement naming no option, … A
    /// release build would parse past such a defect (two `--reference` options made clap
    /// hand a position to the ecmc one); Cargo.toml keeps clap's checks in release builds.
    #[test]
    fn the_command_tree_passes_clap_checks() {
        Cli::command().debug_assert();
    }

    /// The check above can fail in the build the tests run in: a command with one long
    /// name on two options panics.
    #[test]
    fn clap_checks_are_compiled_in() {
        let caught = std::panic::catch_unwind(|| {
            clap::Command::new("twice")
                .arg(clap::Arg::new("a").long("reference"))
                .arg(clap::Arg::new("b").long("reference"))
                .debug_assert()
        });
        assert!(caught.is_err(), "clap's checks are not compiled in");
    }

    /// One row of the README's command table: the command and its options, each with
    /// whether the README shows a value after it.
    #[derive(Debug)]
    struct Row {
        command: String,
        options: Vec<(String, bool)>,
    }

    /// The rows of the `| command | what it does |` table of `readme`.
    fn command_table(readme: &str) -> Vec<Row> {
        let mut lines = readme.lines().skip_while(|l| !l.starts_with("| command |"));
        lines.next();
        lines
            .take_while(|l| l.starts_with('|'))
            .filter_map(|l| l.split('`').nth(1))
            .map(row)
            .collect()
    }

    /// `axcheck run CAMPAIGN [--out DIR] [--wait]` → run, [(out, true), (wait, false)].
    fn row(cell: &str) -> Row {
        let tokens: Vec<&str> = cell.split_whitespace().collect();
        let mut options = Vec::new();
        for (i, token) in tokens.iter().enumerate() {
            let bare = token.trim_start_matches(['[', '(']);
            let Some(name) = bare.strip_prefix("--") else {
                continue;
            };
            let name: String = name
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '-')
                .collect();
            let closed = bare.ends_with([']', ')']);
            let value = !closed
                && tokens
                    .get(i + 1)
                    .is_some_and(|next| !next.starts_with(['[', '(', '-', '\\', '…', '|']));
            options.push((name, value));
        }
        Row {
            command: tokens[1].to_string(),
            options,
        }
    }

    /// Every `--option` of every row of the README's command table is one option of that
    /// command (by its name or an alias, never two options), taking a value where the
    /// README shows one and none where it shows none.
    #[test]
    fn every_option_in_the_readme_command_table_is_accepted() {
        let readme = include_str!("../README.md");
        let rows = command_table(readme);
        assert!(rows.len() >= 9, "the command table has {} rows", rows.len());
        let tree = Cli::command();
        let mut checked = 0;
        for r in &rows {
            let cmd = tree
                .find_subcommand(&r.command)
                .unwrap_or_else(|| panic!("README names `axcheck {}`: no such command", r.command));
            for (name, value) in &r.options {
                let named: Vec<&clap::Arg> = cmd
                    .get_arguments()
                    .filter(|a| {
                        a.get_long() == Some(name.as_str())
                            || a.get_all_aliases()
                                .is_some_and(|x| x.contains(&name.as_str()))
                    })
                    .collect();
                let [arg] = named.as_slice() else {
                    panic!(
                        "`axcheck {} --{name}`: {} options have that name",
                        r.command,
                        named.len()
                    );
                };
                assert_eq!(
                    arg.get_action().takes_values(),
                    *value,
                    "`axcheck {} --{name}`: the README shows {} value",
                    r.command,
                    if *value { "a" } else { "no" }
                );
                checked += 1;
            }
        }
        assert!(checked >= 60, "{checked} options checked");
    }

    #[test]
    fn a_table_row_gives_its_options() {
        let r = row(
            "axcheck plan (--kind linear\\|rotary \\| --from PLAN.yaml) [-o OUT] [--program CONTROL --axis NAME] [--json] [--other AXIS=TABLE …]",
        );
        assert_eq!(r.command, "plan");
        let want = [
            ("kind", true),
            ("from", true),
            ("program", true),
            ("axis", true),
            ("json", false),
            ("other", true),
        ];
        let got: Vec<(&str, bool)> = r.options.iter().map(|(n, v)| (n.as_str(), *v)).collect();
        assert_eq!(got, want);
    }
}
