//! `axcheck eval --test straightness|angular|squareness`: the other laser tests of a
//! linear axis (ISO 230-1), evaluated by `axcheck::geometry`.

use super::text::left;
use anyhow::{Context, Result, bail};
use axcheck::geometry::line::ReferenceLine;
use axcheck::geometry::squareness::{self, Convention};
use axcheck::geometry::{TestKind, angular, straightness};
use axcheck::measurement::{self, ReadOptions, ReadTest};
use axcheck::one_file::{SquarenessJson, SquarenessSide, geometry_json};
use axcheck::units::{fmt_fixed, fmt_position};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// The options of the other tests (`eval --test …`).
#[derive(clap::Args, Debug, Clone)]
#[command(next_help_heading = "Other tests of a linear axis (ISO 230-1)")]
pub struct GeometryArgs {
    /// What the file holds: positioning (ISO 230-2), straightness (µm across the axis,
    /// `deviation_um`), angular (pitch, yaw or roll: `deviation_arcsec` or
    /// `deviation_urad` at `target_mm`), or squareness (with --second).
    #[arg(long, default_value = "positioning", value_parser = parse_test)]
    pub test: TestKind,
    /// Straightness: the axis the deviation is along (Y or Z for an X axis); angular: the
    /// axis of rotation (A roll, B pitch, C yaw for an X axis): ISO 230-1's EYX, EBX.
    #[arg(long, value_name = "LETTER", value_parser = parse_letter)]
    pub direction: Option<char>,
    /// The reference straight line: least-squares or end-point (ISO 230-1 3.4.12).
    #[arg(long, value_parser = parse_line)]
    pub line: Option<ReferenceLine>,
    /// Straightness: also the local straightness over any stretch of this length, mm.
    #[arg(long, value_name = "MM")]
    pub local: Option<f64>,
    /// Squareness: the second axis's straightness test (the first is FILE).
    #[arg(long, value_name = "FILE")]
    pub second: Option<PathBuf>,
    /// Squareness: the optical square's error as printed on it, arcsec.
    #[arg(long, value_name = "ARCSEC", allow_negative_numbers = true)]
    pub square_error: Option<f64>,
    /// Squareness: state it positive when the included angle is larger than 90° (over-90,
    /// HP 5528A §21, the default) or smaller (under-90).
    #[arg(long, value_parser = parse_convention)]
    pub convention: Option<Convention>,
}

fn parse_test(text: &str) -> Result<TestKind, String> {
    TestKind::parse(text)
        .ok_or_else(|| "expected positioning, straightness, angular or squareness".to_string())
}

fn parse_letter(text: &str) -> Result<char, String> {
    match text.to_ascii_uppercase().as_str() {
        l @ ("X" | "Y" | "Z" | "A" | "B" | "C") => Ok(l.chars().next().unwrap_or('?')),
        _ => Err("expected X, Y or Z (straightness) or A, B or C (angular)".into()),
    }
}

fn parse_line(text: &str) -> Result<ReferenceLine, String> {
    ReferenceLine::parse(text).ok_or_else(|| "expected least-squares or end-point".into())
}

fn parse_convention(text: &str) -> Result<Convention, String> {
    match text {
        "over-90" => Ok(Convention::OverNinetyPositive),
        "under-90" => Ok(Convention::UnderNinetyPositive),
        _ => Err("expected over-90 or under-90".into()),
    }
}

/// The options that belong to another test than the one asked, refused by name.
pub fn refuse_others(args: &GeometryArgs) -> Result<()> {
    use TestKind::{Angular, Squareness, Straightness};
    let given: [(&str, bool, &[TestKind]); 6] = [
        (
            "--direction",
            args.direction.is_some(),
            &[Straightness, Angular],
        ),
        ("--line", args.line.is_some(), &[Straightness, Squareness]),
        ("--local", args.local.is_some(), &[Straightness]),
        ("--second", args.second.is_some(), &[Squareness]),
        ("--square-error", args.square_error.is_some(), &[Squareness]),
        ("--convention", args.convention.is_some(), &[Squareness]),
    ];
    for (option, is_given, applies) in given {
        if is_given && !applies.contains(&args.test) {
            let names: Vec<&str> = applies.iter().map(|t| t.key()).collect();
            bail!(
                "{option} applies to --test {}, not to --test {}",
                names.join(" or "),
                args.test.key()
            );
        }
    }
    let rotation = matches!(args.direction, Some('A' | 'B' | 'C'));
    match (args.test, args.direction) {
        (Straightness, Some(_)) if rotation => {
            bail!("--direction of a straightness test is X, Y or Z (the axis it is along)")
        }
        (Angular, Some(_)) if !rotation => {
            bail!("--direction of an angular test is A, B or C (the axis of rotation)")
        }
        _ => Ok(()),
    }
}

