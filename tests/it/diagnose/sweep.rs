//! The diagnosis sweep (issue 31): every case type on seeds of its own, none of which the
//! diagnosis was developed on, with the rates it is judged by — the hidden effects named
//! with accurate estimates, other findings beside them, and on clean data any finding.
//!
//! `cargo test --release --test it diagnose::sweep -- --nocapture` prints the table.

use super::*;

/// Seeds per case type; clean data get three times as many (their rate is the smallest).
const SWEEP: u64 = 200;

/// Run offsets drawn at random, not in time order and not made free of a trend (a random
/// set of offsets has a linear part, as real ones do), RMS 3–6 σ/√n; the truth is the RMS
/// of the offsets about their mean.
fn random_run_offsets(case: &mut Case, stream: u64) {
    let mut rng = Rng::new(case.seed, stream);
    let n = case.sim.plan.runs;
    let sigma = case.sim.model.scatter;
    let z: Vec<f64> = (0..n).map(|_| rng.normal()).collect();
    let mean = z.iter().sum::<f64>() / n as f64;
    let rms = (z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n as f64).sqrt();
    let target = rng.range(3.0, 6.0) * sigma / (n as f64).sqrt();
    case.sim.model.run_offsets = z.iter().map(|v| (v - mean) * target / rms).collect();
    case.truth = target;
}

fn random_run_offset_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 1301);
    let sigma = rng.range(0.3, 1.2);
    let plan = standard_plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    let mut case = Case {
        sim: linear(model, plan, seed),
        seed,
        pitch: None,
        truth: 0.0,
        at: None,
    };
    random_run_offsets(&mut case, 1302);
    case
}

/// A reversal value that changes along the axis, in a test whose runs are shifted at
/// random: the combination the independent sweep named right in only 94 %.
fn reversal_and_run_offset_case(seed: u64) -> Case {
    let mut case = reversal_case(seed);
    let change = case.truth;
    random_run_offsets(&mut case, 1401);
    // The reversal's change is the truth `reversal_right` reads; the offsets are in the
    // model.
    case.truth = change;
    case
}

/// The RMS of the hidden run offsets (centred).
fn offsets_rms(c: &Case) -> f64 {
    let o = &c.sim.model.run_offsets;
    (o.iter().map(|v| v * v).sum::<f64>() / o.len() as f64).sqrt()
}

fn reversal_and_run_offset_right(c: &Case, d: &Diagnosis) -> bool {
    let rms = param(d, Effect::RunOffset, "rms_um");
    reversal_right(c, d)
        && !d.has(Effect::Drift)
        && !d.has(Effect::WarmUp)
        && rel_err(rms, offsets_rms(c)) <= 0.5
}

/// A small plan (issue 43): 5 targets without jitter over 200–1000 mm, `runs` runs.
fn small_plan(rng: &mut Rng, runs: usize) -> TestPlan {
    let mut plan = standard_plan(rng);
    let t = plan.targets.as_mut().unwrap();
    t.end = t.start + rng.range(200.0, 1000.0);
    t.count = 5;
    t.jitter = 0.0;
    plan.runs = runs;
    plan
}

/// Effects whose stated size is measured and printed but not yet held to 70–90 %: none.
const DETECTABLE_OPEN: &[Effect] = &[];

/// Clean data on a plan drawn by `plan` (rng stream `stream`), σ 0.3–1.2, a realistic
/// error with a bow and a scale error up to `bow` µm and `ppm`.
fn clean_on(
    seed: u64,
    stream: u64,
    plan: impl FnOnce(&mut Rng) -> TestPlan,
    bow: f64,
    ppm: f64,
) -> Case {
    let mut rng = Rng::new(seed, stream);
    let sigma = rng.range(0.3, 1.2);
    let plan = plan(&mut rng);
    let (start, end, _) = spacing_of(&plan);
    let model = realistic(&mut rng, start, end, sigma, bow, ppm);
    Case::linear(model, plan, seed, 0.0)
}

/// Clean data on a small plan (5 targets, 3 or 5 runs).
pub(super) fn small_clean_case(seed: u64) -> Case {
    let runs = if seed.is_multiple_of(2) { 3 } else { 5 };
    clean_on(seed, 1501, |r| small_plan(r, runs), 4.0, 10.0)
}

/// Clean data on a fine-step plan (as the periodic cases): periods it resolves.
fn fine_clean_case(seed: u64) -> Case {
    clean_on(seed, 1601, fine_plan, 0.5, 20.0)
}

/// Clean data on a standard plan (11–21 targets).
pub(super) fn standard_clean_case(seed: u64) -> Case {
    clean_on(seed, 1701, standard_plan, 4.0, 10.0)
}

