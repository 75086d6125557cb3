//! `axcheck trend`: every machine, axis and parameter of an inspection history, its slope
//! per year and the date it reaches its limit; the flagged series first.

use anyhow::{Context, Result, anyhow};
use axcheck::export::OutputFile;
use axcheck::history;
use axcheck::safe_text::one_line;
use axcheck::trend::{self, Series, Trend};
use rayon::prelude::*;
use std::fmt::Write;
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// What `trend` was asked for.
#[derive(Debug, clap::Args)]
pub struct TrendArgs {
    /// The history folder (`run --history DIR`).
    dir: PathBuf,
    /// Print JSON (a stable interface): `axes: [{machine, axis, parameter, …}]`.
    #[arg(long)]
    json: bool,
    /// Folder for `trends.csv` (every series) and `trends.pdf` (the flagged axes first, a
    /// chart per parameter).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Years after the latest inspection within which a forecast crossing is flagged.
    #[arg(long = "horizon", default_value_t = 2.0)]
    horizon_years: f64,
    /// Language of trends.pdf: en, zh or ru (default en).
    #[arg(long, value_name = "en|zh|ru")]
    lang: Option<axcheck::lang::Lang>,
}

/// Flagged lines printed before "… and N more".
const SHOWN: usize = 20;

/// Reads the history, fits every series and returns what to print.
pub fn run(request: &TrendArgs) -> Result<String> {
    let options = trend::fit::TrendOptions::with_horizon(request.horizon_years)
        .map_err(|e| anyhow!("--horizon: {e}"))?;
    // The series only, built file by file: the history is never held whole.
    let mut builder = history::SeriesBuilder::default();
    history::visit(&request.dir, |rows| builder.add(rows))?;
    if builder.rows() == 0 {
        return Err(anyhow!(
            "{}: no inspections in this history (run a campaign with --history {} first)",
            request.dir.display(),
            request.dir.display()
        ));
    }
    let dates = builder.dates();
    let series = builder.finish();
    let fits: Vec<Trend> = series
        .par_iter()
        .map(|s| trend::fit::fit(s, &options))
        .collect();
    // Flagged first; the series' own order (machine, axis, parameter) within each group.
    let mut order: Vec<usize> = (0..series.len()).collect();
    order.sort_by_key(|&k| !fits[k].flagged);
    let pairs: Vec<(&Series, &Trend)> = order.iter().map(|&k| (&series[k], &fits[k])).collect();
    if let Some(out) = &request.out {
        write_outputs(out, &pairs, request)?;
    }
    if request.json {
        // Written as it is made (130 MB for 10 000 axes), not held whole.
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        let written = trend::view::write_json(pairs.iter().copied(), &mut out)
            .map_err(std::io::Error::from)
            .and_then(|()| out.write_all(b"\n"))
            .and_then(|()| out.flush());
        return match written {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(String::new()),
            other => other.map(|()| String::new()).context("writing the JSON"),
        };
    }
    Ok(summary(&dates, &pairs, request))
}

/// `OUT/trends.csv` and `OUT/trends.pdf`, written as a campaign's outputs are.
fn write_outputs(out: &Path, pairs: &[(&Series, &Trend)], request: &TrendArgs) -> Result<()> {
    let _lock = axcheck::session::lock_folders(out, None, false, &|m| {
        super::tell(&format!("axcheck: {m}"))
    })?;
    let csv = trend::view::csv(pairs.iter().copied());
    let reports = axcheck::report::Reports::new(None)?.with_lang(request.lang);
    let history = request.dir.display().to_string();
    let pdf = reports
        .trends(&history, pairs, request.horizon_years, "trends.csv")
        .context("typesetting trends.pdf")?;
    let files = [
        OutputFile::new("trends.csv", csv.into_bytes()),
        OutputFile::new("trends.pdf", pdf.pdf),
    ];
    axcheck::export::write_into(out, &files)?;
    Ok(())
}

/// The inspections read, the flagged series with their reasons, and where the table went.
fn summary(dates: &[chrono::NaiveDate], pairs: &[(&Series, &Trend)], r: &TrendArgs) -> String {
    let flagged: Vec<_> = pairs.iter().filter(|(_, t)| t.flagged).collect();
    let mut text = format!(
        "{}: {} inspection dates ({} to {}), {} series; {} flagged (horizon {} years)\n",
        r.dir.display(),
        dates.len(),
        dates[0],
        dates[dates.len() - 1],
        pairs.len(),
        flagged.len(),
        r.horizon_years
    );
    for (s, t) in flagged.iter().take(SHOWN) {
        let reason = t.reason.as_deref().unwrap_or("");
        let (machine, axis) = (one_line(&s.machine), one_line(&s.axis));
        let _ = writeln!(text, "  {machine} {axis} {}: {reason}", s.parameter);
    }
    if flagged.len() > SHOWN {
        let _ = writeln!(text, "  … and {} more", flagged.len() - SHOWN);
    }
    if let Some(out) = &r.out {
        let _ = writeln!(
            text,
            "Table: {}; charts: {}",
            out.join("trends.csv").display(),
            out.join("trends.pdf").display()
        );
    }
    text
}
