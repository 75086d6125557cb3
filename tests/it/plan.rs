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
    let continuous = kind == AxisKind::Rotary && length >= 360.0 && rng.uniform() < 0.5;
    Axis {
        kind,
        standard,
        travel: Travel::Range([start, start + length]),
        continuous,
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
        continuous: false,
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
        &*few.findings[0].message,
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
        continuous: false,
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
        continuous: true,
        pitch: None,
        ..linear
    };
    let p = plan::plan(&table, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [0.0, 360.0]);
    for cardinal in [0.0, 90.0, 180.0, 270.0, 360.0] {
        assert!(p.targets.contains(&cardinal), "{:?}", p.targets);
    }
    assert_eq!(p.targets.len(), 9);
    // Not continuous: the travel's ends kept clear as on a linear axis.
    let stops = Axis {
        continuous: false,
        ..table.clone()
    };
    let p = plan::plan(&stops, &Motion::default(), 1).unwrap();
    assert_eq!(p.measurement_travel, [10.0, 350.0]);
    for cardinal in [90.0, 180.0, 270.0] {
        assert!(p.targets.contains(&cardinal), "{:?}", p.targets);
    }
    let linear_continuous = Axis {
        kind: AxisKind::Linear,
        ..table.clone()
    };
    assert_eq!(
        plan::plan(&linear_continuous, &Motion::default(), 1)
            .unwrap_err()
            .to_string(),
        "continuous: only a rotary axis turns freely; a linear axis has ends"
    );
    let long = Axis {
        kind: AxisKind::Linear,
        travel: Travel::Range([0.0, 4000.0]),
        continuous: false,
        ..table
    };
    let p = plan::plan(&long, &Motion::default(), 1).unwrap();
    assert_eq!((p.targets.len(), p.runs), (17, 1));
}

