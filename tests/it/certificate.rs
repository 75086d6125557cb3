//! A laboratory's certificate (`campaign.certificate`; ISO/IEC 17025:2017 7.8): the number
//! and "page x of y" on every page of every report, the customer, laboratory, dates, method
//! and who authorises it; the traceability table of the campaign's instruments; an
//! instrument without a certificate or due date makes the test noncompliant; a verified
//! axis as found and as left in its report and in `results.json`.

use crate::common::{axcheck, scratch};
use serde_json::Value;
use std::path::{Path, PathBuf};

const CAMPAIGN: &str = "tests/data/certificate/campaign.yaml";

/// The certificate campaign copied into a scratch folder, `edit` applied to its text.
fn copy(name: &str, edit: impl Fn(String) -> String) -> PathBuf {
    let dir = scratch(name);
    let from = Path::new("tests/data/certificate");
    std::fs::create_dir_all(dir.join("active/MILL-3")).unwrap();
    for file in [
        "data/mill3-x.csv",
        "data/mill3-x-before.csv",
        "data/mill8-x-eyx.csv",
        "data/mill8-y.csv",
        "active/MILL-3/X.txt",
    ] {
        std::fs::copy(from.join(file), dir.join(file)).unwrap();
    }
    let text = std::fs::read_to_string(CAMPAIGN).unwrap();
    std::fs::write(dir.join("campaign.yaml"), edit(text)).unwrap();
    dir
}

/// `run` of the campaign in `dir` (PDFs, no HTML): exit code, console and `results.json`.
fn run(dir: &Path) -> (i32, String, Value) {
    let out = dir.join("out");
    let campaign = dir.join("campaign.yaml");
    let args = [
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-html",
    ];
    let (code, stdout, stderr) = axcheck(&args);
    let text = std::fs::read_to_string(out.join("results.json"))
        .unwrap_or_else(|_| panic!("{stdout}{stderr}"));
    (code, stdout, serde_json::from_str(&text).unwrap())
}

/// The text of each page of `pdf`, as pdftotext reads it (pages split at form feeds).
fn page_texts(pdf: &Path) -> Vec<String> {
    let text = crate::common::pdftotext_layout(pdf);
    let mut pages: Vec<String> = text.split('\u{c}').map(str::to_string).collect();
    pages.retain(|p| !p.trim().is_empty());
    pages
}

fn axis<'a>(results: &'a Value, machine: &str, report: &str) -> &'a Value {
    (results["axes"].as_array().unwrap().iter())
        .find(|a| a["machine"] == machine && a["report_number"] == report)
        .unwrap_or_else(|| panic!("no report {report}"))
}

/// The test's `instrument-calibration-due` finding, if any.
fn calibration_rule(test: &Value) -> Option<&Value> {
    (test["rules"].as_array().unwrap().iter()).find(|r| r["id"] == "instrument-calibration-due")
}

#[test]
fn every_page_carries_the_number_and_page_x_of_y() {
    let dir = copy("certificate-pages", |t| t);
    let (code, console, results) = run(&dir);
    assert_eq!(code, 0, "{console}");
    let out = dir.join("out");
    let reports = [
        ("reports/MILL-3/X.pdf", "K-2026-0417/MILL-3-X-P"),
        ("reports/MILL-3/X-EYX.pdf", "K-2026-0417/MILL-3-X-EYX"),
        ("reports/MILL-8/Y.pdf", "K-2026-0417/MILL-8-Y-P"),
        ("summary.pdf", "K-2026-0417"),
    ];
    for (file, number) in reports {
        if file != "summary.pdf" {
            axis(&results, &file[8..14], number);
        }
        let pages = page_texts(&out.join(file));
        assert!(pages.len() >= 2, "{file}: {} pages", pages.len());
        for (k, page) in pages.iter().enumerate() {
            let footer = format!("No. {number} ·");
            assert!(page.contains(&footer), "{file} page {}: no {footer}", k + 1);
            let x_of_y = format!("Page {} of {}", k + 1, pages.len());
            assert!(page.contains(&x_of_y), "{file} page {}: no {x_of_y}", k + 1);
        }
        let first = pages[0].split_whitespace().collect::<Vec<_>>().join(" ");
        for fact in [
            "Calibration certificate",
            "Example Tools GmbH",
            "Werkstrasse 1, 12345 Musterstadt",
            "Example Calibration Lab",
            "DAkkS D-K-00000-01-00 (example)",
            "Date of measurement 2026-11-20",
            "Date of issue 2026-11-27",
            "the air pressure was read from the plant's barometer",
        ] {
            assert!(first.contains(fact), "{file} page 1 lacks {fact}:\n{first}");
        }
        let all = pages
            .join(" ")
            .split_whitespace()
            .collect::<Vec<_>>()
            .join(" ");
        for statement in [
            "Dr. B. Signer",
            "Head of the laboratory",
            "shall not be reproduced except in full",
        ] {
            assert!(all.contains(statement), "{file} lacks {statement}");
        }
    }
}

