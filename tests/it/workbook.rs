//! summary.xlsx read back by two readers that are not its writer (calamine here, openpyxl
//! in Python, as a spreadsheet user's script would read it): the same values as
//! summary.csv, typed, with units in the headers, and the three sheets.

use crate::campaign::read_csv;
use crate::common::axcheck;
use calamine::{Data, Reader, Xlsx, open_workbook};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The example campaign's outputs (no PDFs), made once for this file's tests.
fn example_outputs() -> &'static Path {
    static OUT: OnceLock<PathBuf> = OnceLock::new();
    OUT.get_or_init(|| {
        let out = std::env::temp_dir().join(format!("axcheck-xlsx-ex-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        let args = [
            "run",
            "example-campaign/campaign.yaml",
            "--out",
            out.to_str().unwrap(),
            "--no-pdf",
        ];
        let (code, stdout, stderr) = axcheck(&args);
        assert_eq!(code, 1, "{stdout}{stderr}");
        out
    })
}

fn csv(out: &Path) -> Vec<Vec<String>> {
    read_csv(&std::fs::read_to_string(out.join("summary.csv")).unwrap())
}

/// The `Tests` sheet's column for the CSV column `name`: its header is the name, or the
/// name and its unit in brackets.
fn column_of(header: &[String], name: &str) -> usize {
    let found = header.iter().position(|h| {
        h == name
            || h.strip_prefix(name)
                .is_some_and(|rest| rest.starts_with(" ("))
    });
    found.unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

/// A cell as the CSV writes it (numbers compared as numbers by the caller).
fn cell_text(d: &Data) -> String {
    match d {
        Data::Empty => String::new(),
        Data::String(s) => s.clone(),
        Data::Float(x) => x.to_string(),
        Data::Int(x) => x.to_string(),
        Data::Bool(b) => b.to_string(),
        other => panic!("unexpected cell {other:?}"),
    }
}

#[test]
fn the_tests_sheet_holds_the_csvs_values_typed() {
    let out = example_outputs();
    let csv = csv(out);
    let mut book: Xlsx<_> = open_workbook(out.join("summary.xlsx")).unwrap();
    assert_eq!(book.sheet_names(), ["Tests", "Plan rules", "Diagnosis"]);
    let tests = book.worksheet_range("Tests").unwrap();
    let rows: Vec<&[Data]> = tests.rows().collect();
    let header: Vec<String> = rows[0].iter().map(cell_text).collect();
    assert_eq!(rows.len(), csv.len(), "a row per axis test, and the header");
    // Units in the header: the example has linear and rotary axes.
    assert!(
        header.contains(&"E (µm or arcsec: see unit)".to_string()),
        "{header:?}"
    );
    assert!(
        header.contains(&"travel (mm or deg: see unit)".to_string()),
        "{header:?}"
    );
    let mut numbers = 0;
    for (k, name) in csv[0].iter().enumerate() {
        let col = column_of(&header, name);
        for (r, csv_row) in csv.iter().enumerate().skip(1) {
            let (want, got) = (&csv_row[k], &rows[r][col]);
            let at = format!("row {r}, column {name}");
            match got {
                Data::Float(x) => {
                    numbers += 1;
                    assert_eq!(*x, want.parse::<f64>().unwrap(), "{at}");
                }
                other => assert_eq!(&cell_text(other), want, "{at}"),
            }
        }
    }
    assert!(numbers > 300, "parameters are numbers, not text: {numbers}");
    // The columns beyond the CSV: U of the headline parameters, decision rule, predicted E.
    let u_e = column_of(&header, "U_E");
    let mill_y = find_row(&rows, "MILL-3", "Y");
    assert!((as_f64(&rows[mill_y][u_e]) - 5.32).abs() < 0.005);
    let predicted = column_of(&header, "E_predicted");
    let vmc_y = find_row(&rows, "VMC-07", "Y");
    assert!((as_f64(&rows[vmc_y][predicted]) - 0.66).abs() < 0.005);
    let rule = rows[vmc_y][column_of(&header, "decision_rule")].to_string();
    assert!(!rule.is_empty());
}

fn find_row(rows: &[&[Data]], machine: &str, axis: &str) -> usize {
    let found = rows.iter().position(|r| r[0] == machine && r[1] == axis);
    found.unwrap_or_else(|| panic!("no row for {machine} {axis}"))
}

fn as_f64(d: &Data) -> f64 {
    match d {
        Data::Float(x) => *x,
        other => panic!("not a number: {other:?}"),
    }
}

#[test]
fn the_findings_sheets_list_rules_and_effects() {
    let out = example_outputs();
    let mut book: Xlsx<_> = open_workbook(out.join("summary.xlsx")).unwrap();
    let rules = book.worksheet_range("Plan rules").unwrap();
    let lathe = rules
        .rows()
        .find(|r| r[0] == "LATHE-5" && r[3] == "iso-4.3.2-targets")
        .expect("LATHE-5 X's missing target");
    assert_eq!(lathe[1], "X");
    assert_eq!(lathe[5], "error", "a rule that makes the plan noncompliant");
    let diagnosis = book.worksheet_range("Diagnosis").unwrap();
    let vmc = diagnosis
        .rows()
        .find(|r| r[0] == "VMC-07" && r[1] == "Y")
        .expect("VMC-07 Y's reversal variation");
    assert_eq!(vmc[3], "reversal_variation");
    assert!(cell_text(&vmc[6]).contains("backlash"), "{vmc:?}");
}

/// Frozen header, autofilter, coloured verdicts: in the sheet's own XML.
#[test]
fn the_header_is_frozen_filtered_and_verdicts_styled() {
    let out = example_outputs();
    let file = std::fs::File::open(out.join("summary.xlsx")).unwrap();
    let mut zip = zip::ZipArchive::new(file).unwrap();
    let mut part = |name: &str| {
        let mut text = String::new();
        zip.by_name(name)
            .unwrap()
            .read_to_string(&mut text)
            .unwrap();
        text
    };
    let sheet = part("xl/worksheets/sheet1.xml");
    assert!(
        sheet.contains(
            r#"<pane ySplit="1" topLeftCell="A2" activePane="bottomLeft" state="frozen"/>"#
        ),
        "{sheet:.600}"
    );
    assert!(sheet.contains("<autoFilter ref=\"A1:"), "{sheet:.600}");
    let styles = part("xl/styles.xml");
    for colour in ["FFF8DCDC", "FFE3F1E6", "FFFBE6CF", "FFFDF3C4"] {
        assert!(styles.contains(colour), "verdict fill {colour} missing");
    }
    // A fixed document time: the campaign's date.
    let core = part("docProps/core.xml");
    assert!(core.contains("2026-11-20T00:00:00Z"), "{core}");
}

/// openpyxl, the reader of most plant scripts, reads the same values as summary.csv.
#[test]
fn openpyxl_reads_the_csvs_values() {
    let out = example_outputs();
    let script = r#"
import csv, sys, openpyxl
book = openpyxl.load_workbook(sys.argv[1], read_only=True)
sheet = book["Tests"]
rows = list(sheet.iter_rows(values_only=True))
header = [h for h in rows[0]]
def column(name):
    for k, h in enumerate(header):
        if h == name or h.startswith(name + " ("):
            return k
    raise SystemExit("no column " + name)
with open(sys.argv[2], newline="", encoding="utf-8") as f:
    table = list(csv.reader(f))
assert len(table) == len(rows), (len(table), len(rows))
checked = 0
for k, name in enumerate(table[0]):
    col = column(name)
    for r in range(1, len(table)):
        want, got = table[r][k], rows[r][col]
        if isinstance(got, bool):
            assert want == str(got).lower(), (r, name, want, got)
        elif isinstance(got, float) or isinstance(got, int):
            assert float(want) == float(got), (r, name, want, got)
        else:
            assert (got or "") == want, (r, name, want, got)
        checked += 1
print(checked)
"#;
    let run = std::process::Command::new("python3")
        .args(["-c", script])
        .arg(out.join("summary.xlsx"))
        .arg(out.join("summary.csv"))
        .output()
        .expect("python3 runs (.ci/run installs it with python3-openpyxl)");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    let checked: usize = String::from_utf8_lossy(&run.stdout).trim().parse().unwrap();
    // 34 columns, and 6 since issue 46 (the other laser tests); 33 tests.
    assert_eq!(checked, 40 * 33, "every cell of the CSV");
}
