//! `axcheck verify`: the re-measurement after a table was loaded, compared with the
//! prediction from the measurement before and the table: the verdict, what went wrong and
//! the comparison per target.

use super::compensate::{active_state, controller, read_table};
use super::text::{left, right};
use anyhow::{Result, anyhow};
use axcheck::campaign::stages::compensate::{compared_tables, other_table};
use axcheck::evaluate::StandardId;
use axcheck::measurement;
use axcheck::units::{AxisKind, fmt_fixed, fmt_position};
use axcheck::verify::{self, Effectiveness, Other, Verification};
use std::fmt::Write;
use std::path::PathBuf;

/// What `verify` compares.
#[derive(Debug, clap::Args)]
pub struct VerifyArgs {
    /// The measurement before the table was loaded.
    before: PathBuf,
    /// The re-measurement with the table active.
    after: PathBuf,
    /// The controller whose format the tables are in.
    #[arg(long, short)]
    controller: String,
    /// The table loaded since the measurement before, in the controller's format.
    #[arg(long)]
    table: PathBuf,
    /// The backlash parameter loaded with the table, µm or arcsec (Siemens MD32450, …);
    /// default: the one active before.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    backlash: Option<f64>,
    /// The table active during the measurement before, or `none` (the default): the
    /// prediction applies the difference between the two tables.
    #[arg(long, value_name = "TABLE|none")]
    active: Option<String>,
    /// The backlash parameter active during the measurement before, µm or arcsec.
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    active_backlash: Option<f64>,
    /// The axis's name on the controller, to pick its table from a file of several.
    #[arg(long)]
    axis: Option<String>,
    /// Another axis's table, `AXIS=FILE`, to tell a table loaded on the wrong axis
    /// (repeatable).
    #[arg(long, value_name = "AXIS=FILE")]
    other: Vec<String>,
    #[command(flatten)]
    cross: super::cross::CrossArgs,
    /// Straightness: another output axis's straightness along the same input, before and
    /// after, to tell a cross table loaded on the wrong axis (repeatable).
    #[arg(long, value_name = "AXIS=BEFORE,AFTER")]
    other_straightness: Vec<String>,
    /// Standard for the parameters compared.
    #[arg(long, short, default_value = "iso230-2", value_parser = super::parse_standard)]
    standard: StandardId,
    /// Print JSON (a stable interface) instead of text.
    #[arg(long)]
    json: bool,
}

/// Runs the verification; the text or JSON to print and whether the table was effective.
pub fn run(args: &VerifyArgs) -> Result<(String, bool)> {
    if args.cross.is_cross()? {
        return cross(args);
    }
    if !args.other_straightness.is_empty() {
        return Err(anyhow!(
            "--other-straightness applies to --test straightness"
        ));
    }
    let controller = controller(&args.controller)?;
    let before = measurement::read_file(&args.before, None)?.data;
    let after = measurement::read_file(&args.after, None)?.data;
    let kind = after.kind;
    let axis = args.axis.as_deref();
    let old = active_state(
        args.active.as_deref(),
        args.active_backlash,
        controller,
        kind,
        axis,
    )?
    .unwrap_or_default();
    let table = read_table(&args.table, "--table", controller, kind, axis)?;
    let file = args.table.display().to_string();
    let compared = compared_tables(&old, table, &file, args.backlash, controller, kind)?;
    let others = others(&args.other, controller, kind)?;
    let input = verify::VerifyInput {
        before: &before,
        after: &after,
        old: compared.old.as_ref(),
        new: &compared.new,
        others: &others,
        controller: Some(controller),
        standard: args.standard,
    };
    let mut v = verify::verify(&input)?;
    v.notes.extend(compared.notes);
    let effective = v.verdict == Effectiveness::Effective;
    let text = if args.json {
        let name = args.after.display().to_string();
        super::json_with_file(&v.json(), &name)?
    } else {
        render(&v, kind, &args.after.display().to_string())
    };
    Ok((text, effective))
}

