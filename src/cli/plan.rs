//! `axcheck plan`: the test plan of an axis before the laser is set up, the part program
//! that runs it on the control, and the target list for the laser software.

use super::text::right;
use anyhow::{Context, Result, anyhow, bail};
use axcheck::axis_model::Cycle;
use axcheck::campaign::{AxisEntry, Campaign};
use axcheck::evaluate::StandardId;
use axcheck::geometry::TestKind;
use axcheck::plan::programs::{Coordinates, GcodeSystem};
use axcheck::plan::{self, Axis, Motion, Plan, file, laser, programs};
use axcheck::units::{AxisKind, Travel, fmt_fixed};
use std::fmt::Write;
use std::path::{Path, PathBuf};

/// What `plan` is asked for.
#[derive(Debug, clap::Args)]
pub struct PlanArgs {
    /// The axis's kind: linear or rotary (with --travel).
    #[arg(long, value_parser = parse_kind)]
    kind: Option<AxisKind>,
    /// The axis travel, mm or deg: a length (1000) or its ends (-500,500).
    #[arg(long, allow_hyphen_values = true)]
    travel: Option<String>,
    /// The measurement travel, first,last (default: the axis travel less the overrun at
    /// each end twice: room to reverse, ISO 230-2 2.2, and the ends kept clear).
    #[arg(long, allow_hyphen_values = true, value_name = "FIRST,LAST")]
    measurement_travel: Option<String>,
    /// Standard: iso230-2 (default), gbt17421.2, gost27843, vdi3441 or nmtba.
    #[arg(long, short, value_parser = super::parse_standard)]
    standard: Option<StandardId>,
    /// An axis of a campaign instead of --kind and --travel (with --machine and --axis).
    #[arg(long)]
    campaign: Option<PathBuf>,
    #[arg(long)]
    machine: Option<String>,
    /// The axis: its name in the campaign, and the axis address in the part program (X, C,
    /// X1) unless --address gives another.
    #[arg(long)]
    axis: Option<String>,
    /// The axis address in the part program, where it is not the campaign's axis name.
    #[arg(long)]
    address: Option<String>,
    /// The lead-screw pitch, mm or deg: the targets sample it at spread phases (4.2).
    #[arg(long, allow_negative_numbers = true, value_parser = super::parse_pitch)]
    pitch: Option<f64>,
    /// The scale's (encoder's) pitch, mm or deg: sampled too.
    #[arg(long, allow_negative_numbers = true, value_parser = super::parse_pitch)]
    scale_pitch: Option<f64>,
    /// The seed of the targets' offsets (the same seed, the same plan).
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Targets to check instead of making them, mm or deg: 10,205.3,410.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    targets: Option<Vec<f64>>,
    /// Approaches per direction (default: the standard's, 5, or 1 over a long travel).
    #[arg(long)]
    runs: Option<usize>,
    /// Test cycle: standard, step or pilgrim.
    #[arg(long, value_parser = parse_cycle)]
    cycle: Option<Cycle>,
    /// Travel beyond a target before each reversal, mm or deg (default 5).
    #[arg(long)]
    overrun: Option<f64>,
    /// Dwell at each target, s: the laser's averaging time and the settling (default 4).
    #[arg(long)]
    dwell: Option<f64>,
    /// Feed, mm/min or deg/min (default 1000).
    #[arg(long)]
    feed: Option<f64>,
    /// A plan file to read instead (to write its part program or target list).
    #[arg(long, conflicts_with_all = ["kind", "travel", "campaign", "targets"])]
    from: Option<PathBuf>,
    /// The part program's control: fanuc, siemens-840d, heidenhain, linuxcnc, twincat.
    #[arg(long)]
    program: Option<String>,
    /// A rotary axis that turns freely: measured over its whole travel with overruns
    /// beyond its ends (any other axis keeps every move inside its travel).
    #[arg(long)]
    continuous: bool,
    /// The program's coordinates: machine (default: each control's machine-coordinate
    /// form) or work (the active work offset, which the tables then need added).
    #[arg(long, value_parser = parse_coordinates, default_value = "machine")]
    coordinates: Coordinates,
    /// The machine is a lathe (a campaign machine whose type says lathe or turning is
    /// one): X in radius where the control has a radius mode, in diameter on FANUC.
    #[arg(long)]
    lathe: bool,
    /// FANUC lathe G-code system: a (default), b or c.
    #[arg(long, value_parser = parse_gcode_system)]
    gcode_system: Option<GcodeSystem>,
    /// The program's name (default: the output file's name, else ISO230 and the axis).
    #[arg(long)]
    name: Option<String>,
    /// Where to write: the part program with --program, else the plan (YAML; without -o it
    /// follows the table on the console).
    #[arg(long, short)]
    out: Option<PathBuf>,
    /// Also write the plan (YAML) here, beside a program.
    #[arg(long)]
    save_plan: Option<PathBuf>,
    /// Write the readings in their order (CSV) for the laser software.
    #[arg(long)]
    readings_csv: Option<PathBuf>,
    /// Write the target list as the TARGET DATA block of a Renishaw file.
    #[arg(long)]
    rtl_targets: Option<PathBuf>,
}

