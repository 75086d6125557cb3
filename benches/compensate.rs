//! `cargo bench --bench compensate`: time per axis of a compensation table without the
//! diagnosis (grid, table, the controller's held table, its file and the evaluation with
//! the table applied), for every controller, on one axis like the fleet's: 21 targets × 5
//! runs over 1 m, the table on a 20 mm grid (51 points).
use axcheck::compensate::{Settings, apply, controllers, held_table};
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::simulate::Simulation;
use std::hint::black_box;
use std::time::Instant;

const AXIS: &str = "kind: linear\nseed: 1\nmodel:\n  scale_um_per_m: 15\n  periodic: [{pitch_mm: 600, amplitude_um: 3, phase_deg: 20}]\n  reversal_um: 5\n  scatter_um: 0.3\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21, jitter_mm: 8}\n  runs: 5\n";

fn main() {
    let data = Simulation::from_yaml(AXIS, "bench")
        .expect("bench model")
        .run(1);
    let settings = Settings {
        interval: Some(20.0),
        ..Default::default()
    };
    let iterations = 2000;
    for c in controllers::CONTROLLERS {
        let mut samples: Vec<f64> = (0..5)
            .map(|_| {
                let start = Instant::now();
                for _ in 0..iterations {
                    let table = held_table(*c, black_box(&data), &settings).expect("held");
                    let file = c.write(&table, &[]).expect("written");
                    black_box((file, evaluate(&apply(&table, &data), StandardId::Iso230_2)));
                }
                start.elapsed().as_secs_f64() * 1e6 / iterations as f64
            })
            .collect();
        samples.sort_by(f64::total_cmp);
        println!(
            "{:>13}: {:.1} µs per axis (median of 5 rounds of {iterations})",
            c.name(),
            samples[2]
        );
    }
}
