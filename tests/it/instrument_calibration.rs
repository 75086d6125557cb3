//! `instrument-calibration-due`: a test made after its instrument's calibration was due
//! is noncompliant (ISO/IEC 17025:2017 6.4.4, 6.5), named in `results.json`, on the
//! console and in `summary.md`; a valid calibration says nothing; bad dates stop at their
//! line.

use crate::common::{axcheck, scratch};
use serde_json::Value;

fn campaign(dir: &std::path::Path, calibration: &str) -> std::path::PathBuf {
    std::fs::copy("example-campaign/data/mill8-x.csv", dir.join("data/x.csv")).unwrap();
    let yaml = format!(
        "campaign: {{name: calibration, date: 2026-11-30}}\nmachines:\n  - id: M\n    axes:\n      - name: X\n        kind: linear\n        data: data/x.csv\n        conditions:\n          instrument:\n            name: laser XL-80\n            serial: LI-3307\n            calibration: {calibration}\n"
    );
    let path = dir.join("campaign.yaml");
    std::fs::write(&path, yaml).unwrap();
    path
}

fn run(name: &str, calibration: &str) -> (i32, String, Value) {
    let dir = scratch(name);
    let path = campaign(&dir, calibration);
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    let text =
        std::fs::read_to_string(out.join("results.json")).unwrap_or_else(|_| panic!("{stderr}"));
    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    (
        code,
        stdout + &summary,
        serde_json::from_str(&text).unwrap(),
    )
}

fn rule(results: &Value) -> Option<&Value> {
    (results["axes"][0]["rules"].as_array().unwrap().iter())
        .find(|r| r["id"] == "instrument-calibration-due")
}

#[test]
fn a_calibration_due_before_the_test_makes_it_noncompliant() {
    let (code, text, results) = run(
        "calibration-due",
        "{certificate: C-2025-118, calibrated_on: 2025-06-30, due: 2026-06-30, body: NPL}",
    );
    assert_eq!(code, 1, "{text}");
    assert_eq!(results["axes"][0]["verdict"], "noncompliant");
    let r = rule(&results).expect("the rule's finding");
    assert_eq!(r["severity"], "error");
    assert_eq!(r["clause"], "ISO/IEC 17025:2017 6.4.4, 6.5");
    assert_eq!(
        r["message"],
        "the calibration of the instrument laser XL-80 s/n LI-3307 (certificate C-2025-118) was due on 2026-06-30, before the test on 2026-11-30: its results are not traceable; recalibrate the instrument and measure again"
    );
    assert!(text.contains("instrument-calibration-due"), "{text}");
}

#[test]
fn a_valid_calibration_says_nothing() {
    let (_, _, results) = run(
        "calibration-valid",
        "{certificate: C-2026-031, due: 2026-11-30}",
    );
    assert!(rule(&results).is_none());
    assert_ne!(results["axes"][0]["verdict"], "noncompliant");
}

#[test]
fn calibration_dates_stop_at_their_line() {
    let dir = scratch("calibration-bad");
    for (calibration, message) in [
        (
            "{calibrated_on: 2026-06-30, due: 2025-06-30}",
            "machines[0].axes[0].conditions.instrument.calibration.due: 2025-06-30 is before the calibration on 2026-06-30",
        ),
        (
            "{due: 2026-02-30}",
            "`2026-02-30` is not a day of the calendar",
        ),
    ] {
        let path = campaign(&dir, calibration);
        let (code, stdout, stderr) = axcheck(&["check", path.to_str().unwrap()]);
        let all = stdout + &stderr;
        assert_ne!(code, 0, "{all}");
        assert!(all.contains(message), "{all}");
        assert!(all.contains("campaign.yaml:"), "{all}");
    }
}
