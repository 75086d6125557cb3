//! `axcheck simulate`: an error model and a test plan produce a measurement file.

use anyhow::{Context, Result, bail};
use axcheck::measurement::csv;
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use std::path::{Path, PathBuf};

/// What `simulate` is asked for.
#[derive(Debug, clap::Args)]
pub struct SimulateArgs {
    /// Simulation file: kind, seed, model terms and plan.
    #[arg(required_unless_present = "fleet")]
    model: Option<PathBuf>,
    /// Output CSV (default: standard output); with --fleet the output folder.
    #[arg(long, short, visible_alias = "out")]
    output: Option<PathBuf>,
    /// Write a campaign of this many axes with their data files into --out.
    #[arg(long, conflicts_with = "model", requires = "output")]
    fleet: Option<usize>,
    /// Seed overriding the file's.
    #[arg(long)]
    seed: Option<u64>,
    /// The machine measured with this table active (in --controller's format): its
    /// correction added to every reading, as the controller adds it.
    #[arg(long, value_name = "TABLE", requires = "controller")]
    active: Option<PathBuf>,
    /// The backlash parameter active with it, µm or arcsec.
    #[arg(
        long,
        value_name = "N",
        requires = "controller",
        allow_negative_numbers = true
    )]
    active_backlash: Option<f64>,
    /// The controller whose format --active is in.
    #[arg(long, short)]
    controller: Option<String>,
    /// A plan file (`axcheck plan -o`) in place of the model's plan: its targets, runs,
    /// cycle, overrun, dwell and feed.
    #[arg(long, value_name = "PLAN.yaml")]
    plan: Option<PathBuf>,
    /// Write the model's straightness along this axis (µm) or its rotation about it
    /// (arcsec) instead of the positioning test: a letter of `model.geometry`.
    #[arg(long, value_name = "LETTER", conflicts_with_all = ["fleet", "active", "controller"])]
    geometry: Option<char>,
}

/// Runs `simulate`: writes the fleet or the file, or returns the CSV to print.
pub fn command(args: &SimulateArgs) -> Result<Option<String>> {
    if let (Some(axes), Some(dir)) = (args.fleet, &args.output) {
        fleet(axes, args.seed.unwrap_or(1), dir)?;
        return Ok(None);
    }
    let Some(model) = &args.model else {
        bail!("give a simulation file, or --fleet N --out DIR");
    };
    let active = ActiveRequest {
        table: args.active.as_deref(),
        backlash: args.active_backlash,
        controller: args.controller.as_deref(),
    };
    let csv = run(
        model,
        args.seed,
        &active,
        args.plan.as_deref(),
        args.geometry,
    )?;
    let Some(path) = &args.output else {
        return Ok(Some(csv));
    };
    axcheck::atomic::write(path, csv.as_bytes())
        .with_context(|| format!("cannot write {}", path.display()))?;
    super::tell(&format!("axcheck: wrote {}", path.display()));
    Ok(None)
}

/// The compensation active on the simulated machine (`--active`, `--active-backlash`,
/// `--controller`).
pub struct ActiveRequest<'a> {
    pub table: Option<&'a Path>,
    pub backlash: Option<f64>,
    pub controller: Option<&'a str>,
}

