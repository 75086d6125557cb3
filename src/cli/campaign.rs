//! `axcheck run` and `axcheck check`: a whole campaign.

use anyhow::{Context, Result, anyhow, bail};
use axcheck::batch::{self, AxisTest, CampaignResult};
use axcheck::campaign::Campaign;
use axcheck::export;
use axcheck::history::AxisTrends;
use axcheck::judge::Verdict;
use axcheck::units::fmt_fixed;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

/// Exit status of a campaign: 0 when every axis passes, 1 otherwise.
pub fn exit_code(result: &CampaignResult) -> u8 {
    u8::from(!result.all_pass())
}

/// How `run` and `check` report progress on stderr.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Progress {
    /// A progress bar on a terminal; otherwise a line at every tenth of the campaign (a
    /// CI log of a 10 000-axis fleet gets ten lines, not ten thousand).
    Auto,
    /// A line for every finished test (`--progress`).
    EveryTest,
}

/// Evaluates a campaign, reporting progress on stderr.
pub fn evaluate_with(
    campaign: &Campaign,
    options: batch::Options,
    progress: Progress,
) -> CampaignResult {
    // Progress counts axes, whose number is known before any data folder is read; an axis
    // with several data files is several tests, reported one after the other.
    let total: usize = campaign.axes().count();
    let tests_done = AtomicUsize::new(0);
    let axes_done = AtomicUsize::new(0);
    let tenths = AtomicUsize::new(0);
    let bar = (progress == Progress::Auto && std::io::stderr().is_terminal()).then(|| {
        let bar = indicatif::ProgressBar::new(total as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template("{spinner} {pos}/{len} axes {wide_bar} {msg}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        bar
    });
    let report = |t: &AxisTest| {
        let k = tests_done.fetch_add(1, Ordering::Relaxed) + 1;
        let axes = if t.test == t.tests {
            axes_done.fetch_add(1, Ordering::Relaxed) + 1
        } else {
            axes_done.load(Ordering::Relaxed)
        };
        match (&bar, progress) {
            (Some(bar), _) => {
                bar.set_position(axes as u64);
                bar.set_message(format!("{} {}", t.label(), t.verdict));
            }
            (None, Progress::EveryTest) => eprintln!("axcheck: [{k}] {}: {}", t.label(), t.verdict),
            (None, Progress::Auto) => {
                let tenth = (axes * 10 / total.max(1)).min(10);
                if tenth > tenths.fetch_max(tenth, Ordering::Relaxed) {
                    eprintln!(
                        "axcheck: {} % ({axes} of {total} axes evaluated)",
                        tenth * 10
                    );
                }
            }
        }
    };
    let result = batch::run(campaign, options, &report);
    if let Some(bar) = bar {
        bar.finish_and_clear();
    }
    result
}

/// Refuses an output folder that is a file, or is (or lies inside) a folder holding the
/// campaign's data, so outputs never mix with or overwrite measurements.
pub fn check_output_dir(campaign: &Campaign, out: &Path) -> Result<()> {
    if out.exists() && !out.is_dir() {
        bail!(
            "the output folder {} is a file; choose a folder with --out",
            out.display()
        );
    }
    let canonical = |p: &Path| std::fs::canonicalize(p).ok();
    let Some(out_abs) = canonical(out).or_else(|| {
        let parent = out
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        canonical(parent).map(|p| p.join(out.file_name().unwrap_or_default()))
    }) else {
        return Ok(());
    };
    for (_, entry) in campaign.axes() {
        let Ok(axis) = &entry.spec else { continue };
        let folders: Vec<PathBuf> = match &axis.data {
            axcheck::campaign::data::DataSource::Files(files) => files
                .iter()
                .filter_map(|f| campaign.dir.join(f).parent().map(Path::to_path_buf))
                .collect(),
            axcheck::campaign::data::DataSource::Glob { dir, .. } => vec![campaign.dir.join(dir)],
            axcheck::campaign::data::DataSource::Book { file, .. } => (campaign.dir.join(file))
                .parent()
                .map(Path::to_path_buf)
                .into_iter()
                .collect(),
        };
        for folder in folders {
            if let Some(data) = canonical(&folder)
                && out_abs.starts_with(&data)
            {
                bail!(
                    "the output folder {} is inside the data folder {} of {} {}; choose another --out",
                    out.display(),
                    folder.display(),
                    entry.name,
                    axis.raw.name
                );
            }
        }
    }
    Ok(())
}

/// Lines of the tests that need attention printed at most; the rest are counted.
pub const MAX_PROBLEM_LINES: usize = 20;

/// One line per test that did not pass, failures first, then noncompliant plans, then
/// errors (each in campaign order), at most [`MAX_PROBLEM_LINES`]; then how many more
/// there are and where they are all listed (`where_all`).
pub fn problems(result: &CampaignResult, where_all: &str) -> Vec<String> {
    let mut attention: Vec<&AxisTest> = result
        .tests
        .iter()
        .filter(|t| t.verdict != Verdict::Pass)
        .collect();
    attention.sort_by_key(|t| t.verdict.attention_rank());
    let shown = &attention[..attention.len().min(MAX_PROBLEM_LINES)];
    let width = shown
        .iter()
        .map(|t| t.label().chars().count())
        .max()
        .unwrap_or(0);
    let mut lines: Vec<String> = shown.iter().map(|t| problem_line(t, width)).collect();
    if attention.len() > shown.len() {
        lines.push(format!(
            "  … and {} more ({where_all})",
            attention.len() - shown.len()
        ));
    }
    lines
}

/// One line naming the rule warnings of the campaign and on how many tests each was found
/// (a warning does not change a verdict, so a passing test may carry one): `Warnings:
/// plan-targets on 2 tests, iso-3.3-thermal on 1 (all in summary.md)`. None without any.
pub fn warnings_line(result: &CampaignResult, where_all: &str) -> Option<String> {
    let mut tests_per_rule: std::collections::BTreeMap<&str, usize> = Default::default();
    for t in &result.tests {
        let ids: std::collections::BTreeSet<&str> = (t.findings.iter())
            .filter(|f| f.severity == axcheck::rules::Severity::Warning)
            .map(|f| f.id)
            .collect();
        for id in ids {
            *tests_per_rule.entry(id).or_default() += 1;
        }
    }
    let mut counted: Vec<(&str, usize)> = tests_per_rule.into_iter().collect();
    counted.sort_by_key(|(_, n)| std::cmp::Reverse(*n));
    let parts: Vec<String> = (counted.iter().enumerate())
        .map(|(i, (id, n))| match (i, n) {
            (0, 1) => format!("{id} on 1 test"),
            (0, _) => format!("{id} on {n} tests"),
            _ => format!("{id} on {n}"),
        })
        .collect();
    (!parts.is_empty()).then(|| format!("Warnings: {} ({where_all})", parts.join(", ")))
}

/// `  FAIL         VMC-07 Y  A = 10.96 µm > 8.00 µm, …`
fn problem_line(t: &AxisTest, width: usize) -> String {
    let unit = t.kind().map_or("", |k| k.deviation_symbol());
    let why = match t.verdict {
        Verdict::Error => t.error.clone().unwrap_or_default(),
        Verdict::Noncompliant => t.broken_rules_text(),
        Verdict::Inconclusive => t
            .judgement
            .iter()
            .flat_map(|j| j.inconclusive())
            .map(|c| {
                format!(
                    "{} = {} {unit} ± {} {unit} at its limit {} {unit}",
                    c.key,
                    fmt_fixed(c.value.abs(), 2),
                    fmt_fixed(c.expanded_uncertainty.unwrap_or(0.0), 2),
                    fmt_fixed(c.limit, 2)
                )
            })
            .collect::<Vec<_>>()
            .join(", "),
        _ => t
            .judgement
            .iter()
            .flat_map(|j| j.failed())
            .map(|c| {
                format!(
                    "{} = {} {unit} > {} {unit}",
                    c.key,
                    fmt_fixed(c.value.abs(), 2),
                    fmt_fixed(c.limit, 2)
                )
            })
            .collect::<Vec<_>>()
            .join(", "),
    };
    format!(
        "  {:<12} {:<width$}  {why}",
        t.verdict.name().to_uppercase(),
        t.label()
    )
}

/// The one-line count of verdicts.
pub fn counts_line(result: &CampaignResult) -> String {
    format!(
        "{}: {} tests: {}",
        result.info.name,
        result.tests.len(),
        result.counts_text()
    )
}

/// `axcheck run`'s arguments.
#[derive(clap::Args)]
pub struct RunArgs {
    /// Campaign file (YAML).
    campaign: PathBuf,
    /// Output folder.
    #[arg(long, short, default_value = "out")]
    out: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, short, default_value_t = 0)]
    pub jobs: usize,
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
}