/// The nominal target positions of a plan without jitter.
fn nominal_targets(plan: &TestPlan) -> Vec<f64> {
    let (start, end, count) = spacing_of(plan);
    (0..count)
        .map(|i| start + (end - start) * i as f64 / (count - 1) as f64)
        .collect()
}

/// A reversal that is B everywhere but at the targets `worn` (indices), where it is
/// B + `change`: knots at every target, linear between them.
fn reversal_at_targets(model: &mut ErrorModel, targets: &[f64], worn: &[usize], change: f64) {
    model.reversal_knots = (targets.iter().enumerate())
        .map(|(i, &p)| {
            [
                p,
                model.reversal + if worn.contains(&i) { change } else { 0.0 },
            ]
        })
        .collect();
}

/// A change of the reversal of 8–12 standard errors of Bi, σ√(2/n), either sign.
fn small_plan_change(rng: &mut Rng, sigma: f64, runs: usize) -> f64 {
    rng.range(8.0, 12.0) * sigma * (2.0 / runs as f64).sqrt() * sign(rng)
}

/// A reversal changed at some targets only, 8–12 standard errors of Bi (σ√(2/n)): worn
/// at one end (the last target, or the last two), or a damaged section (one inner target),
/// on a small plan (5 targets, 3 or 5 runs) or a standard one without jitter.
fn worn_case(seed: u64, small: bool, section: bool) -> Case {
    let mut rng = Rng::new(seed, 1601);
    let sigma = rng.range(0.3, 1.2);
    let mut plan = if small {
        small_plan(&mut rng, if seed.is_multiple_of(2) { 3 } else { 5 })
    } else {
        standard_plan(&mut rng)
    };
    plan.targets.as_mut().unwrap().jitter = 0.0;
    let targets = nominal_targets(&plan);
    let (start, end, m) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    let change = small_plan_change(&mut rng, sigma, plan.runs);
    let worn: Vec<usize> = if section {
        vec![1 + (rng.uniform() * (m - 2) as f64) as usize]
    } else if m > 5 && rng.uniform() < 0.5 {
        vec![m - 2, m - 1]
    } else {
        vec![m - 1]
    };
    reversal_at_targets(&mut model, &targets, &worn, change);
    Case::linear(model, plan, seed, change)
}

/// A reversal variation of a few targets named with its range within 50 % of the change.
fn worn_right(c: &Case, d: &Diagnosis) -> bool {
    let range = param(d, Effect::ReversalVariation, "reversal_range_um");
    rel_err(range, c.truth.abs()) <= 0.5
}

/// A reversal along a straight line on a small plan (5 targets, 3 or 5 runs), changing by
/// 8–12 standard errors of Bi over the axis (6 on 5 targets and 3 runs is a slope t of
/// about 4.8 on 20 df, at the edge of what the test at 0.05 % per side can tell).
fn small_reversal_case(seed: u64) -> Case {
    let mut rng = Rng::new(seed, 1701);
    let sigma = rng.range(0.3, 1.2);
    let plan = small_plan(&mut rng, if seed.is_multiple_of(2) { 3 } else { 5 });
    let (start, end, _) = spacing_of(&plan);
    let mut model = realistic(&mut rng, start, end, sigma, 4.0, 10.0);
    let change = small_plan_change(&mut rng, sigma, plan.runs);
    model.reversal_end = Some(model.reversal + change);
    Case::linear(model, plan, seed, change)
}

/// Scatter that changes along the axis in a step (issue 43): σ on one side of a point 30–70 %
/// along the travel, 3–5 times σ on the other, on the scatter plan of the sweep.
fn scatter_step_case(seed: u64) -> Case {
    let mut c = scatter_case(seed);
    let mut rng = Rng::new(seed, 1801);
    let (start, end, _) = spacing_of(&c.sim.plan);
    let at = start + rng.range(0.3, 0.7) * (end - start);
    let m = &mut c.sim.model;
    let (lo, hi) = (m.scatter, m.scatter_end.unwrap());
    let gap = 1e-3 * (end - start);
    m.scatter_knots = vec![[start, lo], [at - gap, lo], [at + gap, hi], [end, hi]];
    c
}

/// One case type of the sweep.
struct Type {
    name: &'static str,
    make: fn(u64) -> Case,
    /// The hidden effects (none: clean data).
    hidden: &'static [Effect],
    /// Named right: every hidden effect named, with accurate estimates.
    right: fn(&Case, &Diagnosis) -> bool,
    /// Measured and printed but not yet held to the rates: a case the diagnosis does not
    /// meet yet, stated in the README (issue 43 open).
    open: bool,
}