/// Simulates `model` (on `plan`'s targets and cycle when one is given), with `active`'s
/// correction added to every reading as the controller adds it, and returns the CSV text.
pub fn run(
    model: &Path,
    seed: Option<u64>,
    active: &ActiveRequest,
    plan: Option<&Path>,
    geometry: Option<char>,
) -> Result<String> {
    let text = axcheck::files::read_to_string(model)
        .with_context(|| format!("cannot read the model file {}", model.display()))?;
    let mut sim = Simulation::from_yaml(&text, &model.display().to_string())?;
    if let Some(path) = plan {
        let text = axcheck::files::read_to_string(path)
            .with_context(|| format!("cannot read the plan {}", path.display()))?;
        let plan = axcheck::plan::file::from_yaml(&text, &path.display().to_string())?;
        if plan.axis.kind != sim.kind {
            bail!(
                "{} is a plan for a {} axis, {} a model of a {} one",
                path.display(),
                plan.axis.kind,
                model.display(),
                sim.kind
            );
        }
        sim.plan = plan.test_plan();
        sim.validate()
            .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    }
    let seed = seed.unwrap_or(sim.seed);
    if let Some(letter) = geometry {
        return geometry_test(&sim, seed, letter.to_ascii_uppercase(), model);
    }
    let mut data = sim.run(seed);
    let mut with = None;
    if let Some(name) = active.controller {
        let controller = super::compensate::controller(name)?;
        let table = active.table.map(|p| p.to_string_lossy().into_owned());
        let state = super::compensate::active_state(
            table.as_deref(),
            active.backlash,
            controller,
            data.kind,
            None,
        )?
        .unwrap_or_default();
        if let Some(total) = state.total(controller.backlash(), data.kind) {
            data = axcheck::compensate::apply(&total, &data);
            with = Some(format!(
                "measured with {} active ({})",
                table.as_deref().unwrap_or("a backlash"),
                controller.name()
            ));
        }
    }
    let name = model
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let mut comments = vec![format!(
        "simulated by axcheck {} from {name}, seed {seed}, {} cycle",
        env!("CARGO_PKG_VERSION"),
        sim.plan.cycle.name()
    )];
    if let Some(d) = &sim.description {
        comments.push(d.clone());
    }
    comments.extend(with);
    Ok(csv::write(&data, &comments))
}

/// The model's straightness or rotation test `letter` as CSV text.
fn geometry_test(sim: &Simulation, seed: u64, letter: char, model: &Path) -> Result<String> {
    let g = &sim.model.geometry;
    let Some(data) = sim.run_geometry(seed, letter) else {
        let known: Vec<String> = (g.straightness.keys().chain(g.angular.keys()))
            .map(char::to_string)
            .collect();
        bail!(
            "--geometry {letter}: {} has no straightness along or rotation about {letter} in model.geometry (it has: {})",
            model.display(),
            match known.is_empty() {
                true => "none".to_string(),
                false => known.join(", "),
            }
        );
    };
    let axis = g.axis.unwrap_or('?');
    let (what, write): (_, fn(&_, &_) -> String) = match g.straightness.contains_key(&letter) {
        true => ("straightness along", csv::write),
        false => ("rotation about", csv::write_angular),
    };
    let name = model.file_name().map(|n| n.to_string_lossy().into_owned());
    let comments = vec![format!(
        "simulated by axcheck {} from {}, seed {seed}: the {axis} axis's {what} {letter} (E{letter}{axis})",
        env!("CARGO_PKG_VERSION"),
        name.unwrap_or_default()
    )];
    Ok(write(&data, &comments))
}

/// Writes a synthetic fleet campaign into `dir`.
pub fn fleet(axes: usize, seed: u64, dir: &Path) -> Result<()> {
    let most = axcheck::simulate::fleet::MAX_AXES;
    if axes == 0 || axes > most {
        anyhow::bail!("--fleet {axes}: a fleet has 1 to {most} axes; ask for fewer");
    }
    let start = std::time::Instant::now();
    let _lock = axcheck::session::lock_folders(dir, None, false, &|m| {
        super::tell(&format!("axcheck: {m}"))
    })?;
    let fleet = axcheck::simulate::fleet::generate(axes, seed);
    for f in &fleet.files {
        let path = dir.join(&f.path);
        axcheck::atomic::write(&path, f.text.as_bytes())
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    let campaign = dir.join("campaign.yaml");
    axcheck::atomic::write(&campaign, fleet.campaign_yaml.as_bytes())
        .with_context(|| format!("cannot write {}", campaign.display()))?;
    super::tell(&format!(
        "axcheck: wrote {} ({} axes, {} readings) in {:.1} s",
        campaign.display(),
        fleet.axes,
        fleet.readings,
        start.elapsed().as_secs_f64()
    ));
    Ok(())
}
