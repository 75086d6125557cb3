//! `cargo bench --bench diagnose`: time per axis of the model check and diagnosis
//! (`axcheck::diagnose::diagnose`, 200 Monte-Carlo tests, 10-fold cross-validation,
//! periodograms) on one core, for axes like the fleet's: 11 targets × 5 runs over 1 m
//! (too coarse for the periodogram), 20 targets × 5 runs over 400 mm (with the
//! periodogram and its Monte-Carlo check) and 40 targets × 1 run over 4 m (n = 1: no
//! Monte-Carlo check, no cross-validation).
use axcheck::diagnose::{Options, diagnose};
use axcheck::measurement::AxisData;
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use std::hint::black_box;
use std::time::Instant;

fn axis(targets: usize, end_mm: f64, runs: usize) -> AxisData {
    let model = format!(
        "kind: linear\nseed: 1\nmodel:\n  scale_um_per_m: 5\n  shape: [[0, 0], [{half}, 2], [{end_mm}, -1]]\n  reversal_um: 3\n  scatter_um: 1\nplan:\n  targets: {{start_mm: 0, end_mm: {end_mm}, count: {targets}, jitter_mm: {jitter}}}\n  runs: {runs}\n",
        half = end_mm / 2.0,
        jitter = end_mm / (targets - 1) as f64 / 5.0,
    );
    Simulation::from_yaml(&model, "bench")
        .expect("bench model")
        .run(1)
}

/// Median of 5 rounds of `iterations` diagnoses, in ms per axis.
fn time_per_axis(data: &AxisData, iterations: usize) -> f64 {
    let options = Options::default();
    let mut samples: Vec<f64> = (0..5)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..iterations {
                black_box(diagnose(black_box(data), &options));
            }
            start.elapsed().as_secs_f64() * 1e3 / iterations as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[samples.len() / 2]
}

fn main() {
    // One core: the Monte-Carlo tests run on rayon's pool.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    pool.install(|| {
        for (label, data, iterations) in [
            ("11 targets x 5 runs, 1 m", axis(11, 1000.0, 5), 40),
            ("20 targets x 5 runs, 400 mm", axis(20, 400.0, 5), 20),
            ("40 targets x 1 run, 4 m", axis(40, 4000.0, 1), 100),
        ] {
            let d = diagnose(&data, &Options::default());
            let checks: Vec<&str> = d.checks.iter().map(|c| c.statistic.as_str()).collect();
            println!(
                "{label}: {:.2} ms per axis (median of 5 rounds of {iterations}; {} model checks{})",
                time_per_axis(&data, iterations),
                checks.len(),
                if checks.contains(&"periodogram_max_f") {
                    ", periodogram included"
                } else {
                    ""
                }
            );
        }
    });
}
