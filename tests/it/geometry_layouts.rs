//! The other laser tests of a linear axis from every table layout (issue 46): the pitch of
//! `tests/data/geometry/x-pitch.csv` (numpy's 20.204″, `EXPECTED.md`) rewritten here as a
//! wide CSV, in µrad, and as the long and the wide table of XLSX sheets (written with
//! rust_xlsxwriter, the crate summary.xlsx is written with) evaluates, by `eval --test
//! angular` and in a campaign, to exactly the long CSV's values; each kind's units are
//! enforced with the file, place and column named.

use crate::common::{axcheck, scratch};
use rust_xlsxwriter::Workbook;
use serde_json::Value;
use std::path::Path;

const PITCH: &str = "tests/data/geometry/x-pitch.csv";

/// One reading of the long CSV: target, direction, run and the angle as written.
struct Reading {
    target: String,
    direction: String,
    run: u32,
    arcsec: String,
}

fn long_readings() -> Vec<Reading> {
    let text = std::fs::read_to_string(PITCH).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next(),
        Some("target_mm,direction,run,deviation_arcsec")
    );
    lines
        .map(|line| {
            let cells: Vec<&str> = line.split(',').collect();
            Reading {
                target: cells[0].into(),
                direction: cells[1].into(),
                run: cells[2].parse().unwrap(),
                arcsec: cells[3].into(),
            }
        })
        .collect()
}

/// The same readings as a wide table: the header, then one row per target (ascending),
/// `value` turning each angle as written into the cell's text.
fn wide_rows(unit: &str, value: &dyn Fn(&str) -> String) -> Vec<Vec<String>> {
    let readings = long_readings();
    let mut targets: Vec<&str> = readings.iter().map(|r| r.target.as_str()).collect();
    targets.sort_by(|a, b| a.parse::<f64>().unwrap().total_cmp(&b.parse().unwrap()));
    targets.dedup();
    let runs = readings.iter().map(|r| r.run).max().unwrap();
    let mut header = vec!["target_mm".to_string()];
    for run in 1..=runs {
        header.push(format!("up_{run}_{unit}"));
        header.push(format!("down_{run}_{unit}"));
    }
    let mut rows = vec![header];
    for target in targets {
        let mut row = vec![target.to_string()];
        for run in 1..=runs {
            for direction in ["up", "down"] {
                let r = (readings.iter())
                    .find(|r| r.target == target && r.run == run && r.direction == direction)
                    .unwrap_or_else(|| panic!("{target} {direction} {run}"));
                row.push(value(&r.arcsec));
            }
        }
        rows.push(row);
    }
    rows
}

fn csv_of(rows: &[Vec<String>]) -> String {
    rows.iter().map(|r| r.join(",") + "\n").collect()
}

/// A book of `sheets`: the long table in `long`, the wide one in `wide`, each under a
/// title row; numbers as numeric cells.
fn book(path: &Path) {
    let mut long = vec![vec![
        "target_mm".to_string(),
        "direction".into(),
        "run".into(),
        "deviation_arcsec".into(),
    ]];
    for r in long_readings() {
        long.push(vec![r.target, r.direction, r.run.to_string(), r.arcsec]);
    }
    let wide = wide_rows("arcsec", &|a| a.to_string());
    let mut workbook = Workbook::new();
    for (name, rows) in [("EBX long", long), ("EBX wide", wide)] {
        let sheet = workbook.add_worksheet();
        sheet.set_name(name).unwrap();
        sheet
            .write_string(0, 0, "Pitch of X, laser 2026-11-30")
            .unwrap();
        for (r, row) in rows.iter().enumerate() {
            for (c, cell) in row.iter().enumerate() {
                let (r, c) = (r as u32 + 1, c as u16);
                match cell.parse::<f64>() {
                    Ok(x) => sheet.write_number(r, c, x).map(|_| ()),
                    Err(_) => sheet.write_string(r, c, cell).map(|_| ()),
                }
                .unwrap();
            }
        }
    }
    workbook.save(path).unwrap();
}

