//! `axcheck reproduce`: a run's recorded inputs checked against their SHA-256, then the
//! campaign run again the same way into a temporary folder and every output compared
//! with the run's, byte for byte.

use anyhow::Result;
use axcheck::campaign::Campaign;
use axcheck::results::AxisTest;
use axcheck::session::compare::{Comparison, Difference, compare};
use axcheck::session::reproduce::{self, InputChange, Places, Scratch};
use axcheck::session::{self, RunOptions};
use std::path::{Path, PathBuf};

/// `axcheck reproduce`'s arguments.
#[derive(clap::Args)]
pub struct ReproduceArgs {
    /// The run: its results.json, the folder it wrote, or a PDF report in that folder.
    run: PathBuf,
    /// The campaign file, when it is not at the path `run` was given (taken from the
    /// current folder).
    #[arg(long, value_name = "FILE")]
    campaign: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long, short, default_value_t = 0)]
    pub jobs: usize,
}

/// What the re-run hears of: nothing but the locks.
struct Quiet;

impl session::Observer for Quiet {
    fn lock(&self, message: &str) {
        super::tell(&format!("axcheck: {message}"));
    }

    fn test_done(&self, _: &AxisTest) {}
}

/// `axcheck reproduce`: 0 when every output is identical, 1 when an input changed or an
/// output differs (the errors that stop it: 2).
pub fn command(args: &ReproduceArgs) -> Result<u8> {
    let recorded = reproduce::recorded(&args.run)?;
    let inputs = &recorded.inputs;
    super::say(&format!(
        "Run: {} (axcheck {}: {})",
        recorded.results.display(),
        inputs.axcheck,
        inputs.command
    ));
    let places = Places::of(inputs, &recorded.out, args.campaign.as_deref())?;
    super::say(&format!("Campaign: {}", places.campaign.display()));
    let changes = reproduce::check_inputs(inputs, &places)?;
    if !changes.is_empty() {
        super::say("Inputs changed since the run (nothing was run again):");
        for change in &changes {
            super::say(&change_line(change));
        }
        return Ok(1);
    }
    super::say(&format!(
        "Inputs: the {} files recorded are unchanged (SHA-256)",
        input_count(inputs)
    ));
    let same_version = inputs.axcheck == env!("CARGO_PKG_VERSION");
    if !same_version {
        super::say(&format!(
            "Note: the run was made by axcheck {}, this is axcheck {}: outputs may differ between versions (results.json names the version), and PDFs may differ in their bytes; PDFs whose bytes differ are compared by their text (pdftotext)",
            inputs.axcheck,
            env!("CARGO_PKG_VERSION")
        ));
    }
    let scratch = Scratch::new()?;
    rerun(&places, inputs, &scratch)?;
    let comparison = compare(&recorded.out, &scratch.dir.join("out"), same_version);
    Ok(print_comparison(
        &comparison,
        &recorded.out,
        &inputs.axcheck,
    ))
}

/// The campaign run again as recorded into `scratch/out`, on a copy of its history in
/// `scratch/history` (the user's history is never appended to).
fn rerun(places: &Places, inputs: &axcheck::inputs::Inputs, scratch: &Scratch) -> Result<()> {
    let campaign = Campaign::load(&places.campaign)?;
    let out = scratch.dir.join("out");
    let dir = places.campaign.parent().unwrap_or(Path::new(""));
    let args =
        super::campaign::RunArgs::recorded(places.campaign.clone(), dir, out, &inputs.options);
    let mut options: RunOptions = super::campaign::run_options(&args, &campaign)?;
    // As recorded, whatever the folders are called from here (the history is a copy).
    options.flags = inputs.options.clone();
    if let Some(history) = options.history.take() {
        let copy = scratch.dir.join("history");
        let n = reproduce::copy_history(&history, &copy)?;
        super::say(&format!(
            "History: run again on a copy of {} ({n} files); the history itself is not appended to",
            history.display()
        ));
        options.history = Some(copy);
    }
    let outcome = session::run(&campaign, &options, &Quiet)?;
    if let Some(Err(e)) = &outcome.appended {
        super::say(&format!(
            "Note: the re-run could not be appended to the copy of its history: {e}"
        ));
    }
    Ok(())
}

/// Every file recorded: the campaign's, the templates', the history's.
fn input_count(inputs: &axcheck::inputs::Inputs) -> usize {
    inputs.files.len()
        + inputs.templates.as_ref().map_or(0, |t| t.files.len())
        + inputs.history.as_ref().map_or(0, |h| h.files.len())
}

/// `  changed: data/x.csv (SHA-256 recorded 1a2b3c4d5e6f…, now 0f1e2d3c4b5a…)`.
fn change_line(change: &InputChange) -> String {
    let short = |sha: &str| format!("{}…", &sha[..sha.len().min(12)]);
    match change {
        InputChange::Changed {
            path,
            recorded,
            now,
        } => format!(
            "  changed: {path} (SHA-256 recorded {}, now {})",
            short(recorded),
            short(now)
        ),
        InputChange::Missing { path } => format!("  missing: {path}"),
        InputChange::Added { path } => {
            format!("  added: {path} (an inspection the run's trends did not include)")
        }
    }
}

/// Prints the comparison; the exit status (0: identical).
fn print_comparison(c: &Comparison, out: &Path, version: &str) -> u8 {
    if c.no_manifest {
        super::say(&format!(
            "Note: {} has no manifest (.axcheck-outputs): outputs there that the re-run does not write cannot be told from other files",
            out.display()
        ));
    }
    if c.incomplete {
        super::say(&format!(
            "Note: the manifest of {} says the run's outputs are incomplete (complete: false)",
            out.display()
        ));
    }
    if c.identical() {
        super::say(&format!(
            "identical: the {} outputs of the re-run are byte for byte those in {}",
            c.compared,
            out.display()
        ));
        return 0;
    }
    let extra = (c.differences.iter())
        .filter(|d| matches!(d, Difference::Extra(_)))
        .count();
    let differing = c.differences.len() - extra + c.same_text.len();
    let extra = match extra {
        0 => String::new(),
        1 => ", and 1 output of the run is not written by the re-run".to_string(),
        n => format!(", and {n} outputs of the run are not written by the re-run"),
    };
    super::say(&format!(
        "not identical: {differing} of the {} outputs {} from those in {}{extra}",
        c.compared,
        if differing == 1 { "differs" } else { "differ" },
        out.display(),
    ));
    for d in &c.differences {
        super::say(&match d {
            Difference::Differs(p) => format!("  differs: {p}"),
            Difference::Missing(p) => {
                format!("  missing: {p} (the re-run writes it; the run's folder has no such file)")
            }
            Difference::Extra(p) => {
                format!("  extra: {p} (listed in the run's manifest; the re-run does not write it)")
            }
            Difference::NotComparable(p) => format!(
                "  not comparable: {p} (a PDF of axcheck {version} whose bytes differ; without pdftotext its text cannot be compared)"
            ),
        });
    }
    for p in &c.same_text {
        super::say(&format!(
            "  same text: {p} (a PDF of axcheck {version}: its bytes differ, its text is the same)"
        ));
    }
    1
}
