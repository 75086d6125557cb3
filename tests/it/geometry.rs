//! `eval --test straightness|angular|squareness` on the files of `tests/data/geometry`,
//! against what numpy computes from the same files (`tests/data/geometry/make.py`, its
//! output in `EXPECTED.md`) and the HP 5528A User's Guide's worked squareness (§21).

use crate::common::axcheck;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let mut all = vec!["eval", "--json"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = axcheck(&all);
    assert_eq!(code, 0, "{stderr}");
    serde_json::from_str(&stdout).unwrap()
}

fn num(v: &Value, path: &[&str]) -> f64 {
    let mut v = v;
    for key in path {
        v = &v[key];
    }
    v.as_f64().unwrap_or_else(|| panic!("{path:?} in {v}"))
}

fn fixed(v: f64, places: usize) -> String {
    format!("{v:.places$}")
}

#[test]
fn straightness_is_numpys_by_both_lines() {
    let file = "tests/data/geometry/x-straightness-y.csv";
    let ls = json(&[file, "--test", "straightness", "--direction", "Y"]);
    assert_eq!(ls["test"], "straightness");
    assert_eq!(ls["direction"], "Y");
    assert_eq!(ls["line"], "least_squares");
    assert_eq!(
        fixed(num(&ls, &["bidirectional", "deviation_um"]), 3),
        "8.124"
    );
    assert_eq!(
        fixed(num(&ls, &["bidirectional", "line", "slope_um_per_m"]), 3),
        "14.948"
    );
    let ep = json(&[file, "--test", "straightness", "--line", "end-point"]);
    assert_eq!(
        fixed(num(&ep, &["bidirectional", "deviation_um"]), 3),
        "8.120"
    );
    assert_eq!(
        fixed(num(&ep, &["bidirectional", "line", "slope_um_per_m"]), 3),
        "14.942"
    );
    // The generating bow (8 µm) and slope (15 µm/m) within the noise's reach.
    assert!((num(&ls, &["bidirectional", "deviation_um"]) - 8.0).abs() < 0.6);
    assert!((num(&ls, &["bidirectional", "line", "slope_um_per_m"]) - 15.0).abs() < 0.3);
}

#[test]
fn pitch_is_the_range_of_the_means() {
    let a = json(&[
        "tests/data/geometry/x-pitch.csv",
        "--test",
        "angular",
        "--direction",
        "b",
    ]);
    assert_eq!(a["direction"], "B");
    assert_eq!(fixed(num(&a, &["deviation_arcsec"]), 3), "20.204");
    // Read as a positioning test, the same file's angles at mm are named an angular test's.
    let (code, _, stderr) = axcheck(&["eval", "tests/data/geometry/x-pitch.csv"]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("tests/data/geometry/x-pitch.csv:1:25: column `deviation_arcsec` holds angles at targets in mm (`target_mm`): this looks like an angular test of a linear axis"),
        "{stderr}"
    );
}

#[test]
fn the_hp_5528a_squareness_and_its_sign() {
    let first = "tests/data/geometry/hp5528a-axis-1.csv";
    let second = "tests/data/geometry/hp5528a-axis-2.csv";
    for (line, printed) in [("least-squares", "-5.2"), ("end-point", "-5.5")] {
        let s = json(&[
            first,
            "--test",
            "squareness",
            "--second",
            second,
            "--line",
            line,
        ]);
        assert_eq!(fixed(num(&s, &["error_arcsec"]), 1), printed);
        assert_eq!(s["convention"], "over_ninety_positive");
        let under = json(&[
            first,
            "--test",
            "squareness",
            "--second",
            second,
            "--line",
            line,
            "--convention",
            "under-90",
        ]);
        assert_eq!(num(&under, &["error_arcsec"]), -num(&s, &["error_arcsec"]));
        assert_eq!(
            num(&under, &["over_ninety_arcsec"]),
            num(&s, &["over_ninety_arcsec"])
        );
    }
    let (code, text, _) = axcheck(&["eval", first, "--test", "squareness", "--second", second]);
    assert_eq!(code, 0);
    assert!(text.contains("-5.17″"), "{text}");
    assert!(
        text.contains("positive: the included angle is larger than 90°"),
        "{text}"
    );
}

