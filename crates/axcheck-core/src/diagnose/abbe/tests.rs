use super::*;
use crate::axis_model::Simulation;
use crate::measurement::AxisData;

/// MILL-8's X as the example simulates it, with a pitch of `bow` arcsec in the middle of
/// the travel (and 22″/m), the beam `beam_z` mm from the tool point along Z.
fn simulation(bow: f64, beam_z: f64) -> Simulation {
    serde_json::from_value(serde_json::json!({
        "kind": "linear",
        "seed": 801,
        "model": {
            "scale_um_per_m": 16, "reversal_um": 1.8, "scatter_um": 0.3,
            "geometry": {
                "axis": "X",
                "angular": {"B": {"slope_arcsec_per_m": 22, "bow_arcsec": bow, "scatter_arcsec": 0.3}},
                "beam_mm": {"Z": beam_z}
            }
        },
        "plan": {"targets": {"start_mm": 5, "end_mm": 795, "count": 9, "jitter_mm": 3}, "runs": 5, "cycle": "standard"}
    }))
    .unwrap()
}

/// The pitch test's mean angle at `x` in direction `d`, linear between its targets (as
/// `geometry::angular::Trace` reads it, which this layer does not use).
fn trace(pitch: &AxisData, x: f64, d: Direction) -> Option<f64> {
    let t = &pitch.targets;
    let mean = |i: usize| {
        let r = pitch.deviations(i, d);
        r.iter().sum::<f64>() / r.len() as f64
    };
    if x < t[0] - 1e-6 || x > t[t.len() - 1] + 1e-6 {
        return None;
    }
    let k = t.partition_point(|&p| p < x).clamp(1, t.len() - 1);
    let u = ((x - t[k - 1]) / (t[k] - t[k - 1])).clamp(0.0, 1.0);
    Some(mean(k - 1) + u * (mean(k) - mean(k - 1)))
}

fn fitted(bow: f64, beam_z: f64, seed: u64) -> AbbeFit {
    let s = simulation(bow, beam_z);
    let positioning = s.run(seed);
    let pitch = s.run_geometry(seed, 'B').unwrap();
    let rotation = Rotation {
        symbol: "EBX",
        lever: 'Z',
        sign: 1.0,
        angle_arcsec: &|x, d| trace(&pitch, x, d),
    };
    fit(&positioning, &[rotation]).unwrap()
}

/// A pitch bow of 8″ read 160 mm off the beam is 6.2 µm of curve in the positioning
/// test: found in each of 20 seeds, the lever −160 mm within 3 u, and u under 10 mm.
#[test]
fn a_pitch_read_off_the_beam_is_found_with_its_lever() {
    for seed in 0..20 {
        let f = fitted(8.0, -160.0, seed);
        assert!(f.found, "{seed}: {}", f.evidence);
        let lever = &f.levers[0];
        let (offset, u) = (lever.offset_mm.unwrap(), lever.u_mm.unwrap());
        assert!((offset + 160.0).abs() < 3.0 * u, "{seed}: {offset} ± {u}");
        assert!(u < 10.0, "{seed}: u {u}");
        assert!(f.rms_with_angles_um < f.rms_progressive_um / 3.0);
    }
}

/// The beam on the line (no offset), or a pitch straight along the travel: no finding in
/// at least 19 of 20 seeds (α = 0.001 and the share rule).
#[test]
fn no_lever_no_finding() {
    let (mut on_line, mut straight) = (0, 0);
    for seed in 0..20 {
        on_line += usize::from(fitted(8.0, 0.0, seed).found);
        straight += usize::from(fitted(0.0, -160.0, seed).found);
    }
    assert!(
        on_line <= 1,
        "found with the beam on the line in {on_line} of 20"
    );
    assert!(
        straight <= 1,
        "found with a straight pitch in {straight} of 20"
    );
}
