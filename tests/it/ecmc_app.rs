//! The ecmc ISO 230 app's files (`tests/data/ecmc_app/`, see EXTERNAL.md): a real report
//! read to the printed precision, the app's own results checked against axcheck's with
//! the cause of each difference, its raw-points CSV, and reports made for the tests
//! (another reference, gain and offset, cut short, targets that disagree).

use crate::common::{axcheck, data_path, scratch};
use serde_json::Value;
use std::path::Path;

fn eval_json(args: &[&str]) -> Value {
    let mut all = vec!["eval", "--json"];
    all.extend(args);
    let (code, stdout, stderr) = axcheck(&all);
    assert_eq!(code, 0, "{stderr}");
    serde_json::from_str(&stdout).unwrap()
}

fn path(name: &str) -> String {
    data_path(&format!("ecmc_app/{name}")).display().to_string()
}

/// The raw table's points of a report: (cycle, up?, target, error in mm), as printed.
fn raw_points(report: &str) -> Vec<(u32, bool, f64, f64)> {
    let table = report.split("## Raw Measured Points").nth(1).unwrap();
    let table = table.split("\n## ").next().unwrap();
    (table.lines())
        .filter(|l| l.contains("| forward |") || l.contains("| reverse |"))
        .map(|l| {
            let c: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
            (
                c[0].parse().unwrap(),
                c[1] == "forward",
                c[2].parse().unwrap(),
                c[7].parse().unwrap(),
            )
        })
        .collect()
}

/// ISO 230-2's parameters written out for the test from the points (errors in µm):
/// (A, E, M, R, B, B̄), clauses 2.10–2.23, independent of axcheck's evaluator.
fn by_hand(points: &[(u32, bool, f64, f64)]) -> [f64; 6] {
    let mut targets: Vec<f64> = points.iter().map(|p| p.2).collect();
    targets.sort_by(f64::total_cmp);
    targets.dedup();
    let stats = |t: f64, up: bool| {
        let x: Vec<f64> = (points.iter())
            .filter(|p| p.2 == t && p.1 == up)
            .map(|p| p.3 * 1000.0)
            .collect();
        let n = x.len() as f64;
        let mean = x.iter().sum::<f64>() / n;
        let s = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        (mean, s)
    };
    let (mut hi, mut lo, mut mhi, mut mlo, mut ehi, mut elo) =
        (f64::MIN, f64::MAX, f64::MIN, f64::MAX, f64::MIN, f64::MAX);
    let (mut r, mut b, mut bsum) = (0f64, 0f64, 0.0);
    for &t in &targets {
        let ((mu, su), (md, sd)) = (stats(t, true), stats(t, false));
        hi = hi.max((mu + 2.0 * su).max(md + 2.0 * sd));
        lo = lo.min((mu - 2.0 * su).min(md - 2.0 * sd));
        ehi = ehi.max(mu.max(md));
        elo = elo.min(mu.min(md));
        let mean = (mu + md) / 2.0;
        mhi = mhi.max(mean);
        mlo = mlo.min(mean);
        let bi = mu - md;
        r = r.max((2.0 * su + 2.0 * sd + bi.abs()).max(4.0 * su).max(4.0 * sd));
        b = b.max(bi.abs());
        bsum += bi;
    }
    [
        hi - lo,
        ehi - elo,
        mhi - mlo,
        r,
        b,
        bsum / targets.len() as f64,
    ]
}

const KEYS: [&str; 6] = ["A", "E", "M", "R", "B", "B_mean"];

#[test]
fn a_real_report_gives_the_parameters_of_its_raw_table() {
    let file = path("owis_openloop_RLS.md");
    let json = eval_json(&[&file]);
    assert_eq!(json["recognised"]["layout"], "ecmc-iso230-report");
    let want = by_hand(&raw_points(&std::fs::read_to_string(&file).unwrap()));
    for (key, want) in KEYS.iter().zip(want) {
        let got = json["parameters"][key].as_f64().unwrap();
        assert!((got - want).abs() < 1e-9, "{key}: {got} against {want}");
    }
    // 8 targets, 5 cycles, the reference named, time stamps kept.
    assert_eq!(json["targets"].as_array().unwrap().len(), 8);
    assert_eq!(json["n"], 5);
    let notes = json["recognised"]["notes"].to_string();
    assert!(notes.contains("c6025a-08:TR_LO-Enc02-PosAct"), "{notes}");
    assert!(notes.contains("taken as mm"), "{notes}");
}

