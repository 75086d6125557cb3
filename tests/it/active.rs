//! The compensation active during a test, as a campaign states it: tables built on it,
//! the unknown or contradicted state said, a table file that cannot be read refused with
//! its line, and the example plant's tables and verifications.

use crate::common::{axcheck, run_campaign, scratch};
use axcheck::campaign::Campaign;
use axcheck::compensate::{self, Mode, Settings};
use axcheck::measurement::csv;
use axcheck::results::{AxisTest, CampaignResult};
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use axcheck::verify::{Effectiveness, Key};
use serde_json::Value;
use std::path::Path;

/// 600 mm every 50 mm, five runs: 18 ppm, a 3 µm bow, 4 µm of reversal.
const AXIS: &str = "kind: linear\nseed: 4\nmodel:\n  scale_um_per_m: 18\n  shape: [[0, 0], [300, 3], [600, 0]]\n  reversal_um: 4\n  scatter_um: 0.3\nplan:\n  targets: {start_mm: 0, end_mm: 600, count: 13}\n  runs: 5\n";

/// Machine M (Siemens) with axes X (an active table every 50 mm and MD32450, an interval
/// of 25 mm asked for), Y (`active: none` but
/// conditions that say compensation was on), Z (nothing stated), W (an active table that
/// is not there) and V (an active table broken on line 12).
fn campaign(dir: &Path) -> std::path::PathBuf {
    let sim = Simulation::from_yaml(AXIS, "axis.yaml").unwrap();
    let data = csv::write(&sim.run(4), &[]);
    for axis in ["x", "y", "z", "w", "v"] {
        std::fs::write(dir.join(format!("data/{axis}.csv")), &data).unwrap();
    }
    let siemens = compensate::controllers::find("siemens-840d").unwrap();
    let other = sim.run(9);
    let settings = Settings {
        interval: Some(50.0),
        active: Some(Default::default()),
        ..Default::default()
    };
    let table = compensate::held_table(siemens, &other, &settings).unwrap();
    let file = siemens.write(&table, &[]).unwrap();
    std::fs::create_dir_all(dir.join("active")).unwrap();
    std::fs::write(dir.join("active/X.ini"), &file).unwrap();
    std::fs::write(
        dir.join("active/V.ini"),
        file.replace("[0,2,<AXIS?>]=", "[0,2,<AXIS?>]=x"),
    )
    .unwrap();
    let axis = |name: &str, compensation: &str, conditions: &str| {
        let lower = name.to_lowercase();
        format!(
            "      - {{name: {name}, kind: linear, data: data/{lower}.csv{compensation}{conditions}}}\n"
        )
    };
    let text = format!(
        "campaign: {{name: active, unjudged: allowed}}\nmachines:\n  - id: M\n    controller: siemens-840d\n    axes:\n{}{}{}{}{}",
        axis(
            "X",
            ", compensation: {interval: 25, active: {file: active/X.ini, backlash_um: 3}}",
            ""
        ),
        axis(
            "Y",
            ", compensation: {active: none}",
            ", conditions: {compensation: lead-screw compensation active}"
        ),
        axis("Z", "", ""),
        axis(
            "W",
            ", compensation: {active: {file: active/missing.ini}}",
            ""
        ),
        axis(
            "V",
            ", compensation: {active: {file: active/V.ini, backlash_um: 3}}",
            ""
        ),
    );
    let path = dir.join("campaign.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

/// The `compensation` block of axis `name` in results.json.
fn block<'a>(json: &'a Value, name: &str) -> &'a Value {
    let axes = json["axes"].as_array().unwrap();
    &axes.iter().find(|a| a["axis"] == name).unwrap()["compensation"]
}

fn keys(block: &Value) -> Vec<&str> {
    let warnings = block["warnings"].as_array().unwrap();
    warnings
        .iter()
        .map(|w| w["key"].as_str().unwrap())
        .collect()
}

