//! The simulator reproduces its own parameters, and its files read back exactly.
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::measurement::{self, csv};
use axcheck::simulate::SimulationFile as _;
use axcheck::simulate::rng::Rng;
use axcheck::simulate::{ErrorModel, Simulation, TargetSpacing, TestPlan};
use axcheck::units::{AxisKind, Direction};

fn simulation(scale_ppm: f64, reversal: f64, scatter: f64, seed: u64) -> Simulation {
    Simulation {
        kind: AxisKind::Linear,
        seed,
        description: None,
        model: ErrorModel {
            scale_ppm,
            reversal,
            scatter,
            ..ErrorModel::default()
        },
        plan: TestPlan {
            targets: Some(TargetSpacing {
                start: 5.0,
                end: 1195.0,
                count: 11,
                jitter: 20.0,
            }),
            target_list: None,
            runs: 5,
            cycle: Default::default(),
            feed_per_min: 2000.0,
            dwell_s: 3.0,
            overrun: 5.0,
        },
    }
}

#[test]
fn recovers_reversal_and_scatter_within_statistical_bounds() {
    let seeds = 60;
    let (mut zb_sum, mut zs_sum, mut within_2) = (0.0, 0.0, 0);
    for seed in 0..seeds {
        // Sizes vary with the seed, so nothing is tuned to one model.
        let mut pick = Rng::new(seed, 99);
        let scatter = pick.range(0.2, 2.0);
        let reversal = pick.range(-6.0, 6.0);
        let scale = pick.range(-20.0, 20.0);
        let sim = simulation(scale, reversal, scatter, seed);
        let data = sim.run(seed);
        let e = evaluate(&data, StandardId::Iso230_2);
        let (m, n) = (data.target_count() as f64, data.runs() as f64);
        // B̄: mean of m differences of two means of n → variance 2σ²/(n m).
        let zb =
            (e.value(ParamKey::BMean).unwrap() - reversal) / (scatter * (2.0 / (n * m)).sqrt());
        // Pooled S over 2m cells with n − 1 degrees of freedom each.
        let pooled = (e
            .targets
            .iter()
            .flat_map(|t| [t.up.s.unwrap(), t.down.s.unwrap()])
            .map(|s| s * s)
            .sum::<f64>()
            / (2.0 * m))
            .sqrt();
        let df = 2.0 * m * (n - 1.0);
        let zs = (pooled - scatter) / (scatter / (2.0 * df).sqrt());
        assert!(zb.abs() < 4.0, "seed {seed}: B̄ z = {zb}");
        assert!(zs.abs() < 4.0, "seed {seed}: pooled S z = {zs}");
        zb_sum += zb;
        zs_sum += zs;
        within_2 += usize::from(zb.abs() < 2.0) + usize::from(zs.abs() < 2.0);
        // The scale error shows as the slope of X̄i: E grows with it.
        let slope_um = scale * 1.19;
        assert!(e.value(ParamKey::E).unwrap() >= slope_um.abs() - 2.0 * scatter - reversal.abs());
    }
    let k = seeds as f64;
    assert!((zb_sum / k).abs() < 0.6, "B̄ biased: mean z {}", zb_sum / k);
    assert!((zs_sum / k).abs() < 0.6, "S biased: mean z {}", zs_sum / k);
    assert!(
        within_2 as f64 >= 0.85 * 2.0 * k,
        "only {within_2} of {} within 2σ",
        2 * seeds
    );
}

#[test]
fn written_file_reads_back_identically() {
    let sim = simulation(8.0, 3.0, 0.7, 5);
    let data = sim.run(5);
    let text = csv::write(&data, &["test".into()]);
    let back = measurement::read(text.as_bytes(), "sim.csv").unwrap().data;
    assert_eq!(back.targets, data.targets);
    assert_eq!(back.run_labels, data.run_labels);
    for i in 0..data.target_count() {
        for d in Direction::BOTH {
            assert_eq!(back.deviations(i, d), data.deviations(i, d));
        }
    }
    for (a, b) in back.readings.iter().zip(&data.readings) {
        assert_eq!(
            (a.target, a.direction, a.run, a.time_s),
            (b.target, b.direction, b.run, b.time_s)
        );
    }
}

#[test]
fn time_terms_follow_the_clock() {
    // Drift only, no scatter: deviation = rate × time.
    let mut sim = simulation(0.0, 0.0, 0.0, 1);
    sim.model.drift_per_h = 3.6; // 0.001 µm per second
    let data = sim.run(1);
    for r in &data.readings {
        let t = r.time_s.unwrap();
        assert!(
            (r.deviation - 0.001 * t).abs() < 1e-3,
            "{} at {t}",
            r.deviation
        );
    }
    // Thermal growth: proportional to position × time.
    let mut sim = simulation(0.0, 0.0, 0.0, 1);
    sim.model.thermal_growth_ppm_per_h = 10.0;
    let data = sim.run(1);
    for r in &data.readings {
        let want = 10.0 * r.time_s.unwrap() / 3600.0 * data.targets[r.target] / 1000.0;
        assert!((r.deviation - want).abs() < 1e-3);
    }
}

#[test]
fn example_model_files_parse() {
    let text = "kind: rotary\nseed: 3\nmodel:\n  reversal_arcsec: 6\n  scatter_arcsec: 1.5\n  periodic: [{pitch_deg: 40, amplitude_arcsec: 2}]\nplan:\n  targets: {start_deg: 0, end_deg: 315, count: 8, jitter_deg: 0}\n  runs: 5\n  cycle: step\n  feed_deg_per_min: 3600\n";
    let sim = Simulation::from_yaml(text, "r.yaml").unwrap();
    let d = sim.run(3);
    assert_eq!(d.kind, AxisKind::Rotary);
    assert_eq!(
        d.targets,
        vec![0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0]
    );
    let e = evaluate(&d, StandardId::Iso230_2);
    assert!((e.value(ParamKey::BMean).unwrap() - 6.0).abs() < 1.5);
}