fn eval(args: &[&str]) -> Value {
    let mut all = vec!["eval", "--json"];
    all.extend_from_slice(args);
    let (code, stdout, stderr) = axcheck(&all);
    assert_eq!(code, 0, "{args:?}: {stderr}");
    serde_json::from_str(&stdout).unwrap()
}

fn angular(file: &str, sheet: Option<&str>) -> Value {
    let mut args = vec![file, "--test", "angular", "--direction", "B"];
    if let Some(sheet) = sheet {
        args.extend(["--sheet", sheet]);
    }
    eval(&args)
}

/// The evaluation without what names the file and its layout.
fn values(mut v: Value) -> Value {
    let object = v.as_object_mut().unwrap();
    object.remove("file");
    object.remove("recognised");
    v
}

#[test]
fn an_angular_test_from_a_wide_csv_and_xlsx_sheets_is_the_long_csvs() {
    let dir = scratch("geometry-layouts");
    let wide = dir.join("data/x-pitch-wide.csv");
    std::fs::write(&wide, csv_of(&wide_rows("arcsec", &|a| a.to_string()))).unwrap();
    let xlsx = dir.join("data/x-pitch.xlsx");
    book(&xlsx);
    let long = angular(PITCH, None);
    let range = long["deviation_arcsec"].as_f64().unwrap();
    assert_eq!(format!("{range:.3}"), "20.204", "EXPECTED.md");
    let from_wide = angular(wide.to_str().unwrap(), None);
    assert_eq!(from_wide["recognised"]["layout"], "wide-csv");
    assert_eq!(from_wide["deviation_arcsec"], long["deviation_arcsec"]);
    assert_eq!(values(from_wide), values(long.clone()));
    for (sheet, table) in [("EBX long", "long"), ("EBX wide", "wide")] {
        let v = angular(xlsx.to_str().unwrap(), Some(sheet));
        assert_eq!(v["recognised"]["layout"], "xlsx");
        assert_eq!(v["recognised"]["table"], table);
        assert_eq!(v["recognised"]["sheet"], sheet);
        assert_eq!(v["deviation_arcsec"], long["deviation_arcsec"], "{sheet}");
        assert_eq!(values(v), values(long.clone()), "{sheet}");
    }
}

/// The same angles in µrad (x · π/0.648, 9 significant digits) read back to arcsec within
/// the digits written.
#[test]
fn an_angular_test_in_urad_is_the_same_within_its_digits() {
    let dir = scratch("geometry-layouts-urad");
    let urad = |a: &str| {
        format!(
            "{:.9e}",
            a.parse::<f64>().unwrap() * std::f64::consts::PI / 0.648
        )
    };
    let wide = dir.join("data/x-pitch-urad.csv");
    std::fs::write(&wide, csv_of(&wide_rows("urad", &urad))).unwrap();
    let v = angular(wide.to_str().unwrap(), None);
    let long = angular(PITCH, None);
    let (a, b) = (
        v["deviation_arcsec"].as_f64().unwrap(),
        long["deviation_arcsec"].as_f64().unwrap(),
    );
    assert!((a - b).abs() < 1e-7, "{a} {b}");
}