fn parse_kind(text: &str) -> Result<AxisKind, String> {
    match text {
        "linear" => Ok(AxisKind::Linear),
        "rotary" => Ok(AxisKind::Rotary),
        _ => Err(format!("expected linear or rotary, got `{text}`")),
    }
}

fn parse_coordinates(text: &str) -> Result<Coordinates, String> {
    Coordinates::parse(text).ok_or_else(|| format!("expected machine or work, got `{text}`"))
}

fn parse_gcode_system(text: &str) -> Result<GcodeSystem, String> {
    GcodeSystem::parse(text).ok_or_else(|| format!("expected a, b or c, got `{text}`"))
}

fn parse_cycle(text: &str) -> Result<Cycle, String> {
    match text {
        "standard" => Ok(Cycle::Standard),
        "step" => Ok(Cycle::Step),
        "pilgrim" => Ok(Cycle::Pilgrim),
        _ => Err(format!("expected standard, step or pilgrim, got `{text}`")),
    }
}

/// `1000` or `-500,500`.
fn parse_pair(text: &str, what: &str) -> Result<Vec<f64>> {
    text.split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or_else(|| anyhow!("{what}: expected numbers, got `{text}`"))
        })
        .collect()
}

/// Runs `plan`: writes what was asked and returns the console's text.
pub fn run(args: &PlanArgs) -> Result<String> {
    let made = make(args)?;
    let plan = made.plan;
    let mut text = table(&plan);
    if let Some(name) = &args.program {
        let dialect = programs::find(name).ok_or_else(|| {
            anyhow!(
                "unknown control `{name}`; known: {}",
                programs::names().join(", ")
            )
        })?;
        let address = made.address.ok_or_else(|| {
            anyhow!("give the axis's address on the control with --axis (X, Y, Z, C …)")
        })?;
        let name = program_name(args, &address);
        let lathe = lathe_of(args, made.lathe)?;
        let job = programs::Job {
            coordinates: args.coordinates,
            lathe,
            ..programs::Job::new(&plan, &address, &name)
        };
        let program = dialect.write(&job)?;
        if args.coordinates == Coordinates::Work {
            let [work, tables] = programs::work_note(&address);
            let _ = writeln!(text, "\nNote: {work}. {tables}.");
        }
        match &args.out {
            Some(path) => written(path, &program, &mut text, "part program")?,
            None => text.push_str(&program),
        }
        if let Some(path) = &args.save_plan {
            written(path, &file::to_yaml(&plan), &mut text, "plan")?;
        }
    } else if let Some(path) = &args.out {
        written(path, &file::to_yaml(&plan), &mut text, "plan")?;
    } else {
        text.push('\n');
        text.push_str(&file::to_yaml(&plan));
    }
    if let Some(path) = &args.readings_csv {
        written(
            path,
            &laser::readings_csv(&plan),
            &mut text,
            "reading order",
        )?;
    }
    if let Some(path) = &args.rtl_targets {
        written(path, &laser::rtl_targets(&plan), &mut text, "target block")?;
    }
    Ok(text)
}

/// Writes `body` to `path` atomically and says so.
fn written(path: &Path, body: &str, text: &mut String, what: &str) -> Result<()> {
    axcheck::atomic::write(path, body.as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))?;
    let _ = writeln!(text, "Wrote the {what} to {}", path.display());
    Ok(())
}

/// The program's name: given, else the output file's stem (letters, digits and _ in upper
/// case), else ISO230 and the axis.
fn program_name(args: &PlanArgs, address: &str) -> String {
    let from_file = args
        .out
        .as_deref()
        .and_then(Path::file_stem)
        .map(|s| s.to_string_lossy().to_uppercase())
        .map(|s| {
            s.chars()
                .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect::<String>()
        })
        .filter(|s| !s.is_empty());
    args.name
        .clone()
        .or(from_file)
        .unwrap_or_else(|| format!("ISO230{address}"))
}

/// The lathe's G-code system when the machine is a lathe (`--lathe`, or a campaign
/// machine's type); `--gcode-system` only with one.
fn lathe_of(args: &PlanArgs, campaign_lathe: bool) -> Result<Option<GcodeSystem>> {
    let lathe = args.lathe || campaign_lathe;
    if args.gcode_system.is_some() && !lathe {
        bail!(
            "--gcode-system applies to a lathe: give --lathe (a campaign machine whose type says lathe or turning is one)"
        );
    }
    Ok(lathe.then(|| args.gcode_system.unwrap_or_default()))
}