/// `axcheck check`'s arguments.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// Campaign file (YAML).
    campaign: PathBuf,
    /// Worker threads (default: all cores).
    #[arg(long, short, default_value_t = 0)]
    pub jobs: usize,
    /// Also run the model check and diagnosis (slower; `run` does it by default).
    #[arg(long)]
    diagnose: bool,
    /// A progress line for every finished test on stderr (without a terminal the
    /// default is a line at every tenth of the campaign).
    #[arg(long)]
    progress: bool,
}

impl Progress {
    /// `--progress`: a line for every test; else the default.
    fn of(every_test: bool) -> Progress {
        match every_test {
            true => Progress::EveryTest,
            false => Progress::Auto,
        }
    }
}

/// `axcheck run`: the exit status.
pub fn run_command(args: &RunArgs) -> Result<u8> {
    let options = RunOptions {
        out: &args.out,
        jobs: args.jobs,
        no_pdf: args.no_pdf,
        no_html: args.no_html,
        no_diagnose: args.no_diagnose,
        templates: args.templates.as_deref(),
        progress: Progress::of(args.progress),
        history: args.history.as_deref(),
        horizon_years: args.horizon_years,
        wait: args.wait,
    };
    run(&args.campaign, &options)
}

/// `axcheck check`: the exit status.
pub fn check_command(args: &CheckArgs) -> Result<u8> {
    let progress = Progress::of(args.progress);
    check(&args.campaign, args.jobs, args.diagnose, progress)
}