fn types() -> Vec<Type> {
    use Effect::*;
    vec![
        Type {
            name: "clean",
            make: clean_case,
            hidden: &[],
            right: |_, d| d.findings.is_empty(),
            open: false,
        },
        Type {
            name: "drift",
            make: drift_case,
            hidden: &[Drift],
            right: drift_right,
            open: false,
        },
        Type {
            name: "warm_up",
            make: |s| warm_up_case(s, false),
            hidden: &[WarmUp],
            right: warm_up_right,
            open: false,
        },
        Type {
            name: "warm_up without time_s",
            make: |s| warm_up_case(s, true),
            hidden: &[WarmUp],
            right: warm_up_right,
            open: false,
        },
        Type {
            name: "thermal_growth",
            make: thermal_case,
            hidden: &[ThermalGrowth],
            right: thermal_right,
            open: false,
        },
        Type {
            name: "run_offset (trend removed)",
            make: run_offset_case,
            hidden: &[RunOffset],
            right: run_offset_right,
            open: false,
        },
        Type {
            name: "run_offset (random)",
            make: random_run_offset_case,
            hidden: &[RunOffset],
            right: run_offset_right,
            open: false,
        },
        Type {
            name: "periodic",
            make: periodic_case,
            hidden: &[Periodic],
            right: periodic_right,
            open: false,
        },
        Type {
            name: "reversal_variation",
            make: reversal_case,
            hidden: &[ReversalVariation],
            right: reversal_right,
            open: false,
        },
        Type {
            name: "outlier",
            make: outlier_case,
            hidden: &[Outlier],
            right: outlier_right,
            open: false,
        },
        Type {
            name: "scatter_variation",
            make: scatter_case,
            hidden: &[ScatterVariation],
            right: scatter_right,
            open: false,
        },
        Type {
            name: "periodic + drift",
            make: periodic_and_drift_case,
            hidden: &[Periodic, Drift],
            right: |c, d| periodic_right(c, d) && d.has(Effect::Drift),
            open: false,
        },
        Type {
            name: "reversal_variation + outlier",
            make: reversal_and_outlier_case,
            hidden: &[ReversalVariation, Outlier],
            right: |c, d| outlier_right(c, d) && d.has(Effect::ReversalVariation),
            open: false,
        },
        Type {
            name: "reversal_variation + run_offset",
            make: reversal_and_run_offset_case,
            hidden: &[ReversalVariation, RunOffset],
            right: reversal_and_run_offset_right,
            open: false,
        },
        Type {
            name: "clean, 5 targets",
            make: small_clean_case,
            hidden: &[],
            right: |_, d| d.findings.is_empty(),
            open: false,
        },
        Type {
            name: "reversal_variation, 5 targets",
            make: small_reversal_case,
            hidden: &[ReversalVariation],
            right: reversal_right,
            open: false,
        },
        Type {
            name: "reversal worn at one end, 5 targets",
            make: |s| worn_case(s, true, false),
            hidden: &[ReversalVariation],
            right: worn_right,
            open: false,
        },
        Type {
            name: "reversal damaged section, 5 targets",
            make: |s| worn_case(s, true, true),
            hidden: &[ReversalVariation],
            right: worn_right,
            open: false,
        },
        Type {
            name: "reversal worn at one end",
            make: |s| worn_case(s, false, false),
            hidden: &[ReversalVariation],
            right: worn_right,
            open: false,
        },
        Type {
            name: "reversal damaged section",
            make: |s| worn_case(s, false, true),
            hidden: &[ReversalVariation],
            right: worn_right,
            open: false,
        },
        Type {
            name: "scatter_variation in a step",
            make: scatter_step_case,
            hidden: &[ScatterVariation],
            right: scatter_right,
            open: false,
        },
    ]
}

/// One type's rates over its seeds.
struct Rates {
    seeds: usize,
    right: usize,
    other: usize,
    /// Cases with a term kept without a positive gain (must be none).
    kept_without_gain: usize,
    /// Cases with a finding of a test that the held-out prediction does not confirm.
    unconfirmed: usize,
    /// What the cases named wrong or with other findings named, for the failures.
    wrong: Vec<String>,
}

