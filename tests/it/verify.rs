//! Verification of a compensation on simulated re-measurements: the table applied right is
//! found effective with no finding; applied with the opposite sign, twice, not at all,
//! shifted by one table interval or scaled by 10, it is named for what went wrong.

use crate::common::{axcheck, scratch};
use axcheck::compensate::{self, Active, Settings, Table};
use axcheck::evaluate::StandardId;
use axcheck::simulate::Simulation;
use axcheck::verify::{self, Key, Verdict, Verification};

/// 1 000 mm measured at 21 jittered targets, five runs: 20 ppm of scale error, a 4 µm sine
/// of 300 mm, 5 µm of reversal, 0.4 µm of scatter.
const AXIS: &str = "kind: linear\nseed: 1\nmodel:\n  scale_um_per_m: 20\n  periodic: [{pitch_mm: 300, amplitude_um: 4, phase_deg: 40}]\n  reversal_um: 5\n  scatter_um: 0.4\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21, jitter_mm: 8}\n  runs: 5\n";

/// The table interval, mm.
const INTERVAL: f64 = 50.0;

/// How the table reached the machine.
#[derive(Debug, Clone, Copy)]
enum Case {
    Right,
    Opposite,
    Twice,
    NotActive,
    Shifted,
    Scaled,
}

/// The table as it acted on the machine in `case`.
fn as_acted(table: &Table, case: Case) -> Option<Table> {
    let scaled = |f: f64| Table {
        up: table.up.iter().map(|v| f * v).collect(),
        down: table.down.iter().map(|v| f * v).collect(),
        ..table.clone()
    };
    match case {
        Case::Right => Some(table.clone()),
        Case::Opposite => Some(scaled(-1.0)),
        Case::Twice => Some(scaled(2.0)),
        Case::NotActive => None,
        Case::Scaled => Some(scaled(10.0)),
        // Its points one interval further along: at P it adds what it holds for P − 50.
        Case::Shifted => Some(Table {
            positions: table.positions.iter().map(|p| p + INTERVAL).collect(),
            ..table.clone()
        }),
    }
}

/// The verification of seed `seed`: measured, compensated by a TwinCAT list every 50 mm,
/// measured again (other scatter) with the table acting as `case` says.
fn verified(seed: u64, case: Case) -> Verification {
    let sim = Simulation::from_yaml(AXIS, "axis.yaml").unwrap();
    let before = sim.run(seed);
    let controller = compensate::controllers::find("twincat").unwrap();
    let settings = Settings {
        interval: Some(INTERVAL),
        active: Some(Active::default()),
        ..Default::default()
    };
    let table = compensate::held_table(controller, &before, &settings).unwrap();
    let again = sim.run(seed + 1000);
    let after = match as_acted(&table, case) {
        Some(t) => compensate::apply(&t, &again),
        None => again,
    };
    let input = verify::Input {
        before: &before,
        after: &after,
        old: None,
        new: &table,
        others: &[],
        standard: StandardId::Iso230_2,
    };
    verify::verify(&input).unwrap()
}

/// 50 seeds per case: the table applied right is effective with no finding, and each
/// mistake is the one finding, in at least 95 % of them (48 of 50).
#[test]
fn each_way_a_table_can_act_is_named_in_95_percent_of_50_seeds() {
    let mut report = Vec::new();
    for (case, expected) in [
        (Case::Right, None),
        (Case::Opposite, Some(Key::SignInverted)),
        (Case::Twice, Some(Key::AppliedTwice)),
        (Case::NotActive, Some(Key::NotActive)),
        (Case::Shifted, Some(Key::PositionShift)),
        (Case::Scaled, Some(Key::Scale)),
    ] {
        let right = (1..=50)
            .filter(|seed| {
                let v = verified(*seed, case);
                let keys: Vec<Key> = v.findings.iter().map(|f| f.effect).collect();
                match expected {
                    None => v.verdict == Verdict::Effective && keys.is_empty(),
                    Some(k) => keys == [k],
                }
            })
            .count();
        report.push(format!("{case:?}: {right} of 50"));
        assert!(right >= 48, "{case:?}: {right} of 50 named right");
    }
    eprintln!("{}", report.join(", "));
}

/// The verdicts of the mistakes: the opposite sign and ten times the table make the axis
/// worse, a table not active leaves it as it was; the finding's evidence names the factor.
#[test]
fn the_verdict_follows_what_the_table_did_to_e() {
    let v = verified(7, Case::Opposite);
    assert_eq!(v.verdict, Verdict::MadeWorse);
    assert!(v.e.achieved > v.e.before + v.e.uncertainty, "{:?}", v.e);
    assert_eq!(v.findings[0].params["factor"], -1.0);
    assert!(
        v.findings[0]
            .evidence
            .starts_with("the table acted with the opposite sign"),
        "{}",
        v.findings[0].evidence
    );
    assert_eq!(verified(7, Case::Scaled).verdict, Verdict::MadeWorse);
    assert_eq!(verified(7, Case::Scaled).findings[0].params["factor"], 10.0);
    let not = verified(7, Case::NotActive);
    assert_eq!(not.verdict, Verdict::NotEffective);
    assert!((not.e.achieved - not.e.before).abs() <= not.e.uncertainty);
    let shifted = verified(7, Case::Shifted);
    assert!((shifted.findings[0].params["shift"] - INTERVAL).abs() < 1e-9);
}