#[test]
fn the_traceability_table_lists_the_campaigns_instruments() {
    let dir = copy("certificate-trace", |t| t);
    let (_, _, results) = run(&dir);
    assert_eq!(results["campaign"]["certificate"]["number"], "K-2026-0417");
    let summary = page_texts(&dir.join("out/summary.pdf")).join(" ");
    let summary = summary.split_whitespace().collect::<Vec<_>>().join(" ");
    for row in [
        "XL-80 laser LI-2231 C-2026-118 2026-03-02 2027-03-02 Renishaw plc",
        "HP 5529A laser 3112A01234 NPL-2025-7781 2025-12-01 2026-12-01 NPL",
    ] {
        assert!(summary.contains(row), "the summary lacks {row}:\n{summary}");
    }
    // An axis report lists its own instrument only.
    let y = page_texts(&dir.join("out/reports/MILL-8/Y.pdf")).join(" ");
    assert!(y.contains("NPL-2025-7781") && !y.contains("C-2026-118"));
}

#[test]
fn an_instrument_without_its_certificate_makes_the_test_noncompliant() {
    let dir = copy("certificate-unstated", |t| {
        t.replace(
            r#"calibration: {certificate: "NPL-2025-7781", calibrated_on: 2025-12-01, due: 2026-12-01, body: "NPL"}"#,
            r#"calibration: {calibrated_on: 2025-12-01, due: 2026-12-01}"#,
        )
    });
    let (code, console, results) = run(&dir);
    assert_eq!(code, 1, "{console}");
    let y = axis(&results, "MILL-8", "K-2026-0417/MILL-8-Y-P");
    assert_eq!(y["verdict"], "noncompliant");
    let rule = calibration_rule(y).expect("the rule's finding");
    assert_eq!(
        rule["message"],
        "the instrument HP 5529A laser s/n 3112A01234 states no calibration certificate (conditions.instrument.calibration): the campaign is a certificate (campaign.certificate), which must show how its results are traceable; copy them from the instrument's calibration certificate"
    );
    assert!(console.contains("instrument-calibration-due"), "{console}");
    let report = page_texts(&dir.join("out/reports/MILL-8/Y.pdf")).join(" ");
    assert!(report.contains("instrument-calibration-due"));
    // The other machine's tests keep their verdicts.
    assert_eq!(
        axis(&results, "MILL-3", "K-2026-0417/MILL-3-X-P")["verdict"],
        "pass"
    );

    // Without a certificate, the same campaign has nothing to show.
    let plain = copy("certificate-plain", |t| {
        let start = t.find("  certificate:").unwrap();
        let end = t.find("machines:").unwrap();
        t[..start].to_string() + &t[end..]
    });
    let plain = run(&plain).2;
    let y = &plain["axes"][2];
    assert!(y.get("report_number").is_none());
    assert!(calibration_rule(y).is_none());
}

#[test]
fn a_calibration_after_the_test_does_not_show_the_instrument_valid_that_day() {
    let dir = copy("certificate-after", |t| {
        t.replace("calibrated_on: 2025-12-01", "calibrated_on: 2026-11-24")
    });
    let (code, _, results) = run(&dir);
    assert_eq!(code, 1);
    let y = axis(&results, "MILL-8", "K-2026-0417/MILL-8-Y-P");
    assert_eq!(y["verdict"], "noncompliant");
    let rule = calibration_rule(y).expect("the rule's finding");
    assert_eq!(
        rule["message"],
        "the instrument HP 5529A laser s/n 3112A01234 was calibrated on 2026-11-24 (certificate NPL-2025-7781), after the test on 2026-11-20: that calibration does not show it was valid on the day; state the calibration that was valid on 2026-11-20"
    );
}