/// The app's printed A, E, M, B and B̄ agree with axcheck's within one unit of their
/// last digit (0.00001 mm); its R is the square-root formula's, and said so.
#[test]
fn the_apps_own_results_agree_but_r_and_its_cause_is_named() {
    let json = eval_json(&[&path("owis_openloop_RLS.md")]);
    let tool = &json["other_tool"];
    assert_eq!(tool["name"], "ecmc ISO 230 app");
    assert_eq!(tool["unit"], "µm");
    let compared = |key: &str| {
        let p = tool["parameters"].as_array().unwrap().iter();
        p.clone().find(|p| p["parameter"] == key).unwrap().clone()
    };
    for key in ["A", "E", "M", "B", "B_mean"] {
        let c = compared(key);
        let (theirs, ours) = (c["theirs"].as_f64().unwrap(), c["ours"].as_f64().unwrap());
        assert!(
            (theirs - ours).abs() <= 0.01 + 1e-9,
            "{key}: {theirs} against {ours}"
        );
        assert_eq!(c["agree"], true, "{key}");
    }
    let r = compared("R");
    assert_eq!(r["agree"], false);
    assert!((r["theirs"].as_f64().unwrap() - 3.62).abs() < 1e-9);
    assert!((r["ours"].as_f64().unwrap() - 5.27).abs() < 0.005);
    let differences = tool["differences"].as_array().unwrap();
    assert_eq!(differences.len(), 1, "{differences:?}");
    let cause = differences[0]["cause"].as_str().unwrap();
    assert!(cause.contains("√(2s↑² + 2s↓² + B_i²)"), "{cause}");
    // The non-ISO results are listed, not compared.
    let other: Vec<&str> = (tool["not_compared"].as_array().unwrap().iter())
        .map(|n| n["label"].as_str().unwrap())
        .collect();
    assert_eq!(
        other,
        [
            "Mean bias",
            "Linearity residual",
            "Linear fit slope",
            "Linear fit intercept"
        ]
    );
    // And the console says the same.
    let (_, text, _) = axcheck(&["eval", &path("owis_openloop_RLS.md")]);
    assert!(
        text.contains("Bidirectional repeatability (R): the tool computes R_i = max(√"),
        "{text}"
    );
}

/// The first version's report: every difference has its formula.
#[test]
fn every_difference_of_the_first_version_is_explained() {
    let json = eval_json(&[&path("demo_iso230_report.md")]);
    let tool = &json["other_tool"];
    assert_eq!(tool["state"], "Demo");
    let differences = tool["differences"].as_array().unwrap();
    let keys: Vec<&str> = differences
        .iter()
        .map(|d| d["parameter"].as_str().unwrap())
        .collect();
    assert_eq!(keys, ["A", "E", "R", "max(R_up, R_down)", "B_mean"]);
    for d in differences {
        assert!(
            d["cause"].as_str().unwrap().contains("before 2026-03-09"),
            "{d}"
        );
    }
}

/// A difference no known formula gives is said as such.
#[test]
fn a_difference_without_a_known_cause_is_said() {
    let dir = scratch("ecmc-app-unknown");
    let text = std::fs::read_to_string(path("owis_openloop_RLS.md")).unwrap();
    let edited = text.replace(
        "- Bidirectional systematic deviation: `0.01368`",
        "- Bidirectional systematic deviation: `0.01400`",
    );
    let file = dir.join("report.md");
    std::fs::write(&file, edited).unwrap();
    let json = eval_json(&[file.to_str().unwrap()]);
    let differences = json["other_tool"]["differences"].as_array().unwrap();
    let e = differences.iter().find(|d| d["parameter"] == "E").unwrap();
    assert!(e["cause"].is_null());
    assert!(
        e["message"].as_str().unwrap().ends_with("no known cause"),
        "{e}"
    );
}

/// The CSV of the demo run holds the report's points at full precision: the same
/// parameters to the report's rounding.
#[test]
fn the_raw_points_csv_is_the_same_test_as_the_report() {
    let csv = eval_json(&[&path("demo_iso230_raw.csv")]);
    assert_eq!(csv["recognised"]["layout"], "ecmc-iso230-csv");
    assert!(csv.get("other_tool").is_none());
    let report = eval_json(&[&path("demo_iso230_report.md")]);
    for key in KEYS {
        let (a, b) = (
            csv["parameters"][key].as_f64().unwrap(),
            report["parameters"][key].as_f64().unwrap(),
        );
        assert!((a - b).abs() < 0.04, "{key}: {a} against {b}");
    }
    // The time stamps, 1 s apart in the demo, are the readings' times.
    let first = &csv["targets"][1]["up"];
    assert!(first.is_object());
    let (code, text, _) = axcheck(&["eval", &path("demo_iso230_raw.csv"), "--reference", "rbv"]);
    assert_eq!(code, 0);
    assert!(
        text.contains("deviations from the readback (RBV)"),
        "{text}"
    );
}

