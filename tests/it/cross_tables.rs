//! A straightness test written as a controller's cross table (`compensate --test
//! straightness`) and its re-measurement checked (`verify --test straightness`): the table
//! read back equals −(the residuals about the least-squares line) by hand; a table built
//! on an active one is their sum; a re-measurement as predicted is effective, with the
//! table's sign inverted it is found so, and on another axis the wrong axis is named.

use crate::common::{axcheck, scratch};
use serde_json::Value;
use std::path::Path;

const TARGETS: [f64; 6] = [0.0, 200.0, 400.0, 600.0, 800.0, 1000.0];

/// A bow of 8 µm on a slope of 15 µm/m plus `added` at each target, 3 runs, a scatter of
/// ±0.1 µm from a fixed sequence.
fn write_test(path: &Path, bow_um: f64, added: &dyn Fn(f64) -> f64) {
    let mut text = String::from("target_mm,direction,run,deviation_um\n");
    let mut k = 0u32;
    for run in 1..=3 {
        for (direction, order) in [("up", false), ("down", true)] {
            let mut targets = TARGETS.to_vec();
            if order {
                targets.reverse();
            }
            for x in targets {
                k += 1;
                let noise = ((k * 37 % 11) as f64 - 5.0) / 50.0;
                let y = bow_um * (1.0 - ((x - 500.0) / 500.0).powi(2)) + 0.015 * x;
                text.push_str(&format!(
                    "{x},{direction},{run},{:.4}\n",
                    y + noise + added(x)
                ));
            }
        }
    }
    std::fs::write(path, text).unwrap();
}

/// The table's correction at `x` (linear between its points).
fn at(table: &Value, x: f64) -> f64 {
    let p: Vec<f64> = serde_json::from_value(table["positions_mm"].clone()).unwrap();
    let c: Vec<f64> = serde_json::from_value(table["corrections_um"].clone()).unwrap();
    let k = p.iter().position(|q| *q >= x).unwrap_or(p.len() - 1).max(1);
    c[k - 1] + (x - p[k - 1]) / (p[k] - p[k - 1]) * (c[k] - c[k - 1])
}

