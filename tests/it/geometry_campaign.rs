//! The other laser tests in a campaign (`test: straightness|angular`): the values are
//! `eval --test`'s (numpy's, `tests/data/geometry/EXPECTED.md`), the limits the written
//! tolerances at the measured travel, the verdicts those of ISO 14253-1 worked by hand
//! here; then every output that lists tests lists them, and bad keys stop at their line.

use crate::common::{axcheck, scratch};
use serde_json::Value;
use std::path::Path;

const CAMPAIGN: &str = "tests/data/geometry/campaign.yaml";

fn eval_json(args: &[&str]) -> Value {
    let mut all = vec!["eval", "--json"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = axcheck(&all);
    assert_eq!(code, 0, "{stderr}");
    serde_json::from_str(&stdout).unwrap()
}

/// `run --no-pdf` of the campaign into a fresh folder (`name`: the test's own): its `results.json` and the folder.
fn run(name: &str) -> (Value, std::path::PathBuf) {
    let out = scratch(&format!("geometry-campaign-{name}")).join("out");
    let (code, stdout, stderr) =
        axcheck(&["run", CAMPAIGN, "--out", out.to_str().unwrap(), "--no-pdf"]);
    assert_eq!(code, 1, "Y's straightness fails: {stdout}{stderr}");
    let json = std::fs::read_to_string(out.join("results.json")).unwrap();
    (serde_json::from_str(&json).unwrap(), out)
}

fn test<'a>(results: &'a Value, symbol: &str) -> &'a Value {
    (results["axes"].as_array().unwrap().iter())
        .find(|t| t["geometry"]["symbol"] == symbol)
        .unwrap_or_else(|| panic!("no {symbol} in {results}"))
}

fn check<'a>(t: &'a Value, key: &str) -> &'a Value {
    (t["checks"].as_array().unwrap().iter())
        .find(|c| c["key"] == key)
        .unwrap_or_else(|| panic!("no check of {key} in {t}"))
}