/// From plan to measurement to evaluation, on the command line: the plan written, an axis
/// simulated on it, a campaign naming it. Measured as planned, no rule finds anything; with
/// a target left out and another moved by 0.5 mm, `plan-targets` names both.
#[test]
fn a_campaign_names_what_its_measurement_changed_from_its_plan() {
    use crate::common::{axcheck, scratch};
    let dir = scratch("plan-campaign");
    let path = |name: &str| dir.join(name).to_string_lossy().into_owned();
    let (code, out, err) = axcheck(&[
        "plan",
        "--kind",
        "linear",
        "--travel",
        "0,800",
        "--pitch",
        "10",
        "--seed",
        "3",
        "-o",
        &path("x-plan.yaml"),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Every test-plan rule holds"), "{out}");
    let model = "kind: linear\nseed: 5\nmodel:\n  scale_um_per_m: 12\n  reversal_um: 3\n  scatter_um: 0.4\nplan:\n  targets: {start_mm: 0, end_mm: 100, count: 2}\n";
    std::fs::write(dir.join("x.yaml"), model).unwrap();
    let (code, _, err) = axcheck(&[
        "simulate",
        &path("x.yaml"),
        "--plan",
        &path("x-plan.yaml"),
        "-o",
        &path("data/x.csv"),
    ]);
    assert_eq!(code, 0, "{err}");
    // The same test with target 3 left out and target 5 typed 0.5 mm further.
    let plan = axcheck::plan::file::from_yaml(
        &std::fs::read_to_string(dir.join("x-plan.yaml")).unwrap(),
        "x-plan.yaml",
    )
    .unwrap();
    let (t3, t5) = (plan.targets[2], plan.targets[4]);
    let csv = std::fs::read_to_string(dir.join("data/x.csv")).unwrap();
    let changed: String = csv
        .lines()
        .filter_map(|l| {
            let target: Option<f64> = l.split(',').next().and_then(|t| t.parse().ok());
            match target {
                Some(t) if t == t3 => None,
                Some(t) if t == t5 => {
                    Some(l.replacen(&format!("{t5}"), &format!("{}", t5 + 0.5), 1))
                }
                _ => Some(l.to_string()),
            }
        })
        .map(|l| l + "\n")
        .collect();
    std::fs::write(dir.join("data/y.csv"), changed).unwrap();
    let axis = |name: &str| {
        format!(
            "      - {{name: {name}, kind: linear, travel: [0, 800], pitch: 10, data: data/{}.csv, plan: x-plan.yaml}}\n",
            name.to_lowercase()
        )
    };
    // Z names a plan that is not there: its axis gets the finding, the others are judged.
    std::fs::copy(dir.join("data/x.csv"), dir.join("data/z.csv")).unwrap();
    let z = axis("Z").replace(
        "plan: x-plan.yaml",
        "plan: {file: none.yaml, tolerance: 0.1}",
    );
    let campaign = format!(
        "campaign: {{name: planned}}\nmachines:\n  - id: M\n    axes:\n{}{}{z}",
        axis("X"),
        axis("Y")
    );
    std::fs::write(dir.join("campaign.yaml"), campaign).unwrap();
    let (_, out, err) = axcheck(&[
        "run",
        &path("campaign.yaml"),
        "--out",
        &path("out"),
        "--no-pdf",
    ]);
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("out/results.json")).unwrap())
            .unwrap();
    // The plan's rules; the campaign states no test conditions (iso-7.1-conditions).
    let rules = |axis: &str| {
        let axes = json["axes"].as_array().unwrap();
        let rules = axes.iter().find(|a| a["axis"] == axis).unwrap()["rules"].clone();
        let plan = (rules.as_array().unwrap().iter())
            .filter(|r| r["id"] != "iso-7.1-conditions")
            .cloned();
        serde_json::Value::Array(plan.collect())
    };
    assert_eq!(rules("X"), serde_json::json!([]), "{err}");
    let y = rules("Y");
    let found: Vec<&str> = y
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["id"].as_str().unwrap())
        .collect();
    assert!(found.contains(&"plan-targets"), "{y}");
    let message = y
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["id"] == "plan-targets")
        .unwrap()["message"]
        .as_str()
        .unwrap()
        .to_string();
    // The console names the warnings, which leave X and Z passing.
    assert!(
        out.contains("\nWarnings: ") && out.contains("plan-targets on 2"),
        "{out}"
    );
    let z = rules("Z");
    let z_message = z[0]["message"].as_str().unwrap();
    assert_eq!(z[0]["id"], "plan-targets", "{z}");
    assert!(
        z_message.starts_with("the plan none.yaml cannot be read: "),
        "{z_message}"
    );
    let at = |x: f64| format!("{x:.3} mm");
    assert_eq!(
        message,
        format!(
            "against the plan x-plan.yaml: T3 at {} is missing; T5 planned at {} was measured at {} (0.500 mm off, over the tolerance of 0.010 mm)",
            at(t3),
            at(t5),
            at(t5 + 0.5)
        )
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The target block for the laser software reads back, with axcheck's Renishaw reader, as
/// the plan's targets in their numbers; the reading order lists each reading once.
#[test]
fn the_laser_software_gets_the_plans_targets_and_order() {
    let axis = Axis {
        kind: AxisKind::Linear,
        standard: StandardId::Iso230_2,
        travel: Travel::Range([0.0, 1500.0]),
        continuous: false,
        measurement_travel: None,
        pitch: Some(20.0),
        scale_pitch: None,
    };
    let p = plan::plan(&axis, &Motion::default(), 4).unwrap();
    let m = p.targets.len();
    let mut rtl =
        String::from("HEADER::\nFile type  : rtl\nOwner      : Linear\nVersion no : V20.02.02\n\n");
    rtl.push_str(&plan::laser::rtl_targets(&p));
    rtl.push_str("\nRUNS::\nRun-count:2\n\nDEVIATIONS::\nRun Target Data:\n");
    for i in 1..=m {
        rtl.push_str(&format!("1 {i} 0.500\n"));
    }
    for i in (1..=m).rev() {
        rtl.push_str(&format!("2 {i} -0.500\n"));
    }
    rtl.push_str("\nEOF::\n");
    let read = axcheck::measurement::read(rtl.as_bytes(), "plan.rtl").unwrap();
    assert_eq!(read.data.targets, p.targets);
    let csv = plan::laser::readings_csv(&p);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "reading,run,direction,target,position_mm");
    assert_eq!(lines.len(), 1 + 2 * m * p.runs);
    assert_eq!(lines[1], format!("1,1,up,1,{:.3}", p.targets[0]));
    assert_eq!(
        lines[m + 1],
        format!("{},1,down,{m},{:.3}", m + 1, p.targets[m - 1])
    );
}

