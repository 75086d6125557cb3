//! The compensation section of the axis report: what it shows for a table the controller
//! holds, for one it refuses and for one it should not be trusted with, read from the
//! report's data (its Serialize view) rather than from the PDF.

use crate::common::{axcheck, scratch};
use axcheck::report::charts::compensation as compensation_chart;
use axcheck::report::{Reports, data};
use axcheck::results::CampaignResult;
use serde_json::Value;
use std::fmt::Write;
use std::path::Path;

/// A linear axis, `targets` targets 2 mm apart, `runs` runs, a slow sine and a reversal.
fn readings(targets: usize, runs: u32) -> String {
    let mut csv = String::from("target_mm,direction,run,deviation_um\n");
    for run in 1..=runs {
        for (direction, reversal) in [("up", 0.0), ("down", 0.8)] {
            for i in 0..targets {
                let target = i as f64 * 2.0;
                let scatter = 0.1 * ((i * 7 + run as usize * 3) % 5) as f64 - 0.2;
                let deviation = 3.0 * (target / 100.0).sin() + reversal + scatter;
                writeln!(csv, "{target},{direction},{run},{deviation:.2}").unwrap();
            }
        }
    }
    csv
}

/// Machines `TABLE` (controller csv, ISO 230-2's Table 2 data), `LONG` (linuxcnc, 300
/// targets), `ONCE` (csv, one run per direction) and `PLAIN` (no controller).
fn campaign(dir: &Path) -> std::path::PathBuf {
    std::fs::copy(
        "tests/data/iso230-2_table2.csv",
        dir.join("data/table2.csv"),
    )
    .unwrap();
    std::fs::write(dir.join("data/long.csv"), readings(300, 2)).unwrap();
    std::fs::write(dir.join("data/once.csv"), readings(11, 1)).unwrap();
    let axis = |name: &str, file: &str| {
        format!(
            "    axes:\n      - {{name: {name}, kind: linear, data: data/{file}, compensation: {{active: none}}}}\n"
        )
    };
    let text = format!(
        "campaign: {{name: comp}}\nmachines:\n  - id: TABLE\n    controller: csv\n{}  - id: LONG\n    controller: linuxcnc\n{}  - id: ONCE\n    controller: csv\n{}  - id: PLAIN\n{}",
        axis("X", "table2.csv"),
        axis("X", "long.csv"),
        axis("X", "once.csv"),
        axis("X", "table2.csv"),
    );
    let path = dir.join("campaign.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

fn run(path: &Path) -> CampaignResult {
    crate::common::run_campaign(path, true)
}

/// The compensation part of the report data of machine `id`.
fn section(result: &CampaignResult, id: &str) -> Value {
    let test = result.tests.iter().find(|t| t.machine.id == id).unwrap();
    let view = serde_json::to_value(data::axis_report(result, test, &Default::default())).unwrap();
    view["compensation"].clone()
}

/// The row of parameter `key`: (measured, predicted).
fn row(section: &Value, key: &str) -> (String, String) {
    let rows = section["parameters"].as_array().unwrap();
    let row = rows.iter().find(|r| r["key"] == key).unwrap();
    let text = |field: &str| row[field].as_str().unwrap().to_string();
    (text("measured"), text("predicted"))
}

#[test]
fn the_axis_report_shows_the_compensation_of_a_controller() {
    let dir = scratch("report-compensation");
    let path = campaign(&dir);
    let result = run(&path);

    // ISO 230-2 Table 2 with a table on its 11 targets: the means vanish, the scatter stays.
    let table = section(&result, "TABLE");
    assert_eq!(table["controller"], "csv");
    assert_eq!(table["refusal"], Value::Null);
    let fact = |label: &str| -> String {
        let facts = table["facts"].as_array().unwrap();
        let row = facts.iter().find(|r| r["label"] == label).unwrap();
        row["value"].as_str().unwrap().to_string()
    };
    assert_eq!(fact("Controller"), "csv (file .csv)");
    assert!(fact("Table points").starts_with("11, a correction per direction"));
    assert_eq!(fact("Reference point"), "6.711 mm");
    assert!(fact("Interval").contains("the measured targets"));
    assert_eq!(row(&table, "A"), ("9.59".into(), "2.99".into()));
    assert_eq!(row(&table, "E"), ("7.70".into(), "0.00".into()));
    assert_eq!(row(&table, "B_mean"), ("−3.69".into(), "0.00".into()));
    assert_eq!(row(&table, "R_up"), ("2.99".into(), "2.99".into()));
    let floor = table["floor"].as_str().unwrap();
    assert!(
        floor.starts_with("The floor is the repeatability"),
        "{floor}"
    );
    assert!(
        floor.contains("R↑ and R↓ (ISO 230-2 2.18 (2.16))"),
        "{floor}"
    );
    assert_eq!(table["warnings"], serde_json::json!([]));

    // The chart: measured means as evaluated, compensated ones cancelled on the targets.
    let test = &result.tests[0];
    let measured = test.evaluated().map(|e| &e.evaluation).unwrap();
    let compensation = test
        .evaluated()
        .and_then(|e| e.compensation.as_deref())
        .unwrap();
    let chart = data::compensation_chart(measured, compensation.outcome.as_ref().unwrap());
    assert_eq!(chart.table_points.len(), 11);
    assert_eq!(chart.measured_up[0], measured.targets[0].up.mean);
    assert!(chart.compensated_up.iter().all(|m| m.abs() < 1e-3));
    assert!(chart.compensated_down.iter().all(|m| m.abs() < 1e-3));
    let scene = compensation_chart::compensation(
        &chart,
        &compensation_chart::Style {
            width_px: 900,
            height_px: 420,
        },
    );
    assert!(
        scene
            .texts
            .iter()
            .any(|t| t.text == "Target position Pi / mm")
    );
    assert!(
        scene
            .texts
            .iter()
            .any(|t| t.text == "Positional deviation / µm")
    );

    // 300 points are more than LinuxCNC holds: the refusal instead of the rest.
    let long = section(&result, "LONG");
    let refusal = long["refusal"].as_str().unwrap();
    assert!(refusal.starts_with("300 points"), "{refusal}");
    assert!(refusal.contains("at most 256"), "{refusal}");
    assert_eq!(long["facts"], serde_json::json!([]));
    assert_eq!(long["parameters"], serde_json::json!([]));

    // One run per direction: the table is written, with the warning.
    let once = section(&result, "ONCE");
    assert_eq!(once["refusal"], Value::Null);
    let warnings = once["warnings"].as_array().unwrap();
    assert!(
        warnings.iter().any(|w| w
            .as_str()
            .unwrap()
            .starts_with("one run per direction (n = 1)")),
        "{warnings:?}"
    );

    // No controller, no section.
    assert_eq!(section(&result, "PLAIN"), Value::Null);

    // Every report typesets without warnings, and `run` writes them.
    let reports = Reports::new(None).unwrap();
    for t in &result.tests {
        let rendered = reports.axis(&result, t).unwrap();
        assert!(
            rendered.warnings.is_empty(),
            "{}: {:?}",
            t.label(),
            rendered.warnings
        );
    }
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        path.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(code <= 1, "{stdout}{stderr}");
    for id in ["TABLE", "LONG", "ONCE", "PLAIN"] {
        let pdf = std::fs::read(out.join(format!("reports/{id}/X.pdf"))).unwrap();
        assert!(pdf.starts_with(b"%PDF-"), "{id}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