/// From the command line as a metrologist works: measure, write the table, measure again
/// with it loaded (here: with it loaded with the opposite sign), verify. The JSON keys are a
/// stable interface; the exit status says whether the table was effective.
#[test]
fn the_cli_verifies_a_re_measurement() {
    let dir = scratch("verify-cli");
    let path = |name: &str| dir.join(name).to_string_lossy().into_owned();
    std::fs::write(dir.join("axis.yaml"), AXIS).unwrap();
    let run = |args: &[&str]| {
        let (code, out, err) = axcheck(args);
        assert!(code <= 1, "{args:?}: {err}");
        (code, out)
    };
    run(&["simulate", &path("axis.yaml"), "-o", &path("before.csv")]);
    run(&[
        "compensate",
        &path("before.csv"),
        "--controller",
        "linuxcnc",
        "--comp-file-type",
        "1",
        "--active",
        "none",
        "-o",
        &path("x.txt"),
    ]);
    // The same file (type 1: trims) with every trim negated: loaded by a user who read
    // LinuxCNC's INI documentation rather than its code.
    let table = std::fs::read_to_string(dir.join("x.txt")).unwrap();
    let negated: String = table
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            format!("{} {} {}\n", v[0], -v[1], -v[2])
        })
        .collect();
    std::fs::write(dir.join("negated.txt"), negated).unwrap();
    for (loaded, verdict, code) in [("x.txt", "effective", 0), ("negated.txt", "made_worse", 1)] {
        run(&[
            "simulate",
            &path("axis.yaml"),
            "--seed",
            "77",
            "--controller",
            "linuxcnc",
            "--active",
            &path(loaded),
            "-o",
            &path("after.csv"),
        ]);
        let (status, out) = run(&[
            "verify",
            &path("before.csv"),
            &path("after.csv"),
            "--controller",
            "linuxcnc",
            "--table",
            &path("x.txt"),
            "--json",
        ]);
        let json: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(json["verdict"], verdict, "{out}");
        assert_eq!(status, code);
        for set in ["before", "predicted", "achieved"] {
            assert!(json[set]["parameters"]["E"].is_number(), "{set}: {out}");
        }
        assert_eq!(json["per_target"].as_array().unwrap().len(), 42);
        let first = &json["per_target"][0];
        for key in [
            "position",
            "direction",
            "before",
            "applied",
            "predicted",
            "achieved",
            "difference",
            "u",
        ] {
            assert!(!first[key].is_null(), "{key}: {first}");
        }
        let findings: Vec<&str> = json["findings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["effect"].as_str().unwrap())
            .collect();
        let expected: &[&str] = if code == 0 { &[] } else { &["sign_inverted"] };
        assert_eq!(findings, expected);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A machine whose X and Y tables were swapped when loaded: each axis's change follows the
/// other axis's table, and the verification names it.
#[test]
fn a_table_loaded_on_the_other_axis_is_named() {
    let sim = Simulation::from_yaml(AXIS, "axis.yaml").unwrap();
    let other_axis = AXIS
        .replace("scale_um_per_m: 20", "scale_um_per_m: -25")
        .replace("pitch_mm: 300", "pitch_mm: 450");
    let sim_y = Simulation::from_yaml(&other_axis, "y.yaml").unwrap();
    let controller = compensate::controllers::find("twincat").unwrap();
    let settings = Settings {
        interval: Some(INTERVAL),
        active: Some(Active::default()),
        ..Default::default()
    };
    let before = sim.run(3);
    let x_table = compensate::held_table(controller, &before, &settings).unwrap();
    let y_table = compensate::held_table(controller, &sim_y.run(3), &settings).unwrap();
    let after = compensate::apply(&y_table, &sim.run(1003));
    let others = [verify::Other {
        axis: "Y".into(),
        new: y_table,
    }];
    let input = verify::Input {
        before: &before,
        after: &after,
        old: None,
        new: &x_table,
        others: &others,
        standard: StandardId::Iso230_2,
    };
    let v = verify::verify(&input).unwrap();
    assert_eq!(v.findings.len(), 1, "{:?}", v.findings);
    assert_eq!(v.findings[0].effect, Key::WrongAxis);
    assert!(
        v.findings[0]
            .evidence
            .starts_with("the table that acted is axis Y's, not this axis's")
    );
    assert_ne!(v.verdict, Verdict::Effective);
}