/// A report made for the test: `targets` × `cycles`, reference 1 evaluated with `gain`
/// and `offset`, reference 2 in the appendix; raw means are target + `f(k)` mm.
fn made_report(targets: &[f64], cycles: u32, gain: f64, offset: f64) -> String {
    let list: Vec<String> = targets.iter().map(|t| format!("{t:.5}")).collect();
    let mut s = format!(
        "# ecmc ISO 230 Bidirectional Positioning Report\n\nGenerated: `2026-11-20 10:00:00`\n\n## Status\n\n- State: `Complete`\n- Bidirectional accuracy: `0.00100`\n\n## Configuration\n\n- Configured reference PVs: `Ref 1=LASER, Ref 2=ENC`\n- Reference used for report calculations: `LASER`\n- Reference gain: `{gain:.5}`\n- Reference offset: `{offset:.5}`\n- Targets: `{}`\n- Cycles: `{cycles}`\n\n## Raw Measured Points\n\n| Cycle | Direction | Target | Raw Ref Mean | Raw Ref Std | RBV Mean | RBV Std | Raw Ref Err | RBV Err | Timestamp |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
        list.join(", ")
    );
    let mut appendix = String::from(
        "\n## Appendix: Additional Reference PVs\n\n### Ref 2: `ENC`\n\n| Cycle | Direction | Target | Raw Ref Mean | Raw Ref Std | Raw Ref Err | Timestamp |\n| --- | --- | --- | --- | --- | --- | --- |\n",
    );
    let mut second = 0;
    for c in 1..=cycles {
        for (dir, order) in [("forward", false), ("reverse", true)] {
            let mut ts: Vec<f64> = targets.to_vec();
            if order {
                ts.reverse();
            }
            for t in ts {
                let raw = t + 0.001 * f64::from(c) + if order { 0.002 } else { 0.0 };
                let time = format!("2026-11-20 10:{:02}:{:02}", second / 60, second % 60);
                second += 4;
                s += &format!(
                    "| {c} | {dir} | {t:.5} | {raw:.5} | 0.00010 | {t:.5} | 0.00000 | {:.5} | 0.00000 | {time} |\n",
                    raw - t
                );
                let enc = t - 0.003;
                appendix +=
                    &format!("| {c} | {dir} | {t:.5} | {enc:.5} | 0.00000 | -0.00300 | {time} |\n");
            }
        }
    }
    s + &appendix
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let file = dir.join(name);
    std::fs::write(&file, text).unwrap();
    file.display().to_string()
}

#[test]
fn gain_offset_references_and_readback_are_read_as_the_app_reads_them() {
    let dir = scratch("ecmc-app-made");
    let targets = [0.0, 250.0, 500.0, 750.0, 1000.0];
    let file = write(&dir, "r.md", &made_report(&targets, 3, 1.0002, -0.001));
    let json = eval_json(&[&file]);
    // x = gain · raw + offset − target, in µm: at 1000 mm up, cycle 1: raw = 1000.001.
    let x = json["targets"][4]["up"]["deviations"][0].as_f64().unwrap();
    let want = (1.0002 * 1000.001 - 0.001 - 1000.0) * 1000.0;
    assert!((x - want).abs() < 1e-6, "{x} against {want}");
    let notes = json["recognised"]["notes"].to_string();
    assert!(notes.contains("gain 1.0002 and offset -0.001"), "{notes}");
    // Reference 2, from the appendix: −3 µm everywhere (gain and offset apply to it too).
    let json = eval_json(&[&file, "--reference", "2"]);
    let x = json["targets"][0]["down"]["deviations"][2]
        .as_f64()
        .unwrap();
    assert!((x - (1.0002 * -0.003 - 0.001) * 1000.0).abs() < 1e-6, "{x}");
    assert!(
        json.get("other_tool").is_none(),
        "the app's results are reference 1's"
    );
    // The readback: 0 everywhere, no transform.
    let json = eval_json(&[&file, "--reference", "rbv"]);
    assert_eq!(json["parameters"]["A"].as_f64().unwrap(), 0.0);
    // Reference 3 was not recorded.
    let (code, _, stderr) = axcheck(&["eval", &file, "--reference", "3"]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("reference 3 was not recorded in this report"),
        "{stderr}"
    );
    assert!(stderr.contains("Ref 1=LASER, Ref 2=ENC"), "{stderr}");
    // A file without references refuses the option.
    let (code, _, stderr) = axcheck(&[
        "eval",
        &data_path("iso230-2_table2.csv").display().to_string(),
        "--reference",
        "2",
    ]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("reference 2 was asked for, but a long CSV file has one position source"),
        "{stderr}"
    );
}