/// What `make` finds: the plan, the axis address for a program, and whether the
/// campaign's machine is a lathe.
struct Made {
    plan: Plan,
    address: Option<String>,
    lathe: bool,
}

/// The plan asked for, and the axis address for a program.
fn make(args: &PlanArgs) -> Result<Made> {
    if let Some(path) = &args.from {
        let text = axcheck::files::read_to_string(path)
            .with_context(|| format!("cannot read the plan {}", path.display()))?;
        let mut plan = file::from_yaml(&text, &path.display().to_string())?;
        if args.continuous {
            plan.axis.continuous = true;
            plan::measurement_travel(&plan.axis, plan.motion.overrun)?;
        }
        let address = args.address.clone().or(args.axis.clone());
        return Ok(Made {
            plan,
            address,
            lathe: false,
        });
    }
    let (axis, motion, address, lathe) = match &args.campaign {
        Some(path) => from_campaign(path, args)?,
        None => (
            standalone_axis(args)?,
            motion(args, &Motion::default()),
            args.axis.clone(),
            false,
        ),
    };
    let plan = match &args.targets {
        Some(t) => plan::with_targets(&axis, &motion, t.clone())?,
        None => {
            check_target_count(&axis, &motion)?;
            plan::plan(&axis, &motion, args.seed)?
        }
    };
    Ok(Made {
        plan,
        address: args.address.clone().or(address),
        lathe,
    })
}

/// Refuses, before any target is placed, an axis whose travel asks for more targets than
/// a plan holds ([`plan::MAX_TARGETS`]): `--travel 1e9` placed 4 million and wrote a
/// 658 MB program.
fn check_target_count(axis: &Axis, motion: &Motion) -> Result<()> {
    let [first, last] = plan::measurement_travel(axis, motion.overrun)?;
    let (least, _) = plan::targets::least(axis.kind, axis.standard, last - first);
    if least > plan::MAX_TARGETS {
        let unit = axis.kind.position_unit();
        bail!(
            "a measurement travel of {} {unit} needs {least} targets under {}, more than the {} a plan holds; check --travel (mm for a linear axis, deg for a rotary one) or plan the travel in parts",
            last - first,
            axis.standard.title(),
            plan::MAX_TARGETS
        );
    }
    Ok(())
}

/// The axis from --kind, --travel, --measurement-travel, --standard, --pitch.
fn standalone_axis(args: &PlanArgs) -> Result<Axis> {
    let kind = args.kind.ok_or_else(|| {
        anyhow!("give --kind linear|rotary and --travel, or --campaign FILE --machine M --axis A")
    })?;
    let travel = args
        .travel
        .as_deref()
        .ok_or_else(|| anyhow!("give --travel LENGTH or --travel START,END"))?;
    Ok(Axis {
        kind,
        standard: args.standard.unwrap_or(StandardId::Iso230_2),
        travel: travel_of(&parse_pair(travel, "--travel")?)?,
        continuous: args.continuous,
        measurement_travel: measurement_of(args)?,
        pitch: args.pitch,
        scale_pitch: args.scale_pitch,
    })
}

fn travel_of(v: &[f64]) -> Result<Travel> {
    match v {
        [l] if *l > 0.0 => Ok(Travel::Length(*l)),
        [a, b] if b > a => Ok(Travel::Range([*a, *b])),
        _ => bail!("--travel: expected a length > 0 or START,END with END > START"),
    }
}

fn measurement_of(args: &PlanArgs) -> Result<Option<[f64; 2]>> {
    let Some(text) = &args.measurement_travel else {
        return Ok(None);
    };
    match parse_pair(text, "--measurement-travel")?[..] {
        [a, b] if b > a => Ok(Some([a, b])),
        _ => bail!("--measurement-travel: expected FIRST,LAST with LAST > FIRST"),
    }
}

/// The motion from the arguments over `base`.
fn motion(args: &PlanArgs, base: &Motion) -> Motion {
    Motion {
        runs: args.runs.or(base.runs),
        cycle: args.cycle.unwrap_or(base.cycle),
        overrun: args.overrun.unwrap_or(base.overrun),
        dwell_s: args.dwell.unwrap_or(base.dwell_s),
        feed: args.feed.unwrap_or(base.feed),
    }
}

/// The axis, the motion, the axis address and whether the machine is a lathe.
type CampaignAxis = (Axis, Motion, Option<String>, bool);

/// Whether a machine's `type` says it is a lathe (`CNC turning centre`, `lathe`).
fn is_lathe(machine_type: Option<&str>) -> bool {
    machine_type.is_some_and(|t| {
        let t = t.to_lowercase();
        t.contains("lathe") || t.contains("turning")
    })
}

