//! `compensate --test straightness` and `verify --test straightness`: a straightness test
//! (ISO 230-1, EYX) written as the controller's cross-axis table, built on the cross table
//! active during the test, and the re-measurement after it was loaded compared with the
//! prediction (`axcheck::compensate::cross`).

use super::text::{left, right};
use anyhow::{Context, Result, anyhow, bail};
use axcheck::campaign::stages::compensate::TableFile;
use axcheck::campaign::stages::cross::read_cross_table;
use axcheck::compensate::cross::build::{CrossActive, CrossCompensation, CrossRequest, compensate};
use axcheck::compensate::cross::verify::{
    CrossFinding, CrossVerdict, CrossVerification, OtherOutput, verify,
};
use axcheck::compensate::cross::{self, CrossFormat, CrossTable};
use axcheck::geometry::TestKind;
use axcheck::geometry::line::ReferenceLine;
use axcheck::measurement::{AxisData, ReadOptions};
use axcheck::units::fmt_fixed;
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// Which test the table is of, and the cross table's axes.
#[derive(clap::Args, Debug, Clone)]
#[command(next_help_heading = "Cross-axis tables (from a straightness test)")]
pub struct CrossArgs {
    /// positioning (a pitch table, the default) or straightness (a cross-axis table: the
    /// output axis corrected as a function of this one's position).
    #[arg(long, default_value = "positioning", value_parser = super::geometry::parse_test)]
    pub test: TestKind,
    /// Straightness: the axis measured along (the table's input), as the controller names
    /// it (Siemens `X1`, HEIDENHAIN `X`, TwinCAT its logical number); default: the active
    /// table's.
    #[arg(long, value_name = "AXIS")]
    pub input: Option<String>,
    /// Straightness: the axis the deviation is along (the table's output, corrected), as
    /// the controller names it; default: the active table's.
    #[arg(long, value_name = "AXIS")]
    pub output: Option<String>,
    /// Straightness: the reference straight line removed, least-squares (the default) or
    /// end-point (ISO 230-1 3.4.12); the table corrects the deviations about it.
    #[arg(long, value_parser = super::geometry::parse_line)]
    pub line: Option<ReferenceLine>,
}

impl CrossArgs {
    /// Whether a cross table is asked for; another test than straightness has none.
    pub fn is_cross(&self) -> Result<bool> {
        match self.test {
            TestKind::Positioning => {
                if self.input.is_some() || self.output.is_some() || self.line.is_some() {
                    bail!("--input, --output and --line apply to --test straightness");
                }
                Ok(false)
            }
            TestKind::Straightness => Ok(true),
            other => bail!(
                "--test {}: compensation tables are of positioning (pitch) and straightness (cross-axis) tests only",
                other.key()
            ),
        }
    }
}

/// The controller's cross format, or the error that lists those that have one.
pub fn format(controller: &str) -> Result<&'static dyn CrossFormat> {
    cross::find(controller).ok_or_else(|| {
        anyhow!(
            "the controller `{controller}` has no cross-axis table in axcheck; those that have: {}",
            cross::names().join(", ")
        )
    })
}

/// A cross-table file given as the option `key`, with its other parts beside it.
pub fn read_table(path: &Path, key: &'static str, format: &dyn CrossFormat) -> Result<CrossTable> {
    Ok(read_cross_table(TableFile::Given { path, key }, format)?)
}

/// `--active FILE|none` of a cross table.
fn active(given: Option<&str>, format: &dyn CrossFormat) -> Result<CrossActive> {
    Ok(match given {
        None => CrossActive::Unstated,
        Some("none") => CrossActive::None,
        Some(file) => CrossActive::Table {
            table: read_table(Path::new(file), "--active", format)?,
            file: file.to_string(),
        },
    })
}

/// What `compensate --test straightness` was asked for.
pub struct CompensateCross<'a> {
    pub file: &'a Path,
    pub sheet: ReadOptions<'a>,
    pub controller: &'a str,
    pub out: Option<&'a Path>,
    pub interval_mm: Option<f64>,
    pub active: Option<&'a str>,
    pub json: bool,
    pub cross: &'a CrossArgs,
}