#[test]
fn a_report_cut_short_or_disagreeing_with_its_configuration_is_refused_with_the_line() {
    let dir = scratch("ecmc-app-broken");
    let targets = [0.0, 250.0, 500.0, 750.0, 1000.0];
    let whole = made_report(&targets, 2, 1.0, 0.0);
    // Cut after the 17th point: the table ends on line 18 of its rows.
    let cut: String = {
        let head = whole.split("\n## Appendix").next().unwrap();
        let lines: Vec<&str> = head.lines().collect();
        let rows_from = lines.iter().position(|l| l.starts_with("| 1 |")).unwrap();
        lines[..rows_from + 17].join("\n") + "\n"
    };
    let file = write(&dir, "cut.md", &cut);
    let (code, _, stderr) = axcheck(&["eval", &file]);
    assert_eq!(code, 2);
    let last_line = cut.lines().count();
    assert!(
        stderr.contains(&format!(
            "cut.md:{last_line}: the Raw Measured Points table ends here after 17 of 20 points"
        )),
        "{stderr}"
    );
    assert!(stderr.contains("cut short"), "{stderr}");
    // A target the configuration does not list.
    let moved = whole.replacen(
        "Targets: `0.00000, 250.00000",
        "Targets: `0.00000, 260.00000",
        1,
    );
    let file = write(&dir, "moved.md", &moved);
    let (code, _, stderr) = axcheck(&["eval", &file]);
    assert_eq!(code, 2);
    let first_250 = moved
        .lines()
        .position(|l| l.starts_with("| 1 | forward | 250.00000"))
        .unwrap()
        + 1;
    assert!(
        stderr.contains(&format!(
            "moved.md:{first_250}: target 250 is not among the Configuration's `Targets`"
        )),
        "{stderr}"
    );
    // A direction the app does not write.
    let bad = whole.replacen("| 1 | forward | 500.00000", "| 1 | up | 500.00000", 1);
    let file = write(&dir, "dir.md", &bad);
    let (code, _, stderr) = axcheck(&["eval", &file]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("column `Direction`: expected `forward` or `reverse`, found `up`"),
        "{stderr}"
    );
}

/// In a campaign, `data: {file, reference}` picks the source.
#[test]
fn a_campaign_names_the_reference_of_its_data() {
    let dir = scratch("ecmc-app-campaign");
    let targets = [0.0, 250.0, 500.0, 750.0, 1000.0];
    write(&dir, "data/r.md", &made_report(&targets, 5, 1.0, 0.0));
    let campaign = "campaign: {name: Refs, date: 2026-11-20, spec: none, unjudged: allowed}\nmachines:\n  - id: M1\n    axes:\n      - {name: X, kind: linear, data: {file: data/r.md, reference: 2}}\n      - {name: Y, kind: linear, data: {file: data/r.md, reference: 7}}\n";
    let c = write(&dir, "campaign.yaml", campaign);
    // The broken axis fails alone, its error naming file, line and key.
    let (code, stdout, stderr) = axcheck(&["check", &c]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(stdout.contains("ERROR        M1 Y"), "{stdout}");
    assert!(stdout.contains("campaign.yaml:6:68: machines[0].axes[1].data.reference: expected a reference number 1 to 5, `rbv` (the readback) or `selected`, got `7`"), "{stdout}");
    assert!(!stdout.contains("M1 X"), "X passes: {stdout}");
    let campaign = campaign.replace("reference: 7", "reference: rbv");
    let c = write(&dir, "campaign.yaml", &campaign);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        &c,
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
        "--no-html",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let results: Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let x = &results["axes"][0];
    assert!(
        (x["parameters"]["B_mean"].as_f64().unwrap() - 0.0).abs() < 1e-9,
        "reference 2 has no reversal"
    );
    assert!(x["recognised"]["notes"].to_string().contains("ENC"), "{x}");
    assert!(
        x.get("other_tool").is_none(),
        "reference 2 is not what the app evaluated"
    );
    // The readback axis: not the app's reference either; the report's own (selected) is.
    let campaign = campaign.replace("reference: rbv", "reference: selected");
    let c = write(&dir, "campaign.yaml", &campaign);
    let (code, stdout, stderr) = axcheck(&[
        "run",
        &c,
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
        "--no-html",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let results: Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let y = &results["axes"][1]["other_tool"];
    assert_eq!(y["name"], "ecmc ISO 230 app");
    assert_eq!(y["parameters"][0]["parameter"], "A");
}
