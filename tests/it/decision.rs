//! Decision rules (ISO 14253-1) from the campaign, an axis and a spec: which decides, what
//! `results.json` and the console say, and a wrong name in the user's words.

use crate::common::{axcheck, scratch};

const SPEC: &str = "name: agreed\nstandard: iso230-2\ndecision_rule: simple\nlinear:\n  - tolerances: {E: 20, R: 12}\n";

/// Campaign iso14253-1; X follows it, Y says `simple`, Z's spec says `simple`, W's spec
/// says `simple` but W itself `iso14253-1`: most specific first (axis, spec, campaign).
/// The file has no temperatures, so its budget assumes ±1 °C about 20 °C: U(E) = 14.08 µm,
/// and E = 7.70 µm against 20 µm is inconclusive under ISO 14253-1 (7.70 > 20 − 14.08).
#[test]
fn the_axis_then_its_spec_then_the_campaign_decide() {
    let dir = scratch("decision-rule");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    std::fs::create_dir_all(dir.join("specs")).unwrap();
    std::fs::write(dir.join("specs/agreed.yaml"), SPEC).unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: rules, decision_rule: iso14253-1}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/x.csv, tolerances: {E: 20}}\n      - {name: Y, kind: linear, data: data/x.csv, tolerances: {E: 20}, decision_rule: simple}\n      - {name: Z, kind: linear, data: data/x.csv, spec: agreed}\n      - {name: W, kind: linear, data: data/x.csv, spec: agreed, decision_rule: iso14253-1}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&crate::common::run_args(&campaign, &out, &[]));
    assert_eq!(code, 1, "inconclusive fails the gate: {stdout}{stderr}");
    assert!(
        stdout.contains("4 tests: 2 pass, 0 fail, 0 noncompliant, 0 error, 2 inconclusive"),
        "{stdout}"
    );
    assert!(
        stdout.contains("INCONCLUSIVE M X  E = 7.70 µm ± 14.08 µm at its limit 20.00 µm"),
        "{stdout}"
    );
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let rules: Vec<&str> = json["axes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|a| a["decision_rule"].as_str().unwrap())
        .collect();
    assert_eq!(rules, ["iso14253-1", "simple", "simple", "iso14253-1"]);
    let x = &json["axes"][0];
    let check = &x["checks"][0];
    assert_eq!(check["key"], "E");
    assert_eq!(check["outcome"], "inconclusive");
    assert_eq!(check["pass"], false);
    // The U the rule used is the budget's U of E.
    assert_eq!(check["U"], x["uncertainty"]["U"]["E"]);
    assert!((check["U"].as_f64().unwrap() - 14.08).abs() < 0.005);
    assert_eq!(x["uncertainty"]["k"], 2.0);
    assert_eq!(x["verdict"], "inconclusive");
    assert_eq!(x["inconclusive"], serde_json::json!(["E"]));
    // Under the simple rule the same value passes and no U is used.
    assert_eq!(json["axes"][1]["verdict"], "pass");
    assert!(json["axes"][1]["checks"][0].get("U").is_none());
    assert_eq!(json["counts"]["inconclusive"], 2);
    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(summary.contains("0 error, 2 inconclusive"), "{summary}");
    let junit = std::fs::read_to_string(out.join("junit.xml")).unwrap();
    assert!(
        junit.contains("<failure type=\"inconclusive\" message=\"E = 7.700 µm within U = 14.085 µm of its limit 20.000 µm"),
        "{junit}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A wrong name on an axis fails that axis (the rest of the campaign goes on); on the
/// campaign it stops the run (exit 2). Both name file, line, column and the names.
#[test]
fn a_wrong_rule_name_is_said_with_its_place_and_the_names() {
    let dir = scratch("decision-rule-bad");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    let axes = "machines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, data: data/x.csv, decision_rule: iso-14253}\n      - {name: Y, kind: linear, data: data/x.csv}\n";
    std::fs::write(&campaign, format!("campaign: {{name: rules}}\n{axes}")).unwrap();
    let (code, stdout, stderr) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stdout.contains("0 pass, 0 fail, 0 noncompliant, 1 error, 1 not judged"),
        "{stdout}"
    );
    assert!(
        stdout.contains("campaign.yaml:5:66: machines[0].axes[0].decision_rule: unknown decision_rule `iso-14253`; expected simple or iso14253-1"),
        "{stdout}"
    );
    std::fs::write(
        &campaign,
        format!(
            "campaign: {{name: rules, decision_rule: iso}}\n{}",
            axes.replace(", decision_rule: iso-14253", "")
        ),
    )
    .unwrap();
    let (code, _, stderr) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("campaign.yaml:1:40: campaign.decision_rule: unknown decision_rule `iso`; expected simple or iso14253-1"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The instrument's stated accuracy enters the budget: an encoder with a certificate's
/// U = 1 µm (k = 2) gives a calibration line of u = 0.5 µm (normal), its 0.05 µm steps a
/// resolution line of 0.025/√3 µm (rectangular, half a step); a negative accuracy fails
/// the axis naming the key as written.
#[test]
fn the_instruments_stated_accuracy_enters_the_budget() {
    let dir = scratch("instrument-accuracy");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    let write = |accuracy: &str| {
        std::fs::write(
            &campaign,
            format!("campaign: {{name: acc, unjudged: allowed}}\nmachines:\n  - id: M\n    axes:\n      - {{name: X, kind: linear, data: data/x.csv, conditions: {{instrument: {{kind: linear-encoder, accuracy_um: {accuracy}, accuracy_k: 2, resolution_um: 0.05}}}}}}\n"),
        )
        .unwrap();
    };
    write("1");
    let out = dir.join("out");
    let args = [
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ];
    let (code, stdout, stderr) = axcheck(&args);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let budget = json["axes"][0]["uncertainty"]["budget"].as_array().unwrap();
    let line = |name: &str| budget.iter().find(|l| l["contributor"] == name).unwrap();
    let calibration = line("calibration");
    assert_eq!(calibration["value"], 1.0);
    assert_eq!(calibration["distribution"], "normal");
    assert!((calibration["u"].as_f64().unwrap() - 0.5).abs() < 1e-12);
    let resolution = line("resolution");
    assert!((resolution["value"].as_f64().unwrap() - 0.025).abs() < 1e-12);
    assert!((resolution["u"].as_f64().unwrap() - 0.025 / 3f64.sqrt()).abs() < 1e-12);
    // An encoder has no air path: no air lines.
    assert!(budget.iter().all(|l| l["contributor"] != "air_pressure"));

    write("-1");
    let (code, stdout, _) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        stdout.contains("conditions.instrument.accuracy_um: expected a number ≥ 0, got -1"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