/// An axis of a campaign is planned with its travels, pitch and conditions; its name is the
/// program's axis address; a control that cannot take the name says so.
#[test]
fn a_campaign_axis_is_planned_with_its_conditions() {
    use crate::common::axcheck;
    let (code, out, err) = axcheck(&[
        "plan",
        "--campaign",
        "example-campaign/campaign.yaml",
        "--machine",
        "VMC-07",
        "--axis",
        "X",
        "--program",
        "linuxcnc",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("Test plan: 5 targets over 10.000 … 990.000 mm (ISO 230-2:1997), n = 5, standard cycle, overrun 5.000 mm, dwell 4.0 s, feed 2000 mm/min\n"),
        "{out}"
    );
    assert!(
        out.contains("\nG53 G1 X5.000 F2000.000 (start at 5.000 mm)\n"),
        "{out}"
    );
    assert!(out.contains("\nG4 P4.000\n"), "{out}");
    let (code, _, err) = axcheck(&[
        "plan",
        "--campaign",
        "example-campaign/campaign.yaml",
        "--machine",
        "ESS-BIFROST",
        "--axis",
        "slit 1",
        "--program",
        "fanuc",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("axis `slit 1` of machine `ESS-BIFROST` gives no travel: a plan needs it; add `travel:` to the axis"),
        "{err}"
    );
    let (code, _, err) = axcheck(&[
        "plan",
        "--kind",
        "linear",
        "--travel",
        "600",
        "--program",
        "fanuc",
        "--axis",
        "X1",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("FANUC addresses an axis by one of the letters X, Y, Z, A, B, C, U, V, W; got `X1` (--axis)"), "{err}");
}

/// The example's LATHE-5 is a FANUC lathe ("CNC turning centre"): its X program, in lathe
/// G-code system A, has no G91 and no G90 or G94 (turning cycles there), feeds per
/// minute with G98 and states that X is programmed in diameter, each X word twice the
/// slide's position.
#[test]
fn the_example_lathe_gets_a_turning_program() {
    use crate::common::axcheck;
    let (code, out, err) = axcheck(&[
        "plan",
        "--campaign",
        "example-campaign/campaign.yaml",
        "--machine",
        "LATHE-5",
        "--axis",
        "X",
        "--program",
        "fanuc",
    ]);
    assert_eq!(code, 0, "{err}");
    let program = &out[out.find("%\n").unwrap()..];
    let words: Vec<&str> = program
        .lines()
        .flat_map(|l| l.split('(').next().unwrap().split_whitespace())
        .collect();
    for word in ["G90", "G91", "G94"] {
        assert!(!words.contains(&word), "{word}: {program}");
    }
    assert!(program.contains("\nG18 G21 G40 G98 G54\n"), "{program}");
    assert!(
        program.contains("X IS PROGRAMMED IN DIAMETER, PARAMETER 1006 BIT 3 DIA = 1 EVERY X WORD IS TWICE THE SLIDE S POSITION"),
        "{program}"
    );
    assert!(
        program.contains("\nG01 X10.000 F1000.000 (START AT 5.000 MM)\n"),
        "{program}"
    );
    // B and C only on a lathe.
    let (code, _, err) = axcheck(&[
        "plan",
        "--kind",
        "linear",
        "--travel",
        "600",
        "--program",
        "fanuc",
        "--axis",
        "X",
        "--gcode-system",
        "b",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("--gcode-system applies to a lathe"), "{err}");
    let (code, out, err) = axcheck(&[
        "plan",
        "--kind",
        "linear",
        "--travel",
        "600",
        "--program",
        "fanuc",
        "--axis",
        "X",
        "--lathe",
        "--gcode-system",
        "b",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("\nG90 G01 X10.000 F1000.000 (START AT 5.000 MM)\n"),
        "{out}"
    );
}

/// `--continuous` (a rotary axis that turns freely) plans the whole travel with its
/// overruns beyond the ends and starts within one turn; without it a rotary axis keeps
/// clear of its travel's ends. An old plan file of 0…360° is refused, naming the move
/// and the travel, unless the axis is marked continuous; a campaign axis's
/// `continuous: true` does the same as the option.
#[test]
fn only_a_continuous_rotary_axis_overruns_its_travel() {
    use crate::common::{axcheck, scratch};
    let rotary = [
        "plan",
        "--kind",
        "rotary",
        "--travel",
        "0,360",
        "--program",
        "linuxcnc",
        "--axis",
        "C",
    ];
    let (code, out, err) = axcheck(&rotary);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("Test plan: 9 targets over 10.000 … 350.000 deg"),
        "{out}"
    );
    assert!(
        out.contains("\nG53 G1 C5.000 F1000.000 (start at 5.000 deg)\n"),
        "{out}"
    );
    let (code, out, err) = axcheck(&[&rotary[..], &["--continuous"]].concat());
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("Test plan: 9 targets over 0.000 … 360.000 deg"),
        "{out}"
    );
    assert!(
        out.contains("\nG53 G1 C0.000 F1000.000 (align at 0.000 deg)\n")
            && out.contains("\nG91\nG1 C-5.000 (start at -5.000 deg)\n"),
        "{out}"
    );
    let dir = scratch("plan-continuous");
    let old = "kind: rotary\nstandard: iso230-2\naxis_travel: [0, 360]\nmeasurement_travel: [0, 360]\ntargets: [0, 90, 180, 270, 360]\nruns: 2\ncycle: standard\noverrun: 5\ndwell_s: 2\nfeed: 1000\n";
    let path = dir.join("old.yaml").to_string_lossy().into_owned();
    std::fs::write(&path, old).unwrap();
    let from = ["plan", "--from", &path, "--program", "fanuc", "--axis", "C"];
    let (code, _, err) = axcheck(&from);
    assert_eq!(code, 2);
    assert!(
        err.contains("the start move to -5.000 deg leaves the axis travel 0.000 to 360.000 deg of axis C, which is not continuous"),
        "{err}"
    );
    let (code, out, err) = axcheck(&[&from[..], &["--continuous"]].concat());
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains(
            "\nG90 G01 C0.000 F1000.000 (ALIGN AT 0.000 DEG)\nG91\nC-5.000 (START AT -5.000 DEG)\n"
        ),
        "{out}"
    );
    let campaign = "campaign: {name: c}\nmachines:\n  - id: M\n    axes:\n      - {name: C, kind: rotary, travel: 360, continuous: true, data: c.csv}\n";
    std::fs::write(dir.join("campaign.yaml"), campaign).unwrap();
    let campaign_path = dir.join("campaign.yaml").to_string_lossy().into_owned();
    let (code, out, err) = axcheck(&[
        "plan",
        "--campaign",
        &campaign_path,
        "--machine",
        "M",
        "--axis",
        "C",
        "-o",
        &dir.join("c.yaml").to_string_lossy(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("Test plan: 9 targets over 0.000 … 360.000 deg"),
        "{out}"
    );
    let saved = std::fs::read_to_string(dir.join("c.yaml")).unwrap();
    assert!(
        saved.contains("\naxis_travel: 360.0\ncontinuous: true\n"),
        "{saved}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `--coordinates work` writes the moves in the active work offset, and the console and
/// the head say that the tables then need it added; a program still needs `--axis`.
#[test]
fn work_coordinates_are_said_to_need_the_offset_added() {
    use crate::common::axcheck;
    let args = [
        "plan",
        "--kind",
        "linear",
        "--travel",
        "600",
        "--program",
        "siemens-840d",
        "--axis",
        "X",
    ];
    let (code, out, err) = axcheck(&[&args[..], &["--coordinates", "work"]].concat());
    assert_eq!(code, 0, "{err}");
    let work =
        "Work coordinates, as --coordinates work asks: every position is in the active work offset";
    let tables = "The compensation tables axcheck writes are in machine positions: add the active work offset of axis X to each table position";
    assert!(
        out.contains(&format!("\nNote: {work}. {tables}.\n")),
        "{out}"
    );
    assert!(out.contains(&format!("\n; {work}\n; {tables}\n")), "{out}");
    assert!(
        out.contains("\nG1 X5.000 F1000.000 ; start at 5.000 mm\n"),
        "{out}"
    );
    let (code, out, _) = axcheck(&args);
    assert_eq!(code, 0);
    assert!(!out.contains("Note: Work") && out.contains("\nG1 SUPA X5.000 F1000.000"));
    let (code, _, err) = axcheck(&[
        "plan",
        "--kind",
        "linear",
        "--travel",
        "600",
        "--program",
        "fanuc",
    ]);
    assert_eq!(code, 2);
    assert!(
        err.contains("give the axis's address on the control with --axis"),
        "{err}"
    );
    let (code, _, err) = axcheck(&[&args[..], &["--coordinates", "joint"]].concat());
    assert_eq!(code, 2);
    assert!(
        err.contains("expected machine or work, got `joint`"),
        "{err}"
    );
}