/// Options of `axcheck run`.
pub struct RunOptions<'a> {
    pub out: &'a Path,
    pub jobs: usize,
    /// Write no PDFs (also `campaign.output.pdf: false`).
    pub no_pdf: bool,
    /// Write no summary.html (also `campaign.output.html: false`).
    pub no_html: bool,
    /// A customised copy of `templates/`.
    pub templates: Option<&'a Path>,
    /// Skip the model check and diagnosis (also `campaign.output.diagnose: false`).
    pub no_diagnose: bool,
    pub progress: Progress,
    /// Folder of the inspection history to append to (overrides `campaign.history`).
    pub history: Option<&'a Path>,
    /// Trend horizon in years (`--horizon`; overrides `campaign.trend_horizon_years`).
    pub horizon_years: Option<f64>,
    /// Wait for another run that holds the output or history folder (`--wait`).
    pub wait: bool,
}

/// `axcheck run`.
pub fn run(path: &Path, options: &RunOptions) -> Result<u8> {
    let start = Instant::now();
    let out = options.out;
    let campaign = Campaign::load(path)?;
    check_output_dir(&campaign, out)?;
    let history = (options.history.map(Path::to_path_buf)).or_else(|| campaign.history.clone());
    let horizon = trend_options(options.horizon_years, &campaign)?;
    if history.is_some() {
        // Before the evaluation: a history needs the run's date.
        axcheck::history::run_date(&campaign.info, &campaign.file.display().to_string())?;
    }
    // One writer per folder, from before the manifest is read until the history is
    // appended: a second run on the folder stops here (or waits), not half-way.
    let _locks = lock_folders(out, history.as_deref(), options.wait)?;
    // A broken manifest is refused before the evaluation; the output paths themselves are
    // checked by `write_all` before anything is written.
    axcheck::atomic::OutputDir::open(out)?;
    let mut exporters = export::table_exporters();
    let pdf = !options.no_pdf && campaign.info.output.pdf;
    // Built before the evaluation, so bad templates stop the run at once.
    let reports = match pdf {
        true => Some(axcheck::report::Reports::new(options.templates)?),
        false => None,
    };
    let result = evaluate_with(
        &campaign,
        batch::Options {
            jobs: options.jobs,
            diagnose: campaign.info.output.diagnose && !options.no_diagnose,
            drop_data: false,
            compensate: true,
        },
        options.progress,
    );
    // The history first: the reports show each axis over it, this run included. A history
    // that cannot be appended to or read costs the reports their history, not the outputs.
    let appended = (history.as_deref()).map(|dir| append_history(&result, dir, horizon));
    let trends = match &appended {
        Some(Ok(appended)) => appended.trends.clone(),
        _ => None,
    };
    exporters.push(Box::new(export::xlsx::Xlsx {
        trends: trends.clone(),
    }));
    let html = !options.no_html && campaign.info.output.html;
    if html {
        exporters.push(Box::new(export::html::Html {
            reports: reports.is_some(),
            trends: trends.clone(),
        }));
    }
    if let Some(reports) = reports {
        exporters.push(Box::new(export::pdf::Pdf {
            reports,
            trends: trends.clone(),
        }));
    }
    let written = export::write_all(&result, &exporters, out)
        .with_context(|| format!("writing the outputs to {}", out.display()))?;
    println!("{}", counts_line(&result));
    for line in problems(&result, "all in summary.md") {
        println!("{line}");
    }
    if let Some(line) = warnings_line(&result, "all in summary.md") {
        println!("{line}");
    }
    for line in super::tables::lines(&result) {
        println!("{line}");
    }
    let tables = result.tests.iter().any(|t| t.compensation.is_some());
    println!(
        "Outputs in {} ({} files) after {:.2} s: summary.md, summary.csv, summary.xlsx, summary.parquet, results.json, junit.xml{}{}{}",
        out.display(),
        written.len(),
        start.elapsed().as_secs_f64(),
        if html { ", summary.html" } else { "" },
        if pdf {
            ", summary.pdf, reports/MACHINE/AXIS.pdf"
        } else {
            ""
        },
        if tables {
            ", compensation/MACHINE/AXIS.*"
        } else {
            ""
        }
    );
    match appended {
        Some(Ok(appended)) => println!("{}", appended.line),
        Some(Err(e)) => {
            return Err(e.context(format!(
                "the outputs are written, but the run is not in the history {}",
                history.unwrap_or_default().display()
            )));
        }
        None => {}
    }
    if let Some(trends) = &trends {
        print!("{}", flagged_lines(trends));
    }
    Ok(exit_code(&result))
}