fn compensate(args: &[&str]) -> Value {
    let mut all = vec!["compensate", "--test", "straightness", "--json"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = axcheck(&all);
    assert_eq!(code, 0, "{stderr}");
    serde_json::from_str(&stdout).unwrap()
}

/// The means of a bow of 8 µm about their least-squares line, by hand: the bow's values
/// 0, 5.12, 7.68, 7.68, 5.12, 0 (the slope is removed with the line) less their line
/// (flat by symmetry, at their mean 4.2667).
#[test]
fn a_heidenhain_table_is_minus_the_residuals() {
    let dir = scratch("cross-tables-hand");
    let before = dir.join("data/eyx.csv");
    write_test(&before, 8.0, &|_| 0.0);
    let out = dir.join("YX.COM");
    let json = compensate(&[
        before.to_str().unwrap(),
        "--controller",
        "heidenhain",
        "--input",
        "X",
        "--output",
        "Y",
        "--active",
        "none",
        "--out",
        out.to_str().unwrap(),
    ]);
    let c = &json["compensation"];
    let bow = [0.0, 5.12, 7.68, 7.68, 5.12, 0.0];
    let mean = bow.iter().sum::<f64>() / 6.0;
    for (k, b) in bow.iter().enumerate() {
        let got = c["table"]["corrections_um"][k].as_f64().unwrap();
        // The scatter's mean at a target is within 0.1 µm.
        assert!(
            (got + b - mean).abs() < 0.1,
            "{k}: {got} against {}",
            mean - b
        );
    }
    assert!((c["measured_um"].as_f64().unwrap() - 7.68).abs() < 0.2);
    assert!(c["predicted_um"].as_f64().unwrap() < 1e-9);
    assert_eq!(c["mode"], "absolute");
    // Both files, and the .CMA assigns the .COM to X.
    let com = std::fs::read_to_string(&out).unwrap();
    assert!(
        com.starts_with("BEGIN YX.COM MM\nNR   AXISPOS      Y\n"),
        "{com}"
    );
    let cma = std::fs::read_to_string(dir.join("YX.CMA")).unwrap();
    assert!(cma.contains("ACTIVE  X\n0    *       YX.COM"), "{cma}");
}

/// With half the correction active during the test, the table written is the whole one
/// again (the active half plus what the test shows), and its mode says so.
#[test]
fn a_table_builds_on_the_active_cross_table() {
    let dir = scratch("cross-tables-active");
    let first = dir.join("data/first.csv");
    write_test(&first, 8.0, &|_| 0.0);
    let whole = compensate(&[
        first.to_str().unwrap(),
        "--controller",
        "csv",
        "--input",
        "X1",
        "--output",
        "Y1",
        "--active",
        "none",
        "--out",
        dir.join("whole.csv").to_str().unwrap(),
    ]);
    let table = &whole["compensation"]["table"];
    let half: String = {
        let p = table["positions_mm"].as_array().unwrap();
        let c = table["corrections_um"].as_array().unwrap();
        let rows: String = (p.iter().zip(c))
            .map(|(p, c)| format!("{p},{:.3}\n", c.as_f64().unwrap() / 2.0))
            .collect();
        format!(
            "# axcheck cross-axis table: output Y1 as a function of input X1\ninput_mm,correction_um\n{rows}"
        )
    };
    std::fs::write(dir.join("half.csv"), half).unwrap();
    let second = dir.join("data/second.csv");
    write_test(&second, 8.0, &|x| at(table, x) / 2.0);
    let json = compensate(&[
        second.to_str().unwrap(),
        "--controller",
        "csv",
        "--active",
        dir.join("half.csv").to_str().unwrap(),
    ]);
    let c = &json["compensation"];
    assert_eq!(c["mode"], "incremental");
    assert_eq!(c["table"]["output"], "Y1");
    for (k, want) in table["corrections_um"]
        .as_array()
        .unwrap()
        .iter()
        .enumerate()
    {
        let got = c["table"]["corrections_um"][k].as_f64().unwrap();
        // Two scatters of 0.1 µm apart, and the halves' rounding to 1 nm.
        assert!(
            (got - want.as_f64().unwrap()).abs() < 0.25,
            "{k}: {got} {want}"
        );
    }
    assert!((c["measured_um"].as_f64().unwrap() - 3.84).abs() < 0.25);
}

fn verify(dir: &Path, after: &Path, extra: &[&str]) -> (i32, Value) {
    let mut all = vec![
        "verify",
        "--test",
        "straightness",
        "--json",
        "--controller",
        "siemens-840d",
    ];
    let before = dir.join("data/before.csv");
    let table = dir.join("cec.ini");
    all.extend([before.to_str().unwrap(), after.to_str().unwrap()]);
    all.extend(["--table", table.to_str().unwrap()]);
    all.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&all);
    assert!(code == 0 || code == 1, "{stderr}");
    (code, serde_json::from_str(&stdout).unwrap())
}

/// A CEC table loaded as written is effective (exit 0); loaded with the wrong sign it is
/// made worse with the sign named (exit 1); loaded on Z it leaves Y as it was and Z's
/// test names Z.
#[test]
fn verify_names_the_sign_and_the_axis() {
    let dir = scratch("cross-tables-verify");
    let before = dir.join("data/before.csv");
    write_test(&before, 8.0, &|_| 0.0);
    let json = compensate(&[
        before.to_str().unwrap(),
        "--controller",
        "siemens-840d",
        "--input",
        "X1",
        "--output",
        "Y1",
        "--active",
        "none",
        "--out",
        dir.join("cec.ini").to_str().unwrap(),
    ]);
    let table = json["compensation"]["table"].clone();
    let c = |x: f64| at(&table, x);
    let files = [
        ("right", &c as &dyn Fn(f64) -> f64, 8.0),
        ("minus", &|x| -c(x), 8.0),
        ("unchanged", &|_| 0.0, 8.0),
        ("z-before", &|_| 0.0, -3.0),
        ("z-after", &c, -3.0),
    ];
    for (name, added, bow) in files {
        write_test(&dir.join(format!("data/{name}.csv")), bow, added);
    }
    let after = |name: &str| dir.join(format!("data/{name}.csv"));
    let (code, v) = verify(&dir, &after("right"), &[]);
    assert_eq!(
        (code, &v["verification"]["verdict"]),
        (0, &"effective".into())
    );
    assert!(v["verification"]["achieved_um"].as_f64().unwrap() < 0.5);
    let (code, v) = verify(&dir, &after("minus"), &[]);
    assert_eq!(
        (code, &v["verification"]["verdict"]),
        (1, &"made_worse".into())
    );
    assert_eq!(v["verification"]["findings"][0]["effect"], "sign_inverted");
    let z = format!(
        "Z1={},{}",
        after("z-before").display(),
        after("z-after").display()
    );
    let (code, v) = verify(&dir, &after("unchanged"), &["--other-straightness", &z]);
    assert_eq!(
        (code, &v["verification"]["verdict"]),
        (1, &"not_effective".into())
    );
    assert_eq!(v["verification"]["findings"][0]["effect"], "wrong_axis");
    assert_eq!(v["verification"]["findings"][0]["output"], "Z1");
}

