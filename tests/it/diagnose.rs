//! The diagnosis (issue 5): hidden effects in simulated tests must be found and named,
//! clean tests must stay clean, and the real measurements must diagnose without error.
//!
//! Every hidden-effect test draws, per seed, a realistic axis — a smooth systematic
//! deviation (scale error and a cubic through random knots), a reversal value and white
//! scatter — and a test plan, hides one effect of moderate size among them (sizes are
//! drawn per seed, in units of the scatter's standard error σ/√n or of the estimator's own
//! standard error, always ≥ 3σ/√n), simulates the test with `axcheck simulate`'s model and
//! diagnoses it. Seeds and sizes vary; nothing is tuned to one seed.

use axcheck::diagnose::effects::outlier::Outlier as FoundOutlier;
use axcheck::diagnose::{self, Diagnosis, Effect, Options};
use axcheck::evaluate::StandardId;
use axcheck::measurement::AxisData;
use axcheck::simulate::SimulationFile as _;
use axcheck::simulate::rng::Rng;
use axcheck::simulate::{
    Cycle, ErrorModel, PeriodicTerm, PlantedOutlier, Simulation, TargetSpacing, TestPlan,
};
use axcheck::units::{AxisKind, Direction};
use rayon::prelude::*;

mod shown;
mod sweep;
mod worn;

/// Monte-Carlo simulations per diagnosis in these tests (the checks do not decide
/// findings; they cost time).
const SIMS: usize = 60;

fn options(seed: u64, pitch: Option<f64>) -> Options {
    Options {
        pitch,
        thermal_origin: None,
        simulations: SIMS,
        seed,
        standard: StandardId::Iso230_2,
    }
}

/// A realistic axis over `plan`: scale error, a smooth shape through random knots,
/// reversal and scatter.
fn realistic(rng: &mut Rng, start: f64, end: f64, sigma: f64, bow: f64, ppm: f64) -> ErrorModel {
    let knots = 4;
    let shape = (0..knots)
        .map(|k| {
            let p = start + (end - start) * k as f64 / (knots - 1) as f64;
            [p, rng.range(-bow, bow)]
        })
        .collect();
    ErrorModel {
        scale_ppm: rng.range(-ppm, ppm),
        shape,
        reversal: rng.range(1.0, 5.0),
        scatter: sigma,
        ..ErrorModel::default()
    }
}

/// A plan after ISO 230-2 (4.2, 4.3.2): 11–21 targets over 400–1500 mm, 5–7 runs.
fn standard_plan(rng: &mut Rng) -> TestPlan {
    let start = rng.range(0.0, 20.0);
    let end = start + rng.range(400.0, 1500.0);
    let count = 11 + (rng.uniform() * 11.0) as usize;
    let spacing = (end - start) / (count - 1) as f64;
    TestPlan {
        targets: Some(TargetSpacing {
            start,
            end,
            count,
            jitter: 0.2 * spacing,
        }),
        target_list: None,
        runs: 5 + (rng.uniform() * 3.0) as usize,
        cycle: Cycle::Standard,
        feed_per_min: rng.range(1000.0, 3000.0),
        dwell_s: rng.range(2.0, 5.0),
        overrun: 5.0,
    }
}

/// A short, finely stepped plan (Hemingray et al. 1971, §4: ~25 mm with ~0.5 mm steps).
fn fine_plan(rng: &mut Rng) -> TestPlan {
    let start = rng.range(0.0, 200.0);
    let length = rng.range(20.0, 40.0);
    let step = rng.range(0.4, 0.8);
    let count = (length / step).round() as usize + 1;
    TestPlan {
        targets: Some(TargetSpacing {
            start,
            end: start + step * (count - 1) as f64,
            count,
            jitter: 0.2 * step,
        }),
        target_list: None,
        runs: 5,
        cycle: Cycle::Standard,
        feed_per_min: rng.range(200.0, 1000.0),
        dwell_s: rng.range(1.0, 3.0),
        overrun: 1.0,
    }
}

fn spacing_of(plan: &TestPlan) -> (f64, f64, usize) {
    let t = plan.targets.as_ref().unwrap();
    (t.start, t.end, t.count)
}

fn test_hours(sim: &Simulation, seed: u64) -> f64 {
    let targets = sim.plan.target_positions(seed);
    sim.plan.schedule(&targets).last().unwrap().time_s / 3600.0
}

/// A hidden-effect case: the simulation, its seed and what was hidden.
struct Case {
    sim: Simulation,
    seed: u64,
    pitch: Option<f64>,
    /// The hidden value to compare (drift rate µm/h, period mm, …).
    truth: f64,
    /// For an outlier: (run, direction, target).
    at: Option<(u32, Direction, usize)>,
}

impl Case {
    /// A linear axis with its hidden value `truth` and nothing located.
    fn linear(model: ErrorModel, plan: TestPlan, seed: u64, truth: f64) -> Case {
        Case {
            sim: linear(model, plan, seed),
            seed,
            pitch: None,
            truth,
            at: None,
        }
    }
}

fn linear(model: ErrorModel, plan: TestPlan, seed: u64) -> Simulation {
    Simulation {
        kind: AxisKind::Linear,
        seed,
        description: None,
        model,
        plan,
    }
}

fn clean_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 101);
    let sigma = rng.range(0.3, 1.2);
    let which = seed % 4;
    let (plan, bow, ppm) = match which {
        0 | 1 => (standard_plan(&mut rng), 4.0, 10.0),
        2 => (fine_plan(&mut rng), 0.5, 20.0),
        _ => (scatter_plan(&mut rng), 4.0, 10.0),
    };
    let (start, end, _) = spacing_of(&plan);
    let model = realistic(&mut rng, start, end, sigma, bow, ppm);
    if which == 1 && seed % 8 == 1 {
        return Case {
            sim: rotary(&mut rng, sigma * 2.0, seed),
            seed,
            pitch: None,
            truth: 0.0,
            at: None,
        };
    }
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: 0.0,
        at: None,
    }
}

/// A rotary table: 8–24 targets over 0–345°, arcsec, n = 5.
fn rotary(rng: &mut Rng, sigma: f64, seed: u64) -> Simulation {
    let count = 8 + (rng.uniform() * 17.0) as usize;
    let mut model = realistic(rng, 0.0, 345.0, sigma, 6.0, 0.0);
    model.scale_ppm = 0.0;
    Simulation {
        kind: AxisKind::Rotary,
        seed,
        description: None,
        model,
        plan: TestPlan {
            targets: Some(TargetSpacing {
                start: 0.0,
                end: 345.0,
                count,
                jitter: 0.0,
            }),
            target_list: None,
            runs: 5,
            cycle: Cycle::Standard,
            feed_per_min: 3600.0,
            dwell_s: 3.0,
            overrun: 2.0,
        },
    }
}

/// More targets and runs: what a scatter test along the axis needs.
fn scatter_plan(rng: &mut Rng) -> TestPlan {
    let mut p = standard_plan(rng);
    let t = p.targets.as_mut().unwrap();
    t.count = 21 + (rng.uniform() * 11.0) as usize;
    t.jitter = 0.2 * (t.end - t.start) / (t.count - 1) as f64;
    p.runs = 6 + (rng.uniform() * 3.0) as usize;
    p
}