/// Locks the output folder and the history folder (once when they are one), in the order
/// of their real paths so that two waiting runs never hold one each. Also the one folder
/// that `trend --out` and `simulate --fleet` write.
pub(crate) fn lock_folders(
    out: &Path,
    history: Option<&Path>,
    wait: bool,
) -> Result<Vec<axcheck::lock::FolderLock>> {
    let real = |p: &Path| axcheck::campaign::paths::real_path(p).unwrap_or_else(|_| p.into());
    let mut folders: Vec<(PathBuf, &Path)> = std::iter::once(out)
        .chain(history)
        .map(|p| (real(p), p))
        .collect();
    folders.sort();
    folders.dedup_by(|a, b| a.0 == b.0);
    let mut locks = Vec::new();
    for (_, dir) in folders {
        let lock = axcheck::lock::FolderLock::acquire(dir, wait, |locked| {
            eprintln!("axcheck: {locked}; waiting for it to finish (--wait)");
        })?;
        if let Some(ended) = &lock.taken_over {
            eprintln!(
                "axcheck: {} holds the lock file of a run that ended without removing it ({}); taken over",
                dir.display(),
                ended.describe()
            );
        }
        locks.push(lock);
    }
    Ok(locks)
}

/// The trend horizon of a run: `--horizon`, else `campaign.trend_horizon_years`, else 2.
fn trend_options(
    horizon_years: Option<f64>,
    campaign: &Campaign,
) -> Result<axcheck::trend::fit::Options> {
    use axcheck::trend::fit::Options;
    match (horizon_years, campaign.info.trend_horizon_years) {
        (Some(years), _) => Options::with_horizon(years).map_err(|e| anyhow!("--horizon: {e}")),
        // Checked when the campaign was loaded.
        (None, Some(years)) => Ok(Options::with_horizon(years).unwrap_or_default()),
        (None, None) => Ok(Options::default()),
    }
}