/// Each kind's units, enforced: angles at mm read as a positioning test are named an
/// angular test's, lengths read as an angular test name their column, in a CSV and a
/// sheet alike, and a campaign reads an angular test from a workbook's sheet.
#[test]
fn each_tests_units_are_enforced_and_a_campaign_reads_a_sheet() {
    let dir = scratch("geometry-layouts-units");
    let wide = dir.join("data/x-pitch-wide.csv");
    std::fs::write(&wide, csv_of(&wide_rows("arcsec", &|a| a.to_string()))).unwrap();
    let (code, _, stderr) = axcheck(&["eval", wide.to_str().unwrap()]);
    assert_eq!(code, 2);
    let says = format!(
        "{}:1:11: column `up_1_arcsec` holds angles at targets in mm (`target_mm`): this looks like an angular test of a linear axis",
        wide.display()
    );
    assert!(stderr.contains(&says), "{stderr}");
    assert!(
        stderr.contains("`eval --test angular --direction A|B|C`"),
        "{stderr}"
    );
    let straightness = dir.join("data/eyx-wide.csv");
    std::fs::write(
        &straightness,
        "target_mm,up_1_um,down_1_um\n0,0.0,0.4\n500,2.1,2.6\n1000,-1.3,-0.9\n",
    )
    .unwrap();
    let (code, _, stderr) = axcheck(&[
        "eval",
        straightness.to_str().unwrap(),
        "--test",
        "angular",
        "--direction",
        "B",
    ]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("1:11: column `up_1_um`: an angular test of a linear axis takes angular deviations (`up_1_arcsec`, `up_1_urad` or `up_1_deg`)"),
        "{stderr}"
    );
    // The same µm as a straightness test, as the long CSV of the same readings gives it:
    // the line of both directions' means (0.2, 2.35, −1.1 µm; least squares, slope
    // −1.3 µm/m) leaves up −1.133, 1.617, −1.133 and down −0.733, 2.117, −0.733 µm, a
    // range of 2.117 + 1.133 = 3.25 µm (README: the bidirectional straightness).
    let long = dir.join("data/eyx-long.csv");
    std::fs::write(
        &long,
        "target_mm,direction,run,deviation_um\n0,up,1,0.0\n500,up,1,2.1\n1000,up,1,-1.3\n\
         1000,down,1,-0.9\n500,down,1,2.6\n0,down,1,0.4\n",
    )
    .unwrap();
    let straight = |file: &Path| {
        eval(&[
            file.to_str().unwrap(),
            "--test",
            "straightness",
            "--direction",
            "Y",
        ])
    };
    let s = straight(&straightness);
    assert_eq!(s["recognised"]["layout"], "wide-csv");
    let range = s["bidirectional"]["deviation_um"].as_f64().unwrap();
    assert_eq!(format!("{range:.3}"), "3.250");
    assert_eq!(values(s), values(straight(&long)));

    // A Renishaw file records no test type: an angular test is refused, not guessed.
    let rtl = dir.join("data/x.rtl");
    std::fs::write(
        &rtl,
        "HEADER::\nFile type  : rtl\nTARGET DATA::\nTarget-count: 2\nTargets :\n0.000000  100.000000\nFlags: 0 0 2 0\nRUNS::\nRun-count:2\nDEVIATIONS::\nRun Target Data:\n1 1 0.000\n1 2 1.000\n2 2 1.200\n2 1 0.100\nEOF::\n",
    )
    .unwrap();
    let (code, _, stderr) = axcheck(&["eval", rtl.to_str().unwrap(), "--test", "angular"]);
    assert_eq!(code, 2);
    let says = format!(
        "{}: an angular test of a linear axis is not read from a Renishaw file: its header records no test type",
        rtl.display()
    );
    assert!(stderr.contains(&says), "{stderr}");

    let xlsx = dir.join("data/x-pitch.xlsx");
    book(&xlsx);
    let (code, _, stderr) = axcheck(&["eval", xlsx.to_str().unwrap(), "--sheet", "EBX wide"]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("sheet \"EBX wide\", cell B2: column `up_1_arcsec` holds angles"),
        "{stderr}"
    );
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: sheets, date: 2026-11-30}\nmachines:\n  - id: M\n    axes:\n      - {name: X, kind: linear, test: angular, about: B, data: {file: data/x-pitch.xlsx, sheet: EBX wide}, tolerance: 30″}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert!(code == 0 || code == 1, "{stdout}{stderr}");
    let results: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let pitch = &results["axes"][0];
    assert_eq!(pitch["geometry"]["symbol"], "EBX");
    assert_eq!(
        pitch["geometry"]["deviation_arcsec"],
        angular(PITCH, None)["deviation_arcsec"]
    );
}
