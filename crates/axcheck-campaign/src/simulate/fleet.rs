//! A synthetic fleet for benchmarks: a campaign of N axes with a realistic mix, written
//! by `axcheck simulate --fleet N --out DIR`, deterministic from a seed.
//!
//! Mix: 70 % linear axes up to 2000 mm (5–20 targets, n = 5), 10 % long linear axes
//! (n = 1, up to 40 targets at ≤ 250 mm), 12 % rotary axes up to 360° (n = 5) and 8 %
//! rotary axes over 360° (n = 1, 45° steps). Three to five axes per machine.

use crate::axis_model::rng::Rng;
use crate::axis_model::{Cycle, ErrorModel, PeriodicTerm, Simulation, TestPlan};
use crate::measurement::csv;
use crate::units::AxisKind;
use rayon::prelude::*;

/// One generated file: its path relative to the fleet folder and its text.
pub struct FleetFile {
    pub path: String,
    pub text: String,
}

/// The campaign file and every measurement file of a fleet.
pub struct Fleet {
    pub campaign_yaml: String,
    pub files: Vec<FleetFile>,
    pub axes: usize,
    pub readings: usize,
}

struct AxisPlan {
    machine: usize,
    name: &'static str,
    sim: Simulation,
    travel: f64,
}

/// Test plan with `targets`, `runs` runs of the standard cycle.
fn plan_with(targets: Vec<f64>, runs: usize) -> TestPlan {
    TestPlan {
        targets: None,
        target_list: Some(targets),
        runs,
        cycle: Cycle::Standard,
        feed_per_min: 2000.0,
        dwell_s: 3.0,
        overrun: 5.0,
    }
}

/// `count` targets from `start` to `end`, the inner ones moved by up to a fifth of the
/// spacing (ISO 230-2 4.2), rounded to 1 µm.
fn spread(r: &mut Rng, start: f64, end: f64, count: usize) -> Vec<f64> {
    let step = (end - start) / (count - 1) as f64;
    (0..count)
        .map(|i| {
            let j = if i == 0 || i + 1 == count {
                0.0
            } else {
                r.range(-0.2, 0.2) * step
            };
            ((start + i as f64 * step + j) * 1000.0).round() / 1000.0
        })
        .collect()
}

/// The `k`th axis of the fleet: 70 % linear axes up to 2 m (5 runs), 10 % long linear
/// axes (1 run), 12 % rotary tables (5 runs), 8 % multi-turn rotary axes (1 run).
fn axis_plan(k: usize, seed: u64) -> (AxisKind, Simulation, f64) {
    let mut r = Rng::new(seed, 1000 + k as u64);
    let pick = r.uniform();
    let model = ErrorModel {
        scale_ppm: r.range(-12.0, 12.0),
        reversal: r.range(0.5, 5.0),
        scatter: r.range(0.2, 1.0),
        ..ErrorModel::default()
    };
    let (kind, model, plan, travel) = if pick < 0.70 {
        linear(&mut r, model)
    } else if pick < 0.80 {
        long_linear(&mut r, model)
    } else if pick < 0.92 {
        rotary_table(&mut r, model)
    } else {
        multi_turn(&mut r, model)
    };
    let sim = Simulation {
        kind,
        seed,
        description: None,
        model,
        plan,
    };
    (kind, sim, travel)
}

type AxisDraw = (AxisKind, ErrorModel, TestPlan, f64);

fn linear(r: &mut Rng, mut model: ErrorModel) -> AxisDraw {
    let travel = (r.range(300.0, 2000.0) / 10.0).round() * 10.0;
    let need = ((5.0 * (travel - 10.0) / 1000.0).ceil() as usize).max(5);
    let count = need + (r.uniform() * (21 - need.min(20)) as f64) as usize;
    let count = count.clamp(need, 20.max(need));
    model.shape = vec![
        [0.0, 0.0],
        [travel / 2.0, r.range(-3.0, 3.0)],
        [travel, r.range(-3.0, 3.0)],
    ];
    model.periodic = vec![PeriodicTerm {
        pitch: [5.0, 10.0, 16.0, 20.0][(r.uniform() * 4.0) as usize % 4],
        amplitude: r.range(0.0, 0.8),
        phase_deg: r.range(0.0, 360.0),
    }];
    let targets = spread(r, 5.0, travel - 5.0, count);
    (AxisKind::Linear, model, plan_with(targets, 5), travel)
}

fn long_linear(r: &mut Rng, mut model: ErrorModel) -> AxisDraw {
    let travel = (r.range(2500.0, 9500.0) / 10.0).round() * 10.0;
    let count = (((travel - 20.0) / 250.0).ceil() as usize + 1).min(40);
    model.shape = vec![
        [0.0, 0.0],
        [travel / 3.0, r.range(-6.0, 6.0)],
        [travel, r.range(-6.0, 6.0)],
    ];
    let targets = spread(r, 10.0, travel - 10.0, count);
    (AxisKind::Linear, model, plan_with(targets, 1), travel)
}

