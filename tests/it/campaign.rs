//! Campaigns end to end: `axcheck run` and `axcheck check`.

use crate::common::{axcheck, copy_data, scratch};
use std::path::{Path, PathBuf};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

const MIXED: &str = "campaign: {name: Mixed, date: 2026-11-20, spec: general}
machines:
  - id: M1
    axes:
      - {name: X, kind: linear, data: data/iso230-2_table2.csv}
      - {name: Y, kind: linear, data: data/missing.csv}
      - {name: Z, kind: linear, data: data/broken.csv}
  - id: M2
    axes:
      - {name: X, kind: linear, data: data/gost27843_example.csv, tolerance: {A: 1}}
      - {name: Y, kind: linear, standard: gost27843, data: data/gost27843_example.csv, tolerances: {A: 10}}
      - {name: Z, kind: linear, data: data/ess_muts_target_x.dat, spec: none}
";

#[test]
fn one_broken_axis_fails_alone() {
    let dir = scratch("mixed");
    copy_data(&dir, "iso230-2_table2.csv");
    copy_data(&dir, "gost27843_example.csv");
    copy_data(&dir, "ess_muts_target_x.dat");
    std::fs::write(
        dir.join("data/broken.csv"),
        "target_mm,direction,run,deviation_um\n0,up,1,1\n0,down,1,oops\n",
    )
    .unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(&campaign, MIXED).unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let axes = results["axes"].as_array().unwrap();
    assert_eq!(axes.len(), 6, "every axis is reported");
    let verdict = |k: usize| axes[k]["verdict"].as_str().unwrap().to_string();
    let error = |k: usize| axes[k]["error"].as_str().unwrap_or("").to_string();
    assert_eq!(verdict(0), "pass");
    assert!((axes[0]["parameters"]["A"].as_f64().unwrap() - 9.586).abs() < 0.001);
    assert_eq!(verdict(1), "error");
    assert!(error(1).contains("missing.csv"), "{}", error(1));
    assert_eq!(verdict(2), "error");
    assert!(
        error(2).contains("broken.csv:3:10:") && error(2).contains("oops"),
        "{}",
        error(2)
    );
    assert_eq!(verdict(3), "error");
    assert!(
        error(3).contains("campaign.yaml:10:78: machines[1].axes[0].tolerance: limits by parameter are `tolerances: {A: …}` (did you mean `tolerances`?)"),
        "{}",
        error(3)
    );
    // A = 18.0 µm over the axis's own limit of 10 µm; R↑ = 6S = 11.84 µm over the
    // campaign spec's 10 µm.
    assert_eq!(verdict(4), "fail");
    assert_eq!(axes[4]["standard"], "gost27843-88");
    assert_eq!(axes[4]["failed"], serde_json::json!(["A", "R_up"]));
    assert_eq!(axes[4]["spec"], "general (linear ≤ 2000 mm)");
    assert_eq!(axes[4]["limits"]["A"], 10.0);
    // No spec, no tolerances: not judged (issue 42), never a pass.
    assert_eq!(verdict(5), "not_judged");
    assert_eq!(axes[5]["no_tolerance"], true);
    assert_eq!(results["counts"]["error"], 3);
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert!(
        junit.contains("tests=\"6\" failures=\"2\" errors=\"3\""),
        "{junit}"
    );
    assert!(
        junit.contains("A = 18.004 µm over its limit 10.000 µm"),
        "{junit}"
    );
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("no tolerance applied"), "{md}");
    assert!(
        stdout.contains("ERROR") && stdout.contains("M1 Y"),
        "{stdout}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn exit_codes_of_check() {
    let dir = scratch("exit");
    copy_data(&dir, "iso230-2_table2.csv");
    let good = dir.join("good.yaml");
    std::fs::write(&good, "campaign: {name: Good, spec: general}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/iso230-2_table2.csv}\n").unwrap();
    let (code, stdout, _) = axcheck(&["check", s(&good)]);
    assert_eq!(code, 0, "{stdout}");
    assert!(stdout.contains("1 tests: 1 pass"), "{stdout}");
    assert!(!dir.join("out").exists(), "check writes nothing");
    let failing = dir.join("failing.yaml");
    std::fs::write(&failing, "campaign: {name: Tight}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 5, B: 4}}\n").unwrap();
    let (code, stdout, _) = axcheck(&["check", s(&failing)]);
    assert_eq!(code, 1);
    assert!(
        stdout.contains("FAIL")
            && stdout.contains("M X")
            && stdout.contains("A = 9.59 µm > 5.00 µm")
            && stdout.contains("B = 4.12 µm > 4.00 µm"),
        "{stdout}"
    );
    let broken = dir.join("broken.yaml");
    std::fs::write(&broken, "campaign: {name: x\nmachines: []\n").unwrap();
    let (code, _, stderr) = axcheck(&["check", s(&broken)]);
    assert_eq!(code, 2);
    assert!(stderr.contains("broken.yaml:"), "{stderr}");
    let (code, _, stderr) = axcheck(&["check", s(&dir.join("nope.yaml"))]);
    assert_eq!(code, 2);
    assert!(stderr.contains("nope.yaml"), "{stderr}");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Every file under `dir`, relative, sorted.
fn files(dir: &Path) -> Vec<PathBuf> {
    fn walk(base: &Path, dir: &Path, out: &mut Vec<PathBuf>) {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                walk(base, &p, out);
            } else {
                out.push(p.strip_prefix(base).unwrap().to_path_buf());
            }
        }
    }
    let mut out = Vec::new();
    walk(dir, dir, &mut out);
    out.sort();
    out
}

