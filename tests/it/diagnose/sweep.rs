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

/// One case type of the sweep.
struct Type {
    name: &'static str,
    make: fn(u64) -> Case,
    /// The hidden effects (none: clean data).
    hidden: &'static [Effect],
    /// Named right: every hidden effect named, with accurate estimates.
    right: fn(&Case, &Diagnosis) -> bool,
}

fn types() -> Vec<Type> {
    use Effect::*;
    vec![
        Type {
            name: "clean",
            make: clean_case,
            hidden: &[],
            right: |_, d| d.findings.is_empty(),
        },
        Type {
            name: "drift",
            make: drift_case,
            hidden: &[Drift],
            right: drift_right,
        },
        Type {
            name: "warm_up",
            make: |s| warm_up_case(s, false),
            hidden: &[WarmUp],
            right: warm_up_right,
        },
        Type {
            name: "warm_up without time_s",
            make: |s| warm_up_case(s, true),
            hidden: &[WarmUp],
            right: warm_up_right,
        },
        Type {
            name: "thermal_growth",
            make: thermal_case,
            hidden: &[ThermalGrowth],
            right: thermal_right,
        },
        Type {
            name: "run_offset (trend removed)",
            make: run_offset_case,
            hidden: &[RunOffset],
            right: run_offset_right,
        },
        Type {
            name: "run_offset (random)",
            make: random_run_offset_case,
            hidden: &[RunOffset],
            right: run_offset_right,
        },
        Type {
            name: "periodic",
            make: periodic_case,
            hidden: &[Periodic],
            right: periodic_right,
        },
        Type {
            name: "reversal_variation",
            make: reversal_case,
            hidden: &[ReversalVariation],
            right: reversal_right,
        },
        Type {
            name: "outlier",
            make: outlier_case,
            hidden: &[Outlier],
            right: outlier_right,
        },
        Type {
            name: "scatter_variation",
            make: scatter_case,
            hidden: &[ScatterVariation],
            right: scatter_right,
        },
        Type {
            name: "periodic + drift",
            make: periodic_and_drift_case,
            hidden: &[Periodic, Drift],
            right: |c, d| periodic_right(c, d) && d.has(Effect::Drift),
        },
        Type {
            name: "reversal_variation + outlier",
            make: reversal_and_outlier_case,
            hidden: &[ReversalVariation, Outlier],
            right: |c, d| outlier_right(c, d) && d.has(Effect::ReversalVariation),
        },
        Type {
            name: "reversal_variation + run_offset",
            make: reversal_and_run_offset_case,
            hidden: &[ReversalVariation, RunOffset],
            right: reversal_and_run_offset_right,
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

/// Every type named right in at least 95 % of its seeds with other findings in at most
/// 2 %; clean data with any finding in at most 1 %; every kept term with a positive gain.
#[test]
fn sweep_of_every_case_type() {
    let mut table = vec![format!(
        "{:<34} {:>6} {:>14} {:>16} {:>14}",
        "case type", "seeds", "named right %", "other findings %", "unconfirmed %"
    )];
    let mut failures = Vec::new();
    for (k, t) in types().iter().enumerate() {
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
            right >= 95.0 && other <= 2.0
        };
        if !ok || r.kept_without_gain > 0 {
            failures.push(format!(
                "{}: named right {right:.1} %, other {other:.1} %, kept without gain {}: {:?}",
                t.name, r.kept_without_gain, r.wrong
            ));
        }
    }
    eprintln!("{}", table.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
