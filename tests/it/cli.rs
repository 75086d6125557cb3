//! The `axcheck` command as a user runs it.

use crate::common::axcheck;
use std::path::PathBuf;

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = axcheck(args);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}\n{out}"))
}

#[test]
fn eval_prints_the_table_2_parameters() {
    let (code, out, err) = axcheck(&["eval", "tests/data/iso230-2_table2.csv"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("A = 9.59 µm"), "{out}");
    assert!(out.contains("R = 6.55 µm"), "{out}");
    assert!(out.contains("at i = 9 (1408.462 mm)"), "{out}");
    assert!(
        out.contains("B̄ = -3.69 µm") || out.contains("B̄ = -3.70 µm"),
        "{out}"
    );
    assert!(out.contains("X̄i + 2Si"), "{out}");
    assert!(out.contains("1750.92"), "{out}");
}

#[test]
fn eval_json_is_the_stable_interface() {
    let v = json(&["eval", "tests/data/iso230-2_table2.csv", "--json"]);
    assert_eq!(v["standard"], "iso230-2:1997");
    assert_eq!(v["kind"], "linear");
    assert_eq!(v["unit"], "um");
    assert_eq!(v["n"], 5);
    let a = v["parameters"]["A"].as_f64().unwrap();
    assert!((a - 9.586).abs() < 0.001);
    for key in [
        "A", "A_up", "A_down", "E", "E_up", "E_down", "M", "R", "R_up", "R_down", "B", "B_mean",
    ] {
        assert!(v["parameters"][key].is_number(), "{key}");
    }
    assert_eq!(v["at_target"]["R"], 9);
    assert_eq!(v["targets"].as_array().unwrap().len(), 11);
    assert_eq!(
        v["targets"][0]["up"]["deviations"]
            .as_array()
            .unwrap()
            .len(),
        5
    );

    let g = json(&[
        "eval",
        "tests/data/gost27843_example.csv",
        "--standard",
        "gost27843",
        "--json",
    ]);
    assert_eq!(g["standard"], "gost27843-88");
    for key in [
        "A", "A_up", "A_down", "R_max", "R_up", "R_down", "R_mean", "B_max", "B_mean",
    ] {
        assert!(g["parameters"][key].is_number(), "{key}");
    }
    assert!(g["parameters"].get("E").is_none());
}

#[test]
fn key_value_and_csv_versions_of_real_data_agree() {
    for name in ["ess_bifrost_slit_axis1", "ess_muts_target_x"] {
        let kv = json(&["eval", &format!("tests/data/{name}.dat"), "--json"]);
        let csv = json(&["eval", &format!("tests/data/{name}.csv"), "--json"]);
        for (key, value) in csv["parameters"].as_object().unwrap() {
            let a = value.as_f64().unwrap();
            let b = kv["parameters"][key].as_f64().unwrap();
            // The CSV copies round the deviations to 0.001 µm.
            assert!((a - b).abs() < 0.005, "{name} {key}: {a} vs {b}");
        }
    }
}

#[test]
fn every_standard_evaluates_the_reference_data() {
    for standard in ["iso230-2", "gbt17421.2", "gost27843", "vdi3441", "nmtba"] {
        for file in [
            "iso230-2_table2.csv",
            "gost27843_example.csv",
            "ess_muts_target_x.dat",
        ] {
            let (code, out, err) =
                axcheck(&["eval", &format!("tests/data/{file}"), "-s", standard]);
            assert_eq!(code, 0, "{standard} {file}: {err}");
            assert!(out.contains("Per-target results"), "{out}");
        }
    }
}

#[test]
fn errors_name_the_file_and_exit_2() {
    let dir = std::env::temp_dir().join(format!("axcheck-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "target_mm,direction,run,deviation_um\n0,up,1,x\n").unwrap();
    let (code, _, err) = axcheck(&["eval", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("bad.csv:2:8:"), "{err}");
    let (code, _, err) = axcheck(&["eval", "tests/data/nope.csv"]);
    assert_eq!(code, 2);
    assert!(err.contains("nope.csv"), "{err}");
    let (code, _, err) = axcheck(&["eval", "tests/data/iso230-2_table2.csv", "-s", "iso9999"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown standard"), "{err}");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn simulate_then_eval_closes_the_loop() {
    let dir = std::env::temp_dir().join(format!("axcheck-sim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let model = dir.join("m.yaml");
    std::fs::write(
        &model,
        "kind: linear\nseed: 4\nmodel: {scale_um_per_m: 12, reversal_um: 3, scatter_um: 0.3}\nplan:\n  targets: {start_mm: 0, end_mm: 800, count: 9, jitter_mm: 10}\n  runs: 5\n",
    )
    .unwrap();
    let out: PathBuf = dir.join("out/data.csv");
    let (code, _, err) = axcheck(&[
        "simulate",
        model.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let first = std::fs::read(&out).unwrap();
    let (code, _, _) = axcheck(&[
        "simulate",
        model.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0);
    assert_eq!(first, std::fs::read(&out).unwrap(), "same seed, same bytes");
    let v = json(&["eval", out.to_str().unwrap(), "--json"]);
    let b = v["parameters"]["B_mean"].as_f64().unwrap();
    assert!((b - 3.0).abs() < 0.5, "B̄ = {b}");
    let (_, other, _) = axcheck(&["simulate", model.to_str().unwrap(), "--seed", "5"]);
    assert_ne!(
        other.as_bytes(),
        first.as_slice(),
        "another seed, other data"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn help_on_every_command() {
    for cmd in [
        vec!["--help"],
        vec!["eval", "--help"],
        vec!["simulate", "--help"],
    ] {
        let (code, out, _) = axcheck(&cmd);
        assert_eq!(code, 0);
        assert!(out.contains("Usage"), "{out}");
    }
}

#[test]
fn diagnose_json_and_the_extended_model_close_the_loop() {
    let dir = std::env::temp_dir().join(format!("axcheck-diag-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let model = dir.join("extended.yaml");
    let v = json(&[
        "diagnose",
        "tests/data/iso230-2_table2.csv",
        "--json",
        "--write-model",
        model.to_str().unwrap(),
    ]);
    for key in ["findings", "base", "extended", "gain_pct"] {
        assert!(v.get(key).is_some(), "{key}");
    }
    let effects: Vec<&str> = v["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["effect"].as_str().unwrap())
        .collect();
    assert!(effects.contains(&"run_offset"), "{effects:?}");
    for f in v["findings"].as_array().unwrap() {
        assert!(f["params"].is_object() || f["params"].is_array(), "{f}");
        assert!(f["evidence"].is_object(), "{f}");
    }
    assert!(
        v["extended"]["heldout_rms"].as_f64().unwrap() < v["base"]["heldout_rms"].as_f64().unwrap()
    );
    // The written model is a simulation file that `axcheck simulate` accepts.
    let (code, csv, err) = axcheck(&["simulate", model.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(
        csv.contains("target_mm,direction,run,deviation_um"),
        "{csv}"
    );
    let (code, text, _) = axcheck(&["diagnose", "tests/data/ess_muts_target_x.dat"]);
    assert_eq!(code, 0);
    assert!(
        text.contains("drift") && text.contains("Held-out error"),
        "{text}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn diagnose_does_not_write_a_model_that_simulate_would_refuse() {
    // Targets 0.0004 mm apart are one position in a simulated file (recorded to 0.001):
    // the model is not written, the diagnosis is still printed, and the exit is 2.
    let dir = crate::common::scratch("close-model");
    let csv = dir.join("data/close.csv");
    let mut text = String::from("target_mm,direction,run,deviation_um\n");
    for (i, target) in ["0", "0.0004", "10", "20", "30"].iter().enumerate() {
        for run in 1..=3 {
            for dir in ["up", "down"] {
                let dev = (i as f64 * 1.3 + run as f64 * 0.7).sin();
                text.push_str(&format!("{target},{dir},{run},{dev:.3}\n"));
            }
        }
    }
    std::fs::write(&csv, text).unwrap();
    let model = dir.join("model.yaml");
    let (code, out, err) = axcheck(&[
        "diagnose",
        csv.to_str().unwrap(),
        "--write-model",
        model.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{err}");
    assert!(out.contains("Held-out error"), "{out}");
    assert!(
        err.contains(&format!(
            "did not write the extended model to {}: `axcheck simulate` would refuse it: \
             plan.targets_mm: targets 0 and 0.0004 are the same position as recorded (to 0.001)",
            model.display()
        )),
        "{err}"
    );
    assert!(!model.exists());
    std::fs::remove_dir_all(dir).unwrap();
}

/// `eval` says what it did not apply: `vmc07-x.csv` read as it is gives A = 19.48 µm where
/// the campaign's report (NDE with α = 11.5 µm/(m·°C) at the material sensors' mean,
/// 21.15 °C) gives 7.27 µm; eval says it is not corrected, and `--nde` with
/// `--material-temperature` gives the report's value. No tolerance, no decision rule.
#[test]
fn eval_says_what_it_did_not_apply_and_applies_nde_when_asked() {
    let file = "example-campaign/data/vmc07-x.csv";
    let (code, out, err) = axcheck(&["eval", file]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("A = 19.48 µm"), "{out}");
    assert!(
        out.contains("not corrected to 20 °C (ISO 230-2 3.1): the deviations are as read"),
        "{out}"
    );
    assert!(out.contains("not judged: eval applies no tolerance and no decision rule"));
    let args = [
        "eval",
        file,
        "--nde",
        "11.5",
        "--material-temperature",
        "21.15",
    ];
    let (code, out, err) = axcheck(&args);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("A = 7.27 µm"), "{out}");
    assert!(
        out.contains("corrected to 20 °C (ISO 230-2 3.1): α = 11.50 µm/(m·°C), temperature 21.15 °C (--material-temperature)"),
        "{out}"
    );
    let v = json(&[&args[..], &["--json"]].concat());
    assert_eq!(v["applied"]["nde"]["coefficient_um_per_m_c"], 11.5);
    assert!(v["applied"]["tolerance"].is_null() && v["applied"]["decision_rule"].is_null());
    let plain = json(&["eval", file, "--json"]);
    assert!(plain["applied"]["nde"].is_null(), "{}", plain["applied"]);
    let (code, _, err) = axcheck(&["eval", file, "--nde", "11.5"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("has no material temperature column")
            && err.contains("--material-temperature T"),
        "{err}"
    );
}
