//! `cargo bench --bench evaluate`: time per axis of the evaluation core (ISO 230-2 and
//! GOST 27843 parameters, pure computation) on one core, for an axis of 11 targets × 5 runs
//! (a 1 m axis per clause 4.3.2 at 100 mm spacing) and one of 200 targets × 5 runs.
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use std::hint::black_box;
use std::time::Instant;

fn axis(targets: usize, end_mm: f64) -> axcheck::measurement::AxisData {
    let model = format!(
        "kind: linear\nseed: 1\nmodel:\n  scale_um_per_m: 5\n  reversal_um: 3\n  scatter_um: 1\nplan:\n  targets: {{start_mm: 0, end_mm: {end_mm}, count: {targets}, jitter_mm: 0}}\n  runs: 5\n"
    );
    Simulation::from_yaml(&model, "bench")
        .expect("bench model")
        .run(1)
}

/// Median of `rounds` timings of `iterations` evaluations, in µs per evaluation.
fn time_per_axis(data: &axcheck::measurement::AxisData, standard: StandardId) -> f64 {
    let iterations = 2_000;
    let mut samples: Vec<f64> = (0..9)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iterations {
                black_box(evaluate(black_box(data), standard));
            }
            start.elapsed().as_secs_f64() * 1e6 / iterations as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

fn main() {
    for (label, data) in [
        ("11 targets x 5 runs", axis(11, 1000.0)),
        ("200 targets x 5 runs", axis(200, 19900.0)),
    ] {
        assert_eq!(
            data.targets.len(),
            if label.starts_with("11") { 11 } else { 200 }
        );
        for standard in [StandardId::Iso230_2, StandardId::Gost27843] {
            println!(
                "{label}, {standard:?}: {:.1} µs per axis (median of 9 rounds of 2000)",
                time_per_axis(&data, standard)
            );
        }
    }
}