fn f(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// EYX of X: numpy's 8.124 µm, against `0.020 per 1000` over the file's 1000 mm (20 µm)
/// and its local value against `0.010 over any 300`, both by ISO 14253-1 with eval's U.
#[test]
fn a_straightness_is_judged_by_its_written_tolerances() {
    let (results, _) = run("eyx");
    let t = test(&results, "EYX");
    let eval = eval_json(&[
        "tests/data/geometry/x-straightness-y.csv",
        "--test",
        "straightness",
        "--direction",
        "Y",
        "--local",
        "300",
    ]);
    assert_eq!(t["geometry"]["test"], "straightness");
    assert_eq!(t["geometry"]["direction"], "Y");
    assert_eq!(t["unit"], "um");
    assert_eq!(t["standard"], Value::Null);
    let value = f(&t["geometry"]["bidirectional"]["deviation_um"]);
    assert_eq!(format!("{value:.3}"), "8.124", "EXPECTED.md");
    assert_eq!(t["geometry"]["bidirectional"], eval["bidirectional"]);
    assert_eq!(t["geometry"]["local"], eval["local"]);
    let u = f(&eval["uncertainty"]["U"]);
    assert_eq!(t["geometry"]["uncertainty"]["U"], eval["uncertainty"]["U"]);
    let whole = check(t, "straightness");
    assert!((f(&whole["limit"]) - 20.0).abs() < 1e-9, "{whole}");
    assert_eq!(f(&whole["U"]), u);
    // By hand: conformance proven when value ≤ limit − U.
    let want = if value <= 20.0 - u {
        "pass"
    } else {
        "inconclusive"
    };
    assert_eq!(whole["outcome"], want);
    let local = check(t, "straightness_local");
    let local_value = f(&eval["local"]["deviation_um"]);
    assert_eq!(f(&local["value"]), local_value);
    assert!((f(&local["limit"]) - 10.0).abs() < 1e-9);
    let want = if local_value <= 10.0 - u {
        "pass"
    } else {
        "inconclusive"
    };
    assert_eq!(local["outcome"], want);
    assert_eq!(t["decision_rule"], "iso14253-1");
    assert_eq!(t["verdict"], "pass", "{t}");
    assert_eq!(
        t["geometry"]["tolerance"],
        serde_json::json!(["0.020 per 1000", "0.010 over any 300"])
    );
}

/// EBX of X: numpy's 20.204″ against 30″; EXY of Y by end points: 0.264 µm against
/// 0.1 µm, judged by the simple rule its axis states: fail.
#[test]
fn an_angular_test_passes_and_a_straightness_fails() {
    let (results, _) = run("ebx");
    let pitch = test(&results, "EBX");
    assert_eq!(pitch["unit"], "arcsec");
    assert_eq!(
        format!("{:.3}", f(&pitch["geometry"]["deviation_arcsec"])),
        "20.204"
    );
    let c = check(pitch, "angular");
    assert_eq!(f(&c["limit"]), 30.0);
    let u = f(&c["U"]);
    assert_eq!(
        c["outcome"],
        if 20.204 + u <= 30.0 {
            "pass"
        } else {
            "inconclusive"
        }
    );
    let y = test(&results, "EXY");
    assert_eq!(y["geometry"]["line"], "end_point");
    assert_eq!(
        format!("{:.3}", f(&y["geometry"]["bidirectional"]["deviation_um"])),
        "0.264"
    );
    let c = check(y, "straightness");
    assert!((f(&c["limit"]) - 0.1).abs() < 1e-12);
    assert_eq!(c["outcome"], "fail");
    assert_eq!(c.get("U"), None, "the simple rule uses no U");
    assert_eq!(y["decision_rule"], "simple");
    assert_eq!(y["verdict"], "fail");
    assert_eq!(results["counts"]["fail"], 1);
}

/// X–Y squareness from EYX and EXY: numpy's −8.222″ (`EXPECTED.md`), its U as
/// `eval --test squareness` gives it, against `0.060 per 1000` = arctan(6·10⁻⁵).
#[test]
fn a_squareness_pair_is_judged() {
    let (results, _) = run("squareness");
    let sq = (results["axes"].as_array().unwrap().iter())
        .find(|t| t["geometry"]["test"] == "squareness")
        .unwrap();
    assert_eq!(sq["axis"], "X-Y");
    assert_eq!(sq["geometry"]["axes"], "X-Y");
    assert_eq!(
        format!("{:.3}", f(&sq["geometry"]["error_arcsec"])),
        "-8.222"
    );
    assert_eq!(sq["geometry"]["convention"], "over_ninety_positive");
    assert_eq!(sq["geometry"]["from"][0]["symbol"], "EYX");
    assert_eq!(sq["geometry"]["from"][1]["file"], "y-straightness-x.csv");
    let eval = eval_json(&[
        "tests/data/geometry/x-straightness-y.csv",
        "--test",
        "squareness",
        "--second",
        "tests/data/geometry/y-straightness-x.csv",
    ]);
    assert_eq!(sq["geometry"]["uncertainty"]["U"], eval["uncertainty"]["U"]);
    assert_eq!(sq["geometry"]["error_arcsec"], eval["error_arcsec"]);
    let c = check(sq, "squareness");
    let limit = (6e-5f64).atan() * 648_000.0 / std::f64::consts::PI;
    assert!((f(&c["limit"]) - limit).abs() < 1e-9, "{c}");
    assert_eq!(format!("{limit:.3}"), "12.376");
    let u = f(&eval["uncertainty"]["U"]);
    let want = if 8.222 + u <= limit {
        "pass"
    } else {
        "inconclusive"
    };
    assert_eq!(c["outcome"], want);
    assert_eq!(sq["unit"], "arcsec");
}

/// Every table lists the three tests by ISO 230-1's symbol, with their values.
#[test]
fn the_summaries_list_each_test() {
    let (_, out) = run("summaries");
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    // No cell here holds a comma or a quote: a split is the CSV.
    let mut lines = csv.lines().map(|l| l.split(',').collect::<Vec<&str>>());
    let header = lines.next().unwrap();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let records: Vec<Vec<&str>> = lines.collect();
    assert_eq!(records.len(), 4);
    let row = |symbol: &str| {
        records
            .iter()
            .find(|r| r[column("symbol")] == symbol)
            .unwrap()
    };
    assert_eq!(row("EYX")[column("test_kind")], "straightness");
    assert_eq!(row("EYX")[column("axis")], "X");
    assert!(row("EYX")[column("straightness")].starts_with("8.12"));
    assert!(row("EBX")[column("angular")].starts_with("20.20"));
    assert_eq!(row("EBX")[column("unit")], "arcsec");
    assert_eq!(row("EXY")[column("verdict")], "fail");
    assert_eq!(row("EXY")[column("failed")], "straightness");
    assert_eq!(row("EYX")[column("A")], "", "no positioning parameter");
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert!(junit.contains("name=\"Y EXY\""), "{junit}");
    assert!(junit.contains("straightness = 0.26"), "{junit}");
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("| X EBX |"), "{md}");
    assert!(md.contains("| X-Y squareness |"), "{md}");
    assert!(row("")[column("test_kind")] == "squareness");
    let (code, stdout, _) = axcheck(&["check", CAMPAIGN, "--jobs", "1"]);
    assert_eq!(code, 1);
    assert!(stdout.contains("MILL-G Y EXY"), "{stdout}");
    assert!(
        stdout.contains("straightness = 0.26 µm > 0.10 µm"),
        "{stdout}"
    );
}

