//! `axcheck eval --test straightness|angular|squareness`: the other laser tests of a
//! linear axis (ISO 230-1), evaluated by `axcheck::geometry`.

use super::text::left;
use anyhow::{Context, Result, bail};
use axcheck::geometry::line::ReferenceLine;
use axcheck::geometry::optics::{Optics, Preset};
use axcheck::geometry::squareness::Convention;
use axcheck::geometry::uncertainty::{Accuracy, Uncertain};
use axcheck::geometry::{TestKind, angular, straightness};
use axcheck::measurement::{self, ReadOptions, ReadTest};
use axcheck::one_file::{
    OtherOptions, OtherResult, SquarenessOptions, evaluate_other, evaluate_squareness,
    geometry_json,
};
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
    /// Squareness: the standard uncertainty of the square's error (its calibration),
    /// arcsec.
    #[arg(long, value_name = "ARCSEC")]
    pub square_u: Option<f64>,
    /// The optics' accuracy for U, as its specification states it:
    /// `PERCENT,FIXED,PER_M[,PER_M2]` (± PERCENT % of the value + FIXED + PER_M·M +
    /// PER_M2·M², M the travel in metres, in µm for straightness and arcsec for angular and
    /// squareness), or a preset's name: `hp5528a-squareness-short`,
    /// `hp5528a-squareness-long` (HP 5528A User's Guide §13). Unstated, U holds the scatter
    /// only and says so.
    #[arg(long, value_name = "SPEC", value_parser = parse_optics)]
    pub optics: Option<Optics>,
}

pub fn parse_test(text: &str) -> Result<TestKind, String> {
    TestKind::parse(text)
        .ok_or_else(|| "expected positioning, straightness, angular or squareness".to_string())
}

fn parse_letter(text: &str) -> Result<char, String> {
    match text.to_ascii_uppercase().as_str() {
        l @ ("X" | "Y" | "Z" | "A" | "B" | "C") => Ok(l.chars().next().unwrap_or('?')),
        _ => Err("expected X, Y or Z (straightness) or A, B or C (angular)".into()),
    }
}

pub fn parse_line(text: &str) -> Result<ReferenceLine, String> {
    ReferenceLine::parse(text).ok_or_else(|| "expected least-squares or end-point".into())
}

fn parse_optics(text: &str) -> Result<Optics, String> {
    let numbers = || {
        format!(
            "expected PERCENT,FIXED,PER_M[,PER_M2] (numbers ≥ 0) or a preset: {}",
            Accuracy::preset_names().join(", ")
        )
    };
    if text.trim().starts_with(|c: char| c.is_ascii_alphabetic()) {
        return Preset::find(text)
            .map(Optics::from)
            .ok_or_else(|| format!("unknown optics `{text}`; {}", numbers()));
    }
    let parts: Vec<f64> = (text.split(','))
        .map(|p| p.trim().parse::<f64>())
        .collect::<Result<_, _>>()
        .map_err(|_| numbers())?;
    if !parts.iter().all(|v| v.is_finite() && *v >= 0.0) {
        return Err(numbers());
    }
    match parts[..] {
        [percent, fixed, per_m] | [percent, fixed, per_m, _] => Ok(Accuracy {
            fraction: percent / 100.0,
            fixed,
            per_m,
            per_m2: parts.get(3).copied().unwrap_or(0.0),
        }
        .into()),
        _ => Err(numbers()),
    }
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
    let given: [(&str, bool, &[TestKind]); 8] = [
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
        ("--square-u", args.square_u.is_some(), &[Squareness]),
        (
            "--optics",
            args.optics.is_some(),
            &[Straightness, Angular, Squareness],
        ),
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
    if let Some(preset) = args.optics.and_then(|o| o.preset) {
        Preset::for_test(preset.name, args.test).map_err(|e| anyhow::anyhow!("--optics {e}"))?;
    }
    let name = file.display().to_string();
    match args.test {
        TestKind::Squareness => return squareness_of(file, sheet, args, json),
        TestKind::Positioning => unreachable!("positioning is eval's own"),
        _ => {}
    }
    let ReadTest { data, recognised } = read(file, args.test, sheet)?;
    let options = OtherOptions {
        straightness: straightness::Options {
            line: args.line.unwrap_or_default(),
            local_length_mm: args.local,
        },
        optics: args.optics,
    };
    let done = evaluate_other(&data, args.test, &options)
        .with_context(|| format!("{name}: the test needs two targets or more"))?;
    if json {
        let text = geometry_json(args.test, args.direction, &data, &done, &name, &recognised)?;
        return Ok(text + "\n");
    }
    let (result, u) = &done;
    let body = match result {
        OtherResult::Straightness(s) => straightness_text(s, u, &data.targets),
        OtherResult::Angular(a) => angular_text(a, u),
        // Only a campaign's squareness pair holds one; `eval` prints its own below.
        OtherResult::Squareness(s) => {
            format!(
                "  squareness {}″\n",
                fmt_fixed(s.squareness.error_arcsec, 2)
            )
        }
    };
    Ok(head(&name, &recognised, &data, args) + &body + &u_notes(u))
}

/// What U leaves out, a line each.
fn u_notes(u: &Uncertain) -> String {
    u.notes.iter().map(|n| format!("  U: {n}\n")).collect()
}

/// `± U` after a value.
fn plus_minus(u: &Uncertain, unit: &str) -> String {
    format!("± {}{unit} (U, k = {})", fmt_fixed(u.expanded, 2), u.k)
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

fn straightness_text(s: &straightness::Straightness, u: &Uncertain, targets: &[f64]) -> String {
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
    let both = format!("{}  {}", trace(&s.bidirectional), plus_minus(u, " µm"));
    row("straightness, both directions", both);
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

fn angular_text(a: &angular::Angular, u: &Uncertain) -> String {
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
    let both = format!("{}  {}", arcsec(a.deviation_arcsec), plus_minus(u, "″"));
    row("angular deviation, both", both);
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
    let first_read = read(file, TestKind::Straightness, sheet)?;
    let second_read = read(second, TestKind::Straightness, sheet)?;
    let options = SquarenessOptions {
        line: method,
        square_error_arcsec: args.square_error.unwrap_or(0.0),
        square_u_arcsec: args.square_u,
        convention,
        optics: args.optics,
    };
    let done = evaluate_squareness(&first_read.data, &second_read.data, &options).map_err(|k| {
        let path = [file, second.as_path()][k - 1];
        anyhow::anyhow!(
            "{}: a straightness needs two targets or more",
            path.display()
        )
    })?;
    let (sq, first, second_trace) = (&done.squareness, &done.first, &done.second);
    let (a, b) = (file.display().to_string(), second.display().to_string());
    if json {
        let sides = (
            (a.as_str(), &first_read.recognised),
            (b.as_str(), &second_read.recognised),
        );
        return Ok(done.json(sides.0, sides.1)? + "\n");
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
            slope(first)
        ),
    );
    row(
        "second axis θ₂",
        format!(
            "{}″  slope {} µm/m  {b}",
            fmt_fixed(sq.second_arcsec, 2),
            slope(second_trace)
        ),
    );
    row(
        "optical square's error",
        format!("{}″", fmt_fixed(sq.square_error_arcsec, 2)),
    );
    row(
        "squareness",
        format!(
            "{}″ = {} µm/m  {}  ({sign})",
            fmt_fixed(sq.error_arcsec, 2),
            fmt_fixed(sq.error_um_per_m, 2),
            plus_minus(&done.uncertainty, "″")
        ),
    );
    Ok(out + &u_notes(&done.uncertainty))
}
