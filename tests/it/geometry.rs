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
    // Read as a positioning test, the same file mixes a length and an angle.
    let (code, _, stderr) = axcheck(&["eval", "tests/data/geometry/x-pitch.csv"]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("`deviation_arcsec` is an angle but `target_mm` is a length"),
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
