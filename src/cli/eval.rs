//! `axcheck eval`: the parameters of one measurement file and its per-target table.

use super::text::{left, right};
use anyhow::{Result, bail};
use axcheck::evaluate::gost27843::SMethod;
use axcheck::evaluate::{Evaluation, StandardId};
use axcheck::measurement::{self, AxisData, Recognised};
use axcheck::nde::{self, NdeCorrection};
use axcheck::one_file::{Applied, EvalJson};
use axcheck::units::{AxisKind, Direction, fmt_fixed, fmt_position};
use std::fmt::Write;

/// `axcheck eval`'s arguments (`--reference` is `--ecmc-reference` here: eval has no
/// reference point).
#[derive(clap::Args)]
#[command(mut_arg(super::ECMC_REFERENCE, |a| a.visible_alias(super::REFERENCE_ALIAS)))]
pub struct EvalArgs {
    /// Measurement file (long or wide CSV, XLSX workbook, ecmc key=value or report, ecmc
    /// ISO 230 app report or CSV, Renishaw .rtl/.rta; the layout is recognised from the
    /// content).
    file: std::path::PathBuf,
    #[command(flatten)]
    sheet: super::SheetArg,
    /// Standard: iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba.
    #[arg(long, short, default_value = "iso230-2", value_parser = super::parse_standard)]
    standard: StandardId,
    /// GOST 27843 only: estimate S from the ranges, formula (6), instead of formula (5).
    #[arg(long)]
    s_from_ranges: bool,
    /// Correct the deviations to 20 °C (ISO 230-2 3.1, nominal differential expansion)
    /// with this expansion coefficient of the positioning system, µm/(m·°C); the
    /// temperature from --material-temperature, else from the file's material temperature
    /// columns.
    #[arg(long, value_name = "COEFF", allow_negative_numbers = true)]
    nde: Option<f64>,
    /// The positioning system's mean temperature during the test, °C (with --nde).
    #[arg(
        long,
        value_name = "T",
        requires = "nde",
        allow_negative_numbers = true
    )]
    material_temperature: Option<f64>,
    /// Print JSON (a stable interface) instead of text.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    other: super::geometry::GeometryArgs,
}

/// `axcheck eval`: the parameters of one file, what it was read as, and the results of
/// the tool that wrote it beside them; the text to print.
pub fn run(args: &EvalArgs) -> Result<String> {
    super::geometry::refuse_others(&args.other)?;
    if args.other.test != axcheck::geometry::TestKind::Positioning {
        refuse_positioning_options(args)?;
        return super::geometry::run(&args.file, args.sheet.options(), &args.other, args.json);
    }
    if args.s_from_ranges && args.standard != StandardId::Gost27843 {
        bail!("--s-from-ranges applies to --standard gost27843 only");
    }
    let measurement::ReadTest { data, recognised } =
        measurement::read_file_with(&args.file, &args.sheet.options())?;
    let (data, nde) = correct(args, data)?;
    let applied = Applied {
        nde,
        tolerance: None,
        decision_rule: None,
    };
    let s_method = match args.s_from_ranges {
        true => SMethod::Ranges,
        false => SMethod::Formula5,
    };
    let evaluation = axcheck::evaluate::evaluate_by(&data, args.standard, s_method);
    let name = args.file.display().to_string();
    let other = (recognised.reported.as_ref()).map(|r| axcheck::crosscheck::compare(r, &data));
    Ok(match args.json {
        true => {
            let value = EvalJson {
                evaluation: evaluation.json(),
                applied: &applied,
                file: &name,
                recognised: &recognised,
                other_tool: other.as_ref(),
                uncertainty: None,
            };
            serde_json::to_string_pretty(&value)? + "\n"
        }
        false => {
            let mut text = render(&name, &recognised, &evaluation, other.as_ref());
            let at = text.find("\nAxis parameters").unwrap_or(text.len());
            text.insert_str(at, &applied_lines(&applied));
            text
        }
    })
}

/// The options of a positioning test refused for the other tests, by name.
fn refuse_positioning_options(args: &EvalArgs) -> Result<()> {
    let test = args.other.test.key();
    if args.nde.is_some() {
        bail!("--nde corrects a positioning test to 20 °C; --test {test} takes none");
    }
    if args.s_from_ranges || args.standard != StandardId::Iso230_2 {
        bail!(
            "--standard and --s-from-ranges evaluate a positioning test; --test {test} is evaluated by ISO 230-1"
        );
    }
    if args.sheet.names_source() {
        bail!(
            "--ecmc-reference reads an ecmc ISO 230 app file, a positioning test; not --test {test}"
        );
    }
    Ok(())
}