/// Writes the cross table (to `out`, or standard output when it is one file) and returns
/// what to print.
pub fn compensate_command(c: CompensateCross) -> Result<String> {
    let format = format(c.controller)?;
    let read = axcheck::one_file::read_geometry(c.file, TestKind::Straightness, c.sheet)?;
    let request = CrossRequest {
        input: c.cross.input.clone(),
        output: c.cross.output.clone(),
        interval_mm: c.interval_mm,
        line: c.cross.line.unwrap_or_default(),
        active: active(c.active, format)?,
        stem: (c.out.and_then(Path::file_stem))
            .map_or(String::new(), |s| s.to_string_lossy().into_owned()),
    };
    let done = compensate(format, &read.data, &request)
        .map_err(|refused| anyhow!("{}: {refused}", c.file.display()))?;
    let written = match c.out {
        Some(out) => write_parts(out, &done)?,
        None if done.parts.len() == 1 => Vec::new(),
        None => bail!(
            "a {} cross table is {} files ({}): give --out",
            format.name(),
            done.parts.len(),
            format.extensions().join(", ")
        ),
    };
    if c.json {
        let json = serde_json::json!({ "file": c.file.display().to_string(), "written": written, "compensation": done });
        return Ok(serde_json::to_string_pretty(&json)? + "\n");
    }
    if c.out.is_none() {
        for w in &done.warnings {
            super::tell(&format!("axcheck: warning: {w}"));
        }
        return Ok(done.parts[0].text.clone());
    }
    Ok(summary(&done, &written, request.line))
}

/// Each part to `out` (one file) or beside it with its extension (several), atomically.
fn write_parts(out: &Path, done: &CrossCompensation) -> Result<Vec<String>> {
    let one = done.parts.len() == 1;
    done.parts
        .iter()
        .map(|p| {
            let path: PathBuf = if one {
                out.to_path_buf()
            } else {
                out.with_extension(p.extension)
            };
            axcheck::atomic::write(&path, p.text.as_bytes())
                .with_context(|| format!("cannot write {}", path.display()))?;
            Ok(path.display().to_string())
        })
        .collect()
}

/// What was written and what it predicts.
fn summary(done: &CrossCompensation, written: &[String], line: ReferenceLine) -> String {
    let t = &done.table;
    let mode = match &done.active_file {
        Some(file) => {
            format!("incremental: the active table {file} plus this measurement's correction")
        }
        None => "absolute: this measurement's correction alone".into(),
    };
    let mut text = format!(
        "{} cross table written to {} ({mode})\n{} corrected as a function of {} at {} points, {} to {} mm; each value is added to {}'s commanded position.\n\n",
        done.format,
        written.join(" and "),
        t.output,
        t.input,
        t.positions_mm.len(),
        t.positions_mm.first().copied().unwrap_or(0.0),
        t.positions_mm.last().copied().unwrap_or(0.0),
        t.output
    );
    let _ = writeln!(
        text,
        "{}  {}  {}",
        left("Straightness", 14),
        right("measured (µm)", 14),
        right("predicted (µm)", 15)
    );
    let _ = writeln!(
        text,
        "{}  {}  {}",
        left(&line.key().replace('_', "-"), 14),
        right(&fmt_fixed(done.measured_um, 2), 14),
        right(&fmt_fixed(done.predicted_um, 2), 15)
    );
    text.push_str(
        "\nThe slope of the reference line is not corrected: it is the axes' squareness (or the optics' alignment).\nNo manual available states the sign a controller gives its cross table: check it with one point on the machine first (docs/cross-axis-compensation.md).\n",
    );
    for w in &done.warnings {
        let _ = writeln!(text, "Warning: {w}");
    }
    text
}

/// What `verify --test straightness` compares.
pub struct VerifyCross<'a> {
    pub before: &'a Path,
    pub after: &'a Path,
    pub controller: &'a str,
    pub table: &'a Path,
    pub active: Option<&'a str>,
    pub others: &'a [String],
    pub json: bool,
    pub cross: &'a CrossArgs,
}