/// A campaign with one axis entry replaced by `entry`: the error `check` prints.
fn refused(entry: &str) -> String {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = scratch(&format!("geometry-bad-{k}"));
    for f in ["x-straightness-y.csv", "x-pitch.csv"] {
        std::fs::copy(Path::new("tests/data/geometry").join(f), dir.join(f)).unwrap();
    }
    let text = format!(
        "campaign: {{name: bad}}\nmachines:\n  - id: M\n    axes:\n      - name: X\n        kind: linear\n{entry}"
    );
    let file = dir.join("campaign.yaml");
    std::fs::write(&file, text).unwrap();
    let (code, stdout, stderr) = axcheck(&["check", file.to_str().unwrap()]);
    assert_ne!(code, 0, "{stdout}");
    format!("{stdout}{stderr}")
}

#[test]
fn bad_keys_stop_at_their_line() {
    let e = refused(
        "        test: straightness\n        direction: Y\n        data: x-straightness-y.csv\n        tolerance: 30″\n",
    );
    assert!(e.contains("campaign.yaml:10:"), "{e}");
    assert!(e.contains("cannot limit a straightness test"), "{e}");
    let e = refused("        test: straightness\n        data: x-straightness-y.csv\n");
    assert!(e.contains("states the direction of its deviation"), "{e}");
    let e = refused(
        "        test: straightness\n        direction: X\n        data: x-straightness-y.csv\n",
    );
    assert!(e.contains("a straightness of axis X is across it"), "{e}");
    let e = refused(
        "        test: angular\n        about: B\n        data: x-pitch.csv\n        tolerances: {A: 5}\n",
    );
    assert!(
        e.contains("campaign.yaml:10:") && e.contains("`tolerances` belongs to a positioning test"),
        "{e}"
    );
    let e = refused("        direction: Y\n        data: x-straightness-y.csv\n");
    assert!(
        e.contains("`direction` belongs to a straightness or angular test"),
        "{e}"
    );
    let e = refused(
        "        test: angular\n        about: B\n        data: x-pitch.csv\n        tolerance: 0.010 per 1000 mm per\n",
    );
    assert!(e.contains("tolerance `0.010 per 1000 mm per`"), "{e}");
    let e = refused(
        "        test: straightness\n        direction: Y\n        local_mm: 200\n        data: x-straightness-y.csv\n        tolerance: 0.010 over any 300\n",
    );
    assert!(
        e.contains("over 200 mm but its tolerance is over any 300 mm"),
        "{e}"
    );
}

/// A positioning file read as an angular test is refused by its unit, naming the column.
#[test]
fn an_angular_test_takes_angles() {
    let e = refused(
        "        test: angular\n        about: C\n        data: x-straightness-y.csv\n        tolerance: 30″\n",
    );
    assert!(e.contains("deviation_um"), "{e}");
}

/// Each reading's mean per (target, direction) of a long CSV: (targets, up, down).
fn means(path: &Path) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut sums: std::collections::BTreeMap<(i64, bool), (f64, f64)> = Default::default();
    // Comment lines, then the header.
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let cells: Vec<&str> = line.split(',').collect();
        let target: f64 = cells[0].parse().unwrap();
        let sum = sums
            .entry(((target * 1000.0).round() as i64, cells[1] == "up"))
            .or_default();
        sum.0 += cells[3].parse::<f64>().unwrap();
        sum.1 += 1.0;
    }
    let mut targets: Vec<f64> = sums.keys().map(|(t, _)| *t as f64 / 1000.0).collect();
    targets.dedup();
    let mean = |up| {
        (targets.iter())
            .map(|t| {
                let (s, n) = sums[&((t * 1000.0).round() as i64, up)];
                s / n
            })
            .collect()
    };
    (targets.clone(), mean(true), mean(false))
}