/// `verify --test straightness`: a cross table; the pitch table's options refused.
fn cross(args: &VerifyArgs) -> Result<(String, bool)> {
    let pitch_only = [
        ("--backlash", args.backlash.is_some()),
        ("--active-backlash", args.active_backlash.is_some()),
        ("--axis", args.axis.is_some()),
        ("--other", !args.other.is_empty()),
    ];
    if let Some((option, _)) = pitch_only.iter().find(|(_, given)| *given) {
        return Err(anyhow!(
            "{option} applies to a positioning test's table, not to a cross table (--other-straightness names another output axis's tests)"
        ));
    }
    super::cross::verify_command(super::cross::VerifyCross {
        before: &args.before,
        after: &args.after,
        controller: &args.controller,
        table: &args.table,
        active: args.active.as_deref(),
        others: &args.other_straightness,
        json: args.json,
        cross: &args.cross,
    })
}

/// `--other AXIS=FILE`, each table read as the controller reads it.
fn others(
    given: &[String],
    controller: &dyn axcheck::compensate::controllers::Controller,
    kind: AxisKind,
) -> Result<Vec<Other>> {
    given
        .iter()
        .map(|g| {
            let (axis, file) = g
                .split_once('=')
                .ok_or_else(|| anyhow!("--other: expected AXIS=FILE, got `{g}`"))?;
            let path = std::path::Path::new(file);
            Ok(other_table(axis, path, "--other", controller, kind)?)
        })
        .collect()
}

/// The verdict, E, the findings and the comparison per target.
fn render(v: &Verification, kind: AxisKind, name: &str) -> String {
    let unit = kind.deviation_symbol();
    let e = &v.e;
    let mut out = format!("Verification of {name}: {}\n\n", v.verdict.words());
    let _ = writeln!(
        out,
        "E (ISO 230-2 2.20)  before {}  predicted {}  achieved {} {unit}  (U = {} {unit}, 95 %)",
        fmt_fixed(e.before, 2),
        fmt_fixed(e.predicted, 2),
        fmt_fixed(e.achieved, 2),
        fmt_fixed(e.uncertainty, 2)
    );
    let p = axcheck::diagnose::stats::chi2_upper(v.chi2, v.dof as f64);
    let _ = writeln!(
        out,
        "Per target: χ² = {} on {} degrees of freedom against the table named ({}; rejected below P = {})",
        fmt_fixed(v.chi2, 1),
        v.dof,
        verify::explain::fmt_p(p),
        verify::ALPHA
    );
    for f in &v.findings {
        let _ = writeln!(out, "\n{}: {}", f.effect.name(), f.evidence);
    }
    for n in &v.notes {
        let _ = writeln!(out, "\nNote: {n}");
    }
    let _ = writeln!(
        out,
        "\n{}  {}  {}  {}  {}  {}  {}",
        right("target", 10),
        left("", 1),
        right("before", 9),
        right("applied", 9),
        right("predicted", 9),
        right("achieved", 9),
        right("diff", 8)
    );
    for r in &v.per_target {
        let _ = writeln!(
            out,
            "{}  {}  {}  {}  {}  {}  {}",
            right(&fmt_position(r.position), 10),
            r.direction.arrow(),
            right(&fmt_fixed(r.before, 2), 9),
            right(&fmt_fixed(r.applied, 2), 9),
            right(&fmt_fixed(r.predicted, 2), 9),
            right(&fmt_fixed(r.achieved, 2), 9),
            right(&fmt_fixed(r.difference, 2), 8)
        );
    }
    let _ = writeln!(
        out,
        "\n{unit}; diff: achieved − predicted less the constant offset {} {unit} between the two measurements (which no parameter sees); u of a diff {} {unit}.",
        fmt_fixed(v.offset, 2),
        fmt_fixed(v.per_target.first().map_or(0.0, |r| r.u), 2)
    );
    out
}