#[test]
fn a_campaign_states_what_was_active_and_is_told_what_it_did_not() {
    let dir = scratch("active-campaign");
    let path = campaign(&dir);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let json: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    // X: incremental on its active table, the prediction far below what was measured.
    let x = block(&json, "X");
    assert_eq!(x["mode"], "incremental");
    assert_eq!(x["active_file"], "active/X.ini");
    // Its grid is the active table's: the interval given is not used, and it is said.
    // No axis named in the campaign: the file says what to replace.
    assert_eq!(keys(x), ["active_grid_kept", "axis_placeholder"], "{x}");
    let written = std::fs::read_to_string(out.join("compensation/M/X.ini")).unwrap();
    assert!(
        written.contains("\n; Incremental: the table active during the measurement (active/X.ini) plus this measurement's correction; load it in place of that table.\n"),
        "{written}"
    );
    // Y: `none` stated, but the conditions say compensation was on.
    let y = block(&json, "Y");
    assert_eq!(y["mode"], "absolute");
    assert_eq!(
        keys(y),
        ["active_compensation_contradiction", "axis_placeholder"]
    );
    // Z: nothing stated: the file, the JSON and the console say so.
    let z = block(&json, "Z");
    assert_eq!(keys(z), ["active_compensation_unknown", "axis_placeholder"]);
    let head = std::fs::read_to_string(out.join("compensation/M/Z.ini")).unwrap();
    assert!(
        head.contains("\n; Warning: the compensation active during the test was not stated"),
        "{head}"
    );
    assert!(
        stdout.contains("  M Z (active_compensation_unknown): the compensation active during the test is not stated"),
        "{stdout}"
    );
    assert!(
        stdout.contains("  M Y (active_compensation_contradiction): "),
        "{stdout}"
    );
    // W and V: no table, the reason naming the file (and line and field); still evaluated.
    let w = block(&json, "W")["refused"].as_str().unwrap();
    assert!(
        w.contains("active/missing.ini: cannot read the table"),
        "{w}"
    );
    let v = block(&json, "V")["refused"].as_str().unwrap();
    assert!(
        v.contains("active/V.ini: line 12, field `$AA_ENC_COMP`: expected a number, got `x"),
        "{v}"
    );
    assert!(
        v.ends_with("(read as a siemens-840d table for compensation.active)"),
        "{v}"
    );
    let axes = json["axes"].as_array().unwrap();
    // No limits (allowed): evaluated, not judged (issue 42).
    assert!(
        axes.iter().all(|a| a["verdict"] == "not_judged"),
        "{stdout}"
    );
    assert!(!out.join("compensation/M/W.ini").exists());
    assert!(
        stdout.contains(
            "Compensation tables: 3 written (1 incremental on the active tables), 2 not written"
        ),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// What a campaign may state, checked where it is written.
#[test]
fn the_stated_state_is_checked_where_it_is_written() {
    let dir = scratch("active-keys");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let path = dir.join("campaign.yaml");
    for (compensation, message) in [
        (
            "{active: {backlash_arcsec: 3}}",
            "machines[0].axes[0].compensation.active.backlash_arcsec: a linear axis states its backlash as backlash_um",
        ),
        (
            "{measuring_system: 2}",
            "machines[0].axes[0].compensation.measuring_system: expected 0 (the first encoder) or 1 (a direct measuring system)",
        ),
        (
            "{active: off}",
            "machines[0].axes[0].compensation.active: expected `none` or {file: TABLE, backlash_um: N}, got the text `off`",
        ),
        (
            "{verifies: {table: t.ini}}",
            "machines[0].axes[0].compensation.verifies: missing key `before`",
        ),
    ] {
        std::fs::write(
            &path,
            format!("campaign: {{name: keys}}\nmachines:\n  - id: M\n    controller: siemens-840d\n    axes:\n      - {{name: X, kind: linear, data: data/x.csv, compensation: {compensation}}}\n"),
        )
        .unwrap();
        let campaign = Campaign::load(&path).unwrap();
        let error = campaign.machines[0].axes[0].spec.as_ref().unwrap_err();
        assert_eq!(error.line, 6, "{error}");
        let error = error.to_string();
        assert!(error.contains(message), "{compensation}: {error}");
        assert!(error.contains(":6:"), "{error}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

fn test<'a>(result: &'a CampaignResult, machine: &str, axis: &str) -> &'a AxisTest {
    let found = result
        .tests
        .iter()
        .find(|t| t.machine.id == machine && t.axis == axis);
    found.unwrap()
}

/// VMC-07's tables are built on its active tables; no table is written over an unknown
/// state without the warning; MILL-3 X's table is effective, Y's (negated trims) made the
/// axis worse and is named, and no table is built on it.
#[test]
fn the_example_plant_builds_on_its_active_tables_and_verifies_two() {
    let result = run_campaign(Path::new("example-campaign/campaign.yaml"), false);
    for axis in ["X", "Y", "Z"] {
        let c = test(&result, "VMC-07", axis)
            .evaluated()
            .unwrap()
            .compensation
            .as_ref()
            .unwrap();
        assert_eq!(c.mode, Mode::Incremental, "VMC-07 {axis}");
        assert_eq!(
            c.active_file.as_deref(),
            Some(format!("active/VMC-07/{axis}.ini").as_str())
        );
        let file = &c.outcome.as_ref().unwrap().file;
        assert!(
            file.contains(&format!("$AA_ENC_COMP[0,0,{axis}1]=")),
            "{file}"
        );
    }
    for t in &result.tests {
        let Some(c) = t.evaluated().and_then(|e| e.compensation.as_deref()) else {
            continue;
        };
        let unknown = c
            .warnings
            .iter()
            .any(|w| w.key == "active_compensation_unknown");
        assert!(
            !unknown,
            "{}: the example states every axis's state",
            t.label()
        );
    }
    let x = test(&result, "MILL-3", "X")
        .evaluated()
        .unwrap()
        .verification
        .as_deref()
        .unwrap()
        .as_ref()
        .unwrap();
    assert_eq!(x.verdict, Effectiveness::Effective);
    assert!(x.findings.is_empty());
    let y_test = test(&result, "MILL-3", "Y");
    let y = y_test
        .evaluated()
        .unwrap()
        .verification
        .as_deref()
        .unwrap()
        .as_ref()
        .unwrap();
    assert_eq!(y.verdict, Effectiveness::MadeWorse);
    assert_eq!(
        y.findings.iter().map(|f| f.effect).collect::<Vec<_>>(),
        [Key::SignInverted]
    );
    let refused = y_test
        .evaluated()
        .unwrap()
        .compensation
        .as_deref()
        .unwrap()
        .outcome
        .as_ref()
        .unwrap_err();
    assert!(
        refused
            .reason
            .contains("found it made_worse (sign_inverted)"),
        "{refused}"
    );
}