/// X at the beam, 150 mm below the tool point, with its pitch EBX (20″/m) and yaw ECX:
/// E at the tool point by hand (each mean plus tan(EBX)·150 mm, E = the range of the
/// means, ISO 230-2 2.16), as `results.json` gives it; the measured E is kept beside it.
#[test]
fn a_positioning_test_is_carried_to_its_tool_point() {
    let dir = scratch("geometry-tool-point");
    let model = "tests/data/geometry/x-whole.yaml";
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    for (file, geometry) in [
        ("x.csv", None),
        ("x-ebx.csv", Some("B")),
        ("x-ecx.csv", Some("C")),
    ] {
        let mut args = vec!["simulate", model, "-o"];
        let out = path(&format!("data/{file}"));
        args.push(&out);
        if let Some(letter) = geometry {
            args.extend(["--geometry", letter]);
        }
        let (code, _, stderr) = axcheck(&args);
        assert_eq!(code, 0, "{stderr}");
    }
    let campaign = "campaign: {name: tool point, date: 2026-11-30}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/x.csv, tolerances: {E: 9}, tool_point: {y_mm: 0, z_mm: 150}}\n      - {name: X, kind: linear, test: angular, about: B, data: data/x-ebx.csv, tolerance: 30″}\n      - {name: X, kind: linear, test: angular, about: C, data: data/x-ecx.csv, tolerance: 30″}\n";
    std::fs::write(dir.join("campaign.yaml"), campaign).unwrap();
    let out = path("out");
    let (code, stdout, stderr) =
        axcheck(&["run", &path("campaign.yaml"), "--out", &out, "--no-pdf"]);
    let results = std::fs::read_to_string(dir.join("out/results.json"))
        .unwrap_or_else(|e| panic!("{e}: {stdout}{stderr}"));
    let results: Value = serde_json::from_str(&results).unwrap();
    let x = &results["axes"][0];
    let carried = &x["tool_point"];
    assert_eq!(
        carried["rotations"],
        serde_json::json!(["EBX", "ECX"]),
        "{x}"
    );
    assert_eq!(
        carried["offsets_mm"],
        serde_json::json!({"y": 0.0, "z": 150.0})
    );
    // By hand: the pitch's mean per target and direction, its tangent times 150 mm.
    let (targets, up, down) = means(&dir.join("data/x.csv"));
    let (pitch_targets, pitch_up, pitch_down) = means(&dir.join("data/x-ebx.csv"));
    assert_eq!(
        targets, pitch_targets,
        "the same targets: no interpolation to check"
    );
    let arcsec = std::f64::consts::PI / 648_000.0;
    let tool = |m: &[f64], p: &[f64]| -> Vec<f64> {
        m.iter()
            .zip(p)
            .map(|(m, p)| m + (p * arcsec).tan() * 150_000.0)
            .collect()
    };
    let range = |a: &[f64], b: &[f64]| {
        let all = a.iter().chain(b);
        all.clone().cloned().fold(f64::MIN, f64::max) - all.cloned().fold(f64::MAX, f64::min)
    };
    let e_beam = range(&up, &down);
    let e_tool = range(&tool(&up, &pitch_up), &tool(&down, &pitch_down));
    assert!(
        (f(&x["parameters"]["E"]) - e_beam).abs() < 1e-9,
        "{e_beam} {x}"
    );
    assert!(
        (f(&carried["parameters"]["E"]) - e_tool).abs() < 1e-9,
        "{e_tool} {carried}"
    );
    // 20″/m of pitch at 1000 mm, 150 mm from the beam, is tan(20″) × 150 mm = 14.5 µm.
    let end = targets.len() - 1;
    let moved = tool(&up, &pitch_up)[end] - up[end];
    assert!((moved - 14.544).abs() < 0.3, "{moved}");
    assert!(e_beam - e_tool > 3.0, "beam {e_beam}, tool {e_tool}");
    // E ≤ 9 µm fails at the beam and passes at the tool point: a finding.
    assert_eq!(x["verdict"], "fail");
    assert_eq!(carried["verdict"], "pass", "{carried}");
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stdout.contains("Verdict changes at the tool point (Abbe, through EBX and ECX): M X is fail at the beam, pass at the tool point"),
        "{stdout}"
    );
    // A tool point without the angular test its offset needs says which.
    let campaign = campaign.replace(
        "about: B, data: data/x-ebx.csv",
        "about: A, data: data/x-ebx.csv",
    );
    std::fs::write(dir.join("campaign.yaml"), campaign).unwrap();
    let (_, stdout, _) = axcheck(&["check", &path("campaign.yaml")]);
    assert!(stdout.contains("Not carried to the tool point: M X: the tool point's offset of 150 mm along Z needs the rotation of X about Y (EBX)"), "{stdout}");
}