/// The axis `--axis` of machine `--machine` in the campaign, its conditions as the motion's
/// defaults.
fn from_campaign(path: &Path, args: &PlanArgs) -> Result<CampaignAxis> {
    let (machine, name) = match (&args.machine, &args.axis) {
        (Some(m), Some(a)) => (m, a),
        _ => bail!("--campaign needs --machine M and --axis A"),
    };
    let campaign = Campaign::load(path)?;
    let entries: Vec<_> = (campaign.axes())
        .filter(|(m, a)| &m.info.id == machine && &a.name == name)
        .collect();
    // A plan is of a positioning test (ISO 230-2): the axis's straightness and angular
    // entries (ISO 230-1) are not planned by its rules.
    let positioning = |(_, a): &&(&_, &AxisEntry)| {
        (a.spec.as_ref()).map_or(true, |s| s.raw.test == TestKind::Positioning)
    };
    let Some(&(found, entry)) = entries.iter().find(positioning) else {
        match entries.is_empty() {
            true => bail!(
                "{}: no axis `{name}` of machine `{machine}`",
                path.display()
            ),
            false => bail!(
                "{}: axis `{name}` of machine `{machine}` has no positioning test: `plan` plans an ISO 230-2 positioning test, not its straightness or angular tests",
                path.display()
            ),
        }
    };
    let lathe = is_lathe(found.info.machine_type.as_deref());
    let spec = entry.spec.as_ref().map_err(|e| anyhow!("{e}"))?;
    let raw = &spec.raw;
    let travel = raw.travel.ok_or_else(|| {
        anyhow!(
            "{}: axis `{name}` of machine `{machine}` gives no travel: a plan needs it; add `travel:` to the axis",
            path.display()
        )
    })?;
    let c = &raw.conditions;
    let base = Motion {
        cycle: c.cycle.unwrap_or_default(),
        dwell_s: c.dwell_s.unwrap_or(4.0),
        feed: c.feed_mm_per_min.unwrap_or(1000.0),
        ..Motion::default()
    };
    let axis = Axis {
        kind: raw.kind,
        standard: args.standard.unwrap_or(spec.standard),
        travel,
        continuous: raw.continuous || args.continuous,
        measurement_travel: measurement_of(args)?.or(raw.measurement_travel),
        pitch: args.pitch.or(raw.pitch),
        scale_pitch: args.scale_pitch,
    };
    Ok((axis, motion(args, &base), Some(name.clone()), lathe))
}

/// The plan as a table: each target, its offset r from even spacing, and the rules.
fn table(plan: &Plan) -> String {
    let unit = plan.axis.kind.position_unit();
    let [a, b] = plan.measurement_travel;
    let m = plan.targets.len();
    let even = |i: usize| a + (b - a) * i as f64 / (m.max(2) - 1) as f64;
    let mut text = format!(
        "Test plan: {} targets over {} … {} {unit} ({}), n = {}, {} cycle, overrun {} {unit}, dwell {} s, feed {} {unit}/min\n\n",
        m,
        fmt_fixed(a, 3),
        fmt_fixed(b, 3),
        plan.axis.standard.title(),
        plan.runs,
        plan.motion.cycle.name(),
        fmt_fixed(plan.motion.overrun, 3),
        fmt_fixed(plan.motion.dwell_s, 1),
        fmt_fixed(plan.motion.feed, 0)
    );
    let pitch = plan.axis.pitch;
    let _ = writeln!(
        text,
        "{}  {}  {}{}",
        right("i", 5),
        right(&format!("P_i ({unit})"), 14),
        right(&format!("r ({unit})"), 10),
        if pitch.is_some() {
            "  phase of the pitch"
        } else {
            ""
        }
    );
    for (i, t) in plan.targets.iter().enumerate() {
        let phase = pitch.map_or(String::new(), |p| {
            format!("  {}", right(&fmt_fixed((t / p).rem_euclid(1.0), 2), 18))
        });
        let _ = writeln!(
            text,
            "{}  {}  {}{phase}",
            right(&(i + 1).to_string(), 5),
            right(&fmt_fixed(*t, 3), 14),
            right(&fmt_fixed(t - even(i), 3), 10)
        );
    }
    text.push('\n');
    if plan.findings.is_empty() {
        let _ = writeln!(
            text,
            "Every test-plan rule holds (the rules `check` and `run` apply to its measurement)."
        );
    }
    for f in &plan.findings {
        let _ = writeln!(
            text,
            "{} {} ({}): {}",
            f.severity.name().to_uppercase(),
            f.id,
            f.clause,
            f.message
        );
    }
    text
}