fn rates(t: &Type, seeds: std::ops::Range<u64>) -> Rates {
    let results: Vec<(u64, bool, bool, bool, bool, String)> = seeds
        .into_par_iter()
        .map(|s| {
            let case = (t.make)(s);
            let (_, d) = run_case(&case);
            let right = t.hidden.iter().all(|e| d.has(*e)) && (t.right)(&case, &d);
            let other = d.findings.iter().any(|f| !t.hidden.contains(&f.effect()));
            let bad_gain =
                (d.term_gains.iter()).any(|g| g.kept && (g.gain_pct.is_nan() || g.gain_pct <= 0.0));
            let unconfirmed = !d.unconfirmed.is_empty();
            (s, right, other, bad_gain, unconfirmed, d.effects_label())
        })
        .collect();
    Rates {
        seeds: results.len(),
        right: results.iter().filter(|r| r.1).count(),
        other: results.iter().filter(|r| r.2).count(),
        kept_without_gain: results.iter().filter(|r| r.3).count(),
        unconfirmed: results.iter().filter(|r| r.4).count(),
        wrong: results
            .iter()
            .filter(|r| !r.1 || r.2)
            .map(|r| format!("{}: {}", r.0, r.5))
            .collect(),
    }
}

fn pct(k: usize, n: usize) -> f64 {
    100.0 * k as f64 / n as f64
}