/// Minimal RFC 4180 reader for the test.
pub(crate) fn read_csv(text: &str) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    let mut row = Vec::new();
    let mut field = String::new();
    let mut quoted = false;
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                field.push('"');
                chars.next();
            }
            (true, '"') => quoted = false,
            (true, c) => field.push(c),
            (false, '"') => quoted = true,
            (false, ',') => row.push(std::mem::take(&mut field)),
            (false, '\n') => {
                row.push(std::mem::take(&mut field));
                rows.push(std::mem::take(&mut row));
            }
            (false, c) => field.push(c),
        }
    }
    rows
}

#[test]
fn outputs_agree_and_are_deterministic() {
    let a = std::env::temp_dir().join(format!("axcheck-ex-a-{}", std::process::id()));
    let b = std::env::temp_dir().join(format!("axcheck-ex-b-{}", std::process::id()));
    for out in [&a, &b] {
        let _ = std::fs::remove_dir_all(out);
        let (code, stdout, stderr) = axcheck(&[
            "run",
            "example-campaign/campaign.yaml",
            "--out",
            s(out),
            "--jobs",
            "2",
        ]);
        assert_eq!(code, 1, "the example has a failing axis: {stdout}{stderr}");
        assert!(stdout.contains("Outputs in"), "{stdout}");
    }
    let names = files(&a);
    assert_eq!(files(&b), names);
    assert!(
        names.len() >= 6 + 19,
        "tables, summary.pdf and one report per test: {names:?}"
    );
    for name in &names {
        assert_eq!(
            std::fs::read(a.join(name)).unwrap(),
            std::fs::read(b.join(name)).unwrap(),
            "{name:?} differs between runs"
        );
    }

    // results.json and summary.csv agree.
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(a.join("results.json")).unwrap()).unwrap();
    let axes = results["axes"].as_array().unwrap();
    let csv = read_csv(&std::fs::read_to_string(a.join("summary.csv")).unwrap());
    let header = &csv[0];
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    assert_eq!(csv.len() - 1, axes.len());
    assert!(axes.len() >= 18);
    for (row, axis) in csv[1..].iter().zip(axes) {
        assert_eq!(row[col("machine")], axis["machine"].as_str().unwrap());
        assert_eq!(row[col("axis")], axis["axis"].as_str().unwrap());
        assert_eq!(row[col("verdict")], axis["verdict"].as_str().unwrap());
        for key in ["A", "E", "M", "R", "B", "B_mean", "R_max", "B_max"] {
            let from_csv = &row[col(key)];
            match axis["parameters"].get(key) {
                Some(v) => assert_eq!(
                    from_csv.parse::<f64>().unwrap(),
                    v.as_f64().unwrap(),
                    "{key}"
                ),
                None => assert!(from_csv.is_empty(), "{key} should be empty"),
            }
        }
    }
    let verdicts: Vec<&str> = axes
        .iter()
        .map(|a| a["verdict"].as_str().unwrap())
        .collect();
    assert!(verdicts.contains(&"fail") && verdicts.contains(&"noncompliant"));

    // The parquet file reads back with the same rows.
    use polars::prelude::*;
    let file = std::fs::File::open(a.join("summary.parquet")).unwrap();
    let df = ParquetReader::new(file).finish().unwrap();
    assert_eq!(df.height(), axes.len());
    let names: Vec<String> = df
        .get_column_names()
        .iter()
        .map(|n| n.to_string())
        .collect();
    assert_eq!(&names, header);
    let machine = df.column("machine").unwrap().str().unwrap();
    let a_col = df.column("A").unwrap().f64().unwrap();
    let n_col = df.column("n").unwrap().i64().unwrap();
    let example = df.column("example_limits").unwrap().bool().unwrap();
    for (k, axis) in axes.iter().enumerate() {
        assert_eq!(machine.get(k), axis["machine"].as_str());
        assert_eq!(
            a_col.get(k),
            axis["parameters"].get("A").and_then(|v| v.as_f64())
        );
        // The other laser tests give n in their `geometry` (a squareness has none).
        let n = axis["n"].as_i64().or(axis["geometry"]["n"].as_i64());
        assert_eq!(n_col.get(k), n);
        // Issue 42: `example_limits` where a limit applied, as results.json says it.
        let judged = axis["checks"].as_array().is_some_and(|c| !c.is_empty());
        let want = judged.then(|| axis["example_limits"].as_bool().unwrap_or(false));
        assert_eq!(example.get(k), want, "{}", axis["machine"]);
    }
    let examples = (0..axes.len()).filter(|&k| example.get(k) == Some(true));
    assert!(examples.count() > 0, "gost-example is an example spec");
    std::fs::remove_dir_all(&a).unwrap();
    std::fs::remove_dir_all(&b).unwrap();
}