fn rotary_table(r: &mut Rng, mut model: ErrorModel) -> AxisDraw {
    let mut targets: Vec<f64> = vec![0.0, 90.0, 180.0, 270.0];
    let extra = 4 + (r.uniform() * 5.0) as usize;
    for e in 0..extra {
        let base = 360.0 * (e as f64 + 0.5) / extra as f64;
        let t = ((base + r.range(-10.0, 10.0)) * 1000.0).round() / 1000.0;
        if targets.iter().all(|x| (x - t).abs() > 8.0) && t > 0.0 && t < 355.0 {
            targets.push(t);
        }
    }
    targets.sort_by(f64::total_cmp);
    model.periodic = vec![PeriodicTerm {
        pitch: 360.0,
        amplitude: r.range(0.5, 3.0),
        phase_deg: r.range(0.0, 360.0),
    }];
    let mut plan = plan_with(targets, 5);
    plan.feed_per_min = 3600.0;
    (AxisKind::Rotary, model, plan, 360.0)
}

fn multi_turn(r: &mut Rng, mut model: ErrorModel) -> AxisDraw {
    let turns = if r.uniform() < 0.5 { 2.0 } else { 3.0 };
    let targets: Vec<f64> = (0..=(8 * turns as usize))
        .map(|k| 45.0 * k as f64)
        .collect();
    model.periodic = vec![PeriodicTerm {
        pitch: 360.0,
        amplitude: r.range(0.5, 3.0),
        phase_deg: 0.0,
    }];
    let mut plan = plan_with(targets, 1);
    plan.feed_per_min = 7200.0;
    (AxisKind::Rotary, model, plan, 360.0 * turns)
}

/// The largest fleet written: ten times the largest benchmark (10 000 axes). The fleet is
/// built in memory before it is written (about 6 kB an axis); `--fleet 99999999999` grew
/// past 5.5 GB before this bound.
pub const MAX_AXES: usize = 100_000;

/// Generates a fleet of `axes` axes from `seed`.
pub fn generate(axes: usize, seed: u64) -> Fleet {
    const LINEAR: [&str; 5] = ["X", "Y", "Z", "U", "W"];
    const ROTARY: [&str; 3] = ["A", "B", "C"];
    // Machines of 3 to 5 axes.
    let mut plans: Vec<AxisPlan> = Vec::with_capacity(axes);
    let mut r = Rng::new(seed, 7);
    let mut machine = 0;
    while plans.len() < axes {
        let size = (3 + (r.uniform() * 3.0) as usize).min(axes - plans.len());
        let (mut l, mut rot) = (0, 0);
        for _ in 0..size {
            let k = plans.len();
            let (kind, sim, travel) = axis_plan(k, seed);
            let name = match kind {
                AxisKind::Linear => {
                    l += 1;
                    LINEAR[(l - 1) % LINEAR.len()]
                }
                AxisKind::Rotary => {
                    rot += 1;
                    ROTARY[(rot - 1) % ROTARY.len()]
                }
            };
            plans.push(AxisPlan {
                machine,
                name,
                sim,
                travel,
            });
        }
        machine += 1;
    }
    // Names must be unique within a machine.
    let mut seen = std::collections::BTreeSet::new();
    let names: Vec<String> = plans
        .iter()
        .map(|p| {
            let mut name = p.name.to_string();
            let mut k = 2;
            while !seen.insert((p.machine, name.clone())) {
                name = format!("{}{k}", p.name);
                k += 1;
            }
            name
        })
        .collect();
    let files: Vec<(FleetFile, usize)> = plans
        .par_iter()
        .zip(&names)
        .enumerate()
        .map(|(k, (p, name))| {
            let data = p.sim.run(seed.wrapping_add(k as u64));
            let readings = data.readings.len();
            let path = format!(
                "data/m{:05}/{}.csv",
                p.machine + 1,
                name.to_ascii_lowercase()
            );
            (
                FleetFile {
                    path,
                    text: csv::write(&data, &[]),
                },
                readings,
            )
        })
        .collect();
    let mut yaml = format!(
        "# Synthetic fleet of {axes} axes (axcheck simulate --fleet {axes} --seed {seed})\ncampaign: {{name: Fleet of {axes} axes, date: 2026-11-20, standard: iso230-2, spec: general}}\nmachines:\n"
    );
    let mut current = usize::MAX;
    for (k, p) in plans.iter().enumerate() {
        if p.machine != current {
            current = p.machine;
            yaml.push_str(&format!(
                "  - id: M{:05}\n    model: synthetic\n    type: machining centre\n    axes:\n",
                p.machine + 1
            ));
        }
        yaml.push_str(&format!(
            "      - {{name: {}, kind: {}, travel: {}, data: {}}}\n",
            names[k], p.sim.kind, p.travel, files[k].0.path
        ));
    }
    let readings = files.iter().map(|(_, n)| n).sum();
    Fleet {
        campaign_yaml: yaml,
        files: files.into_iter().map(|(f, _)| f).collect(),
        axes,
        readings,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_small_fleet_is_deterministic_and_mixed() {
        let a = generate(40, 3);
        let b = generate(40, 3);
        assert_eq!(a.campaign_yaml, b.campaign_yaml);
        assert_eq!(a.files.len(), 40);
        assert!(a.files.iter().zip(&b.files).all(|(x, y)| x.text == y.text));
        assert!(
            a.campaign_yaml.contains("kind: rotary") && a.campaign_yaml.contains("kind: linear")
        );
        assert!(a.readings > 40 * 20);
    }
}