/// A squareness pair naming a straightness test the machine does not hold is an error
/// of its own, at its line; the machine's tests still run.
#[test]
fn a_squareness_without_its_test_says_which() {
    let dir = scratch("geometry-squareness-missing");
    std::fs::copy(
        "tests/data/geometry/x-straightness-y.csv",
        dir.join("x.csv"),
    )
    .unwrap();
    let text = "campaign: {name: bad}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, test: straightness, direction: Y, data: x.csv, tolerance: 0.02}\n    squareness:\n      - axes: [X, Y]\n        tolerance: 20″\n";
    std::fs::write(dir.join("campaign.yaml"), text).unwrap();
    let (code, stdout, _) = axcheck(&["check", dir.join("campaign.yaml").to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        stdout.contains("1 pass, 0 fail, 0 noncompliant, 1 error"),
        "{stdout}"
    );
    // Named by its pair (`M X-Y`), the message by its place: `squareness[0]`.
    assert!(
        stdout.contains("M X-Y ") && stdout.contains("squareness[0].axes"),
        "{stdout}"
    );
    assert!(
        stdout.contains("campaign.yaml:7:")
            && stdout.contains("takes the straightness of Y along X (EXY)"),
        "{stdout}"
    );
}

/// The other tests in the inspection history: a row per value, each test its own series
/// (`X EYX`), read back by `trend` with the value and limit of `results.json`.
#[test]
fn the_other_tests_have_their_own_series() {
    let dir = scratch("geometry-history");
    let out = dir.join("out");
    let history = dir.join("history");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        CAMPAIGN,
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
        "--history",
        history.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stdout.contains("History: 5 rows appended"), "{stdout}");
    let (code, json, stderr) = axcheck(&["trend", history.to_str().unwrap(), "--json"]);
    assert_eq!(code, 0, "{stderr}");
    let trends: Value = serde_json::from_str(&json).unwrap();
    let series = |axis: &str, parameter: &str| {
        (trends["axes"].as_array().unwrap().iter())
            .find(|s| s["axis"] == axis && s["parameter"] == parameter)
            .unwrap_or_else(|| panic!("no {axis} {parameter} in {trends}"))
            .clone()
    };
    let eyx = series("X EYX", "straightness");
    assert_eq!(format!("{:.3}", f(&eyx["points"][0]["value"])), "8.124");
    assert!((f(&eyx["limit"]) - 20.0).abs() < 1e-9);
    assert_eq!(eyx["unit"], "um");
    let local = series("X EYX", "straightness_local");
    assert!((f(&local["limit"]) - 10.0).abs() < 1e-9);
    assert_eq!(
        format!(
            "{:.3}",
            f(&series("X EBX", "angular")["points"][0]["value"])
        ),
        "20.204"
    );
    let sq = series("X-Y squareness", "squareness");
    assert_eq!(format!("{:.3}", f(&sq["points"][0]["value"])), "-8.222");
    assert_eq!(sq["unit"], "arcsec");
}

/// The campaign of `CAMPAIGN` with `optics:` stated on its three tests (`optics` the text
/// after each tolerance), run into a fresh folder: its `results.json`.
fn run_with_optics(name: &str, eyx: &str, ebx: &str, pair: &str) -> Value {
    let root = scratch(&format!("geometry-optics-{name}"));
    let dir = root.join("data");
    for f in [
        "x-straightness-y.csv",
        "x-pitch.csv",
        "y-straightness-x.csv",
    ] {
        std::fs::copy(Path::new("tests/data/geometry").join(f), dir.join(f)).unwrap();
    }
    let text = std::fs::read_to_string(CAMPAIGN).unwrap();
    let text = text
        .replace(
            "        tolerance: [\"0.020 per 1000\", \"0.010 over any 300\"]\n",
            &format!("        tolerance: [\"0.020 per 1000\", \"0.010 over any 300\"]\n        optics: {eyx}\n"),
        )
        .replace(
            "        tolerance: 30″\n",
            &format!("        tolerance: 30″\n        optics: {ebx}\n"),
        )
        .replace(
            "        tolerance: 0.060 per 1000\n",
            &format!("        tolerance: 0.060 per 1000\n        optics: {pair}\n"),
        );
    assert_eq!(text.matches("optics:").count(), 3);
    let file = dir.join("campaign.yaml");
    std::fs::write(&file, text).unwrap();
    let out = root.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert_eq!(code, 1, "Y's straightness fails: {stdout}{stderr}");
    serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap()
}