fn sign(rng: &mut Rng) -> f64 {
    if rng.uniform() < 0.5 { -1.0 } else { 1.0 }
}

fn drift_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 201);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let mut sim = if seed % 4 == 3 {
        rotary(&mut rng, 2.0 * sigma, seed)
    } else {
        let model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
        linear(model, plan, seed)
    };
    let sigma = sim.model.scatter;
    let mut model = sim.model.clone();
    // Drift over the test: 5–10 σ.
    let total = rng.range(5.0, 10.0) * sigma * sign(&mut rng);
    let rate = total / test_hours(&sim, seed);
    model.drift_per_h = rate;
    sim.model = model;
    Case {
        sim,
        seed,
        pitch: None,
        truth: rate,
        at: None,
    }
}

fn thermal_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 301);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    let mut sim = linear(model.clone(), plan, seed);
    // Growth at the free end over the test: 10–20 σ; the screw fixed at one end.
    let hours = test_hours(&sim, seed);
    let growth = rng.range(10.0, 20.0) * sigma;
    let origin = if rng.uniform() < 0.5 { 0.0 } else { end + 10.0 };
    let reach = if origin == 0.0 { end } else { origin - start };
    let ppm = growth / (reach / 1000.0) / hours * sign(&mut rng);
    model.thermal_growth_ppm_per_h = ppm;
    model.thermal_origin = origin;
    sim.model = model;
    Case {
        sim,
        seed,
        pitch: None,
        truth: ppm,
        at: None,
    }
}

fn run_offset_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 401);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let n = plan.runs;
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    // Zero shifts not ordered in time: random, with mean and linear trend over the runs
    // removed, RMS 3–6 σ/√n.
    let unit = offsets_beyond_a_line(n, 1.0, &mut rng);
    let target = rng.range(3.0, 6.0) * sigma / (n as f64).sqrt();
    model.run_offsets = unit.iter().map(|v| v * target).collect();
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: target,
        at: None,
    }
}

/// Random run offsets with RMS `rms` about the straight line through them in run order
/// (what no drift explains).
fn offsets_beyond_a_line(runs: usize, rms: f64, rng: &mut Rng) -> Vec<f64> {
    let jbar = (runs - 1) as f64 / 2.0;
    let mut z: Vec<f64> = (0..runs).map(|_| rng.normal()).collect();
    let mean = z.iter().sum::<f64>() / runs as f64;
    let sjj: f64 = (0..runs).map(|j| (j as f64 - jbar).powi(2)).sum();
    let slope = (z.iter().enumerate())
        .map(|(j, v)| (j as f64 - jbar) * v)
        .sum::<f64>()
        / sjj;
    for (j, v) in z.iter_mut().enumerate() {
        *v -= mean + slope * (j as f64 - jbar);
    }
    let now = (z.iter().map(|v| v * v).sum::<f64>() / runs as f64).sqrt();
    z.iter().map(|v| v * rms / now).collect()
}

fn periodic_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 501);
    let sigma = rng.range(0.3, 1.2);
    let plan = fine_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let step = (end - start) / (spacing_of(&plan).2 - 1) as f64;
    let mut model = realistic(&mut rng, start, end, sigma, 0.5, 20.0);
    let period = rng.range((4.0 * step).max(2.0), (end - start) / 4.0);
    let amplitude = rng.range(3.0, 6.0) * sigma / (plan.runs as f64).sqrt();
    model.periodic = vec![PeriodicTerm {
        pitch: period,
        amplitude,
        phase_deg: rng.range(0.0, 360.0),
    }];
    let pitch = (rng.uniform() < 0.5).then_some(period);
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch,
        truth: period,
        at: None,
    }
}

fn reversal_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 601);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    // Change of B along the axis: 6–10 standard errors of Bi, σ√(2/n).
    let se_b = sigma * (2.0 / plan.runs as f64).sqrt();
    let change = rng.range(6.0, 10.0) * se_b * sign(&mut rng);
    model.reversal_end = Some(model.reversal + change);
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: change,
        at: None,
    }
}

fn outlier_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 701);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let (start, end, count) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    // One reading off by 8–15 σ (a 3σ reading is not inconsistent with 100 others).
    let size = rng.range(8.0, 15.0) * sigma * sign(&mut rng);
    let run = 1 + (rng.uniform() * plan.runs as f64) as u32;
    let direction = if rng.uniform() < 0.5 {
        Direction::Up
    } else {
        Direction::Down
    };
    let target = 1 + (rng.uniform() * count as f64) as usize;
    model.outliers = vec![PlantedOutlier {
        run,
        direction,
        target,
        size,
    }];
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: size,
        at: Some((run, direction, target)),
    }
}

fn scatter_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 801);
    let sigma = rng.range(0.3, 1.0);
    let plan = scatter_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    let ratio = rng.range(3.0, 5.0);
    if rng.uniform() < 0.5 {
        model.scatter_end = Some(sigma * ratio);
    } else {
        model.scatter = sigma * ratio;
        model.scatter_end = Some(sigma);
    }
    Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: ratio,
        at: None,
    }
}

/// A warm-up (ISO 230-2 clause 3.3): the deviations approach a new level exponentially,
/// A·(1 − e^(−t/τ)) from the start of the test, in a test of 20–60 min (dwell 5–10 s, as
/// laser tests with averaging take) with τ 15–40 % of it, so that the curve shows: a
/// longer τ is a straight line over the test (a drift), a shorter one is over within the
/// first run. A: 6–12 σ from the first reading to the final level; in every third case
/// part of it grows with the position (the screw's expansion, origin at one end).
/// `without_times` reads the test as a file without time stamps.
fn warm_up_case(seed: u64, without_times: bool) -> Case {
    let mut rng = Rng::new(seed, 901);
    let sigma = rng.range(0.3, 1.2);
    let mut plan = standard_plan(&mut rng);
    plan.dwell_s = rng.range(5.0, 10.0);
    plan.feed_per_min = rng.range(500.0, 1500.0);
    let (start, end, _) = spacing_of(&plan);
    let mut sim = linear(
        realistic(&mut rng, start, end, sigma, 4.0, 10.0),
        plan,
        seed,
    );
    let targets = sim.plan.target_positions(seed);
    let visits = sim.plan.schedule(&targets);
    let first_min = visits[0].time_s / 60.0;
    let minutes = visits.last().unwrap().time_s / 60.0;
    let tau = minutes * rng.range(0.15, 0.4);
    // The size at the first reading, at the mean target.
    let size = rng.range(6.0, 12.0) * sigma * sign(&mut rng);
    let at_first = (-first_min / tau).exp();
    let centre = (start + end) / 2.0;
    if seed % 3 == 1 {
        // Half of it in proportion to the position, zero at the start of the travel.
        let ppm = 0.5 * size / ((centre - start) / 1000.0);
        sim.model.warm_up_ppm = ppm / at_first;
        sim.model.thermal_origin = start;
        sim.model.warm_up = 0.5 * size / at_first;
    } else {
        sim.model.warm_up = size / at_first;
    }
    sim.model.warm_up_tau_min = tau;
    if without_times {
        sim.description = Some(NO_TIME_STAMPS.to_string());
    }
    Case {
        sim,
        seed,
        pitch: None,
        truth: tau,
        at: None,
    }
}

