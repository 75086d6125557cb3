//! Test plans made before the measurement: every plan passes every plan rule and samples the
//! declared pitches, the part programs visit every target as the cycle asks, and a campaign
//! names what its measurement changed from its plan.

use axcheck::evaluate::StandardId;
use axcheck::plan::{self, Axis, Motion};
use axcheck::simulate::rng::Rng;
use axcheck::units::{AxisKind, Travel};

/// A random axis: linear 100 mm to 6 m or rotary 90° to 1080°, any standard, a lead-screw
/// pitch and sometimes a scale pitch.
fn random_axis(seed: u64) -> Axis {
    let mut rng = Rng::new(seed, 7);
    let kind = if rng.uniform() < 0.5 {
        AxisKind::Linear
    } else {
        AxisKind::Rotary
    };
    let length = match kind {
        AxisKind::Linear => rng.range(100.0, 6000.0),
        AxisKind::Rotary => rng.range(90.0, 1080.0),
    };
    let length = (length * 10.0).round() / 10.0;
    let start = (rng.range(-500.0, 500.0) * 10.0).round() / 10.0;
    let standard = StandardId::ALL[(rng.uniform() * 5.0) as usize % 5];
    let pitch = match kind {
        AxisKind::Linear => [5.0, 10.0, 16.0, 20.0, 25.0][(rng.uniform() * 5.0) as usize % 5],
        AxisKind::Rotary => [1.0, 5.0, 10.0][(rng.uniform() * 3.0) as usize % 3],
    };
    let scale_pitch = (rng.uniform() < 0.3).then_some(0.02);
    Axis {
        kind,
        standard,
        travel: Travel::Range([start, start + length]),
        measurement_travel: None,
        pitch: Some(pitch),
        scale_pitch,
    }
}

/// 200 random axes: every plan passes every plan rule (by construction; the rules are the
/// ones its measurement will be judged by), the pitch-alias rule included, for the lead
/// screw's pitch and the scale's.
#[test]
fn every_plan_of_200_random_axes_passes_every_rule() {
    for seed in 0..200 {
        let axis = random_axis(seed);
        let p = plan::plan(&axis, &Motion::default(), seed).unwrap();
        assert!(
            p.findings.is_empty(),
            "{axis:?}: {:?}\n{:?}",
            p.findings,
            p.targets
        );
        let [a, b] = p.measurement_travel;
        assert_eq!(
            (p.targets[0], p.targets[p.targets.len() - 1]),
            (a, b),
            "{axis:?}"
        );
    }
}

/// Targets given are checked, not changed: eleven every 100 mm over a 10 mm pitch break the
/// spacing and alias rules; four over 600 mm are too few for clause 4.3.2.
#[test]
fn targets_given_are_checked_by_the_rules() {
    let axis = Axis {
        kind: AxisKind::Linear,
        standard: StandardId::Iso230_2,
        travel: Travel::Range([0.0, 1100.0]),
        measurement_travel: None,
        pitch: Some(10.0),
        scale_pitch: None,
    };
    let even: Vec<f64> = (0..11).map(|k| 50.0 + 100.0 * k as f64).collect();
    let p = plan::with_targets(&axis, &Motion::default(), even).unwrap();
    let ids: Vec<&str> = p.findings.iter().map(|f| f.id).collect();
    assert_eq!(ids, ["iso-4.2-uniform-spacing", "iso-4.2-pitch-alias"]);
    let few =
        plan::with_targets(&axis, &Motion::default(), vec![10.0, 203.0, 411.0, 610.0]).unwrap();
    let ids: Vec<&str> = few.findings.iter().map(|f| f.id).collect();
    assert_eq!(ids, ["iso-4.3.2-targets"]);
    assert_eq!(
        few.findings[0].message,
        "4 targets over 600 mm of measurement travel; at least 5 per metre and 5 in all are needed (5): add 1 target(s)"
    );
}

/// A made plan keeps the ends of the axis travel out by the overrun, holds the principal
/// positions of a rotary axis, and spreads its targets' phases over the pitch.
#[test]
fn a_plan_keeps_room_to_reverse_and_the_principal_positions() {
    let linear = Axis {
        kind: AxisKind::Linear,
        standard: StandardId::Iso230_2,
        travel: Travel::Range([0.0, 1000.0]),
        measurement_travel: None,
        pitch: Some(10.0),
        scale_pitch: None,
    };
    let p = plan::plan(&linear, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [10.0, 990.0]);
    assert_eq!(p.targets.len(), 5);
    assert_eq!(p.runs, 5);
    let mut phases: Vec<f64> = p
        .targets
        .iter()
        .map(|t| (t / 10.0).rem_euclid(1.0))
        .collect();
    phases.sort_by(f64::total_cmp);
    let widest = phases
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(phases[0] + 1.0 - phases[4], f64::max);
    assert!(widest < 0.5, "phases {phases:?}");
    let table = Axis {
        kind: AxisKind::Rotary,
        travel: Travel::Length(360.0),
        pitch: None,
        ..linear
    };
    let p = plan::plan(&table, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [0.0, 360.0]);
    for cardinal in [0.0, 90.0, 180.0, 270.0, 360.0] {
        assert!(p.targets.contains(&cardinal), "{:?}", p.targets);
    }
    assert_eq!(p.targets.len(), 9);
    let long = Axis {
        kind: AxisKind::Linear,
        travel: Travel::Range([0.0, 4000.0]),
        ..table
    };
    let p = plan::plan(&long, &Motion::default(), 1).unwrap();
    assert_eq!((p.targets.len(), p.runs), (17, 1));
}