fn squareness_test(results: &Value) -> &Value {
    (results["axes"].as_array().unwrap().iter())
        .find(|t| t["geometry"]["test"] == "squareness")
        .unwrap()
}

/// `optics:` on a straightness, an angular test and a squareness pair: each U grows by
/// the optics' bound worked by hand (rectangular: u = bound/√3, U² grows by 4u²), the
/// budget has the line and the notes name the specification; `eval --optics` agrees.
#[test]
fn the_optics_stated_enter_u() {
    let (bare, _) = run("optics-bare");
    let with = run_with_optics(
        "stated",
        "{percent: 0.5, fixed: 0.5, per_m: 0.15}",
        "{percent: 0.2, fixed: 0.5, per_m2: 0.1}",
        "hp5528a-squareness-long",
    );
    let u_of = |t: &Value| f(&t["geometry"]["uncertainty"]["U"]);
    let grows = |before: f64, after: f64, bound: f64| {
        let u = bound / 3f64.sqrt();
        let by = (after * after - before * before) / 4.0;
        assert!(
            (by - u * u).abs() < 1e-9,
            "{before} → {after}: {by} for {u}²"
        );
    };
    // EYX: 8.124 µm over 1 m: 0.5 % × 8.124 + 0.5 + 0.15 × 1 = 0.69062 µm.
    let (b, w) = (test(&bare, "EYX"), test(&with, "EYX"));
    let value = f(&w["geometry"]["bidirectional"]["deviation_um"]);
    let bound = 0.005 * value + 0.5 + 0.15;
    assert_eq!(format!("{bound:.5}"), "0.69062");
    grows(u_of(b), u_of(w), bound);
    let lines = w["geometry"]["uncertainty"]["budget"]["lines"].to_string();
    assert!(lines.contains("\"optics\""), "{lines}");
    let notes = w["geometry"]["uncertainty"]["notes"].to_string();
    assert!(
        notes.contains("±(0.5 % of the value + 0.5 + 0.15·M) µm"),
        "{notes}"
    );
    assert!(!notes.contains("was not stated"), "{notes}");
    assert!(
        b["geometry"]["uncertainty"]["notes"]
            .to_string()
            .contains("was not stated")
    );
    let eval = eval_json(&[
        "tests/data/geometry/x-straightness-y.csv",
        "--test",
        "straightness",
        "--local",
        "300",
        "--optics",
        "0.5,0.5,0.15",
    ]);
    assert_eq!(w["geometry"]["uncertainty"]["U"], eval["uncertainty"]["U"]);
    // EBX: 20.20″ over 1 m: 0.2 % × 20.20 + 0.5 + 0.1 × 1² = 0.6404″.
    let (b, w) = (test(&bare, "EBX"), test(&with, "EBX"));
    let value = f(&w["geometry"]["deviation_arcsec"]);
    let bound = 0.002 * value + 0.5 + 0.1;
    assert_eq!(format!("{bound:.4}"), "0.6404");
    grows(u_of(b), u_of(w), bound);
    // X-Y: −8.2223″, the longer travel 1 m, long-range optics: 2.5 % × 8.2223 + 0.5 +
    // 0.01 × 1 = 0.71556″.
    let (b, w) = (squareness_test(&bare), squareness_test(&with));
    let theta = f(&w["geometry"]["error_arcsec"]);
    let bound = 0.025 * theta.abs() + 0.5 + 0.01;
    assert_eq!(format!("{bound:.5}"), "0.71556");
    grows(u_of(b), u_of(w), bound);
    let notes = w["geometry"]["uncertainty"]["notes"].to_string();
    assert!(
        notes.contains("long-range optics") && notes.contains("section 13"),
        "{notes}"
    );
}