#[test]
fn forty_um_per_m_out_of_square() {
    let s = json(&[
        "tests/data/geometry/x-straightness-y.csv",
        "--test",
        "squareness",
        "--second",
        "tests/data/geometry/y-straightness-x.csv",
    ]);
    assert_eq!(fixed(num(&s, &["error_arcsec"]), 3), "-8.222");
    assert_eq!(fixed(num(&s, &["error_um_per_m"]), 3), "-39.864");
    // A square 1.5″ over 90° adds 1.5″.
    let with = json(&[
        "tests/data/geometry/x-straightness-y.csv",
        "--test",
        "squareness",
        "--second",
        "tests/data/geometry/y-straightness-x.csv",
        "--square-error",
        "1.5",
    ]);
    assert!((num(&with, &["error_arcsec"]) - num(&s, &["error_arcsec"]) - 1.5).abs() < 1e-9);
}

#[test]
fn options_of_another_test_are_refused_by_name() {
    let file = "tests/data/geometry/x-straightness-y.csv";
    for (args, says) in [
        (
            vec!["--test", "angular", "--local", "300"],
            "--local applies to --test straightness",
        ),
        (
            vec!["--test", "straightness", "--direction", "B"],
            "X, Y or Z",
        ),
        (
            vec!["--test", "angular"],
            "an angular test of a linear axis takes angular deviations",
        ),
        (vec!["--test", "squareness"], "needs --second FILE"),
        (
            vec!["--local", "300"],
            "--local applies to --test straightness, not to --test positioning",
        ),
        (
            vec!["--test", "angular", "--line", "end-point"],
            "--line applies to --test straightness or squareness",
        ),
        (
            vec!["--test", "straightness", "--nde", "11.5"],
            "--nde corrects a positioning test",
        ),
        (
            vec!["--test", "straightness", "--standard", "gost27843"],
            "evaluated by ISO 230-1",
        ),
    ] {
        let mut all = vec!["eval", file];
        all.extend(args.iter().copied());
        let (code, _, stderr) = axcheck(&all);
        assert_eq!(code, 2, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

/// `simulate --geometry` writes the model's straightness and rotations; `eval --test`
/// finds the generating values within what the scatter allows, and squareness from two
/// simulated axes is the 40 µm/m the models differ by.
#[test]
fn simulated_geometry_is_found_again() {
    let dir = crate::common::scratch("geometry-sim");
    let sim = |model: &str, letter: &str, name: &str| -> String {
        let out = dir.join(name).display().to_string();
        let model = format!("tests/data/geometry/{model}");
        let (code, _, stderr) = axcheck(&["simulate", &model, "--geometry", letter, "-o", &out]);
        assert_eq!(code, 0, "{stderr}");
        out
    };
    let ey = sim("x-whole.yaml", "Y", "eyx.csv");
    let eb = sim("x-whole.yaml", "B", "ebx.csv");
    let ex = sim("y-whole.yaml", "X", "exy.csv");
    let text = std::fs::read_to_string(&eb).unwrap();
    assert!(
        text.contains("target_mm,direction,run,deviation_arcsec"),
        "{text}"
    );
    assert!(
        text.contains("the X axis's rotation about B (EBX)"),
        "{text}"
    );
    // The bow (8 µm) and slope (15 µm/m) of EYX; scatter 0.3 µm over 5 runs moves a
    // target's mean by about 0.13 µm, the range by a few tenths.
    let s = json(&[&ey, "--test", "straightness", "--line", "end-point"]);
    assert!(
        (num(&s, &["bidirectional", "deviation_um"]) - 8.0).abs() < 0.6,
        "{s}"
    );
    assert!((num(&s, &["bidirectional", "line", "slope_um_per_m"]) - 15.0).abs() < 0.5);
    let a = json(&[&eb, "--test", "angular"]);
    assert!((num(&a, &["deviation_arcsec"]) - 20.0).abs() < 0.6, "{a}");
    let sq = json(&[&ey, "--test", "squareness", "--second", &ex]);
    assert!((num(&sq, &["error_um_per_m"]) + 40.0).abs() < 1.0, "{sq}");
    // A letter the model lacks is named with those it has.
    let (code, _, stderr) = axcheck(&[
        "simulate",
        "tests/data/geometry/x-whole.yaml",
        "--geometry",
        "A",
    ]);
    assert_eq!(code, 2);
    assert!(stderr.contains("(it has: Y, Z, B, C)"), "{stderr}");
}

/// The positioning test at the beam, 150 mm below the tool point, carries the pitch's
/// Abbe error; carried to the tool point with the simulated pitch test it is the same
/// model's test without it, within the pitch test's scatter (0.3″ × 150 mm ≈ 0.2 µm).
#[test]
fn the_tool_point_takes_the_abbe_error_out_again() {
    use axcheck::axis_model::Simulation;
    use axcheck::geometry::{abbe, angular};
    use axcheck::simulate::SimulationFile as _;
    let text = std::fs::read_to_string("tests/data/geometry/x-whole.yaml").unwrap();
    let sim = Simulation::from_yaml(&text, "x-whole.yaml").unwrap();
    let at_beam = sim.run(7);
    let mut flat = sim.clone();
    flat.model.geometry.beam_mm.clear();
    let at_tool_model = flat.run(7);
    let pitch = angular::Trace::of(&sim.run_geometry(7, 'B').unwrap());
    let yaw = angular::Trace::of(&sim.run_geometry(7, 'C').unwrap());
    let rotations = abbe::Rotations {
        about_v: Some(&pitch),
        about_w: Some(&yaw),
    };
    // The tool point from the beam: 150 mm up (Z), the beam being at Z −150 from it.
    let offset = abbe::Offset {
        v_mm: 0.0,
        w_mm: 150.0,
    };
    let carried = abbe::to_tool_point(&at_beam, rotations, offset).unwrap();
    let mut worst: f64 = 0.0;
    let mut abbe_at_end: f64 = 0.0;
    for ((c, m), b) in carried
        .readings
        .iter()
        .zip(&at_tool_model.readings)
        .zip(&at_beam.readings)
    {
        worst = worst.max((c.deviation - m.deviation).abs());
        abbe_at_end = abbe_at_end.max((b.deviation - m.deviation).abs());
    }
    // The Abbe error at the beam reaches tan(20″) × 150 mm = 14.5 µm at the travel's end.
    assert!((abbe_at_end - 14.544).abs() < 0.01, "{abbe_at_end}");
    assert!(worst < 0.5, "{worst}");
}

/// U through the command line: the scatter only (and a note saying so) unless the
/// optics' accuracy is stated; squareness with HP 5528A's short-range optics preset.
#[test]
fn u_says_what_it_holds() {
    let file = "tests/data/geometry/x-straightness-y.csv";
    let bare = json(&[file, "--test", "straightness"]);
    let u = num(&bare, &["uncertainty", "U"]);
    assert!(u > 0.0 && u < 1.0, "{bare}");
    let notes = bare["uncertainty"]["notes"].to_string();
    assert!(
        notes.contains("the optics' accuracy was not stated"),
        "{notes}"
    );
    // ± (0.5 % of 8.12 µm + 0.5 µm + 0.15 µm/m × 1 m) = 0.6906 µm, rectangular: 0.3987.
    let with = json(&[file, "--test", "straightness", "--optics", "0.5,0.5,0.15"]);
    let optics = &with["uncertainty"]["budget"]["lines"][1];
    assert_eq!(optics["contributor"], "optics");
    assert_eq!(fixed(optics["u"].as_f64().unwrap(), 4), "0.3987");
    let (code, _, stderr) = axcheck(&[
        "eval",
        file,
        "--test",
        "straightness",
        "--optics",
        "hp5528a-short",
    ]);
    assert_eq!(code, 2);
    assert!(stderr.contains("hp5528a-squareness-short"), "{stderr}");
    assert!(
        stderr.contains("stated for squareness), not for this straightness test"),
        "{stderr}"
    );
    let sq = json(&[
        "tests/data/geometry/hp5528a-axis-1.csv",
        "--test",
        "squareness",
        "--second",
        "tests/data/geometry/hp5528a-axis-2.csv",
        "--optics",
        "hp5528a-short",
        "--square-u",
        "0.2",
    ]);
    // One run: the lines' scatter is unknown (noted); the square 0.2″ and the optics'
    // ±(0.5 + 0.1 × 0.9 m (the longer travel) + 1 % × 5.17″) = 0.6417″ / √3 = 0.3705″:
    // U = 2·√(0.2² + 0.3705²) = 0.842″.
    let lines = sq["uncertainty"]["budget"]["lines"]
        .as_array()
        .unwrap()
        .len();
    assert_eq!(lines, 2);
    assert_eq!(fixed(num(&sq, &["uncertainty", "U"]), 3), "0.842");
}

/// Every preset through `--optics`, and the optics' four terms: the long-range squareness
/// optics and a term per square metre by hand; a preset of another test, an unknown name
/// and `--optics` on a positioning test are refused.
#[test]
fn optics_presets_and_terms_by_hand() {
    let (first, second) = (
        "tests/data/geometry/hp5528a-axis-1.csv",
        "tests/data/geometry/hp5528a-axis-2.csv",
    );
    let squareness = |optics: &str| {
        json(&[
            first,
            "--test",
            "squareness",
            "--second",
            second,
            "--optics",
            optics,
            "--square-u",
            "0.2",
        ])
    };
    // θ = −5.1716″ over the longer travel 0.9 m, long-range optics: ±(0.5 + 0.01 × 0.9 +
    // 2.5 % × 5.1716) = 0.6383″, u = 0.3685″; U = 2·√(0.2² + 0.3685²) = 0.839″.
    let long = squareness("hp5528a-squareness-long");
    let line = &long["uncertainty"]["budget"]["lines"][1];
    assert_eq!(line["contributor"], "optics");
    assert_eq!(fixed(line["value"].as_f64().unwrap(), 4), "0.6383");
    assert_eq!(fixed(num(&long, &["uncertainty", "U"]), 3), "0.839");
    let notes = long["uncertainty"]["notes"].to_string();
    assert!(
        notes.contains("long-range optics") && notes.contains("section 13"),
        "{notes}"
    );
    // The short-range optics by their name and their earlier one alike: 0.842″.
    for name in ["hp5528a-squareness-short", "hp5528a-short"] {
        assert_eq!(
            fixed(num(&squareness(name), &["uncertainty", "U"]), 3),
            "0.842"
        );
    }
    // Only a term per square metre: 1 × 0.9² = 0.81″, u = 0.4677″; U = 2·√(0.04 +
    // 0.21870) = 1.017″.
    let m2 = squareness("0,0,0,1");
    let line = &m2["uncertainty"]["budget"]["lines"][1];
    assert_eq!(fixed(line["value"].as_f64().unwrap(), 4), "0.8100");
    assert_eq!(fixed(num(&m2, &["uncertainty", "U"]), 3), "1.017");
    let notes = m2["uncertainty"]["notes"].to_string();
    assert!(notes.contains("±(1·M²) arcsec"), "{notes}");

    let file = "tests/data/geometry/x-straightness-y.csv";
    let refused = |args: &[&str]| {
        let (code, _, stderr) = crate::common::axcheck(args);
        assert_eq!(code, 2, "{stderr}");
        stderr
    };
    let e = refused(&[
        "eval",
        file,
        "--test",
        "angular",
        "--optics",
        "hp5528a-squareness-long",
    ]);
    assert!(
        e.contains("`hp5528a-squareness-long`") && e.contains("not for this angular test"),
        "{e}"
    );
    let e = refused(&["eval", file, "--test", "straightness", "--optics", "xl80"]);
    assert!(e.contains("unknown optics `xl80`"), "{e}");
    assert!(
        e.contains("hp5528a-squareness-short, hp5528a-squareness-long"),
        "{e}"
    );
    let e = refused(&["eval", file, "--optics", "0.5,0.5,0.15"]);
    assert!(
        e.contains("--optics applies to --test straightness or angular or squareness"),
        "{e}"
    );
    let e = refused(&["eval", file, "--test", "straightness", "--optics", "1,2"]);
    assert!(e.contains("PERCENT,FIXED,PER_M[,PER_M2]"), "{e}");
}