#[test]
fn the_output_folder_must_not_be_a_data_folder_or_a_file() {
    let dir = scratch("outdir");
    copy_data(&dir, "iso230-2_table2.csv");
    let campaign = dir.join("c.yaml");
    std::fs::write(&campaign, "campaign: {name: C}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/iso230-2_table2.csv}\n").unwrap();
    let (code, _, stderr) = axcheck(&["run", s(&campaign), "--out", s(&dir.join("data"))]);
    assert_eq!(code, 2);
    assert!(stderr.contains("inside the data folder"), "{stderr}");
    let (code, _, stderr) = axcheck(&[
        "run",
        s(&campaign),
        "--out",
        s(&dir.join("data/iso230-2_table2.csv")),
    ]);
    assert_eq!(code, 2);
    assert!(stderr.contains("is a file"), "{stderr}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn nde_correction_is_applied_and_reported() {
    let dir = scratch("nde");
    std::fs::write(
        dir.join("data/x.csv"),
        "target_mm,direction,run,deviation_um\n0,up,1,0\n0,down,1,0\n1000,up,1,22\n1000,down,1,22\n",
    )
    .unwrap();
    let campaign = dir.join("c.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: C}
machines:
  - id: M
    axes:
      - name: X
        kind: linear
        data: data/x.csv
        conditions:
          nde: {coefficient_um_per_m_c: 11}
          temperature_sensors:
            - {name: table, kind: material, start_c: 21.5, end_c: 22.5}
            - {name: air, kind: air, start_c: 30, end_c: 30}
",
    )
    .unwrap();
    let out = dir.join("out");
    let (_, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap())
            .unwrap_or_else(|e| panic!("{e}: {stdout}{stderr}"));
    let axis = &results["axes"][0];
    // 11 µm/(m·°C) × 2 °C × 1 m = 22 µm removed: the axis is straight at 20 °C.
    assert_eq!(axis["nde"]["coefficient_um_per_m_c"], 11.0);
    assert_eq!(axis["nde"]["mean_temperature_c"], 22.0);
    assert!(
        axis["parameters"]["E"].as_f64().unwrap().abs() < 1e-9,
        "{axis}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}