/// The pitch table's options are refused on a cross table, and a controller without a
/// cross format names those that have one.
#[test]
fn cross_tables_refuse_what_they_cannot_be() {
    let dir = scratch("cross-tables-refused");
    let before = dir.join("data/eyx.csv");
    write_test(&before, 8.0, &|_| 0.0);
    let file = before.to_str().unwrap();
    let base = ["compensate", file, "--test", "straightness", "--input", "X"];
    let (code, _, stderr) =
        axcheck(&[&base[..], &["--controller", "csv", "--pitch", "5"]].concat());
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("--pitch applies to a positioning test's table"),
        "{stderr}"
    );
    let (code, _, stderr) = axcheck(&[&base[..], &["--controller", "fanuc"]].concat());
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("csv, siemens-840d, heidenhain, twincat"),
        "{stderr}"
    );
    let (code, _, stderr) = axcheck(&[&base[..], &["--controller", "csv"]].concat());
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("name the output axis"), "{stderr}");
    let (code, _, stderr) =
        axcheck(&[&base[..], &["--controller", "heidenhain", "--output", "Y"]].concat());
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("give --out"), "{stderr}");
}

/// A campaign whose machine names HEIDENHAIN writes each straightness test's cross table
/// under `compensation/` (the .CMA entering the .COM by its name there); its
/// re-measurements after the tables were loaded — Y's as predicted, Z's table loaded on Y
/// — are compared in `results.json`: Y's effective, Z's not effective with Y named, and a
/// table built on Z's loaded one withheld.
#[test]
fn a_campaign_writes_and_verifies_cross_tables() {
    let dir = scratch("cross-tables-campaign");
    write_test(&dir.join("data/y-before.csv"), 8.0, &|_| 0.0);
    write_test(&dir.join("data/z-before.csv"), -3.0, &|_| 0.0);
    let campaign = |files: [&str; 2], compensation: [&str; 2]| {
        format!(
            "campaign: {{name: cross tables, date: 2026-11-30}}\nmachines:\n  - id: M\n    controller: heidenhain\n    axes:\n      - {{name: X, kind: linear, test: straightness, direction: Y, data: {}, compensation: {}}}\n      - {{name: X, kind: linear, test: straightness, direction: Z, data: {}, compensation: {}}}\n",
            files[0], compensation[0], files[1], compensation[1]
        )
    };
    std::fs::write(
        dir.join("before.yaml"),
        campaign(
            ["data/y-before.csv", "data/z-before.csv"],
            ["{active: none}", "{input: X, output: Z, active: none}"],
        ),
    )
    .unwrap();
    let out = dir.join("out-before");
    let (code, _, stderr) = axcheck(&[
        "run",
        dir.join("before.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert!(code == 0 || code == 1, "{stderr}");
    let com = std::fs::read_to_string(out.join("compensation/M/X-EYX.COM")).unwrap();
    assert!(
        com.starts_with("BEGIN X-EYX.COM MM\nNR   AXISPOS      Y\n"),
        "{com}"
    );
    let cma = std::fs::read_to_string(out.join("compensation/M/X-EYX.CMA")).unwrap();
    assert!(cma.contains("0    *       X-EYX.COM"), "{cma}");
    assert!(out.join("compensation/M/X-EZX.CMA").exists());
    let results: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let y = &results["axes"][0]["geometry"]["cross_table"];
    assert_eq!(y["file"], "compensation/M/X-EYX.COM");
    assert_eq!(y["mode"], "absolute");
    assert!(
        y["warnings"][0]
            .as_str()
            .unwrap()
            .contains("compensation.input"),
        "{y}"
    );
    assert!(y["predicted_um"].as_f64().unwrap() < 1e-9);
    // The tables as loaded: Y's on Y; Z's on Y (the wrong axis), Z unchanged.
    for name in ["X-EYX.COM", "X-EYX.CMA", "X-EZX.COM", "X-EZX.CMA"] {
        std::fs::copy(out.join("compensation/M").join(name), dir.join(name)).unwrap();
    }
    let y_table = &y["table"];
    let z_table = results["axes"][1]["geometry"]["cross_table"]["table"].clone();
    write_test(&dir.join("data/y-after.csv"), 8.0, &|x| {
        at(y_table, x) + at(&z_table, x)
    });
    write_test(&dir.join("data/z-after.csv"), -3.0, &|_| 0.0);
    std::fs::write(
        dir.join("after.yaml"),
        campaign(
            ["data/y-after.csv", "data/z-after.csv"],
            [
                "{verifies: {before: data/y-before.csv, table: X-EYX.COM}}",
                "{verifies: {before: data/z-before.csv, table: X-EZX.COM}}",
            ],
        ),
    )
    .unwrap();
    let out = dir.join("out-after");
    let (code, _, stderr) = axcheck(&[
        "run",
        dir.join("after.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert!(code == 0 || code == 1, "{stderr}");
    let results: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let (y, z) = (
        &results["axes"][0]["geometry"],
        &results["axes"][1]["geometry"],
    );
    // Y got its own table and Z's: not as its own predicted, so Y is not "effective".
    assert_ne!(y["cross_verification"]["verdict"], "effective", "{y}");
    assert_eq!(z["cross_verification"]["verdict"], "not_effective", "{z}");
    assert_eq!(
        z["cross_verification"]["findings"][0]["effect"],
        "wrong_axis"
    );
    assert_eq!(z["cross_verification"]["findings"][0]["output"], "Y");
    assert!(
        z["cross_table"]["refused"]
            .as_str()
            .unwrap()
            .starts_with("withheld because"),
        "{z}"
    );
    assert!(!out.join("compensation/M/X-EZX.COM").exists());
}

/// A pitch table's key on a straightness test, and a cross table's on a positioning test,
/// stop at their line.
#[test]
fn compensation_keys_of_the_other_table_stop_at_their_line() {
    let dir = scratch("cross-tables-keys");
    write_test(&dir.join("data/eyx.csv"), 8.0, &|_| 0.0);
    let cases = [
        (
            "{name: X, kind: linear, test: straightness, direction: Y, data: data/eyx.csv, compensation: {reference: 0}}",
            "machines[0].axes[0].compensation.reference: is of a positioning test's pitch table",
        ),
        (
            "{name: X, kind: linear, data: data/eyx.csv, compensation: {input: X1}}",
            "machines[0].axes[0].compensation.input: names a cross table's axis",
        ),
    ];
    for (axis, message) in cases {
        let yaml = format!(
            "campaign: {{name: keys, date: 2026-11-30}}\nmachines:\n  - id: M\n    controller: csv\n    axes:\n      - {axis}\n"
        );
        let path = dir.join("campaign.yaml");
        std::fs::write(&path, yaml).unwrap();
        let (code, stdout, stderr) = axcheck(&["check", path.to_str().unwrap()]);
        let all = format!("{stdout}{stderr}");
        assert_ne!(code, 0, "{all}");
        assert!(all.contains(message), "{all}");
        assert!(all.contains("campaign.yaml:6"), "{all}");
    }
}

/// A positioning test read 160 mm off the line the axis positions on, with a pitch bowed
/// 8″: `run` fits it on the campaign's pitch test and finds the lever (−160 mm within
/// 3 u, the model's), and says so on the console; the beam on the line, nothing.
#[test]
fn a_campaign_finds_an_abbe_error_from_the_pitch_test() {
    let dir = scratch("abbe-campaign");
    for (name, beam) in [("off", -160.0), ("on", 0.0)] {
        let model = format!(
            "kind: linear\nseed: 7\nmodel:\n  scale_um_per_m: 16\n  reversal_um: 1.8\n  scatter_um: 0.3\n  geometry:\n    axis: X\n    angular:\n      B: {{slope_arcsec_per_m: 22, bow_arcsec: 8, scatter_arcsec: 0.3}}\n    beam_mm: {{Z: {beam}}}\nplan:\n  targets: {{start_mm: 5, end_mm: 795, count: 9}}\n  runs: 5\n  cycle: standard\n"
        );
        let path = dir.join(format!("{name}.yaml"));
        std::fs::write(&path, model).unwrap();
        for (suffix, extra) in [("x", vec![]), ("ebx", vec!["--geometry", "B"])] {
            let out = dir.join(format!("data/{name}-{suffix}.csv"));
            let mut args = vec![
                "simulate",
                path.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
            ];
            args.extend(extra);
            let (code, _, stderr) = axcheck(&args);
            assert_eq!(code, 0, "{stderr}");
        }
    }
    let campaign = "campaign: {name: abbe, date: 2026-11-30}\nmachines:\n  - id: OFF\n    axes:\n      - {name: X, kind: linear, data: data/off-x.csv}\n      - {name: X, kind: linear, test: angular, about: B, data: data/off-ebx.csv}\n  - id: ON\n    axes:\n      - {name: X, kind: linear, data: data/on-x.csv}\n      - {name: X, kind: linear, test: angular, about: B, data: data/on-ebx.csv}\n";
    std::fs::write(dir.join("campaign.yaml"), campaign).unwrap();
    let out = dir.join("out");
    let (_, stdout, stderr) = axcheck(&[
        "run",
        dir.join("campaign.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    let results: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let abbe = |machine: &str| {
        (results["axes"].as_array().unwrap().iter())
            .find(|t| t["machine"] == machine && t["abbe"].is_object())
            .map(|t| t["abbe"].clone())
            .unwrap_or_else(|| panic!("no abbe for {machine}: {stderr}"))
    };
    let off = abbe("OFF");
    assert_eq!(off["found"], true, "{off}");
    let lever = &off["levers"][0];
    assert_eq!(
        (&lever["symbol"], &lever["along"]),
        (&"EBX".into(), &"Z".into())
    );
    let (o, u) = (
        lever["offset_mm"].as_f64().unwrap(),
        lever["u_mm"].as_f64().unwrap(),
    );
    assert!((o + 160.0).abs() < 3.0 * u && u < 10.0, "{o} ± {u}");
    assert_eq!(abbe("ON")["found"], false);
    assert!(
        stdout.contains("Abbe error: OFF X's positioning error follows EBX as a lever of -1"),
        "{stdout}"
    );
    assert!(!stdout.contains("Abbe error: ON X"), "{stdout}");
}

/// A campaign whose names would write lines of their own into a SINUMERIK part program
/// (`X\nM17`, an output `Y1\nM30`) gets no table, and `results.json` says why.
#[test]
fn hostile_axis_names_write_no_cross_table() {
    let dir = scratch("cross-tables-hostile");
    write_test(&dir.join("data/eyx.csv"), 8.0, &|_| 0.0);
    let yaml = "campaign: {name: hostile, date: 2026-11-30}\nmachines:\n  - id: M\n    controller: siemens-840d\n    axes:\n      - {name: \"X\\nM17\", kind: linear, test: straightness, direction: Y, data: data/eyx.csv, compensation: {output: \"Y1\\nM30\", active: none}}\n";
    std::fs::write(dir.join("campaign.yaml"), yaml).unwrap();
    let out = dir.join("out");
    let (_, _, stderr) = axcheck(&[
        "run",
        dir.join("campaign.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    let results: Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("results.json")).unwrap_or_else(|_| panic!("{stderr}")),
    )
    .unwrap();
    let refused = results["axes"][0]["geometry"]["cross_table"]["refused"]
        .as_str()
        .unwrap_or_else(|| panic!("{results}"));
    assert!(
        refused.contains("is not a name the file can hold"),
        "{refused}"
    );
    assert!(!out.join("compensation").exists());
}