/// A warm-up is named, with its time constant and size, kept by the held-out prediction,
/// and not split into drift and run offsets; `accurate` holds in 95 % of the cases, other
/// findings in at most 5 %.
fn require_warm_up(name: &str, seeds: std::ops::Range<u64>, without_times: bool) {
    let gains = std::sync::Mutex::new(Vec::new());
    let others = require_recall(
        name,
        seeds,
        |s| warm_up_case(s, without_times),
        Effect::WarmUp,
        |c, d| {
            gains.lock().unwrap().push(d.gain_pct);
            warm_up_right(c, d)
        },
    );
    let mut gains = gains.into_inner().unwrap();
    gains.sort_by(f64::total_cmp);
    eprintln!(
        "{name}: held-out gain {:.1} % (lowest), {:.1} % (median)",
        gains[0],
        gains[gains.len() / 2]
    );
    assert!(
        others <= 0.05,
        "{name}: other findings in {:.1} %",
        others * 100.0
    );
}

/// The time constant within 30 % (40 % in runs, without time stamps), the size at the
/// first reading within 30 %, the term kept with a positive overall gain.
fn warm_up_right(c: &Case, d: &Diagnosis) -> bool {
    let without_times = c.sim.description.as_deref() == Some(NO_TIME_STAMPS);
    let model = &c.sim.model;
    let key = if without_times { "tau_run" } else { "tau_min" };
    let tau = param(d, Effect::WarmUp, key);
    let tau_ok = if without_times {
        // Runs of the standard cycle: the test's runs over its minutes.
        let minutes = test_hours(&c.sim, c.seed) * 60.0;
        rel_err(tau * minutes / c.sim.plan.runs as f64, c.truth) <= 0.4
    } else {
        rel_err(tau, c.truth) <= 0.3
    };
    let targets = c.sim.plan.target_positions(c.seed);
    let first = c.sim.plan.schedule(&targets)[0].time_s / 60.0;
    let centre = (targets[0] + targets[targets.len() - 1]) / 2.0;
    let level = model.warm_up + model.warm_up_ppm * (centre - model.thermal_origin) / 1000.0;
    let size = level * (-first / model.warm_up_tau_min).exp();
    let amplitude = param(d, Effect::WarmUp, "amplitude_um");
    let kept = d.extended.terms.iter().any(|t| t == "warm_up");
    tau_ok && rel_err(amplitude, size) <= 0.3 && kept && d.gain_pct > 0.0
}

#[test]
fn hidden_warm_up_is_found_with_its_time_constant() {
    require_warm_up("warm_up", 90_000..90_000 + SEEDS, false);
}

#[test]
fn hidden_warm_up_is_found_without_time_stamps() {
    require_warm_up("warm_up without time_s", 95_000..95_000 + SEEDS, true);
}

/// Behaviour smooth in time is never named as run offsets alone, whatever the time
/// constant of a warm-up, with and without time stamps. What it is named instead: a
/// warm-up that is over within the first few readings (τ below a quarter of a run, the
/// shortest the search tries) leaves those readings as outliers or nothing; one of
/// 2–50 % of the test is a warm-up; one slower than the test is a straight line over it,
/// a drift (or, in proportion to position, a thermal growth).
#[test]
fn smooth_time_behaviour_is_never_run_offsets_alone() {
    let fractions = [0.005, 0.02, 0.1, 0.5, 1.0, 2.0, 4.0];
    let results: Vec<(f64, bool, u64, String)> = fractions
        .par_iter()
        .flat_map(|&fraction| {
            (0..30u64).into_par_iter().flat_map(move |s| {
                [false, true].into_par_iter().map(move |without_times| {
                    let mut case = warm_up_case(90_000 + s, without_times);
                    let minutes = test_hours(&case.sim, case.seed) * 60.0;
                    let targets = case.sim.plan.target_positions(case.seed);
                    let first = case.sim.plan.schedule(&targets)[0].time_s / 60.0;
                    let m = &mut case.sim.model;
                    // The same size at the first reading, another time constant.
                    let at_first = m.warm_up * (-first / m.warm_up_tau_min).exp();
                    let at_first_ppm = m.warm_up_ppm * (-first / m.warm_up_tau_min).exp();
                    let tau = fraction * minutes;
                    m.warm_up = at_first * (first / tau).exp();
                    m.warm_up_ppm = at_first_ppm * (first / tau).exp();
                    m.warm_up_tau_min = tau;
                    let (_, d) = run_case(&case);
                    (fraction, without_times, s, d.effects_label())
                })
            })
        })
        .collect();
    let alone: Vec<_> = results.iter().filter(|r| r.3 == "run_offset").collect();
    assert!(alone.is_empty(), "{alone:?}");
    for &fraction in &fractions {
        let of = |name: &str| {
            let n = results
                .iter()
                .filter(|r| r.0 == fraction && r.3.split(' ').any(|e| e == name))
                .count();
            n as f64 / 60.0
        };
        let linear = results
            .iter()
            .filter(|r| r.0 == fraction && (r.3.contains("drift") || r.3.contains("thermal")))
            .count() as f64
            / 60.0;
        eprintln!(
            "τ = {fraction} × the test: warm_up {:.0} %, drift or thermal_growth {:.0} %, run_offset {:.0} %, outlier {:.0} %",
            of("warm_up") * 100.0,
            linear * 100.0,
            of("run_offset") * 100.0,
            of("outlier") * 100.0
        );
        if (0.02..=0.5).contains(&fraction) {
            assert!(of("warm_up") >= 0.85, "τ = {fraction} × the test");
        }
        if fraction >= 2.0 {
            assert!(linear >= 0.9, "τ = {fraction} × the test");
        }
    }
}

/// Removes the time stamps (a file without `time_s`).
fn without_times(mut data: AxisData) -> AxisData {
    for r in &mut data.readings {
        r.time_s = None;
    }
    data
}

/// The description of a simulated test that is read as a file without time stamps.
const NO_TIME_STAMPS: &str = "read without time stamps";

fn run_case(case: &Case) -> (AxisData, Diagnosis) {
    run_case_declaring(case, None)
}

/// [`run_case`], the thermal origin declared (`thermal_origin`).
fn run_case_declaring(case: &Case, thermal_origin: Option<f64>) -> (AxisData, Diagnosis) {
    let data = case.sim.run(case.seed);
    // Clean cases with seed ≡ 2 (mod 3) are read as files without time stamps, and so are
    // the cases that say so.
    let clean_without = case.truth == 0.0 && case.at.is_none() && case.seed % 3 == 2;
    let data = if clean_without || case.sim.description.as_deref() == Some(NO_TIME_STAMPS) {
        without_times(data)
    } else {
        data
    };
    let options = Options {
        thermal_origin,
        ..options(case.seed ^ 0x5EED, case.pitch)
    };
    let d = diagnose::diagnose(&data, &options);
    (data, d)
}

fn effects(d: &Diagnosis) -> Vec<&'static str> {
    let mut v: Vec<&'static str> = d.findings.iter().map(|f| f.effect().name()).collect();
    v.dedup();
    v
}

fn param(d: &Diagnosis, effect: Effect, key: &str) -> f64 {
    d.of(effect)
        .next()
        .and_then(|f| f.param(key))
        .unwrap_or(f64::NAN)
}