/// The run appended to its history: the line that says where, and the trends of the run's
/// axes over the whole history (none when the history cannot be read back).
struct Appended {
    line: String,
    trends: Option<Arc<AxisTrends>>,
}

/// Appends the run to the history in `dir` and fits the trends of the run's axes over it.
/// A history file that cannot be read (another run's, damaged) leaves the reports without
/// their history sections, said in the line; it does not undo the append.
fn append_history(
    result: &CampaignResult,
    dir: &Path,
    horizon: axcheck::trend::fit::Options,
) -> Result<Appended> {
    let start = Instant::now();
    let records = axcheck::history::records(result)?;
    let written = axcheck::history::append(dir, &records)
        .with_context(|| format!("appending the run to the history {}", dir.display()))?;
    let Some(path) = written else {
        let line = format!(
            "History: no test was evaluated; {} left as it was",
            dir.display()
        );
        return Ok(Appended { line, trends: None });
    };
    let appended = format!(
        "History: {} rows appended to {}",
        records.len(),
        path.display()
    );
    let elapsed = || start.elapsed().as_secs_f64();
    Ok(match axcheck::history::read(dir) {
        Ok(all) => Appended {
            line: format!("{appended} after {:.2} s", elapsed()),
            trends: Some(Arc::new(AxisTrends::of_run(&all, &records, horizon))),
        },
        Err(e) => Appended {
            line: format!(
                "{appended} after {:.2} s; no trends, as the history cannot be read: {e}",
                elapsed()
            ),
            trends: None,
        },
    })
}

/// Flagged series printed by `run` before "… and N more".
const FLAGGED_SHOWN: usize = 10;

/// The run's axes whose trends are flagged, a line each (nothing when none is).
fn flagged_lines(trends: &AxisTrends) -> String {
    let flagged: Vec<_> = trends.flagged().collect();
    let Some((first, last)) = trends.dates().filter(|_| !flagged.is_empty()) else {
        return String::new();
    };
    let mut text = format!(
        "Trends ({first} to {last}, horizon {} years): {} series flagged\n",
        trends.options.horizon_years,
        flagged.len()
    );
    for (s, t) in flagged.iter().take(FLAGGED_SHOWN) {
        let reason = t.reason.as_deref().unwrap_or("");
        text += &format!("  {} {} {}: {reason}\n", s.machine, s.axis, s.parameter);
    }
    if flagged.len() > FLAGGED_SHOWN {
        text += &format!(
            "  … and {} more (axcheck trend HISTORY lists them all)\n",
            flagged.len() - FLAGGED_SHOWN
        );
    }
    text
}

/// `axcheck check`: the CI gate; writes nothing.
pub fn check(path: &Path, jobs: usize, diagnose: bool, progress: Progress) -> Result<u8> {
    let options = batch::Options {
        jobs,
        diagnose,
        drop_data: true,
        compensate: false,
    };
    let result = evaluate_with(&Campaign::load(path)?, options, progress);
    println!("{}", counts_line(&result));
    for line in problems(&result, "`axcheck run` lists them all in summary.md") {
        println!("{line}");
    }
    if let Some(line) = warnings_line(&result, "`axcheck run` lists them in summary.md") {
        println!("{line}");
    }
    Ok(exit_code(&result))
}
