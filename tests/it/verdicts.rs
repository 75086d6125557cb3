//! Verdicts a metrologist can sign (issue 42): a test no limit was applied to is
//! `not_judged` and fails the gate unless the campaign allows it; example limits say so;
//! the test conditions of ISO 230-2 7.1 that a campaign leaves out are named; n = 1 has a
//! statistical U; a U large against its limit or its value is flagged beside the verdict.

use crate::common::{axcheck, pdf_text, run_campaign, scratch};
use std::path::{Path, PathBuf};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The README's campaign block and machine VMC-07 with the example's data of VMC-07 Y
/// (the axis that fails in the example), with `extra` keys in the campaign block and no
/// `spec:` unless `extra` gives one.
fn readme_campaign(dir: &Path, extra: &str) -> PathBuf {
    let data = Path::new(env!("CARGO_MANIFEST_DIR")).join("example-campaign/data/vmc07-y.csv");
    std::fs::copy(data, dir.join("data/vmc07-y.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    let text = format!(
        "campaign:
  name: Plant 2 annual inspection
  site: Plant 2, Hall B
  purpose: periodic
  date: 2026-11-20
  inspector: A. Metrologist
  standard: iso230-2
{extra}machines:
  - id: VMC-07
    model: DMU 50
    serial: \"VMC-2019-0417\"
    type: vertical machining centre
    axes:
      - {{name: Y, kind: linear, travel: [0, 600], data: data/vmc07-y.csv}}
"
    );
    std::fs::write(&campaign, text).unwrap();
    campaign
}

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap()
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// Issue 42, "No limit is a PASS": the README's campaign without `spec:` passed VMC-07 Y
/// with exit 0; now the test is `not_judged` everywhere and the gate fails.
#[test]
fn a_campaign_without_a_spec_is_not_judged_and_fails_the_gate() {
    let dir = scratch("not-judged");
    let campaign = readme_campaign(&dir, "");
    let (code, stdout, stderr) = axcheck(&["check", s(&campaign)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        stdout.contains("1 tests: 0 pass, 0 fail, 0 noncompliant, 0 error, 1 not judged\n"),
        "{stdout}"
    );
    assert!(
        stdout.contains("  NOT JUDGED   VMC-07 Y  no limit applied (no spec, no tolerances)"),
        "{stdout}"
    );
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let flat = |p: &Path| pdf_text(p).split_whitespace().collect::<Vec<_>>().join(" ");
    let report = flat(&out.join("reports/VMC-07/Y.pdf"));
    assert!(
        report.contains("NOT JUDGED") && !report.contains("PASS"),
        "{report}"
    );
    let summary = flat(&out.join("summary.pdf"));
    assert!(summary.contains("1 NOT JUDGED"), "{summary}");
    let html = read(&out.join("summary.html"));
    assert!(
        html.contains(".v-not_judged {"),
        "the page has the verdict's colour"
    );
    let results = json(&out.join("results.json"));
    assert_eq!(results["axes"][0]["verdict"], "not_judged");
    assert_eq!(results["axes"][0]["no_tolerance"], true);
    assert_eq!(results["counts"]["not_judged"], 1);
    assert_eq!(results["counts"]["pass"], 0);
    let junit = read(&out.join("junit.xml"));
    assert!(
        junit.contains("tests=\"1\" failures=\"1\" errors=\"0\" skipped=\"0\"")
            && junit
                .contains("<failure type=\"not_judged\" message=\"not judged: no limit applied"),
        "{junit}"
    );
    let md = read(&out.join("summary.md"));
    assert!(
        md.contains("**1** tests: 0 pass, 0 fail, 0 noncompliant, 0 error, 1 not judged"),
        "{md}"
    );
    assert!(md.contains("| **not_judged** |"), "{md}");
    let csv = read(&out.join("summary.csv"));
    assert!(csv.contains(",not_judged,"), "{csv}");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Issue 42: with `unjudged: allowed` the gate passes, the count is shown, and JUnit
/// reports the test as skipped, not as passed; a wrong value is refused with the names.
#[test]
fn unjudged_allowed_passes_the_gate_with_the_count_shown() {
    let dir = scratch("unjudged-allowed");
    let campaign = readme_campaign(&dir, "  unjudged: allowed\n");
    let (code, stdout, stderr) = axcheck(&["check", s(&campaign)]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains("1 tests: 0 pass, 0 fail, 0 noncompliant, 0 error, 1 not judged (allowed by the campaign)"),
        "{stdout}"
    );
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out), "--no-pdf"]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let junit = read(&out.join("junit.xml"));
    assert!(
        junit.contains("failures=\"0\" errors=\"0\" skipped=\"1\"")
            && junit.contains("<skipped message=\"not judged: no limit applied"),
        "{junit}"
    );
    let results = json(&out.join("results.json"));
    assert_eq!(results["campaign"]["unjudged"], "allowed");
    assert_eq!(results["axes"][0]["verdict"], "not_judged");
    let wrong = readme_campaign(&dir, "  unjudged: yes\n");
    let (code, _, stderr) = axcheck(&["check", s(&wrong)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("campaign.unjudged")
            && stderr.contains("refused")
            && stderr.contains("allowed"),
        "{stderr}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// Issue 42, "Example limits reach acceptance reports unlabeled": every console line,
/// summary and report judged by `specs/precision.yaml` says its limits are examples; a
/// spec of one's own without `example: true` does not.
#[test]
fn example_limits_say_they_are_examples() {
    const LABEL: &str = "example limits, not from a standard";
    let dir = scratch("example-limits");
    let campaign = readme_campaign(&dir, "  spec: precision\n");
    let (code, stdout, _) = axcheck(&["check", s(&campaign)]);
    assert_eq!(code, 1, "{stdout}");
    assert!(
        stdout
            .contains("Example limits, not from a standard: 1 of 1 tests judged by spec precision"),
        "{stdout}"
    );
    assert!(
        stdout.contains("B = 7.81 µm > 3.00 µm (example limits, not from a standard)"),
        "{stdout}"
    );
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out), "--no-html"]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let results = json(&out.join("results.json"));
    assert_eq!(results["axes"][0]["example_limits"], true);
    let csv = crate::campaign::read_csv(&read(&out.join("summary.csv")));
    let column = csv[0].iter().position(|h| h == "example_limits").unwrap();
    assert_eq!(csv[1][column], "true", "summary.csv");
    let md = read(&out.join("summary.md"));
    assert!(
        md.contains(&format!("precision (linear ≤ 1000 mm) — {LABEL}")),
        "{md}"
    );
    assert!(
        md.contains("- Example limits, not from a standard: 1 of 1 tests"),
        "{md}"
    );
    assert!(read(&out.join("junit.xml")).contains(LABEL));
    let flat = |p: &Path| pdf_text(p).split_whitespace().collect::<Vec<_>>().join(" ");
    let report = flat(&out.join("reports/VMC-07/Y.pdf"));
    assert!(report.contains(LABEL), "{report}");
    let summary = flat(&out.join("summary.pdf"));
    assert!(
        summary.contains("Example limits, not from a standard"),
        "{summary}"
    );
    // The same limits in a spec of one's own, without `example: true`.
    std::fs::create_dir_all(dir.join("specs")).unwrap();
    let precision = include_str!("../../specs/precision.yaml")
        .replace("example: true\n", "")
        .replace("name: precision", "name: house");
    std::fs::write(dir.join("specs/house.yaml"), precision).unwrap();
    let house = readme_campaign(&dir, "  spec: house\n");
    let (_, stdout, _) = axcheck(&["check", s(&house)]);
    assert!(
        !stdout.to_lowercase().contains("example limits"),
        "{stdout}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// Issue 42, "Clause 7.1 gaps are silent": an axis without `conditions` gets each missing
/// item as "not stated" in its report, a warning of rule `iso-7.1-conditions` naming them,
/// and a count on the console and in the summary; VMC-07 X of the example states all.
#[test]
fn unstated_test_conditions_are_named_and_counted() {
    let dir = scratch("clause-7-1");
    let campaign = readme_campaign(&dir, "  spec: precision\n");
    let out = dir.join("out");
    let (_, stdout, stderr) = axcheck(&["run", s(&campaign), "--out", s(&out), "--no-html"]);
    // Neither the axis nor the file states anything of `conditions:`: 15 items (the
    // machine's model and type and the date are given, the axis travel too).
    assert!(
        stdout.contains("Test conditions not stated (ISO 230-2 7.1): 15 items over 1 of 1 tests"),
        "{stdout}{stderr}"
    );
    assert!(
        stdout.contains("Warnings: iso-7.1-conditions on 1 test"),
        "{stdout}"
    );
    let results = json(&out.join("results.json"));
    let axis = &results["axes"][0];
    let missing = axis["conditions_not_stated"].as_array().unwrap();
    assert_eq!(missing.len(), 15);
    assert_eq!(missing[0], "Position of the measuring instrument");
    assert!(missing.contains(&"Air pressure and humidity at start and end".into()));
    let rule = (axis["rules"].as_array().unwrap().iter())
        .find(|r| r["id"] == "iso-7.1-conditions")
        .expect("the rule fires");
    assert_eq!(rule["severity"], "warning");
    assert_eq!(rule["clause"], "ISO 230-2 7.1");
    let message = rule["message"].as_str().unwrap();
    assert!(
        message.starts_with("15 of the test conditions of clause 7.1 not stated: position of the measuring instrument, positions of the temperature sensors, NDE correction (3.1),"),
        "{message}"
    );
    let md = read(&out.join("summary.md"));
    assert!(
        md.contains("- Test conditions not stated (ISO 230-2 7.1): 15 items"),
        "{md}"
    );
    assert!(md.contains("warning `iso-7.1-conditions`"), "{md}");
    let report = pdf_text(&out.join("reports/VMC-07/Y.pdf"));
    assert!(report.matches("not stated").count() >= 15, "{report}");
    // The example's VMC-07 X states every item; its HMC-02 Y (warm-up only) does not.
    let example = run_campaign(Path::new("example-campaign/campaign.yaml"), false);
    let of = |m: &str, a: &str| {
        let t = (example.tests.iter())
            .find(|t| t.machine.id == m && t.axis == a)
            .unwrap();
        t.evaluated().unwrap().unstated.clone()
    };
    assert_eq!(of("VMC-07", "X"), Vec::<&str>::new());
    let hmc = of("HMC-02", "Y");
    assert!(
        !hmc.contains(&"Warm-up (3.3)") && hmc.contains(&"Feed rate"),
        "{hmc:?}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

/// Issue 42, "n = 1 shows U(B) = 0.00 µm" (GANTRY-1 X and Y): the statistical part is
/// estimated from the reversals over the targets, ŝ = s(Bi)/√2, and stated; U(B) holds
/// at least its share 2·√2·ŝ.
#[test]
fn one_run_per_direction_has_a_statistical_uncertainty() {
    let example = run_campaign(Path::new("example-campaign/campaign.yaml"), false);
    let n1: Vec<_> = (example.tests.iter())
        .filter(|t| t.machine.id == "GANTRY-1")
        .filter_map(|t| t.evaluated())
        .filter(|e| e.evaluation.n == 1)
        .collect();
    assert_eq!(n1.len(), 2, "GANTRY-1 X (full travel) and Y");
    for e in n1 {
        let reversals: Vec<f64> = e.evaluation.targets.iter().map(|t| t.reversal).collect();
        let m = reversals.len() as f64;
        let mean = reversals.iter().sum::<f64>() / m;
        let sd = (reversals.iter().map(|b| (b - mean).powi(2)).sum::<f64>() / (m - 1.0)).sqrt();
        let s_hat = sd / 2f64.sqrt();
        let u = e.uncertainty.as_ref().unwrap();
        let u_b = u.expanded_of(axcheck::evaluate::ParamKey::B).unwrap();
        assert!(
            u_b >= 2.0 * 2f64.sqrt() * s_hat - 1e-9,
            "U(B) = {u_b}, ŝ = {s_hat}"
        );
        assert!(u_b > 0.5, "U(B) = {u_b} µm is not 0.00");
        let note = u.notes.iter().find(|n| n.starts_with("n = 1")).unwrap();
        assert!(
            note.contains(&format!("s = s(Bi)/√2 = {:.3} µm", s_hat)) && note.contains("GUM 4.2.4"),
            "{note}"
        );
    }
}

/// Issue 42: HMC-02 Y passes with A = 11.55 ± 45.58 µm; the large U is now flagged beside
/// the verdict on the console, in summary.md and in results.json.
#[test]
fn a_large_uncertainty_is_flagged_beside_the_verdict() {
    let dir = scratch("large-u");
    let out = dir.join("out");
    let campaign = Path::new(env!("CARGO_MANIFEST_DIR")).join("example-campaign/campaign.yaml");
    let (_, stdout, stderr) = axcheck(&[
        "run",
        s(&campaign),
        "--out",
        s(&out),
        "--no-pdf",
        "--no-html",
    ]);
    assert!(
        stdout.contains("  HMC-02 Y (pass): A = 11.55 ± 45.58 µm against its limit 28.00 µm: U over half its limit and over the value (and 4 more parameters)"),
        "{stdout}{stderr}"
    );
    assert!(
        stdout.contains(
            "Uncertainty large for the verdict (U over half its limit or over the value): "
        ),
        "{stdout}"
    );
    let md = read(&out.join("summary.md"));
    assert!(
        md.contains(r"| **pass** (U large: A, A\_up, A\_down, E, M) |"),
        "{md}"
    );
    let results = json(&out.join("results.json"));
    let hmc = (results["axes"].as_array().unwrap().iter())
        .find(|a| a["machine"] == "HMC-02" && a["axis"] == "Y")
        .unwrap();
    assert_eq!(hmc["large_uncertainty"][0]["key"], "A");
    assert_eq!(hmc["large_uncertainty"][0]["over_value"], true);
    std::fs::remove_dir_all(dir).unwrap();
}