/// The readings corrected to 20 °C when `--nde` asks (linear axes only), with what was
/// applied; else the readings as read.
fn correct(args: &EvalArgs, data: AxisData) -> Result<(AxisData, Option<NdeCorrection>)> {
    let Some(alpha) = args.nde else {
        return Ok((data, None));
    };
    if data.kind != AxisKind::Linear {
        bail!(
            "--nde: the correction to 20 °C (ISO 230-2 3.1) applies to linear axes; {} is a rotary axis's file",
            args.file.display()
        );
    }
    let temperature = match args.material_temperature {
        Some(t) => nde::Temperature::Constant(t),
        None => nde::Temperature::PerReading,
    };
    let Some((corrected, mut info)) = nde::correct(&data, alpha, temperature) else {
        bail!(
            "--nde: {} has no material temperature column (temp_NAME_c other than air): give the positioning system's mean temperature with --material-temperature T (°C)",
            args.file.display()
        );
    };
    if args.material_temperature.is_some() {
        info.source = "--material-temperature".into();
    }
    Ok((corrected, Some(info)))
}

/// `corrected to 20 °C …` or `not corrected …`, and `not judged …`, after the header.
fn applied_lines(a: &Applied) -> String {
    let nde = match &a.nde {
        Some(n) => format!(
            "corrected to 20 °C (ISO 230-2 3.1): α = {} µm/(m·°C), temperature {} °C ({}), largest correction {} µm",
            fmt_fixed(n.coefficient_um_per_m_c, 2),
            fmt_fixed(n.mean_temperature_c, 2),
            n.source,
            fmt_fixed(n.max_correction_um, 2)
        ),
        None => "not corrected to 20 °C (ISO 230-2 3.1): the deviations are as read; --nde COEFF --material-temperature T applies the correction a campaign's `nde:` applies".into(),
    };
    format!(
        "{nde}\nnot judged: eval applies no tolerance and no decision rule (a campaign's `spec:` does, in `axcheck check` and `run`)\n"
    )
}

/// Targets per block of the per-target table (keeps lines under 90 columns).
const TARGETS_PER_BLOCK: usize = 5;
const LABEL: usize = 14;
const CELL: usize = 7;

/// The report printed by `axcheck eval`: the file, what it was read as, the parameters,
/// the results of the tool that wrote the file beside them, and the per-target table.
pub fn render(
    file: &str,
    recognised: &Recognised,
    e: &Evaluation,
    other: Option<&axcheck::crosscheck::OtherTool>,
) -> String {
    let mut out = String::new();
    let unit = e.kind.deviation_symbol();
    let pos = e.kind.position_symbol();
    let (first, last) = (
        e.targets[0].position,
        e.targets[e.targets.len() - 1].position,
    );
    let _ = writeln!(out, "{file}");
    let _ = writeln!(out, "read as {}", recognised.layout.name());
    for note in &recognised.notes {
        let _ = writeln!(out, "  {note}");
    }
    let _ = writeln!(
        out,
        "{} · {} axis · {} targets {} … {} {pos} · n = {} per direction · coverage factor {}",
        e.standard.title(),
        e.kind,
        e.targets.len(),
        fmt_position(first),
        fmt_position(last),
        e.n,
        e.coverage_factor
    );
    let _ = writeln!(out, "\nAxis parameters");
    let lines: Vec<(String, String, String)> = e
        .parameters
        .iter()
        .map(|p| {
            let head = format!("{} = {} {unit}", p.symbol(), fmt_fixed(p.value, 2));
            let mut where_ = String::new();
            if let Some(i) = p.at_target {
                where_ = format!(
                    "at i = {} ({} {pos})",
                    i + 1,
                    fmt_position(e.targets[i].position)
                );
            } else if let Some((hi, lo)) = p.span {
                where_ = format!("{} − ({})", fmt_fixed(hi, 2), fmt_fixed(lo, 2));
            }
            (head, format!("{} [{}]", p.name(), p.clause()), where_)
        })
        .collect();
    let w_head = lines
        .iter()
        .map(|l| super::text::width(&l.0))
        .max()
        .unwrap_or(0);
    let w_name = lines
        .iter()
        .map(|l| super::text::width(&l.1))
        .max()
        .unwrap_or(0);
    for (head, name, where_) in &lines {
        let _ = writeln!(
            out,
            "  {}  {}  {}",
            left(head, w_head),
            left(name, w_name),
            where_
        )
        .map(|_| ());
    }
    let missing = not_applicable(e);
    if !missing.is_empty() {
        let _ = writeln!(out, "  not applicable: {}", missing.join(", "));
    }
    for note in &e.notes {
        let _ = writeln!(out, "  note: {note}");
    }
    if let Some(tool) = other {
        super::other_tool::render(&mut out, tool);
    }
    let _ = writeln!(
        out,
        "\nPer-target results ({unit}), in the layout of ISO 230-2 Table 2"
    );
    for block in (0..e.targets.len())
        .collect::<Vec<_>>()
        .chunks(TARGETS_PER_BLOCK)
    {
        out.push('\n');
        table_block(&mut out, e, block);
    }
    out
}