/// `optics:` stops at its line: an unknown name (listing the presets), a preset of
/// another test (naming both), a term of a wrong form, and on a positioning test.
#[test]
fn bad_optics_stop_at_their_line() {
    let straightness =
        "        test: straightness\n        direction: Y\n        data: x-straightness-y.csv\n";
    let e = refused(&format!("{straightness}        optics: xl80-short\n"));
    assert!(e.contains("campaign.yaml:10:"), "{e}");
    assert!(e.contains("unknown optics `xl80-short`"), "{e}");
    assert!(
        e.contains("hp5528a-squareness-short, hp5528a-squareness-long"),
        "{e}"
    );
    assert!(
        e.contains("{percent: , fixed: , per_m: , per_m2: } (in µm)"),
        "{e}"
    );
    let e = refused(&format!(
        "{straightness}        optics: hp5528a-squareness-short\n"
    ));
    assert!(e.contains("campaign.yaml:10:"), "{e}");
    assert!(
        e.contains("`hp5528a-squareness-short` is the HP 5528A squareness, short-range optics")
            && e.contains("not for this straightness test"),
        "{e}"
    );
    let e = refused(&format!("{straightness}        optics: {{percent: -1}}\n"));
    assert!(
        e.contains("optics.percent: expected a number ≥ 0, got -1"),
        "{e}"
    );
    let e = refused(&format!("{straightness}        optics: {{per_mm: 1}}\n"));
    assert!(e.contains("per_mm"), "{e}");
    let e = refused(&format!("{straightness}        optics: {{}}\n"));
    assert!(e.contains("state the optics' accuracy as"), "{e}");
    let e = refused(&format!("{straightness}        optics: 0.5\n"));
    assert!(e.contains("expected a preset's name"), "{e}");
    let e = refused("        data: x-straightness-y.csv\n        optics: {fixed: 0.5}\n");
    assert!(
        e.contains("`optics` belongs to a straightness or angular test"),
        "{e}"
    );
}

/// No test-plan rule is cited for straightness and angular tests
/// (docs/optics-specifications.md, "Plan rules for the other tests"), and ISO 230-2's do
/// not hold for them: a straightness of three targets and one run, which would break
/// 4.3.2's targets and runs, has no finding and is judged, not `noncompliant`; `plan`
/// does not plan an axis entry that is not a positioning test.
#[test]
fn positioning_plan_rules_are_not_applied_to_the_other_tests() {
    let dir = scratch("geometry-no-plan-rules");
    let mut csv = String::from("target_mm,direction,run,deviation_um\n");
    for (target, y) in [(0, 0.0), (500, 1.2), (1000, 0.0)] {
        csv += &format!("{target},up,1,{y}\n");
    }
    for (target, y) in [(1000, 0.1), (500, 1.3), (0, 0.1)] {
        csv += &format!("{target},down,1,{y}\n");
    }
    std::fs::write(dir.join("x.csv"), csv).unwrap();
    let text = "campaign: {name: sparse}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, test: straightness, direction: Y, data: x.csv, tolerance: 0.020}\n";
    let file = dir.join("campaign.yaml");
    std::fs::write(&file, text).unwrap();
    let out = scratch("geometry-no-plan-rules-out").join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let results: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let t = test(&results, "EYX");
    assert_eq!(t["rules"], serde_json::json!([]), "{t}");
    assert_eq!(t["verdict"], "pass");
    let (code, _, stderr) = axcheck(&[
        "plan",
        "--campaign",
        CAMPAIGN,
        "--machine",
        "MILL-G",
        "--axis",
        "X",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("axis `X` of machine `MILL-G` has no positioning test"),
        "{stderr}"
    );
    // An axis whose straightness entry comes first is planned from its positioning entry.
    let text = "campaign: {name: order}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, test: straightness, direction: Y, data: x.csv}\n      - {name: X, kind: linear, travel: [0, 800], data: x.csv}\n";
    std::fs::write(&file, text).unwrap();
    let (code, stdout, stderr) = axcheck(&[
        "plan",
        "--campaign",
        file.to_str().unwrap(),
        "--machine",
        "M",
        "--axis",
        "X",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.starts_with("Test plan: "), "{stdout}");
    assert!(stdout.contains("(ISO 230-2:1997)"), "{stdout}");
}