/// A straightness test's file.
fn straightness(path: &Path) -> Result<AxisData> {
    let options = ReadOptions::default();
    Ok(axcheck::one_file::read_geometry(path, TestKind::Straightness, options)?.data)
}

/// `--other-straightness AXIS=BEFORE,AFTER`, each pair read.
fn other_outputs(given: &[String]) -> Result<Vec<(String, AxisData, AxisData)>> {
    given
        .iter()
        .map(|g| {
            let parsed = g
                .split_once('=')
                .and_then(|(axis, files)| Some((axis, files.split_once(',')?)));
            let Some((axis, (before, after))) = parsed else {
                bail!("--other-straightness: expected AXIS=BEFORE,AFTER, got `{g}`");
            };
            let (b, a) = (
                straightness(Path::new(before))?,
                straightness(Path::new(after))?,
            );
            Ok((axis.to_string(), b, a))
        })
        .collect()
}

/// Runs the verification; the text or JSON and whether the table was effective.
pub fn verify_command(v: VerifyCross) -> Result<(String, bool)> {
    let format = format(v.controller)?;
    let (before, after) = (straightness(v.before)?, straightness(v.after)?);
    let new = read_table(v.table, "--table", format)?;
    let old = match v.active {
        None | Some("none") => None,
        Some(file) => Some(read_table(Path::new(file), "--active", format)?),
    };
    let others = other_outputs(v.others)?;
    let others: Vec<OtherOutput> = (others.iter())
        .map(|(output, before, after)| OtherOutput {
            output,
            before,
            after,
            own: None,
        })
        .collect();
    let line = v.cross.line.unwrap_or_default();
    let done = verify(&before, &after, (&new, old.as_ref()), line, &others).ok_or_else(|| {
        anyhow!(
            "{} and {}: the two straightness tests must be at the same targets, two or more",
            v.before.display(),
            v.after.display()
        )
    })?;
    let effective = done.verdict == CrossVerdict::Effective;
    let name = v.after.display().to_string();
    if v.json {
        let json = serde_json::json!({ "file": name, "table": v.table.display().to_string(), "verification": done });
        return Ok((serde_json::to_string_pretty(&json)? + "\n", effective));
    }
    Ok((render(&done, &new, &name, line), effective))
}

/// The verdict, the straightness before, predicted and achieved, and the findings.
fn render(v: &CrossVerification, table: &CrossTable, name: &str, line: ReferenceLine) -> String {
    let mut out = format!(
        "Verification of {name} (cross table: {} corrected along {}): {}\n\n",
        table.output,
        table.input,
        words(v.verdict)
    );
    let _ = writeln!(
        out,
        "Straightness ({} line)  before {}  predicted {}  achieved {} µm  (scatter of a mean {} µm)",
        line.key().replace('_', "-"),
        fmt_fixed(v.before_um, 2),
        fmt_fixed(v.predicted_um, 2),
        fmt_fixed(v.achieved_um, 2),
        fmt_fixed(v.scatter_um, 2)
    );
    for f in &v.findings {
        let text = match f {
            CrossFinding::SignInverted => "sign inverted: the re-measurement is the test before minus the table's corrections; the controller adds the table with the other sign (write it negated)".to_string(),
            CrossFinding::WrongAxis { output } => format!(
                "wrong axis: this test is unchanged and {output}'s straightness moved by the table's corrections; the table acts on {output}"
            ),
        };
        let _ = writeln!(out, "\n{text}");
    }
    out
}

/// The verdict in words.
fn words(v: CrossVerdict) -> &'static str {
    match v {
        CrossVerdict::Effective => "effective (as predicted, within the scatter)",
        CrossVerdict::PartlyEffective => {
            "partly effective (nearer the prediction than before, not within the scatter)"
        }
        CrossVerdict::NotEffective => "not effective (as before the table)",
        CrossVerdict::MadeWorse => "made worse (further from straight than before)",
    }
}
