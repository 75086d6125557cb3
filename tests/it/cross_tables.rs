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
