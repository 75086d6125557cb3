//! `axcheck run` and `axcheck check`: a whole campaign.

use anyhow::{Result, anyhow};
use axcheck::campaign::Campaign;
use axcheck::history::AxisTrends;
use axcheck::judge::Verdict;
use axcheck::results::{AxisTest, CampaignResult};
use axcheck::session;
use axcheck::units::fmt_fixed;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

/// Exit status of a campaign: 0 when every axis passes (or is not judged, where the
/// campaign says `unjudged: allowed`), 1 otherwise.
pub fn exit_code(result: &CampaignResult) -> u8 {
    u8::from(!result.passes_gate())
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

/// The console of a run: progress on stderr (a bar on a terminal, else a line at every
/// tenth or for every test) and the locks' messages.
pub struct Console {
    total: usize,
    progress: Progress,
    tests_done: AtomicUsize,
    axes_done: AtomicUsize,
    tenths: AtomicUsize,
    bar: Option<indicatif::ProgressBar>,
}

impl Console {
    /// Progress counts axes, whose number is known before any data folder is read; an axis
    /// with several data files is several tests, reported one after the other.
    pub fn new(campaign: &Campaign, progress: Progress) -> Console {
        let total: usize = campaign.axes().count();
        let bar = (progress == Progress::Auto && std::io::stderr().is_terminal()).then(|| {
            let bar = indicatif::ProgressBar::new(total as u64);
            bar.set_style(
                indicatif::ProgressStyle::with_template(
                    "{spinner} {pos}/{len} axes {wide_bar} {msg}",
                )
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
            );
            bar
        });
        Console {
            total,
            progress,
            tests_done: AtomicUsize::new(0),
            axes_done: AtomicUsize::new(0),
            tenths: AtomicUsize::new(0),
            bar,
        }
    }

    fn report(&self, t: &AxisTest) {
        let k = self.tests_done.fetch_add(1, Ordering::Relaxed) + 1;
        let axes = match t.test == t.tests {
            true => self.axes_done.fetch_add(1, Ordering::Relaxed) + 1,
            false => self.axes_done.load(Ordering::Relaxed),
        };
        match (&self.bar, self.progress) {
            (Some(bar), _) => {
                bar.set_position(axes as u64);
                let label = format!("{} {}", t.label(), t.verdict());
                bar.set_message(axcheck::safe_text::visible(&label).into_owned());
            }
            (None, Progress::EveryTest) => {
                super::tell(&format!("axcheck: [{k}] {}: {}", t.label(), t.verdict()))
            }
            (None, Progress::Auto) => {
                let total = self.total;
                let tenth = (axes * 10 / total.max(1)).min(10);
                if tenth > self.tenths.fetch_max(tenth, Ordering::Relaxed) {
                    eprintln!(
                        "axcheck: {} % ({axes} of {total} axis entries evaluated)",
                        tenth * 10
                    );
                }
            }
        }
    }

    /// Clears the progress bar.
    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

impl session::Observer for Console {
    fn lock(&self, message: &str) {
        super::tell(&format!("axcheck: {message}"));
    }

    fn test_done(&self, test: &AxisTest) {
        self.report(test);
    }
}

use super::text::MAX_PROBLEM_LINES;

/// One line per test that did not pass, failures first, then noncompliant plans,
/// inconclusive tests, errors, then tests not judged unless the campaign allows them (each
/// in campaign order), at most [`MAX_PROBLEM_LINES`]; then how many more there are and
/// where they are all listed (`where_all`).
pub fn problems(result: &CampaignResult, where_all: &str) -> Vec<String> {
    let allowed = result.info.unjudged_allowed();
    let mut attention: Vec<&AxisTest> = (result.tests.iter())
        .filter(|t| match t.verdict() {
            Verdict::Pass => false,
            Verdict::NotJudged => !allowed,
            _ => true,
        })
        .collect();
    attention.sort_by_key(|t| t.verdict().attention_rank());
    let shown = &attention[..attention.len().min(MAX_PROBLEM_LINES)];
    let width = shown
        .iter()
        .map(|t| super::text::width(&t.label()))
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
        let ids: std::collections::BTreeSet<&str> = (t.findings().iter())
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
    let unit = t.deviation_symbol();
    let why = match t.verdict() {
        Verdict::Error => t.error().unwrap_or_default().to_string(),
        Verdict::Noncompliant => t.broken_rules_text(),
        Verdict::NotJudged => not_judged_why(t),
        Verdict::Inconclusive => t
            .inconclusive()
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
            .judgement()
            .into_iter()
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
    let example = (t.judgement()).is_some_and(|j| j.limits.example)
        && matches!(t.verdict(), Verdict::Fail | Verdict::Inconclusive);
    let why = match example {
        true => format!("{why} ({})", axcheck::judge::EXAMPLE_LIMITS),
        false => why,
    };
    format!(
        "  {:<12} {}  {why}",
        t.verdict().words().to_uppercase(),
        // The label shows hidden characters as escapes already: padded by terminal columns.
        super::text::left(&t.label(), width)
    )
}

/// Why a test is not judged: no limit, or only limits of parameters it does not have.
fn not_judged_why(t: &AxisTest) -> String {
    let judgement = t.judgement();
    match judgement.map(|j| &j.not_applicable) {
        Some(keys) if !keys.is_empty() => format!(
            "no limit applied: the limits of {} do not apply to this test",
            keys.join(", ")
        ),
        _ => "no limit applied (no spec, no tolerances): nothing was compared".to_string(),
    }
}

/// The one-line count of verdicts.
pub fn counts_line(result: &CampaignResult) -> String {
    format!(
        "{}: {} tests: {}",
        axcheck::safe_text::one_line(&result.info.name),
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
    /// Language of the reports (axis reports, summary PDF, summary.html): en, zh or ru
    /// (default: a machine's `report.lang`, else `campaign.report.lang`, else en).
    #[arg(long, value_name = "en|zh|ru")]
    lang: Option<axcheck::lang::Lang>,
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

impl RunArgs {
    /// The arguments of a recorded run (`results.json` `inputs`), into `out`: what
    /// `reproduce` runs again (the folders recorded from the campaign's folder `dir`).
    pub fn recorded(
        campaign: PathBuf,
        dir: &Path,
        out: PathBuf,
        flags: &axcheck::inputs::RunFlags,
    ) -> RunArgs {
        RunArgs {
            campaign,
            out,
            jobs: 0,
            no_pdf: flags.no_pdf,
            no_html: flags.no_html,
            no_diagnose: flags.no_diagnose,
            templates: flags.templates.as_ref().map(|t| dir.join(t)),
            lang: flags.lang,
            progress: false,
            history: flags.history.as_ref().map(|h| dir.join(h)),
            horizon_years: flags.horizon,
            wait: false,
        }
    }
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
    let start = Instant::now();
    let campaign = Campaign::load(&args.campaign)?;
    let options = run_options(args, &campaign)?;
    let outcome = run_with_console(&campaign, &options, args.progress)?;
    print_run(&options, outcome, start)
}

/// `axcheck check`: the CI gate; writes nothing.
pub fn check_command(args: &CheckArgs) -> Result<u8> {
    let campaign = Campaign::load(&args.campaign)?;
    let options = session::RunOptions {
        diagnose: args.diagnose,
        ..session::RunOptions::default()
    };
    let result = run_with_console(&campaign, &options, args.progress)?.result;
    print_summary(
        &result,
        "`axcheck run` lists them all in summary.md",
        "`axcheck run` lists them in summary.md",
    );
    let code = exit_code(&result);
    // The process ends with the gate: freeing a fleet's campaign and results one block at
    // a time cost the gate 6 % of its wall time on 10 000 axes, on one thread after the
    // workers are done, and the system takes the memory back at once anyway.
    std::mem::forget((campaign, result));
    Ok(code)
}

/// The session run with the console's progress on stderr (`--progress`: every test).
fn run_with_console(
    campaign: &Campaign,
    options: &session::RunOptions,
    every_test: bool,
) -> Result<session::RunOutcome, session::SessionError> {
    let console = Console::new(campaign, Progress::of(every_test));
    let outcome = session::run(campaign, options, &console);
    console.finish();
    outcome
}

/// `run`'s flags over the campaign's own settings: `--no-pdf`, `--no-html` and
/// `--no-diagnose` turn off what `campaign.output` turns on; `--history` and `--horizon`
/// override `campaign.history` and `campaign.trend_horizon_years`.
pub fn run_options<'a>(args: &'a RunArgs, campaign: &Campaign) -> Result<session::RunOptions<'a>> {
    let output = &campaign.info.output;
    Ok(session::RunOptions {
        out: Some(&args.out),
        pdf: !args.no_pdf && output.pdf,
        html: !args.no_html && output.html,
        diagnose: output.diagnose && !args.no_diagnose,
        templates: args.templates.as_deref(),
        history: (args.history.clone()).or_else(|| campaign.history.clone()),
        horizon: trend_options(args.horizon_years, campaign)?,
        wait: args.wait,
        flags: axcheck::inputs::RunFlags {
            no_pdf: args.no_pdf,
            no_html: args.no_html,
            no_diagnose: args.no_diagnose,
            templates: (args.templates.as_deref()).map(|p| from_campaign(campaign, p)),
            history: (args.history.as_deref()).map(|p| from_campaign(campaign, p)),
            horizon: args.horizon_years,
            lang: args.lang,
        },
    })
}

/// A folder given on the command line as seen from the campaign's folder (recorded in
/// `results.json`: no place on this machine).
fn from_campaign(campaign: &Campaign, path: &Path) -> String {
    axcheck::files::path_from(&campaign.dir, path)
}

/// What `run` prints after its outputs are written; the exit status.
fn print_run(
    options: &session::RunOptions,
    outcome: session::RunOutcome,
    start: Instant,
) -> Result<u8> {
    let result = &outcome.result;
    print_summary(result, "all in summary.md", "all in summary.md");
    for line in super::tables::lines(result) {
        super::say(&line);
    }
    super::say(&outputs_line(options, &outcome, start));
    match outcome.appended {
        Some(Ok(appended)) => super::say(&appended_line(&appended, options.history.as_deref())),
        Some(Err(e)) => {
            let dir = options.history.clone().unwrap_or_default();
            return Err(anyhow::Error::new(e).context(format!(
                "the outputs are written, but the run is not in the history {}",
                dir.display()
            )));
        }
        None => {}
    }
    if let Some(trends) = &outcome.trends {
        super::print(&flagged_lines(trends))?;
    }
    Ok(exit_code(result))
}

/// What `run` and `check` both print: the counts, the caveats, the problems and the
/// warnings, each list cut with a pointer to where the rest is (`problems_rest`,
/// `warnings_rest`).
fn print_summary(result: &CampaignResult, problems_rest: &str, warnings_rest: &str) {
    super::say(&counts_line(result));
    for line in result.caveats() {
        super::say(&line);
    }
    for line in problems(result, problems_rest) {
        super::say(&line);
    }
    if let Some(line) = warnings_line(result, warnings_rest) {
        super::say(&line);
    }
}

/// `Outputs in out (36 files) after 0.50 s: summary.md, …`.
fn outputs_line(
    plan: &session::RunOptions,
    outcome: &session::RunOutcome,
    start: Instant,
) -> String {
    let tables = outcome
        .result
        .tests
        .iter()
        .any(|t| t.evaluated().is_some_and(|e| e.compensation.is_some()));
    format!(
        "Outputs in {} ({} files) after {:.2} s: summary.md, summary.csv, summary.xlsx, summary.parquet, results.json, junit.xml{}{}{}",
        plan.out.unwrap_or(Path::new("")).display(),
        outcome.written.len(),
        start.elapsed().as_secs_f64(),
        if plan.html { ", summary.html" } else { "" },
        if plan.pdf {
            ", summary.pdf, reports/MACHINE/AXIS.pdf"
        } else {
            ""
        },
        if tables {
            ", compensation/MACHINE/AXIS.*"
        } else {
            ""
        }
    )
}

/// `History: 21 rows appended to … after 0.12 s`, or why nothing was appended or read.
fn appended_line(a: &session::Appended, dir: Option<&Path>) -> String {
    let Some(path) = &a.path else {
        let dir = dir.map(|d| d.display().to_string()).unwrap_or_default();
        return format!("History: no test was evaluated; {dir} left as it was");
    };
    let rows = format!("History: {} rows appended to {}", a.rows, path.display());
    let head = format!("{rows} after {:.2} s", a.seconds);
    match &a.unread {
        None => head,
        Some(e) => format!("{head}; no trends, as the history cannot be read: {e}"),
    }
}

/// The trend horizon of a run: `--horizon`, else `campaign.trend_horizon_years`, else 2.
fn trend_options(
    horizon_years: Option<f64>,
    campaign: &Campaign,
) -> Result<axcheck::trend::fit::TrendOptions> {
    use axcheck::trend::fit::TrendOptions;
    match (horizon_years, campaign.info.trend_horizon_years) {
        (Some(years), _) => {
            TrendOptions::with_horizon(years).map_err(|e| anyhow!("--horizon: {e}"))
        }
        // Checked when the campaign was loaded.
        (None, Some(years)) => Ok(TrendOptions::with_horizon(years).unwrap_or_default()),
        (None, None) => Ok(TrendOptions::default()),
    }
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