/// The stable JSON of a diagnosis.
fn json_of(d: &Diagnosis) -> serde_json::Value {
    serde_json::to_value(d.json(axcheck::simulate::model_text)).expect("a diagnosis serialises")
}

fn rel_err(got: f64, want: f64) -> f64 {
    ((got - want) / want).abs()
}

/// Diagnoses `seeds` cases of `make` in parallel and requires that in at least 95 % of
/// them `effect` is named and `accurate` holds; prints the rates and any other findings,
/// and returns the share of cases with a finding of another effect.
fn require_recall<F, A>(
    name: &str,
    seeds: std::ops::Range<u64>,
    make: F,
    effect: Effect,
    accurate: A,
) -> f64
where
    F: Fn(u64) -> Case + Sync,
    A: Fn(&Case, &Diagnosis) -> bool + Sync,
{
    let results: Vec<(u64, bool, bool, Vec<&'static str>, bool)> = seeds
        .into_par_iter()
        .map(|s| {
            let case = make(s);
            let (_, d) = run_case(&case);
            let found = d.has(effect);
            let gain = positive_gain(&d, effect);
            (s, found, found && accurate(&case, &d), effects(&d), gain)
        })
        .collect();
    let gains = results.iter().filter(|r| r.1 && r.4).count();
    let named = results.iter().filter(|r| r.1).count();
    let n = results.len() as f64;
    let recall = results.iter().filter(|r| r.1).count() as f64 / n;
    let success = results.iter().filter(|r| r.2).count() as f64 / n;
    let failures: Vec<String> = results
        .iter()
        .filter(|r| !r.2)
        .map(|r| format!("seed {}: {:?}", r.0, r.3))
        .collect();
    let others = results
        .iter()
        .filter(|r| r.3.iter().any(|e| *e != effect.name()))
        .count();
    eprintln!(
        "{name}: named in {:.1} %, named with accurate parameters in {:.1} % of {} seeds; other findings beside it in {others}; a positive held-out gain in {gains} of {named} named",
        recall * 100.0,
        success * 100.0,
        results.len()
    );
    assert!(
        success >= 0.95,
        "{name}: {:.1} % < 95 %; failures {failures:?}",
        success * 100.0
    );
    assert_eq!(
        gains, named,
        "{name}: a positive held-out gain in only {gains} of {named} named"
    );
    assert!(
        others as f64 <= 0.05 * n,
        "{name}: other findings in {others} of {n} seeds"
    );
    others as f64 / n
}

/// A hidden periodic error and a drift in one test.
fn periodic_and_drift_case(seed: u64) -> Case {
    let mut case = periodic_case(seed);
    let mut rng = Rng::new(seed, 1101);
    let total = rng.range(5.0, 10.0) * case.sim.model.scatter * sign(&mut rng);
    case.sim.model.drift_per_h = total / test_hours(&case.sim, seed);
    case
}

/// A reversal value that changes along the axis and one outlying reading in one test.
fn reversal_and_outlier_case(seed: u64) -> Case {
    let mut case = outlier_case(seed);
    let mut rng = Rng::new(seed, 1201);
    let se_b = case.sim.model.scatter * (2.0 / case.sim.plan.runs as f64).sqrt();
    let change = rng.range(6.0, 10.0) * se_b * sign(&mut rng);
    case.sim.model.reversal_end = Some(case.sim.model.reversal + change);
    case
}

/// Two hidden effects in each of `seeds` cases: both named in at least 95 %, each kept
/// with a positive held-out gain where named, other findings in at most 5 %.
fn require_both(name: &str, seeds: std::ops::Range<u64>, make: fn(u64) -> Case, pair: [Effect; 2]) {
    let results: Vec<(bool, bool, bool)> = seeds
        .into_par_iter()
        .map(|s| {
            let (_, d) = run_case(&make(s));
            let both = pair.iter().all(|e| d.has(*e));
            let gains = pair.iter().all(|e| positive_gain(&d, *e));
            let other = d.findings.iter().any(|f| !pair.contains(&f.effect()));
            (both, both && gains, other)
        })
        .collect();
    let n = results.len();
    let both = results.iter().filter(|r| r.0).count();
    let gains = results.iter().filter(|r| r.1).count();
    let others = results.iter().filter(|r| r.2).count();
    eprintln!(
        "{name}: both named in {both} of {n}, with positive gains in {gains}; other findings in {others}"
    );
    assert!(
        both as f64 >= 0.95 * n as f64,
        "{name}: both named in {both} of {n}"
    );
    assert_eq!(gains, both, "{name}: positive gains in {gains} of {both}");
    assert!(
        others as f64 <= 0.05 * n as f64,
        "{name}: other findings in {others} of {n}"
    );
}

#[test]
fn hidden_periodic_error_and_drift_are_both_found() {
    require_both(
        "periodic + drift",
        110_000..110_000 + SEEDS,
        periodic_and_drift_case,
        [Effect::Periodic, Effect::Drift],
    );
}

#[test]
fn hidden_reversal_variation_and_outlier_are_both_found() {
    require_both(
        "reversal_variation + outlier",
        120_000..120_000 + SEEDS,
        reversal_and_outlier_case,
        [Effect::ReversalVariation, Effect::Outlier],
    );
}

const SEEDS: u64 = 60;

/// The term of `effect` kept with a positive gain under its scheme, and every kept term's
/// gain positive.
fn positive_gain(d: &Diagnosis, effect: Effect) -> bool {
    for g in &d.term_gains {
        let above = g.gain_pct > 0.0 && g.gain_pct > g.threshold_pct;
        assert_eq!(g.kept, above, "{g:?}");
        let in_model = d.extended.terms.iter().any(|t| t == g.effect.name());
        assert_eq!(g.kept, in_model, "{g:?} {:?}", d.extended.terms);
    }
    d.term_gains
        .iter()
        .any(|g| g.effect == effect && g.kept && g.gain_pct > 0.0)
}

#[test]
fn hidden_drift_is_found_with_its_rate() {
    require_recall(
        "drift",
        10_000..10_000 + SEEDS,
        drift_case,
        Effect::Drift,
        drift_right,
    );
}

/// The drift rate within 20 %, no warm-up beside it.
fn drift_right(c: &Case, d: &Diagnosis) -> bool {
    let key = match c.sim.kind {
        AxisKind::Linear => "rate_um_per_h",
        AxisKind::Rotary => "rate_arcsec_per_h",
    };
    rel_err(param(d, Effect::Drift, key), c.truth) <= 0.20 && !d.has(Effect::WarmUp)
}

#[test]
fn hidden_thermal_growth_is_found() {
    require_recall(
        "thermal_growth",
        20_000..20_000 + SEEDS,
        thermal_case,
        Effect::ThermalGrowth,
        thermal_right,
    );
}

/// The growth rate within 30 %, neither drift nor warm-up beside it.
fn thermal_right(c: &Case, d: &Diagnosis) -> bool {
    let growth = param(d, Effect::ThermalGrowth, "growth_um_per_m_per_h");
    rel_err(growth, c.truth) <= 0.30 && !d.has(Effect::Drift) && !d.has(Effect::WarmUp)
}

#[test]
fn hidden_run_offsets_are_found_not_taken_for_drift() {
    require_recall(
        "run_offset",
        30_000..30_000 + SEEDS,
        run_offset_case,
        Effect::RunOffset,
        run_offset_right,
    );
}

/// The offsets' RMS within 50 %, neither drift nor warm-up beside them.
fn run_offset_right(c: &Case, d: &Diagnosis) -> bool {
    let rms = param(d, Effect::RunOffset, "rms_um");
    !d.has(Effect::Drift) && !d.has(Effect::WarmUp) && rel_err(rms, c.truth) <= 0.5
}

#[test]
fn hidden_periodic_error_is_found_with_its_period() {
    require_recall(
        "periodic",
        40_000..40_000 + SEEDS,
        periodic_case,
        Effect::Periodic,
        periodic_right,
    );
}

/// The period within 3 %.
fn periodic_right(c: &Case, d: &Diagnosis) -> bool {
    rel_err(param(d, Effect::Periodic, "period_mm"), c.truth) <= 0.03
}

#[test]
fn hidden_reversal_variation_is_found() {
    require_recall(
        "reversal_variation",
        50_000..50_000 + SEEDS,
        reversal_case,
        Effect::ReversalVariation,
        reversal_right,
    );
}

/// The reversal value changes along the axis the way it was hidden.
fn reversal_right(c: &Case, d: &Diagnosis) -> bool {
    let change = param(d, Effect::ReversalVariation, "reversal_end_um")
        - param(d, Effect::ReversalVariation, "reversal_start_um");
    change.signum() == c.truth.signum()
}

#[test]
fn hidden_outlier_is_located_exactly() {
    require_recall(
        "outlier",
        60_000..60_000 + SEEDS,
        outlier_case,
        Effect::Outlier,
        outlier_right,
    );
}

/// The hidden reading located exactly, its size within 50 %.
fn outlier_right(c: &Case, d: &Diagnosis) -> bool {
    let (run, dir, target) = c.at.unwrap();
    d.estimates::<FoundOutlier>().any(|o| {
        o.run == run && o.target == target && o.direction == dir && rel_err(o.size, c.truth) <= 0.5
    })
}

#[test]
fn hidden_scatter_variation_is_found() {
    require_recall(
        "scatter_variation",
        70_000..70_000 + SEEDS,
        scatter_case,
        Effect::ScatterVariation,
        scatter_right,
    );
}

/// The scatter grows along the axis the way it was hidden.
fn scatter_right(c: &Case, d: &Diagnosis) -> bool {
    let want = c.sim.model.scatter_end.unwrap() / c.sim.model.scatter;
    let got = param(d, Effect::ScatterVariation, "ratio_end_to_start");
    (got > 1.0) == (want > 1.0)
}

/// Data the base model explains: a finding in at most 5 % of seeds (the design level is
/// 7 × 0.2 %).
#[test]
fn clean_data_has_no_findings() {
    let seeds = 300u64;
    let results: Vec<(u64, Vec<&'static str>)> = (0..seeds)
        .into_par_iter()
        .map(|s| {
            let case = clean_case(80_000 + s);
            let (_, d) = run_case(&case);
            (s, effects(&d))
        })
        .collect();
    let with: Vec<_> = results.iter().filter(|r| !r.1.is_empty()).collect();
    let rate = with.len() as f64 / seeds as f64;
    eprintln!(
        "clean: a finding in {:.1} % of {seeds} seeds: {with:?}",
        rate * 100.0
    );
    assert!(rate <= 0.05, "{with:?}");
}

/// The real measurements: diagnose without error and print what is found
/// (`cargo test --release --test diagnose real -- --nocapture`).
#[test]
fn real_measurements() {
    for (file, pitch) in [
        ("iso230-2_table2.csv", None),
        ("gost27843_example.csv", None),
        ("ess_bifrost_slit_axis1.csv", None),
        ("ess_muts_target_x.csv", None),
    ] {
        let data = crate::common::load(file);
        let d = diagnose::diagnose(&data, &options(7, pitch));
        println!(
            "== {file}: m = {}, n = {}",
            data.target_count(),
            data.runs()
        );
        for f in &d.findings {
            println!(
                "  finding {}: {} | {} = {:.3}, p = {:?}, effect size {:?} | {:?}",
                f.effect().name(),
                f.message,
                f.evidence.statistic,
                f.evidence.value,
                f.evidence.p_value,
                f.evidence.effect_size,
                f.params()
            );
        }
        if d.findings.is_empty() {
            println!("  no finding: the base model explains the data");
        }
        println!(
            "  held-out RMS ({}): base {:.3} {:?} -> extended {:.3} {:?}; gain {:.1} %",
            d.validation,
            d.base.heldout_rms,
            d.base.terms,
            d.extended.heldout_rms,
            d.extended.terms,
            d.gain_pct
        );
        for c in &d.checks {
            println!(
                "  check {}: measured {:.3}, simulated 95 % [{:.3}, {:.3}]{}",
                c.statistic,
                c.measured,
                c.simulated_low,
                c.simulated_high,
                if c.outside { "  OUTSIDE" } else { "" }
            );
        }
        for c in &d.corrected {
            let list: Vec<String> = c
                .parameters
                .iter()
                .filter(|p| ["A", "E", "M", "R", "B"].contains(&p.key.as_str()))
                .map(|p| format!("{} {:.2} -> {:.2}", p.key, p.measured, p.corrected))
                .collect();
            println!("  without {}: {}", c.effect, list.join(", "));
        }
        for note in &d.notes {
            println!("  note: {note}");
        }
        let json = json_of(&d);
        assert!(json["findings"].is_array(), "{file}");
        Simulation::from_yaml(json["extended_model"].as_str().unwrap(), file)
            .unwrap_or_else(|e| panic!("{file}: {e}"));
    }
}

fn drift_data() -> (Case, AxisData, Diagnosis) {
    let case = drift_case(4);
    let (data, d) = run_case(&case);
    (case, data, d)
}

/// A drift found where no warm-up is: the finding says what warm-up would read as it,
/// the size the plan's `detectable` states for a warm-up (issue 43).
#[test]
fn a_drift_names_the_warm_up_this_plan_cannot_tell_from_it() {
    let (_, _, d) = drift_data();
    let json = json_of(&d);
    let warm = (json["detectable"].as_array().unwrap().iter())
        .find(|x| x["effect"] == "warm_up")
        .unwrap();
    let advice = warm["advice"].as_str().unwrap();
    let under = advice
        .split("a warm-up under ")
        .nth(1)
        .and_then(|rest| rest.split(" (reached").next())
        .unwrap();
    assert!(under.ends_with(" µm"), "{advice}");
    let drift = &json["findings"][0];
    assert_eq!(drift["effect"], "drift");
    let message = drift["message"].as_str().unwrap();
    assert!(
        message.ends_with(&format!(
            "; a warm-up approaching a level under {under}, which this plan cannot tell from a drift, would read so"
        )),
        "{message}"
    );
}

#[test]
fn json_has_the_stable_fields_and_is_deterministic() {
    let (case, data, d) = drift_data();
    let json = json_of(&d);
    for key in [
        "unit",
        "position_unit",
        "time_unit",
        "standard",
        "findings",
        "base",
        "extended",
        "gain_pct",
        "validation",
        "checks",
        "corrected",
        "residuals",
        "base_model",
        "extended_model",
        "notes",
    ] {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert_eq!(json["unit"], "um");
    assert_eq!(json["time_unit"], "h");
    let f = &json["findings"][0];
    assert_eq!(f["effect"], "drift");
    assert!(f["params"]["rate_um_per_h"].is_number());
    for key in ["statistic", "value", "p_value", "effect_size"] {
        assert!(f["evidence"].get(key).is_some(), "evidence.{key}");
    }
    for fit in ["base", "extended"] {
        assert!(json[fit]["terms"].is_array());
        assert!(json[fit]["heldout_rms"].is_number());
    }
    assert!(
        json["extended"]["terms"]
            .as_array()
            .unwrap()
            .iter()
            .any(|t| t == "drift")
    );
    assert!(json["gain_pct"].as_f64().unwrap() > 0.0);
    let check = &json["checks"][0];
    for key in [
        "statistic",
        "measured",
        "simulated_low",
        "simulated_high",
        "outside",
    ] {
        assert!(check.get(key).is_some(), "checks[].{key}");
    }
    let residuals = &json["residuals"];
    assert_eq!(
        residuals["readings"].as_array().unwrap().len(),
        data.readings.len()
    );
    assert!(residuals["readings"][0]["time_s"].is_number());
    assert_eq!(
        residuals["along_axis"].as_array().unwrap().len(),
        data.target_count()
    );
    let corrected = json["corrected"].as_array().unwrap();
    assert_eq!(corrected[0]["effect"], "drift");
    let r = &corrected[0]["parameters"]["R"];
    assert!(
        r["corrected"].as_f64().unwrap() < r["measured"].as_f64().unwrap(),
        "R without drift"
    );
    // Deterministic: the same input gives the same JSON, byte for byte.
    let again = json_of(&diagnose::diagnose(
        &data,
        &options(case.seed ^ 0x5EED, None),
    ));
    assert_eq!(json.to_string(), again.to_string());
}

/// The extended model is a simulation file: it parses back, and simulating it and
/// diagnosing the result finds the same effect again (the loop closes).
#[test]
fn extended_model_closes_the_loop() {
    let (case, _, d) = drift_data();
    let yaml = d.extended_model.to_yaml();
    let sim =
        Simulation::from_yaml(&yaml, "extended.yaml").unwrap_or_else(|e| panic!("{e}\n{yaml}"));
    assert_eq!(sim, d.extended_model);
    assert!(yaml.contains("drift_um_per_h"), "{yaml}");
    let rate = param(&d, Effect::Drift, "rate_um_per_h");
    assert!(
        (sim.model.drift_per_h - rate).abs() <= 0.01 * rate.abs() + 1e-3,
        "{yaml}"
    );
    let again = diagnose::diagnose(&sim.run(99), &options(1, None));
    assert!(again.has(Effect::Drift), "{:?}", again.findings);
    assert!(rel_err(param(&again, Effect::Drift, "rate_um_per_h"), case.truth) < 0.3);

    let case = periodic_case(40_003);
    let (_, d) = run_case(&case);
    let sim = Simulation::from_yaml(&d.extended_model.to_yaml(), "p.yaml").unwrap();
    assert_eq!(
        sim.model.periodic.len(),
        1,
        "{}",
        d.extended_model.to_yaml()
    );
    assert!(rel_err(sim.model.periodic[0].pitch, case.truth) < 0.03);
    let again = diagnose::diagnose(&sim.run(5), &options(2, None));
    assert!(again.has(Effect::Periodic));
    // The base model parses too.
    Simulation::from_yaml(&d.base_model.to_yaml(), "base.yaml").unwrap();
}

/// The extended model of a warm-up carries it as simulation keys, parses back, and
/// simulating it finds the warm-up again with its time constant; its "effect removed"
/// parameters are those of the warm machine (R falls).
#[test]
fn warm_up_extended_model_closes_the_loop() {
    let case = warm_up_case(90_004, false);
    let (_, d) = run_case(&case);
    assert!(d.has(Effect::WarmUp), "{:?}", d.findings);
    let yaml = d.extended_model.to_yaml();
    assert!(
        yaml.contains("warm_up_um") && yaml.contains("warm_up_tau_min"),
        "{yaml}"
    );
    let sim =
        Simulation::from_yaml(&yaml, "extended.yaml").unwrap_or_else(|e| panic!("{e}\n{yaml}"));
    assert!(
        rel_err(sim.model.warm_up_tau_min, case.truth) < 0.3,
        "{yaml}"
    );
    let again = diagnose::diagnose(&sim.run(7), &options(3, None));
    assert!(again.has(Effect::WarmUp), "{:?}", again.findings);
    assert!(rel_err(param(&again, Effect::WarmUp, "tau_min"), case.truth) < 0.3);
    let json = json_of(&d);
    let corrected = json["corrected"].as_array().unwrap();
    let without = corrected.iter().find(|c| c["effect"] == "warm_up").unwrap();
    let r = &without["parameters"]["R"];
    assert!(r["corrected"].as_f64().unwrap() < r["measured"].as_f64().unwrap());
    let f = &json["findings"][0];
    assert_eq!(f["effect"], "warm_up");
    for key in [
        "amplitude_um",
        "tau_min",
        "time_to_1um_min",
        "remaining_at_end_um",
    ] {
        assert!(f["params"][key].is_number(), "{key}: {f}");
    }
}

/// A periodic error the plan cannot resolve: no guess, advice on the plan that would.
#[test]
fn unresolvable_periodic_error_gives_the_plan_that_would_resolve_it() {
    let mut rng = Rng::new(5, 5);
    let plan = standard_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, 0.5, 4.0, 10.0);
    model.periodic = vec![PeriodicTerm {
        pitch: 10.0,
        amplitude: 2.0,
        phase_deg: 0.0,
    }];
    let data = linear(model, plan, 5).run(5);
    let d = diagnose::diagnose(&data, &options(1, Some(10.0)));
    assert!(!d.has(Effect::Periodic));
    let note = d
        .notes
        .iter()
        .find(|n| n.contains("Hemingray et al. 1971, §4"))
        .unwrap_or_else(|| panic!("{:?}", d.notes));
    assert!(
        note.contains("Hemingray et al. 1971, §4") && note.contains("mm"),
        "{note}"
    );
    assert!(note.contains("30 mm") && note.contains("0.5 mm"), "{note}");
}

/// n = 1, n = 2, one to three targets, rotary axes, no time stamps, exact readings, the
/// step and pilgrim cycles, targets closer than the simulator's rounding: no panic.
#[test]
fn tiny_and_degenerate_inputs_do_not_panic() {
    use axcheck::measurement::RawReading;
    let mut cases: Vec<AxisData> = Vec::new();
    for (m, n) in [
        (1, 1),
        (1, 2),
        (2, 1),
        (2, 2),
        (3, 1),
        (3, 2),
        (3, 3),
        (3, 5),
        (5, 1),
        (12, 1),
        (40, 1),
        (40, 2),
    ] {
        for kind in [AxisKind::Linear, AxisKind::Rotary] {
            for cycle in [Cycle::Standard, Cycle::Step, Cycle::Pilgrim] {
                let targets: Vec<f64> = (0..m).map(|i| i as f64 * 7.5).collect();
                let sim = Simulation {
                    kind,
                    seed: 1,
                    description: None,
                    model: ErrorModel {
                        scatter: 0.5,
                        reversal: 2.0,
                        ..ErrorModel::default()
                    },
                    plan: TestPlan {
                        targets: None,
                        target_list: Some(targets),
                        runs: n,
                        cycle,
                        feed_per_min: 1000.0,
                        dwell_s: 2.0,
                        overrun: 1.0,
                    },
                };
                let data = sim.run(m as u64 * 10 + n as u64);
                cases.push(without_times(data.clone()));
                cases.push(data);
            }
        }
    }
    // Exact readings (no scatter at all).
    let exact = Simulation {
        kind: AxisKind::Linear,
        seed: 0,
        description: None,
        model: ErrorModel {
            reversal: 1.0,
            ..ErrorModel::default()
        },
        plan: TestPlan {
            targets: None,
            target_list: Some((0..15).map(|i| i as f64).collect()),
            runs: 5,
            cycle: Cycle::Standard,
            feed_per_min: 100.0,
            dwell_s: 1.0,
            overrun: 1.0,
        },
    };
    cases.push(exact.run(0));
    // Targets closer than 0.001, no times, readings in file order.
    let raw: Vec<RawReading> = [0.0, 0.0001, 0.0002, 5.0]
        .iter()
        .flat_map(|&t| {
            (1..=3).flat_map(move |run| {
                [Direction::Up, Direction::Down].map(|direction| RawReading {
                    target: t,
                    direction,
                    run,
                    deviation: (t * 13.0 + run as f64).sin(),
                    time_s: None,
                    temps_c: Vec::new(),
                    line: 0,
                })
            })
        })
        .collect();
    cases.push(AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "close.csv").unwrap());
    let (done, refused): (usize, usize) = cases
        .par_iter()
        .map(|data| {
            let d = diagnose::diagnose(data, &options(3, Some(2.0)));
            let json = json_of(&d);
            assert!(json["findings"].is_array());
            // Targets closer than the simulator records (0.001) cannot be simulated: the
            // model says so when loaded (before, simulating it panicked).
            let refused =
                match Simulation::from_yaml(json["extended_model"].as_str().unwrap(), "x.yaml") {
                    Ok(_) => 0,
                    Err(e) => {
                        assert!(
                            e.to_string()
                                .contains("are the same position as recorded (to 0.001)")
                                && data.target_count() == 4,
                            "{e}\n{}",
                            json["extended_model"]
                        );
                        1
                    }
                };
            if data.runs() == 1 {
                assert!(d.notes.iter().any(|n| n.starts_with("n = 1")));
            }
            (1, refused)
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    assert_eq!((done, refused), (cases.len(), 1));
}

/// A number as the diagnosis prints it in messages and advice: 2 decimals from 1, 3 from
/// 0.01, 1 from 100 (hand rule, to compare the advice with the finding's parameters).
fn shown(v: f64) -> String {
    let a = v.abs();
    let d = if a >= 100.0 {
        1
    } else if a >= 1.0 {
        2
    } else if a >= 0.01 {
        3
    } else {
        5
    };
    axcheck::units::fmt_fixed(v, d)
}

/// The first of `seeds` cases of `make` in which `effect` is found, with the finding's
/// advice, parameters and the JSON's `advice`.
fn advice_of(
    make: fn(u64) -> Case,
    seeds: std::ops::Range<u64>,
    effect: Effect,
) -> (String, Diagnosis) {
    for seed in seeds {
        let (_, d) = run_case(&make(seed));
        let found = d.of(effect).next().map(|f| f.advice());
        if let Some(advice) = found {
            let json = json_of(&d);
            let k = d
                .findings
                .iter()
                .position(|g| g.effect() == effect)
                .unwrap();
            assert_eq!(json["findings"][k]["advice"], advice.as_str());
            return (advice, d);
        }
    }
    panic!("{effect:?} not found in any seed");
}

/// Every effect says what to do next, with the size that decides it, computed from the
/// finding's own parameters.
#[test]
fn each_finding_says_what_to_do_next() {
    let (a, d) = advice_of(drift_case, 10_000..10_010, Effect::Drift);
    let total = param(&d, Effect::Drift, "total_um");
    assert!(
        a.starts_with("re-test once the machine is thermally stable"),
        "{a}"
    );
    assert!(
        a.contains(&format!("the {} µm it moved", shown(total.abs()))),
        "{a}"
    );
    assert!(a.contains("ISO 230-2 3.1, 3.3"), "{a}");

    let (a, d) = advice_of(thermal_case, 20_000..20_010, Effect::ThermalGrowth);
    let grown = param(&d, Effect::ThermalGrowth, "growth_over_travel_and_test_um");
    assert!(
        a.contains(&format!("grew by {} µm", shown(grown.abs()))),
        "{a}"
    );

    let (a, d) = advice_of(run_offset_case, 30_000..30_010, Effect::RunOffset);
    let rms = param(&d, Effect::RunOffset, "rms_um");
    assert!(
        a.contains(&format!("moved by {} µm RMS", shown(rms))),
        "{a}"
    );
    assert!(a.contains("dead path"), "{a}");

    let (a, d) = advice_of(periodic_case, 40_000..40_010, Effect::Periodic);
    let period = param(&d, Effect::Periodic, "period_mm");
    assert!(
        a.contains(&format!("at most {} mm apart", shown(period / 4.0))),
        "{a}"
    );
    assert!(a.contains("short test"), "{a}");

    let (a, d) = advice_of(reversal_case, 50_000..50_010, Effect::ReversalVariation);
    let range = param(&d, Effect::ReversalVariation, "reversal_range_um");
    assert!(
        a.contains(&format!("up to ±{} µm", shown(range / 2.0))),
        "{a}"
    );

    let (a, d) = advice_of(outlier_case, 60_000..60_010, Effect::Outlier);
    let f = d.of(Effect::Outlier).next().unwrap();
    let (run, target) = (f.param("run").unwrap(), f.param("target").unwrap());
    assert!(a.contains(&format!("to target {target} (")), "{a}");
    assert!(a.contains(&format!("in run {run}")), "{a}");

    let (a, d) = advice_of(|s| warm_up_case(s, false), 90_000..90_010, Effect::WarmUp);
    let to_1um = param(&d, Effect::WarmUp, "time_to_1um_min");
    let tau = param(&d, Effect::WarmUp, "tau_min");
    assert!(
        a.starts_with("warm the machine up before re-testing (ISO 230-2 3.3)"),
        "{a}"
    );
    assert!(
        a.contains(&format!(
            "it took {} min to come within 1 µm",
            shown(to_1um)
        )),
        "{a}"
    );
    assert!(a.contains(&format!("(τ = {} min)", shown(tau))), "{a}");

    let (a, d) = advice_of(scatter_case, 70_000..70_010, Effect::ScatterVariation);
    let ratio = param(&d, Effect::ScatterVariation, "ratio_end_to_start");
    let worse = if ratio >= 1.0 { ratio } else { 1.0 / ratio };
    assert!(a.contains(&format!("{}× worse", shown(worse))), "{a}");
}

/// An axis with two data files: each test is predicted by the other's models. The second
/// file is the first shifted by +5 µm (a new laser datum): the fitted models shift with
/// it, so each prediction sees the same errors about a datum offset that differs by 10 µm,
/// and the out-of-test RMS are the same both ways.
#[test]
fn a_second_test_of_the_axis_is_predicted_by_the_first() {
    let dir = crate::common::scratch("out-of-test");
    let text = std::fs::read_to_string("tests/data/iso230-2_table2.csv").unwrap();
    let mut shifted = String::new();
    for (k, line) in text.lines().enumerate() {
        if k == 0 {
            shifted.push_str(line);
        } else {
            let (head, deviation) = line.rsplit_once(',').unwrap();
            let value: f64 = deviation.parse().unwrap();
            shifted.push_str(&format!("{head},{}", value + 5.0));
        }
        shifted.push('\n');
    }
    std::fs::write(dir.join("data/a.csv"), &text).unwrap();
    std::fs::write(dir.join("data/b.csv"), &shifted).unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: two tests}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: [data/a.csv, data/b.csv]}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, _, stderr) = crate::common::axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert!(code == 0 || code == 1, "{stderr}");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let axes = json["axes"].as_array().unwrap();
    let (a, b) = (&axes[0]["out_of_test"][0], &axes[1]["out_of_test"][0]);
    assert_eq!(a["from_test"], 2);
    assert_eq!(a["from_file"], "data/b.csv");
    assert_eq!(b["from_test"], 1);
    assert_eq!(a["readings"], 110);
    assert_eq!(a["unit"], "um");
    let f = |v: &serde_json::Value, k: &str| v[k].as_f64().unwrap();
    assert!((f(b, "datum_offset") - f(a, "datum_offset") - 10.0).abs() < 1e-9);
    for key in ["base_rms", "extended_rms"] {
        assert!((f(a, key) - f(b, key)).abs() < 1e-9, "{key}");
        assert!(f(a, key) > 0.0);
    }
    // The in-test figure beside it is the other test's own held-out RMS.
    let held_out = axes[1]["diagnosis"]["extended"]["heldout_rms"]
        .as_f64()
        .unwrap();
    assert!((f(a, "in_test_rms") - held_out).abs() < 1e-12);
    // `axcheck diagnose` with both files predicts each from the other as the campaign
    // does: the same figures, the files named as given.
    let (a_csv, b_csv) = (dir.join("data/a.csv"), dir.join("data/b.csv"));
    let (a_csv, b_csv) = (a_csv.to_str().unwrap(), b_csv.to_str().unwrap());
    let (code, json, err) = crate::common::axcheck(&["diagnose", a_csv, b_csv, "--json"]);
    assert_eq!(code, 0, "{err}");
    let cli: serde_json::Value = serde_json::from_str(&json).unwrap();
    let tests = cli["tests"].as_array().unwrap();
    assert_eq!(tests.len(), 2);
    assert_eq!(tests[0]["file"], a_csv);
    assert_eq!(tests[0]["out_of_test"][0]["from_file"], b_csv);
    assert_eq!(tests[1]["out_of_test"][0]["from_test"], 1);
    for (k, campaign) in [a, b].into_iter().enumerate() {
        let from_cli = &tests[k]["out_of_test"][0];
        for key in [
            "from_test",
            "readings",
            "unit",
            "datum_offset",
            "base_rms",
            "extended_rms",
            "in_test_rms",
        ] {
            assert_eq!(from_cli[key], campaign[key], "test {}: {key}", k + 1);
        }
        assert_eq!(tests[k]["findings"], axes[k]["diagnosis"]["findings"]);
    }
    let (_, text, _) = crate::common::axcheck(&["diagnose", a_csv, b_csv]);
    assert!(
        text.contains(&format!(
            "Out of test: this test predicted by the models fitted on each other test (position-dependent terms only; one datum offset fitted)\n  from test 2 ({b_csv}): 110 readings inside its travel, datum offset {} µm;",
            axcheck::units::fmt_fixed(f(a, "datum_offset"), 3)
        )),
        "{text}"
    );
    // One file: the JSON as before, with no `tests` and no `out_of_test`.
    let (_, one, _) = crate::common::axcheck(&["diagnose", a_csv, "--json"]);
    let one: serde_json::Value = serde_json::from_str(&one).unwrap();
    assert!(one.get("tests").is_none() && one.get("out_of_test").is_none());
    assert_eq!(one["findings"], tests[0]["findings"]);
    // A model is written for one test only; the tests of one axis have one kind.
    let model = dir.join("m.yaml");
    let args = [
        "diagnose",
        a_csv,
        b_csv,
        "--write-model",
        model.to_str().unwrap(),
    ];
    let (code, _, err) = crate::common::axcheck(&args);
    assert_eq!(code, 2);
    assert!(
        err.contains(
            "--write-model writes the extended model of one test: give one file (2 given)"
        ),
        "{err}"
    );
    let rotary = dir.join("data/r.csv");
    std::fs::write(&rotary, text_as_rotary(&text_of(a_csv))).unwrap();
    let (code, _, err) = crate::common::axcheck(&["diagnose", a_csv, rotary.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(
        err.contains("is a linear axis and") && err.contains("a rotary one"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

fn text_of(path: &str) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// A long CSV of a linear axis as one of a rotary axis (positions in deg, arcsec).
fn text_as_rotary(text: &str) -> String {
    let (head, rest) = text.split_once('\n').unwrap();
    let head = head.replace("_mm", "_deg").replace("_um", "_arcsec");
    format!("{head}\n{rest}")
}

/// A declared thermal origin (`--thermal-origin`, an axis's `thermal_origin:`): the GOST
/// worked example's thermal growth, fitted to hold still at −131.2 mm (within a quarter
/// of the travel before its start), is reported about the declared 0 mm with its label;
/// the growth itself, a coefficient of position × time, is the same.
#[test]
fn a_declared_thermal_origin_is_where_the_growth_holds_still() {
    let file = "tests/data/gost27843_example.csv";
    let thermal = |extra: &[&str]| {
        let mut args = vec!["diagnose", file, "--json"];
        args.extend(extra);
        let (code, json, err) = crate::common::axcheck(&args);
        assert_eq!(code, 0, "{err}");
        let v: serde_json::Value = serde_json::from_str(&json).unwrap();
        let mut found = v["findings"].as_array().unwrap().iter();
        found
            .find(|f| f["effect"] == "thermal_growth")
            .cloned()
            .expect("the example's thermal growth")
    };
    let fitted = thermal(&[]);
    let declared = thermal(&["--thermal-origin", "0"]);
    let origin = |f: &serde_json::Value| f["params"]["origin_mm"].as_f64().unwrap();
    assert!((origin(&fitted) + 131.18).abs() < 0.01, "{fitted}");
    assert_eq!(origin(&declared), 0.0);
    assert_eq!(fitted["labels"], serde_json::json!({}));
    assert_eq!(
        declared["labels"],
        serde_json::json!({"origin": "declared"})
    );
    let growth = |f: &serde_json::Value| f["params"]["growth_um_per_m_per_run"].clone();
    assert_eq!(growth(&fitted), growth(&declared));
    assert!(
        (declared["message"].as_str().unwrap()).contains("zero at 0 mm, the declared origin"),
        "{declared}"
    );
}