/// Every type named right in at least 96 % of its seeds with other findings in at most
/// 2 % (1 in 50; issue 43); clean data, on standard and on small plans, with any finding in
/// at most 1 %; every kept term with a positive gain.
#[test]
fn sweep_of_every_case_type() {
    let mut table = vec![format!(
        "{:<34} {:>6} {:>14} {:>16} {:>14}",
        "case type", "seeds", "named right %", "other findings %", "unconfirmed %"
    )];
    let mut failures = Vec::new();
    // SWEEP_ONLY=<part of a name> runs only the matching types (while tuning).
    let only = std::env::var("SWEEP_ONLY").unwrap_or_default();
    for (k, t) in types().iter().enumerate() {
        if !t.name.contains(only.as_str()) {
            continue;
        }
        let base = 300_000 + 10_000 * k as u64;
        let count = if t.hidden.is_empty() {
            3 * SWEEP
        } else {
            SWEEP
        };
        let r = rates(t, base..base + count);
        table.push(format!(
            "{:<34} {:>6} {:>14.1} {:>16.1} {:>14.1}",
            t.name,
            r.seeds,
            pct(r.right, r.seeds),
            pct(r.other, r.seeds),
            pct(r.unconfirmed, r.seeds)
        ));
        if !r.wrong.is_empty() {
            eprintln!("{}: named wrong or beside others: {:?}", t.name, r.wrong);
        }
        let (right, other) = (pct(r.right, r.seeds), pct(r.other, r.seeds));
        let ok = if t.hidden.is_empty() {
            other <= 1.0
        } else {
            right >= 96.0 && other <= 2.0
        };
        if (!ok && !t.open) || r.kept_without_gain > 0 {
            failures.push(format!(
                "{}: named right {right:.1} %, other {other:.1} %, kept without gain {}: {:?}",
                t.name, r.kept_without_gain, r.wrong
            ));
        }
    }
    eprintln!("{}", table.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Issue 43: `detectable` states, for every effect, the size this plan confirms in 80 %
/// of tests. On 200 clean axes (5 targets, 3 or 5 runs; a periodic error needs a finer
/// plan, so it is checked on 200 clean fine-step axes) an effect of the stated size,
/// added with the same noise, is confirmed in 70–90 % of them.
#[test]
fn the_stated_detectable_size_is_confirmed_in_about_80_percent_of_tests() {
    let seeds = 0..200u64;
    let outcomes: Vec<Vec<Option<(Effect, bool, bool)>>> = seeds
        .into_par_iter()
        .map(|s| {
            let small = small_clean_case(900_000 + s);
            let fine = fine_clean_case(910_000 + s);
            let (_, on_small) = run_case(&small);
            let (_, on_fine) = run_case(&fine);
            assert_eq!(on_small.detectable.len(), Effect::ALL.len());
            (Effect::ALL.iter())
                .map(|&e| {
                    let (base, clean) = if e == Effect::Periodic {
                        (&fine, &on_fine)
                    } else {
                        (&small, &on_small)
                    };
                    let x = (clean.detectable.iter())
                        .find(|x| x.effect == e)
                        .expect("every effect has a detectable size");
                    // An effect the plan cannot test (run offsets on 3 runs) is left
                    // out of its rate.
                    let size = x.size?;
                    let mut case = clean_copy(base);
                    let mut rng = Rng::new(base.seed, 4301);
                    add_effect(&mut case, e, size, &x.assumed, &mut rng);
                    let (_, d) = run_case(&case);
                    let seen = d.has(e) || d.unconfirmed.iter().any(|u| u.finding.effect() == e);
                    Some((e, d.has(e), seen))
                })
                .collect()
        })
        .collect();
    let mut failures = Vec::new();
    for &e in Effect::ALL {
        let count = |hit: fn(&(Effect, bool, bool)) -> bool| {
            (outcomes.iter().flatten().flatten())
                .filter(|o| o.0 == e && hit(o))
                .count()
        };
        let tested = count(|_| true);
        let rate = count(|o| o.1) as f64 / tested.max(1) as f64;
        let seen = count(|o| o.2) as f64 / tested.max(1) as f64;
        eprintln!(
            "detectable {}: confirmed in {:.1} % of {tested} (seen by its test in {:.1} %)",
            e.name(),
            rate * 100.0,
            seen * 100.0
        );
        // Every effect is testable on most of these plans (run offsets: the 5-run half).
        if tested < 90 {
            failures.push(format!("{}: testable on {tested} plans", e.name()));
        }
        if !(0.70..=0.90).contains(&rate) && !DETECTABLE_OPEN.contains(&e) {
            failures.push(format!("{}: {:.1} %", e.name(), rate * 100.0));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join(", "));
}

/// A copy of the clean case `base` to add effects to, read as `base` was (without time
/// stamps for a third of the seeds: `run_case`).
fn clean_copy(base: &Case) -> Case {
    Case {
        sim: base.sim.clone(),
        seed: base.seed,
        pitch: None,
        truth: 0.0,
        at: None,
    }
}

/// Adds effect `e` of the stated `size` (in its `measure`) with the shape `assumed` to the
/// case's model, the sign and placement drawn from `rng`.
fn add_effect(
    case: &mut Case,
    e: Effect,
    size: f64,
    assumed: &std::collections::BTreeMap<String, f64>,
    rng: &mut Rng,
) {
    let hours = test_hours(&case.sim, case.seed);
    let (start, end, _) = spacing_of(&case.sim.plan);
    let runs = case.sim.plan.runs;
    let signed = size * sign(rng);
    let m = &mut case.sim.model;
    match e {
        Effect::Drift => m.drift_per_h = signed / hours,
        Effect::ThermalGrowth => {
            m.thermal_origin = start;
            m.thermal_growth_ppm_per_h = signed / ((end - start) / 1000.0) / hours;
        }
        Effect::WarmUp => {
            let tau_min = assumed
                .get("time_constant_min")
                .copied()
                .unwrap_or(hours * 60.0 / 4.0);
            m.warm_up = signed;
            m.warm_up_tau_min = tau_min;
        }
        Effect::RunOffset => m.run_offsets = offsets_beyond_a_line(runs, size, rng),
        Effect::Periodic => m.periodic.push(PeriodicTerm {
            pitch: assumed["period_mm"],
            amplitude: size,
            phase_deg: rng.range(0.0, 360.0),
        }),
        Effect::ReversalVariation => m.reversal_end = Some(m.reversal + signed),
        Effect::Outlier => {
            let targets = spacing_of(&case.sim.plan).2;
            m.outliers.push(PlantedOutlier {
                run: 1 + (rng.uniform() * runs as f64) as u32,
                direction: if rng.uniform() < 0.5 {
                    Direction::Up
                } else {
                    Direction::Down
                },
                target: 1 + (rng.uniform() * targets as f64) as usize,
                size: signed,
            })
        }
        Effect::ScatterVariation => {
            // σ log-linear along the axis (21 knots), its ratio either way.
            let ratio = if rng.uniform() < 0.5 {
                size
            } else {
                1.0 / size
            };
            let sigma = m.scatter;
            m.scatter_knots = (0..=20)
                .map(|k| {
                    let f = k as f64 / 20.0;
                    [start + f * (end - start), sigma * ratio.powf(f)]
                })
                .collect();
        }
    }
}

/// Each combination of two effects (issue 43): on a clean standard axis (a fine-step axis
/// when one of them is the periodic error), both effects added at 1.5 times the size this
/// plan confirms (`detectable`: a test then finds each alone in about 99 % of tests; a
/// ratio to the power 1.5). Named right: at least one named, and each of the two named or
/// stated by the diagnosis as beyond what the plan confirms beside what it found (its
/// size added under [`RELIABLE`] times its `detectable` size on these data: a drift beside
/// real run offsets is judged against the run-to-run variation, and with 5 runs it is one
/// of their trends); "both named" is printed beside it. Other: any other finding, but a
/// drift where a warm-up so stated was added (its trend, which the drift finding says a
/// warm-up under that size would show). With a thermal
/// growth the diagnosis is told where it holds still (`thermal_origin`, the start of the
/// travel as the simulator has it): a drift and a growth about another origin fit the
/// same readings. Pairs the diagnosis does not separate yet are printed and listed in
/// `OPEN_PAIRS`.
#[test]
fn sweep_of_each_pair_of_effects() {
    let pairs: Vec<(Effect, Effect)> = (Effect::ALL.iter().enumerate())
        .flat_map(|(i, &a)| Effect::ALL[i + 1..].iter().map(move |&b| (a, b)))
        .collect();
    let only = std::env::var("SWEEP_ONLY").unwrap_or_default();
    let skip = std::env::var("SWEEP_SKIP").ok();
    // SWEEP_GAINS=1: each judged term's held-out gain and threshold beside the seeds shown.
    let gains = std::env::var_os("SWEEP_GAINS").is_some();
    // SWEEP_SEED=<s> runs that seed alone (s counts from 0).
    let one: Option<u64> = std::env::var("SWEEP_SEED")
        .ok()
        .and_then(|v| v.parse().ok());
    let per_seed: Vec<Vec<Option<PairOutcome>>> = (0..SWEEP)
        .into_par_iter()
        .filter(|s| one.is_none_or(|o| o == *s))
        .map(|s| {
            let standard = standard_clean_case(920_000 + s);
            let fine = fine_clean_case(930_000 + s);
            let (_, on_standard) = run_case(&standard);
            let (_, on_fine) = run_case(&fine);
            (pairs.iter())
                .map(|&(a, b)| {
                    let name = format!("{} + {}", a.name(), b.name());
                    if !name.contains(only.as_str()) {
                        return None;
                    }
                    let periodic = a == Effect::Periodic || b == Effect::Periodic;
                    let (base, clean) = if periodic {
                        (&fine, &on_fine)
                    } else {
                        (&standard, &on_standard)
                    };
                    let mut case = clean_copy(base);
                    let mut rng = Rng::new(base.seed, 4401);
                    let mut added = Vec::new();
                    for e in [a, b] {
                        let x = (clean.detectable.iter()).find(|x| x.effect == e).unwrap();
                        // A plan that cannot test one of them leaves the seed out.
                        let size = x.size?;
                        let size = if e == Effect::ScatterVariation {
                            size.powf(1.5)
                        } else {
                            1.5 * size
                        };
                        // SWEEP_SKIP=<effect> leaves that effect out of its pairs (the
                        // other added alone on the same axes): which of the two a pair's
                        // misses come from.
                        if skip.as_deref() == Some(e.name()) {
                            continue;
                        }
                        add_effect(&mut case, e, size, &x.assumed, &mut rng);
                        added.push((e, size));
                    }
                    // The growth's origin declared, as the campaign's `thermal_origin`:
                    // without it a drift beside it is a growth about another origin.
                    let thermal = [a, b].contains(&Effect::ThermalGrowth);
                    let origin = thermal.then_some(case.sim.model.thermal_origin);
                    let (_, d) = run_case_declaring(&case, origin);
                    let both = d.has(a) && d.has(b);
                    let right = (d.has(a) || d.has(b))
                        && added
                            .iter()
                            .all(|&(e, size)| d.has(e) || beyond(&d, e, size));
                    // A warm-up this plan cannot confirm shows as its trend: the drift
                    // finding says so, and names the added warm-up.
                    let warm_trend = added
                        .iter()
                        .any(|&(e, size)| e == Effect::WarmUp && !d.has(e) && beyond(&d, e, size));
                    let other = d.findings.iter().any(|f| {
                        let e = f.effect();
                        e != a && e != b && !(e == Effect::Drift && warm_trend)
                    });
                    // The seed and what was left unconfirmed, for `SWEEP_SHOW`.
                    let unconfirmed: Vec<&str> = (d.unconfirmed.iter())
                        .map(|u| u.finding.effect().name())
                        .collect();
                    let sizes: Vec<String> = (added.iter())
                        .map(|&(e, size)| {
                            let stated = (d.detectable.iter()).find(|x| x.effect == e);
                            let stated = stated.and_then(|x| x.size);
                            format!("{} {size:.3} (detectable here {stated:?})", e.name())
                        })
                        .collect();
                    let mut label = format!(
                        "{}: {} (unconfirmed {unconfirmed:?}; right {right}, other {other}; added {})",
                        base.seed,
                        d.effects_label(),
                        sizes.join(", ")
                    );
                    if gains {
                        for g in &d.term_gains {
                            label += &format!("\n    {}", g.describe("µm"));
                        }
                    }
                    Some(PairOutcome {
                        right,
                        other,
                        both,
                        label,
                    })
                })
                .collect()
        })
        .collect();
    let mut table = vec![format!(
        "{:<40} {:>6} {:>14} {:>12} {:>16}",
        "pair", "seeds", "named right %", "both named %", "other findings %"
    )];
    let mut failures = Vec::new();
    for (k, &(a, b)) in pairs.iter().enumerate() {
        let name = format!("{} + {}", a.name(), b.name());
        if !name.contains(only.as_str()) {
            continue;
        }
        let results: Vec<&PairOutcome> = (per_seed.iter()).filter_map(|r| r[k].as_ref()).collect();
        let right = pct(results.iter().filter(|r| r.right).count(), results.len());
        let other = pct(results.iter().filter(|r| r.other).count(), results.len());
        let both = pct(results.iter().filter(|r| r.both).count(), results.len());
        table.push(format!(
            "{name:<40} {:>6} {right:>14.1} {both:>12.1} {other:>16.1}",
            results.len()
        ));
        let open = OPEN_PAIRS.iter().find(|p| (p.0, p.1) == (a, b));
        let held = right >= 96.0 && other <= 2.0;
        // An open pair is held to what it reached, so that it cannot slip back unseen.
        let slipped = open.is_some_and(|p| right < p.2 || other > p.3);
        if slipped || (!held && (open.is_none() || std::env::var("SWEEP_SHOW").is_ok())) {
            let wrong: Vec<&str> = (results.iter())
                .filter(|r| !r.right || r.other)
                .map(|r| r.label.as_str())
                .take(if gains { 40 } else { 10 })
                .collect();
            failures.push(format!(
                "{name}: right {right:.1} %, other {other:.1} %: {wrong:#?}"
            ));
        }
    }
    eprintln!("{}", table.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// One seed of a pair: named right, another finding, both named, and what was named.
struct PairOutcome {
    right: bool,
    other: bool,
    both: bool,
    label: String,
}

/// The multiple of the stated size (the size found in 80 % of tests) at which a test finds
/// an effect in the 96 % these sweeps require: a shift of z(α/2) + z(0.96) = 3.29 + 1.75
/// standard errors against z(α/2) + z(0.80) = 3.29 + 0.84 at α = 0.001, about 1.2.
const RELIABLE: f64 = 1.2;

/// Whether the diagnosis `d` states that effect `e` of `size` (in its `measure`) is beyond
/// what its plan confirms reliably beside the effects it found: untestable, or `size`
/// under [`RELIABLE`] times the detectable size on these data (for the scatter's ratio, to
/// that power). At 1.5 times the clean axis's detectable size a pair's effect is beyond
/// only where the other effect raised it by a quarter or more.
fn beyond(d: &Diagnosis, e: Effect, size: f64) -> bool {
    (d.detectable.iter())
        .find(|x| x.effect == e)
        .is_some_and(|x| {
            x.size.is_none_or(|stated| {
                let reliable = if e == Effect::ScatterVariation {
                    stated.powf(RELIABLE)
                } else {
                    RELIABLE * stated
                };
                reliable > size
            })
        })
}

/// Pairs measured and printed but not yet held to the rates, each with the rates it
/// reached (named right %, at least; other findings %, at most), which the sweep holds it
/// to until it meets the issue's. None since 2026-12-01: the warm-up beside run offsets
/// (97.5 % right, 3.5 % other before) meets them since a reversal or scatter variation
/// whose run-by-run Bi fade is put down to the warm-up (`warm_up::fading`, README); the
/// periodic error beside run offsets since 2026-11-30 (the periodic block rounded to the
/// nearest target and the run offsets' stated size calibrated to 80 %).
const OPEN_PAIRS: &[(Effect, Effect, f64, f64)] = &[];

/// Beside run offsets a few runs may not let a warm-up be tested at all, and its course
/// within the first runs changes Bi and the scatter along the axis (issue 43): a reversal
/// or scatter variation found there whose run-by-run Bi fade is a note that names the
/// warm-up, not a finding; one that does not fade says that the plan could not test a
/// warm-up and asks for a warm re-test first; one found beside no run offsets does
/// neither.
#[test]
fn variations_beside_run_offsets_name_the_warm_up_they_could_not_test() {
    let caveat = "this plan cannot test a warm-up";
    let along = [Effect::ReversalVariation, Effect::ScatterVariation];
    let (beside, notes): (Vec<Vec<axcheck::diagnose::Finding>>, Vec<Vec<String>>) = (0..SWEEP)
        .into_par_iter()
        .map(|s| {
            let base = standard_clean_case(920_000 + s);
            let (_, clean) = run_case(&base);
            let mut case = clean_copy(&base);
            let mut rng = Rng::new(base.seed, 4401);
            for e in [Effect::WarmUp, Effect::RunOffset] {
                let x = (clean.detectable.iter()).find(|x| x.effect == e).unwrap();
                if let Some(size) = x.size {
                    add_effect(&mut case, e, 1.5 * size, &x.assumed, &mut rng);
                }
            }
            let (_, d) = run_case(&case);
            let warm = (d.detectable.iter()).find(|x| x.effect == Effect::WarmUp);
            let untested = warm.is_some_and(|x| x.size.is_none());
            // Why: the warm-up was tested, but beside the offsets no level reaches power.
            if let Some(x) = warm.filter(|_| untested) {
                assert!(
                    x.advice
                        .contains("no warm-up reaches the power of its test"),
                    "{}",
                    x.advice
                );
            }
            let found = (d.findings.into_iter())
                .filter(|f| untested && along.contains(&f.effect()))
                .collect();
            let notes = (d.notes.into_iter())
                .filter(|n| n.starts_with("not reported as a"))
                .collect();
            (found, notes)
        })
        .unzip();
    let (beside, notes): (Vec<_>, Vec<_>) = (beside.concat(), notes.concat());
    let noted = |what: &str| notes.iter().filter(|n| n.contains(what)).count();
    assert!(
        noted("as a reversal variation") >= 2 && noted("as a scatter variation") >= 1,
        "{notes:#?}"
    );
    for n in &notes {
        assert!(
            n.contains("each run's Bi change less than the run's before"),
            "{n}"
        );
        assert!(
            n.contains("re-test the warm machine (ISO 230-2 3.3)"),
            "{n}"
        );
    }
    assert!(
        !beside.is_empty(),
        "no variation left beside the run offsets"
    );
    for f in &beside {
        assert!(f.message.contains(caveat), "{}", f.message);
        assert!(
            f.advice().starts_with("re-test the warm machine"),
            "{}",
            f.advice()
        );
        assert!(
            f.labels()
                .contains(&("warm_up", "untested beside the run offsets"))
        );
    }
    let alone: Vec<String> = (380_000..380_040)
        .into_par_iter()
        .map(reversal_case)
        .chain((400_000..400_040).into_par_iter().map(scatter_case))
        .flat_map_iter(|c| {
            let d = run_case(&c).1;
            let withheld = d
                .notes
                .into_iter()
                .filter(|n| n.starts_with("not reported"));
            (d.findings.into_iter())
                .filter(|f| along.contains(&f.effect()))
                .map(|f| f.message)
                .chain(withheld)
        })
        .collect();
    assert!(alone.len() >= 60, "{} variations alone", alone.len());
    assert!(
        alone.iter().all(|m| !m.starts_with("not reported")),
        "{alone:#?}"
    );
    assert!(alone.iter().all(|m| !m.contains(caveat)), "{alone:#?}");
}

/// Issue 43: the scatter variation's term takes the shape the data show. A scatter that
/// changes in a step (3–5 times on one side of a point) is one σ per target on most axes,
/// with σ at every target in the finding and as the extended model's knots; one that
/// changes log-linearly stays a line or a smooth curve on most.
#[test]
fn the_scatter_variation_takes_the_shape_the_data_show() {
    let shapes = |make: fn(u64) -> Case, seeds: std::ops::Range<u64>| -> Vec<String> {
        seeds
            .into_par_iter()
            .filter_map(|s| {
                let (_, d) = run_case(&make(s));
                let f = d.of(Effect::ScatterVariation).next()?;
                let labels = f.labels();
                let shape = (labels.iter())
                    .find(|l| l.0 == "fitted_shape")
                    .map_or("line", |l| l.1);
                if shape == "per_target" {
                    let per: Vec<(String, f64)> = (f.params().into_iter())
                        .filter(|p| p.0.starts_with("scatter_target_"))
                        .collect();
                    assert!(per.len() >= 3, "{per:?}");
                    assert!(per.iter().all(|p| p.1 > 0.0), "{per:?}");
                    let knots = &d.extended_model.model.scatter_knots;
                    assert_eq!(knots.len(), per.len(), "{knots:?}");
                    assert!(f.message.contains("from target to target"), "{}", f.message);
                }
                Some(shape.to_string())
            })
            .collect()
    };
    let share = |v: &[String], want: &[&str]| {
        v.iter().filter(|s| want.contains(&s.as_str())).count() as f64 / v.len() as f64
    };
    let step = shapes(scatter_step_case, 560_000..560_100);
    let smooth = shapes(scatter_case, 570_000..570_100);
    eprintln!(
        "step: per target {:.0} % of {}; log-linear: line or curve {:.0} % of {}",
        100.0 * share(&step, &["per_target"]),
        step.len(),
        100.0 * share(&smooth, &["line", "curve"]),
        smooth.len()
    );
    assert!(step.len() >= 90 && smooth.len() >= 90);
    // Measured on 2026-12-01: 83 % and 100 %.
    assert!(share(&step, &["per_target"]) >= 0.7, "{step:?}");
    assert!(share(&smooth, &["line", "curve"]) >= 0.9, "{smooth:?}");
}
