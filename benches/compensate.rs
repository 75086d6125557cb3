//! `cargo bench --bench compensate`: time per axis of a compensation table without the
//! diagnosis (grid, table, the controller's held table, its file and the evaluation with
//! the table applied), of reading the file back, and of a table built on that one as the
//! active table (the incremental table and its prediction), for every controller; then of a
//! verification (the re-measurement against the prediction, every effect tried). One axis
//! like the fleet's: 21 targets × 5 runs over 1 m, the table on a 20 mm grid (51 points).
use axcheck::compensate::controllers::ReadAs;
use axcheck::compensate::{Active, Settings, apply, apply_change, controllers, held_table};
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use axcheck::verify;
use std::hint::black_box;
use std::time::Instant;

const AXIS: &str = "kind: linear\nseed: 1\nmodel:\n  scale_um_per_m: 15\n  periodic: [{pitch_mm: 600, amplitude_um: 3, phase_deg: 20}]\n  reversal_um: 5\n  scatter_um: 0.3\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21, jitter_mm: 8}\n  runs: 5\n";

const ITERATIONS: usize = 2000;

/// Median over 5 rounds of `ITERATIONS` calls of `f`, µs per call.
fn median_us(mut f: impl FnMut()) -> f64 {
    let mut samples: Vec<f64> = (0..5)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..ITERATIONS {
                f();
            }
            start.elapsed().as_secs_f64() * 1e6 / ITERATIONS as f64
        })
        .collect();
    samples.sort_by(f64::total_cmp);
    samples[2]
}

fn main() {
    let sim = Simulation::from_yaml(AXIS, "bench").expect("bench model");
    let data = sim.run(1);
    let settings = Settings {
        interval: Some(20.0),
        active: Some(Active::default()),
        ..Default::default()
    };
    let reading = ReadAs {
        kind: data.kind,
        axis: None,
    };
    for c in controllers::CONTROLLERS {
        let table = held_table(*c, &data, &settings).expect("held");
        let file = c.write(&table, &[]).expect("written");
        let built = median_us(|| {
            let table = held_table(*c, black_box(&data), &settings).expect("held");
            let file = c.write(&table, &[]).expect("written");
            black_box((file, evaluate(&apply(&table, &data), StandardId::Iso230_2)));
        });
        let read = median_us(|| {
            black_box(c.read(black_box(&file), reading).expect("read"));
        });
        let active = Active {
            table: Some(c.read(&file, reading).expect("read")),
            ..Active::default()
        };
        let total = active.total(c.backlash(), data.kind);
        let on_active = Settings {
            active: Some(active),
            ..settings.clone()
        };
        let incremental = median_us(|| {
            let table = held_table(*c, black_box(&data), &on_active).expect("held");
            let after = apply_change(&table, total.as_ref(), &data);
            black_box(evaluate(&after, StandardId::Iso230_2));
        });
        println!(
            "{:>13}: {built:.1} µs per axis (median of 5 rounds of {ITERATIONS}); read back {read:.1} µs; built on an active table {incremental:.1} µs",
            c.name()
        );
    }
    let csv = controllers::find("csv").expect("csv");
    let table = held_table(csv, &data, &settings).expect("held");
    let after = apply(&table, &sim.run(2));
    let input = verify::VerifyInput {
        before: &data,
        after: &after,
        old: None,
        new: &table,
        others: &[],
        controller: Some(csv),
        standard: StandardId::Iso230_2,
    };
    let us = median_us(|| {
        black_box(verify::verify(black_box(&input)).expect("verified"));
    });
    println!("verification: {us:.1} µs per axis (median of 5 rounds of {ITERATIONS})");
}