/// Symbols of the standard's parameters that this result leaves out (n = 1).
fn not_applicable(e: &Evaluation) -> Vec<&'static str> {
    e.not_applicable().map(|d| d.symbol).collect()
}

fn table_block(out: &mut String, e: &Evaluation, block: &[usize]) {
    let k = e.coverage_factor;
    let s_name = match e.standard {
        StandardId::Vdi3441 | StandardId::Nmtba => "σ",
        _ => "S",
    };
    let pair = 2 * CELL + 1;
    let mut row = |label: &str, cells: Vec<String>| {
        let mut line = left(label, LABEL);
        for c in cells {
            line.push(' ');
            line.push_str(&c);
        }
        let _ = writeln!(out, "{}", line.trim_end());
    };
    row(
        "i",
        block
            .iter()
            .map(|&i| right(&(i + 1).to_string(), pair))
            .collect(),
    );
    row(
        &format!("P_i / {}", e.kind.position_symbol()),
        block
            .iter()
            .map(|&i| right(&fmt_position(e.targets[i].position), pair))
            .collect(),
    );
    let both = |f: &dyn Fn(&axcheck::evaluate::DirectionResult) -> Option<f64>| -> Vec<String> {
        block
            .iter()
            .map(|&i| {
                let t = &e.targets[i];
                Direction::BOTH
                    .iter()
                    .map(|&d| {
                        right(
                            &f(t.direction(d)).map_or("–".into(), |v| fmt_fixed(v, 2)),
                            CELL,
                        )
                    })
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect()
    };
    row(
        "direction",
        block
            .iter()
            .map(|_| format!("{} {}", right("↑", CELL), right("↓", CELL)))
            .collect(),
    );
    for j in 0..e.n {
        row(
            &format!("j = {}", j + 1),
            both(&|d| d.deviations.get(j).copied()),
        );
    }
    row("X̄i↑, X̄i↓", both(&|d| Some(d.mean)));
    if e.n > 1 {
        row(&format!("{s_name}i"), both(&|d| d.s));
        row(&format!("{k}{s_name}i"), both(&|d| d.s.map(|s| k * s)));
        row(&format!("X̄i + {k}{s_name}i"), both(&|d| d.upper));
        row(&format!("X̄i − {k}{s_name}i"), both(&|d| d.lower));
        row(
            &format!("Ri↑↓ = {}{s_name}i", 2.0 * k),
            both(&|d| d.repeatability),
        );
    }
    let single = |f: &dyn Fn(&axcheck::evaluate::TargetResult) -> Option<f64>| -> Vec<String> {
        block
            .iter()
            .map(|&i| {
                right(
                    &f(&e.targets[i]).map_or("–".into(), |v| fmt_fixed(v, 2)),
                    pair,
                )
            })
            .collect()
    };
    row("Bi", single(&|t| Some(t.reversal)));
    if e.targets.iter().any(|t| t.repeatability.is_some()) {
        row("Ri", single(&|t| t.repeatability));
    }
    row("X̄i", single(&|t| Some(t.mean)));
    if e.targets.iter().any(|t| t.nmtba.is_some()) {
        row("lost_motion", single(&|t| t.nmtba.map(|x| x.lost_motion)));
    }
    if e.targets
        .iter()
        .any(|t| t.nmtba.is_some_and(|x| x.sigma_bi.is_some()))
    {
        row("sigma_bi", single(&|t| t.nmtba.and_then(|x| x.sigma_bi)));
    }
}