/// One test file read as `test` asks: a linear axis's straightness in µm, or its angles.
fn read(path: &Path, test: TestKind, sheet: ReadOptions) -> Result<ReadTest> {
    Ok(axcheck::one_file::read_geometry(path, test, sheet)?)
}

/// `eval --test …`'s output: the text or the JSON.
pub fn run(file: &Path, sheet: ReadOptions, args: &GeometryArgs, json: bool) -> Result<String> {
    refuse_others(args)?;
    let line = args.line.unwrap_or_default();
    let name = file.display().to_string();
    match args.test {
        TestKind::Squareness => return squareness_of(file, sheet, args, json),
        TestKind::Positioning => unreachable!("positioning is eval's own"),
        _ => {}
    }
    let ReadTest { data, recognised } = read(file, args.test, sheet)?;
    let head = head(&name, &recognised, &data, args);
    Ok(match args.test {
        TestKind::Straightness => {
            let options = straightness::Options {
                line,
                local_length_mm: args.local,
            };
            let s = straightness::evaluate(&data, &options)
                .with_context(|| format!("{name}: a straightness needs two targets or more"))?;
            match json {
                true => {
                    geometry_json(args.test, args.direction, &data, &s, &name, &recognised)? + "\n"
                }
                false => head + &straightness_text(&s, &data.targets),
            }
        }
        _ => {
            let a = angular::evaluate(&data).context("no target")?;
            match json {
                true => {
                    geometry_json(args.test, args.direction, &data, &a, &name, &recognised)? + "\n"
                }
                false => head + &angular_text(&a),
            }
        }
    })
}

/// The file, its layout and the test's shape.
fn head(
    name: &str,
    recognised: &measurement::Recognised,
    data: &axcheck::measurement::AxisData,
    args: &GeometryArgs,
) -> String {
    let mut out = format!("{name}\nread as {}\n", recognised.layout.name());
    for note in &recognised.notes {
        let _ = writeln!(out, "  {note}");
    }
    let t = &data.targets;
    let what = match args.test {
        TestKind::Straightness => "Straightness",
        _ => "Angular deviation",
    };
    let symbol = args.direction.map(|d| match args.test {
        TestKind::Straightness => format!(" along {d}"),
        _ => format!(" about {d}"),
    });
    let _ = writeln!(
        out,
        "{what}{} (ISO 230-1) · {} targets {} … {} mm · n = {} per direction",
        symbol.unwrap_or_default(),
        t.len(),
        fmt_position(t[0]),
        fmt_position(t[t.len() - 1]),
        data.runs()
    );
    out
}

fn straightness_text(s: &straightness::Straightness, targets: &[f64]) -> String {
    let mut out = format!("reference line: {}\n\n", s.line.key().replace('_', " "));
    let mut row = |label: &str, value: String| {
        let _ = writeln!(out, "  {}  {value}", left(label, 30));
    };
    let um = |v: f64| format!("{} µm", fmt_fixed(v, 2));
    let trace = |t: &straightness::Trace| {
        format!(
            "{}  (slope removed {} µm/m)",
            um(t.deviation_um),
            fmt_fixed(t.line.slope_um_per_m, 2)
        )
    };
    row("straightness, both directions", trace(&s.bidirectional));
    row("straightness ↑", trace(&s.up));
    row("straightness ↓", trace(&s.down));
    let i = s.reversal_target_index;
    let at = fmt_position(targets[i - 1]);
    row(
        "reversal",
        format!("{}  at i = {i} ({at} mm)", um(s.reversal_um)),
    );
    if let Some(l) = &s.local {
        let label = format!("local, over any {} mm", fmt_position(l.length_mm));
        let span = format!("{} … {} mm", fmt_position(l.from_mm), fmt_position(l.to_mm));
        row(&label, format!("{}  {span}", um(l.deviation_um)));
    }
    let _ = writeln!(
        out,
        "\nPer target: both directions' mean deviation from the reference line (µm)"
    );
    for (p, r) in targets.iter().zip(&s.residuals_um) {
        let _ = writeln!(
            out,
            "  {:>10} mm  {:>8}",
            fmt_position(*p),
            fmt_fixed(*r, 2)
        );
    }
    out
}

