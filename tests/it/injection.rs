//! Text from input that would act instead of being shown (issue 42): names that start a
//! formula in `summary.csv`, markup in `summary.md`, escape sequences and bidirectional
//! overrides on the terminal and in the other outputs. Every output shows them as written
//! (`\u001b`, `\u202e`); `results.json` keeps each name the same string.

use crate::common::{axcheck, copy_data, scratch};
use std::path::{Path, PathBuf};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// The machine and axis names of the campaign, as the YAML gives them.
const MACHINE_FORMULA: &str = "=HYPERLINK(\"http://evil.example/\",\"click\")";
const AXIS_ESC: &str = "\u{1b}[2J\u{1b}]0;pwned\u{7}";
const AXIS_RLO: &str = "X\u{202e}evil | `tick` [link](http://x.example)";
const AXIS_IMG: &str = "<img src=x onerror=alert(1)>";

/// A campaign whose names start formulas, carry HTML and Markdown, clear the screen, set
/// the terminal's title and reverse text; four axes fail (a limit of 0.1 µm), so the
/// console names them.
fn hostile_campaign(dir: &Path) -> PathBuf {
    copy_data(dir, "iso230-2_table2.csv");
    let campaign = dir.join("campaign.yaml");
    let text = r#"campaign: {name: "Plant <script>alert(1)</script>", date: 2026-11-20, spec: general}
machines:
  - id: "=HYPERLINK(\"http://evil.example/\",\"click\")"
    axes:
      - {name: "+1", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
      - {name: "-3.2", kind: linear, data: data/iso230-2_table2.csv}
  - id: "@SUM(1+1)"
    axes:
      - {name: "<img src=x onerror=alert(1)>", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
      - {name: "\x1b[2J\x1b]0;pwned\x07", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
      - {name: "X\u202Eevil | `tick` [link](http://x.example)", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
  - id: "\tTAB"
    axes:
      - {name: "\rCR\x9b2J\u2066", kind: linear, data: data/iso230-2_table2.csv}
"#;
    std::fs::write(&campaign, text).unwrap();
    campaign
}

/// Runs the hostile campaign once (PDFs included): (folder, stdout + stderr).
fn hostile_run(name: &str, extra: &[&str]) -> (PathBuf, String) {
    let dir = scratch(name);
    let campaign = hostile_campaign(&dir);
    let out = dir.join("out");
    let mut args = vec!["run", s(&campaign), "--out", s(&out)];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&args);
    assert_eq!(code, 1, "{stdout}{stderr}");
    (dir, format!("{stdout}{stderr}"))
}

/// Characters no output may carry raw: ESC, BEL, CR, CSI (C1), RLO, LRI.
fn raw_hidden(text: &str) -> Vec<char> {
    text.chars()
        .filter(|c| {
            matches!(
                c,
                '\u{1b}' | '\u{7}' | '\r' | '\u{9b}' | '\u{202e}' | '\u{2066}'
            )
        })
        .collect()
}

/// Runs a Python script with arguments; its standard output.
fn python(script: &str, args: &[&Path]) -> String {
    let run = std::process::Command::new("python3")
        .arg("-c")
        .arg(script)
        .args(args)
        .output()
        .expect("python3 runs (.ci/test installs it with openpyxl)");
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    String::from_utf8_lossy(&run.stdout).into_owned()
}

/// Reads a CSV file as Excel's import does (Python's csv module, RFC 4180) and checks
/// every cell: a text cell never starts with `=`, `+`, `-`, `@`, tab or carriage return
/// (what Excel would evaluate as a formula); a numeric column holds numbers (negative ones
/// included). Prints the number of text cells neutralised with `'` and of negative numbers.
const CSV_CHECK: &str = r#"
import csv, sys
numeric = set(sys.argv[2].split(","))
with open(sys.argv[1], newline="", encoding="utf-8") as f:
    table = list(csv.reader(f))
neutralised = negative = 0
for row in table[1:]:
    assert len(row) == len(table[0]), row
    for name, cell in zip(table[0], row):
        if name in numeric:
            if cell != "":
                float(cell)
                negative += cell.startswith("-")
        else:
            assert not cell.startswith(("=", "+", "-", "@", "\t", "\r")), (name, cell)
            neutralised += cell.startswith("'")
print(neutralised, negative)
"#;

/// `summary.csv` (and `trends.csv`) read as Excel reads it holds no formula: the names
/// that would start one get a leading `'` (OWASP), numbers stay numbers; `summary.xlsx`
/// has no formula cell.
#[test]
fn no_summary_cell_is_a_formula() {
    let history = scratch("inject-csv-history").join("history");
    let (dir, _) = hostile_run("inject-csv", &["--no-pdf", "--history", s(&history)]);
    let out = dir.join("out");
    let numeric: Vec<String> = (axcheck::export::table::columns().into_iter())
        .filter(|(_, kind)| {
            use axcheck::export::table::ColumnKind::{Int, Number};
            matches!(kind, Int | Number)
        })
        .map(|(name, _)| name)
        .collect();
    let counts = python(
        CSV_CHECK,
        &[&out.join("summary.csv"), Path::new(&numeric.join(","))],
    );
    let counts: Vec<usize> = counts
        .split_whitespace()
        .map(|n| n.parse().unwrap())
        .collect();
    // Machine "=HYPERLINK…" (2 rows), "@SUM" (3), "\tTAB" (1); axes "+1", "-3.2".
    assert_eq!(counts[0], 8, "{counts:?}");
    assert!(
        counts[1] > 0,
        "the example's negative numbers are numbers: {counts:?}"
    );
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(csv.contains("\"'=HYPERLINK(\"\"http://evil.example/\"\",\"\"click\"\")\",'+1,"));
    assert!(csv.contains(",'-3.2,"), "{csv}");
    assert_eq!(raw_hidden(&csv), Vec::<char>::new());

    let formulas = python(
        r#"
import sys, openpyxl
book = openpyxl.load_workbook(sys.argv[1])
cells = [c for sheet in book for row in sheet.iter_rows() for c in row]
print(sum(c.data_type == "f" for c in cells), sum(str(c.value).startswith("=HYPERLINK") for c in cells))
"#,
        &[&out.join("summary.xlsx")],
    );
    let formulas: Vec<usize> = formulas
        .split_whitespace()
        .map(|n| n.parse().unwrap())
        .collect();
    assert_eq!(formulas[0], 0, "no cell is a formula");
    assert!(
        formulas[1] >= 2,
        "the name is text, as written: {formulas:?}"
    );

    let trends = dir.join("trends");
    let (code, stdout, stderr) = axcheck(&["trend", s(&history), "--out", s(&trends)]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert_eq!(raw_hidden(&stdout), Vec::<char>::new(), "{stdout}");
    let numeric = "limit,points,first_value,last_value,slope_per_year,slope_se";
    let counts = python(CSV_CHECK, &[&trends.join("trends.csv"), Path::new(numeric)]);
    let neutralised: usize = counts.split_whitespace().next().unwrap().parse().unwrap();
    assert!(neutralised > 6, "{counts}");
    let csv = std::fs::read_to_string(trends.join("trends.csv")).unwrap();
    assert!(csv.contains("\n\"'=HYPERLINK("), "{csv}");
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_dir_all(history.parent().unwrap()).unwrap();
}

/// `summary.md` (a CI job summary) holds no HTML tag and no Markdown syntax from input:
/// every row of its table has the header's cells; names are shown, escaped.
#[test]
fn summary_md_holds_no_markup_from_input() {
    let (dir, _) = hostile_run("inject-md", &["--no-pdf"]);
    let md = std::fs::read_to_string(dir.join("out/summary.md")).unwrap();
    let tag = regex_like_tag(&md);
    assert_eq!(tag, None, "{md}");
    assert!(md.contains("&lt;img src=x onerror=alert(1)&gt;"), "{md}");
    assert!(md.contains("&lt;script&gt;alert(1)&lt;/script&gt;"), "{md}");
    assert!(
        md.contains("X\\u202eevil \\| \\`tick\\` \\[link\\](http://x.example)"),
        "{md}"
    );
    assert_eq!(raw_hidden(&md), Vec::<char>::new());
    // Unescaped pipes: 14 in every line of the table.
    let cells = |line: &str| line.replace("\\|", "").matches('|').count();
    let (tests, inputs) = md.split_once("\n## Inputs\n").unwrap();
    let table: Vec<&str> = tests.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(table.len(), 2 + 6, "{md}");
    assert!(table.iter().all(|l| cells(l) == 14), "{table:#?}");
    // The inputs' table (issue 47): file and SHA-256, 3 pipes a line.
    let table: Vec<&str> = inputs.lines().filter(|l| l.starts_with('|')).collect();
    assert!(table.len() > 2, "{inputs}");
    assert!(table.iter().all(|l| cells(l) == 3), "{table:#?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The first `<` that opens an HTML tag, comment or declaration (`<a`, `</a`, `<!`, `<?`).
fn regex_like_tag(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    (0..bytes.len().saturating_sub(1))
        .find(|&i| {
            bytes[i] == b'<'
                && (bytes[i + 1].is_ascii_alphabetic() || b"/!?".contains(&bytes[i + 1]))
        })
        .map(|i| text[i..].chars().take(30).collect())
}

/// ESC [2J (clear the screen), OSC 0 (the window title), U+202E and the C1 CSI reach
/// neither the terminal nor any output raw: each is shown as `\uXXXX`. `results.json`
/// keeps the names the same strings (JSON escapes); `junit.xml` stays valid XML 1.0;
/// the page and the PDF reports show the escapes.
#[test]
fn escape_sequences_and_bidi_overrides_are_shown_not_obeyed() {
    let (dir, console) = hostile_run("inject-terminal", &[]);
    let out = dir.join("out");
    assert_eq!(raw_hidden(&console), Vec::<char>::new(), "{console}");
    assert!(
        console.contains("@SUM(1+1) \\u001b[2J\\u001b]0;pwned\\u0007"),
        "{console}"
    );
    assert!(console.contains("X\\u202eevil"), "{console}");

    let json = std::fs::read_to_string(out.join("results.json")).unwrap();
    assert_eq!(raw_hidden(&json), Vec::<char>::new());
    let json: serde_json::Value = serde_json::from_str(&json).unwrap();
    let axes: Vec<&str> = (json["axes"].as_array().unwrap().iter())
        .map(|a| a["axis"].as_str().unwrap())
        .collect();
    assert!(
        axes.contains(&AXIS_ESC) && axes.contains(&AXIS_RLO),
        "{axes:?}"
    );
    assert_eq!(json["axes"][0]["machine"], MACHINE_FORMULA);
    assert!(axes.contains(&AXIS_IMG));

    for name in ["junit.xml", "summary.md", "summary.csv", "summary.html"] {
        let text = std::fs::read_to_string(out.join(name)).unwrap();
        assert_eq!(raw_hidden(&text), Vec::<char>::new(), "{name}");
    }
    let junit = out.join("junit.xml");
    let names = python(
        r#"
import sys, xml.etree.ElementTree as ET
print("\n".join(c.get("name") for c in ET.parse(sys.argv[1]).iter("testcase")))
"#,
        &[&junit],
    );
    assert!(
        names.contains("\\u001b[2J\\u001b]0;pwned\\u0007"),
        "{names}"
    );
    assert!(names.contains("\\u000dCR\\u009b2J\\u2066"), "{names}");
    let html = std::fs::read_to_string(out.join("summary.html")).unwrap();
    assert!(
        html.contains("X\\\\u202eevil"),
        "the page's data show the escape as text"
    );

    let mut reports = crate::common::pdf_text(&out.join("summary.pdf"));
    for entry in walkdir::WalkDir::new(out.join("reports")) {
        let entry = entry.unwrap();
        if entry.path().extension().is_some_and(|x| x == "pdf") {
            reports.push_str(&crate::common::pdf_text(entry.path()));
        }
    }
    assert_eq!(raw_hidden(&reports), Vec::<char>::new());
    assert!(
        reports.contains("202eevil"),
        "the report shows U+202E as an escape"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Issue 42: a line break or tab in a name is shown as an escape on the console (one line
/// per test, the campaign's count on one line), and a CJK name takes two columns a
/// character, so the reasons after the names start in one column.
#[test]
fn names_stay_on_one_line_and_in_their_columns() {
    let dir = scratch("inject-lines");
    copy_data(&dir, "iso230-2_table2.csv");
    let campaign = dir.join("campaign.yaml");
    let text = r#"campaign: {name: "Two\nlines", date: 2026-11-20}
machines:
  - id: "VMC\n07"
    axes:
      - {name: "X\tQ", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
      - {name: "长轴", kind: linear, data: data/iso230-2_table2.csv, tolerances: {A: 0.1}}
"#;
    std::fs::write(&campaign, text).unwrap();
    let (code, stdout, stderr) = axcheck(&["check", s(&campaign)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(stdout.starts_with("Two\\u000alines: 2 tests:"), "{stdout}");
    let lines: Vec<&str> = (stdout.lines())
        .filter(|l| l.starts_with("  FAIL"))
        .collect();
    assert_eq!(lines.len(), 2, "{stdout}");
    assert!(lines[0].contains("VMC\\u000a07 X\\u0009Q"), "{stdout}");
    assert!(lines[1].contains("VMC\\u000a07 长轴"), "{stdout}");
    let column = |l: &str| {
        let at = l.find("A =").unwrap();
        unicode_width::UnicodeWidthStr::width(&l[..at])
    };
    assert_eq!(column(lines[0]), column(lines[1]), "{stdout}");
    std::fs::remove_dir_all(dir).unwrap();
}