#[test]
fn the_instruments_rule_holds_for_the_other_laser_tests_too() {
    let dir = copy("certificate-eyx", |t| {
        t.replacen(
            r#"calibration: {certificate: "C-2026-118", calibrated_on: 2026-03-02, due: 2027-03-02, body: "Renishaw plc"}}
  - id: MILL-8"#,
            r#"calibration: {certificate: "C-2025-077", calibrated_on: 2025-03-02, due: 2026-03-02, body: "Renishaw plc"}}
  - id: MILL-8"#,
            1,
        )
    });
    let (code, console, results) = run(&dir);
    assert_eq!(code, 1, "{console}");
    let eyx = axis(&results, "MILL-3", "K-2026-0417/MILL-3-X-EYX");
    assert_eq!(eyx["verdict"], "noncompliant");
    assert_eq!(eyx["rules"][0]["id"], "instrument-calibration-due");
    assert!(
        (eyx["rules"][0]["message"].as_str().unwrap()).contains(
            "(certificate C-2025-077) was due on 2026-03-02, before the test on 2026-11-20"
        )
    );
    // The positioning test of the same axis, measured with the valid calibration, passes.
    assert_eq!(
        axis(&results, "MILL-3", "K-2026-0417/MILL-3-X-P")["verdict"],
        "pass"
    );
    let report = page_texts(&dir.join("out/reports/MILL-3/X-EYX.pdf")).join(" ");
    assert!(report.contains("instrument-calibration-due"), "{report}");
}

#[test]
fn a_verified_axis_is_reported_as_found_and_as_left() {
    let dir = copy("certificate-as-found", |t| t);
    let (_, _, results) = run(&dir);
    let x = axis(&results, "MILL-3", "K-2026-0417/MILL-3-X-P");
    let (found, left) = (&x["as_found"], &x["as_left"]);
    assert_eq!(found["file"], "data/mill3-x-before.csv");
    assert_eq!(left["file"], "data/mill3-x.csv");
    // As found: the file before evaluated on its own, and judged against the same limits.
    let before = dir.join("data/mill3-x-before.csv");
    let (_, json, _) = axcheck(&["eval", before.to_str().unwrap(), "--json"]);
    let eval: Value = serde_json::from_str(&json).unwrap();
    for key in ["A", "E", "M", "R", "B"] {
        assert_eq!(found["parameters"][key], eval["parameters"][key], "{key}");
        assert_eq!(left["parameters"][key], x["parameters"][key], "{key}");
    }
    assert_eq!(found["limits"], x["limits"]);
    assert_eq!(found["verdict"], "fail");
    assert_eq!(
        found["failed"],
        serde_json::json!(["A", "A_up", "A_down", "E", "M"])
    );
    assert_eq!(left["verdict"], "pass");
    assert_eq!(left["verdict"], x["verdict"]);
    let e = |state: &Value| state["parameters"]["E"].as_f64().unwrap();
    assert!((e(found) - 20.33).abs() < 0.005 && (e(left) - 1.07).abs() < 0.005);
    assert!(found["U"]["E"].as_f64().unwrap() > 0.0);
    // The report prints both, side by side.
    let report = page_texts(&dir.join("out/reports/MILL-3/X.pdf")).join(" ");
    let report = report.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(report.contains("As found and as left"), "{report}");
    assert!(
        report.contains("bidirectional systematic positional deviation 15.00 20.33"),
        "{report}"
    );
    // An axis that verifies nothing has neither.
    let y = axis(&results, "MILL-8", "K-2026-0417/MILL-8-Y-P");
    assert!(y.get("as_found").is_none() && y.get("as_left").is_none());
}

#[test]
fn certificate_keys_stop_at_their_line() {
    let cases: [(&str, &str, &str); 4] = [
        (
            "number: K-2026-0417\n",
            "number: K-2026-0417\n    report_number: \"{number}/{machine}/{axes}\"\n",
            "campaign.yaml:14:20: campaign.certificate.report_number: `{axes}` is not a placeholder of a report number; use {number}, {machine}, {axis}, {test}",
        ),
        (
            "    issued: 2026-11-27\n",
            "",
            "campaign.yaml:13:5: campaign.certificate: a certificate states its date of issue (issued: YYYY-MM-DD; ISO/IEC 17025:2017 7.8.2.1 j)",
        ),
        (
            "  date: 2026-11-20\n",
            "",
            "campaign.yaml:12:5: campaign.certificate: a certificate states the date of the measurement: add campaign.date (ISO/IEC 17025:2017 7.8.2.1 i)",
        ),
        (
            "    issued: 2026-11-27\n",
            "    issued: 2026-11-19\n",
            "campaign.yaml:14:13: campaign.certificate.issued: 2026-11-19 is before the measurement on 2026-11-20 (campaign.date)",
        ),
    ];
    for (k, (from, to, message)) in cases.into_iter().enumerate() {
        let dir = copy(&format!("certificate-keys-{k}"), |t| {
            t.replacen(from, to, 1)
        });
        let campaign = dir.join("campaign.yaml");
        let (code, _, stderr) = axcheck(&["check", campaign.to_str().unwrap()]);
        assert_eq!(code, 2, "{stderr}");
        assert!(stderr.contains(message), "{stderr}");
    }
}