fn angular_text(a: &angular::Angular) -> String {
    let mut out = String::from("\n");
    let arcsec = |v: f64| {
        format!(
            "{}″ ({} µrad)",
            fmt_fixed(v, 2),
            fmt_fixed(v / 0.648 * std::f64::consts::PI, 1)
        )
    };
    let mut row = |label: &str, value: String| {
        let _ = writeln!(out, "  {}  {value}", left(label, 30));
    };
    row("angular deviation, both", arcsec(a.deviation_arcsec));
    row("angular deviation ↑", arcsec(a.up_arcsec));
    row("angular deviation ↓", arcsec(a.down_arcsec));
    row("reversal", arcsec(a.reversal_arcsec));
    let r = a
        .repeatability_arcsec
        .map_or("not defined for one run".into(), arcsec);
    row("repeatability (max 4s)", r);
    out
}

/// The squareness of FILE's axis and --second's.
fn squareness_of(
    file: &Path,
    sheet: ReadOptions,
    args: &GeometryArgs,
    json: bool,
) -> Result<String> {
    let Some(second) = &args.second else {
        bail!("--test squareness needs --second FILE, the other axis's straightness test")
    };
    let method = args.line.unwrap_or_default();
    let convention = args.convention.unwrap_or_default();
    let line = |path: &Path| -> Result<(ReadTest, straightness::Trace)> {
        let read = read(path, TestKind::Straightness, sheet)?;
        let options = straightness::Options {
            line: method,
            local_length_mm: None,
        };
        let s = straightness::evaluate(&read.data, &options).with_context(|| {
            format!(
                "{}: a straightness needs two targets or more",
                path.display()
            )
        })?;
        Ok((read, s.bidirectional))
    };
    let (first_read, first) = line(file)?;
    let (second_read, second_trace) = line(second)?;
    let square_error = args.square_error.unwrap_or(0.0);
    let sq = squareness::evaluate(&first.line, &second_trace.line, square_error, convention);
    let (a, b) = (file.display().to_string(), second.display().to_string());
    if json {
        let value = SquarenessJson {
            test: TestKind::Squareness,
            line: method,
            squareness: &sq,
            first: SquarenessSide {
                file: &a,
                recognised: &first_read.recognised,
                straightness: &first,
            },
            second: SquarenessSide {
                file: &b,
                recognised: &second_read.recognised,
                straightness: &second_trace,
            },
        };
        return Ok(serde_json::to_string_pretty(&value)? + "\n");
    }
    let sign = match convention {
        Convention::OverNinetyPositive => "positive: the included angle is larger than 90°",
        Convention::UnderNinetyPositive => "positive: the included angle is smaller than 90°",
    };
    let mut out = format!(
        "Squareness (ISO 230-1 3.6.7; HP 5528A §21: θ₂ − θ₁ + the square's error) · reference lines: {}\n",
        method.key().replace('_', " ")
    );
    let mut row = |label: &str, value: String| {
        let _ = writeln!(out, "  {}  {value}", left(label, 30));
    };
    let slope = |t: &straightness::Trace| fmt_fixed(t.line.slope_um_per_m, 2);
    row(
        "first axis θ₁",
        format!(
            "{}″  slope {} µm/m  {a}",
            fmt_fixed(sq.first_arcsec, 2),
            slope(&first)
        ),
    );
    row(
        "second axis θ₂",
        format!(
            "{}″  slope {} µm/m  {b}",
            fmt_fixed(sq.second_arcsec, 2),
            slope(&second_trace)
        ),
    );
    row(
        "optical square's error",
        format!("{}″", fmt_fixed(sq.square_error_arcsec, 2)),
    );
    row(
        "squareness",
        format!(
            "{}″ = {} µm/m  ({sign})",
            fmt_fixed(sq.error_arcsec, 2),
            fmt_fixed(sq.error_um_per_m, 2)
        ),
    );
    Ok(out)
}
