//! The layouts of a measurement file (long CSV, wide CSV, XLSX sheets, ecmc key=value):
//! the same readings give the same parameters whatever the layout, each file says what it
//! was read as, and broken wide tables and books get errors that name the place.
//!
//! The XLSX books are generated here with rust_xlsxwriter (a dev-dependency), from the
//! ISO 230-2 worked example `tests/data/iso230-2_table2.csv`; the fuzz seeds in
//! `fuzz/corpus/xlsx/` are written by the ignored test `write_xlsx_fuzz_seeds`.

use crate::common::{axcheck, data_path, scratch};
use axcheck::evaluate::{self, StandardId};
use axcheck::measurement::{self, AxisData, Layout, ReadTest, TableKind};
use axcheck::units::Direction;
use rust_xlsxwriter::Workbook;
use std::path::Path;

/// A cell of a generated sheet.
#[derive(Clone)]
enum Cell {
    N(f64),
    S(String),
    Blank,
}

fn s(text: &str) -> Cell {
    Cell::S(text.to_string())
}

/// A workbook with the given sheets (name, rows of cells), as bytes.
fn book(sheets: &[(&str, Vec<Vec<Cell>>)]) -> Vec<u8> {
    let mut workbook = Workbook::new();
    for (name, rows) in sheets {
        let sheet = workbook.add_worksheet();
        sheet.set_name(*name).unwrap();
        for (r, row) in rows.iter().enumerate() {
            for (c, cell) in row.iter().enumerate() {
                let (r, c) = (r as u32, c as u16);
                match cell {
                    Cell::N(x) => sheet.write_number(r, c, *x).map(|_| ()),
                    Cell::S(t) => sheet.write_string(r, c, t).map(|_| ()),
                    Cell::Blank => Ok(()),
                }
                .unwrap();
            }
        }
    }
    workbook.save_to_buffer().unwrap()
}

/// The ISO 230-2 worked example in the long CSV, as read.
fn table2() -> ReadTest {
    measurement::read_file(&data_path("iso230-2_table2.csv"), None).unwrap()
}

/// The long layout's rows of `data`, in its reading order: target, direction, run, X.
fn long_rows(data: &AxisData) -> Vec<Vec<Cell>> {
    let mut rows = vec![
        ["target_mm", "direction", "run", "deviation_um"]
            .map(s)
            .to_vec(),
    ];
    for r in &data.readings {
        rows.push(vec![
            Cell::N(data.targets[r.target]),
            s(r.direction.name()),
            Cell::N(f64::from(data.run_labels[r.run])),
            Cell::N(r.deviation),
        ]);
    }
    rows
}

/// The wide layout's rows of `data`: target, then up_J_um, down_J_um per run.
fn wide_rows(data: &AxisData) -> Vec<Vec<Cell>> {
    let mut header = vec![s("target_mm")];
    for &j in &data.run_labels {
        header.push(s(&format!("up_{j}_um")));
        header.push(s(&format!("down_{j}_um")));
    }
    let mut rows = vec![header];
    for (i, &target) in data.targets.iter().enumerate() {
        let mut row = vec![Cell::N(target)];
        for j in 0..data.runs() {
            row.push(Cell::N(data.deviation(i, Direction::Up, j)));
            row.push(Cell::N(data.deviation(i, Direction::Down, j)));
        }
        rows.push(row);
    }
    rows
}

/// Rows as CSV text with `sep`; numbers in their shortest exact form, with a decimal
/// comma when `comma`.
fn csv_text(rows: &[Vec<Cell>], sep: &str, comma: bool) -> String {
    let mut out = String::new();
    for row in rows {
        let fields: Vec<String> = row
            .iter()
            .map(|c| match c {
                Cell::N(x) if comma => format!("{x}").replace('.', ","),
                Cell::N(x) => format!("{x}"),
                Cell::S(t) => t.clone(),
                Cell::Blank => String::new(),
            })
            .collect();
        out.push_str(&fields.join(sep));
        out.push('\n');
    }
    out
}

/// Readings as (target, direction, run, deviation) in order.
fn readings(data: &AxisData) -> Vec<(f64, Direction, u32, f64)> {
    data.readings
        .iter()
        .map(|r| {
            let target = data.targets[r.target];
            (target, r.direction, data.run_labels[r.run], r.deviation)
        })
        .collect()
}

/// `got` holds exactly the readings of `want`, in the same order, and gives exactly the
/// same evaluation by every standard.
fn assert_same_test(what: &str, got: &AxisData, want: &AxisData) {
    assert_eq!(got.targets, want.targets, "{what}");
    assert_eq!(readings(got), readings(want), "{what}");
    for standard in StandardId::ALL {
        let a = serde_json::to_value(evaluate::evaluate(got, standard).json()).unwrap();
        let b = serde_json::to_value(evaluate::evaluate(want, standard).json()).unwrap();
        assert_eq!(a, b, "{what}, {standard:?}");
    }
}

fn read_bytes(bytes: &[u8], file: &str, sheet: Option<&str>) -> Result<ReadTest, String> {
    measurement::read_sheet(bytes, file, sheet).map_err(|e| e.to_string())
}

#[test]
fn a_wide_csv_gives_the_parameters_of_the_long_one() {
    let long = table2();
    assert_eq!(long.recognised.layout, Layout::LongCsv);
    let rows = wide_rows(&long.data);
    let plain = read_bytes(csv_text(&rows, ",", false).as_bytes(), "w.csv", None).unwrap();
    assert_eq!(plain.recognised.layout, Layout::WideCsv);
    assert_same_test("wide CSV", &plain.data, &long.data);
    let notes = plain.recognised.notes.join("\n");
    assert!(
        notes.contains("11 targets × 5 runs per direction")
            && notes.contains("the standard test cycle (ISO 230-2:1997, Figure 1)"),
        "{notes}"
    );
    // German spreadsheet export: semicolons, decimal commas, a comment, rows descending.
    let mut text = String::from("# Messung VMC-07 X\n");
    let mut reversed = rows.clone();
    reversed[1..].reverse();
    text.push_str(&csv_text(&reversed, ";", true));
    let german = read_bytes(text.as_bytes(), "w.csv", None).unwrap();
    assert_same_test("decimal-comma wide CSV", &german.data, &long.data);
    let notes = german.recognised.notes.join("\n");
    for want in [
        "separator `;`",
        "1 comment line (#) skipped",
        "sorted by target",
    ] {
        assert!(notes.contains(want), "want {want} in {notes}");
    }
}

#[test]
fn xlsx_sheets_in_the_long_and_wide_layouts_give_the_same_parameters() {
    let long = table2();
    let mut titled = vec![vec![s("VMC-07 axis X, 2026-03-02")], vec![Cell::Blank]];
    titled.extend(wide_rows(&long.data));
    let bytes = book(&[
        ("long", long_rows(&long.data)),
        ("X axis", titled),
        ("notes", vec![vec![s("nothing here")]]),
    ]);
    let first = read_bytes(&bytes, "b.xlsx", None).unwrap();
    assert_eq!(
        first.recognised.layout,
        Layout::Xlsx {
            sheet: "long".into(),
            table: TableKind::Long
        }
    );
    assert!(
        first.recognised.notes[0].contains("the first of 3 read"),
        "{:?}",
        first.recognised.notes
    );
    assert_same_test("XLSX long sheet", &first.data, &long.data);
    let wide = read_bytes(&bytes, "b.xlsx", Some("X axis")).unwrap();
    assert_eq!(
        wide.recognised.layout.name(),
        "XLSX sheet \"X axis\", wide table"
    );
    assert_eq!(
        wide.recognised.notes[0],
        "row 1 above the header (row 3) skipped"
    );
    assert_same_test("XLSX wide sheet", &wide.data, &long.data);
    let e = read_bytes(&bytes, "b.xlsx", Some("x-axis")).unwrap_err();
    assert_eq!(
        e,
        "b.xlsx: no sheet named \"x-axis\" (did you mean `X axis`?); the book's sheets are \"long\", \"X axis\", \"notes\""
    );
    let e = read_bytes(&bytes, "b.xlsx", Some("notes")).unwrap_err();
    assert!(
        e.starts_with("b.xlsx, sheet \"notes\": no header row"),
        "{e}"
    );
}

#[test]
fn eval_names_the_layout_in_text_and_json() {
    let dir = scratch("layouts-eval");
    let long = table2();
    let path = dir.join("data/book.xlsx");
    std::fs::write(&path, book(&[("X axis", wide_rows(&long.data))])).unwrap();
    let p = path.to_str().unwrap();
    let (code, out, err) = axcheck(&["eval", p, "--sheet", "X axis"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("read as XLSX sheet \"X axis\", wide table\n  11 targets × 5 runs"),
        "{out}"
    );
    assert!(out.contains("A = 9.59 µm"), "{out}");
    let (code, json, err) = axcheck(&["eval", p, "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    assert_eq!(v["recognised"]["layout"], "xlsx");
    assert_eq!(v["recognised"]["sheet"], "X axis");
    assert_eq!(v["recognised"]["table"], "wide");
    let (_, long_json, _) = axcheck(&["eval", "tests/data/iso230-2_table2.csv", "--json"]);
    let l: serde_json::Value = serde_json::from_str(&long_json).unwrap();
    assert_eq!(v["parameters"], l["parameters"]);
    assert_eq!(l["recognised"]["layout"], "long-csv");
    for command in ["diagnose", "compensate"] {
        let mut args = vec![command, p, "--sheet", "nope"];
        if command == "compensate" {
            args.extend(["--controller", "csv"]);
        }
        let (code, _, err) = axcheck(&args);
        assert_eq!(code, 2, "{command}");
        assert!(err.contains("no sheet named \"nope\""), "{command}: {err}");
    }
    let (code, _, err) = axcheck(&["eval", "tests/data/iso230-2_table2.csv", "--sheet", "X"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("the file is a long CSV, not a workbook"),
        "{err}"
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn an_unrecognised_file_lists_the_layouts_tried() {
    let e = read_bytes(b"# export\nMachine: VMC-07\tAxis X\n", "x.txt", None).unwrap_err();
    assert!(
        e.starts_with("x.txt: no layout recognised; tried: XLSX workbook"),
        "{e}"
    );
    for want in [
        "ecmc key=value: line 2 `Machine: VMC-07\\tAxis X` is not KEY=VALUE",
        "long CSV: line 2",
        "wide CSV: line 2",
    ] {
        assert!(e.contains(want), "want {want} in {e}");
    }
    let e = read_bytes(b"%PDF-1.7\n\xe2\xe3\xcf\xd3\n", "r.csv", None).unwrap_err();
    assert!(e.contains("no layout recognised"), "{e}");
}

/// The wide ISO example with its text changed by `edit`: the error it gives.
fn wide_error(edit: impl Fn(String) -> String) -> String {
    let text = csv_text(&wide_rows(&table2().data), ",", false);
    read_bytes(edit(text).as_bytes(), "w.csv", None).unwrap_err()
}

#[test]
fn hostile_wide_tables_are_named() {
    fn header(f: impl Fn(&str) -> String) -> impl Fn(String) -> String {
        move |text: String| {
            let (head, rest) = text.split_once('\n').unwrap();
            format!("{}\n{rest}", f(head))
        }
    }
    // A run's columns deleted from the header (the rows are not even looked at).
    let e = wide_error(header(|h| h.replace("up_3_um,down_3_um,", "")));
    assert!(
        e.starts_with("w.csv:1: run 3 has no columns but runs 1,2,4,5 have"),
        "{e}"
    );
    // A column deleted from the header but not from the rows.
    let e = wide_error(header(|h| h.replace(",down_5_um", "")));
    assert!(e.contains("column `up_5_um` has no `down_5_um`"), "{e}");
    let e = wide_error(header(|h| h.replace("down_2_um", "down_7_um")));
    assert!(e.contains("`up_2_um` has no `down_2_um`"), "{e}");
    let e = wide_error(header(|h| h.replace("up_4_um", "down_5_um")));
    assert!(e.contains("`down_5_um` appears twice"), "{e}");
    let e = wide_error(|t| t.replacen(",-1.7,", ",,", 1));
    assert!(
        e.starts_with("w.csv:2:") && e.contains("column `up_2_um`: the cell is empty"),
        "{e}"
    );
    let e = wide_error(|t| t.replacen(",-1.7,", ",n/a,", 1));
    assert!(e.contains("expected a number, found `n/a`"), "{e}");
    let e = wide_error(header(|h| h.replace("up_1_um", "up1um")));
    assert!(e.contains("did you mean `up_1_um`"), "{e}");
}

/// A ZIP archive holding one stored file that is not a workbook's.
fn zip_of(name: &str, content: &[u8]) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &b in bytes {
            crc ^= u32::from(b);
            for _ in 0..8 {
                crc = if crc & 1 == 1 {
                    (crc >> 1) ^ 0xEDB8_8320
                } else {
                    crc >> 1
                };
            }
        }
        !crc
    }
    let (crc, size, n) = (crc32(content), content.len() as u32, name.len() as u16);
    let mut z = Vec::new();
    let le32 = |z: &mut Vec<u8>, v: u32| z.extend_from_slice(&v.to_le_bytes());
    let le16 = |z: &mut Vec<u8>, v: u16| z.extend_from_slice(&v.to_le_bytes());
    le32(&mut z, 0x0403_4b50);
    for v in [20, 0, 0, 0, 0] {
        le16(&mut z, v);
    }
    for v in [crc, size, size] {
        le32(&mut z, v);
    }
    le16(&mut z, n);
    le16(&mut z, 0);
    z.extend_from_slice(name.as_bytes());
    z.extend_from_slice(content);
    let central = z.len() as u32;
    le32(&mut z, 0x0201_4b50);
    for v in [20, 20, 0, 0, 0, 0] {
        le16(&mut z, v);
    }
    for v in [crc, size, size] {
        le32(&mut z, v);
    }
    for v in [n, 0, 0, 0, 0] {
        le16(&mut z, v);
    }
    le32(&mut z, 0);
    le32(&mut z, 0);
    z.extend_from_slice(name.as_bytes());
    let central_size = z.len() as u32 - central;
    le32(&mut z, 0x0605_4b50);
    for v in [0, 0, 1, 1] {
        le16(&mut z, v);
    }
    le32(&mut z, central_size);
    le32(&mut z, central);
    le16(&mut z, 0);
    z
}

#[test]
fn hostile_books_are_named() {
    let data = table2().data;
    let with = |edit: &dyn Fn(&mut Vec<Vec<Cell>>)| {
        let mut rows = wide_rows(&data);
        edit(&mut rows);
        read_bytes(&book(&[("X axis", rows)]), "b.xlsx", None).unwrap_err()
    };
    let e = with(&|rows| rows[6][2] = Cell::Blank);
    assert_eq!(
        e,
        "b.xlsx, sheet \"X axis\", cell C7: column `down_1_um`: the cell is empty; expected a number"
    );
    let e = with(&|rows| rows[3][4] = s("1,5"));
    assert_eq!(
        e,
        "b.xlsx, sheet \"X axis\", cell E4: column `down_2_um`: expected a number, found `1,5`"
    );
    let e = with(&|rows| rows[0][1] = s("up_6_um"));
    assert!(
        e.contains("cell B1: column `up_6_um` has no `down_6_um`"),
        "{e}"
    );
    let e = with(&|rows| rows[0][3] = s("up_1_um"));
    assert!(e.contains("cell D1: column `up_1_um` appears twice"), "{e}");
    let e = with(&|rows| rows[5].push(s("checked")));
    assert!(
        e.contains("cell L6: the cell holds `checked` but its column has no header"),
        "{e}"
    );
    let e = with(&|rows| {
        for row in rows.iter_mut() {
            row.truncate(2);
        }
        rows[0][1] = s("remark");
    });
    assert!(
        e.contains("cell B1: unknown column `remark`; the wide layout"),
        "{e}"
    );
    // A title of one cell is never the header, even one that names a column.
    let mut titled = wide_rows(&data);
    titled.insert(0, vec![s("Run 3")]);
    let read = read_bytes(&book(&[("X axis", titled)]), "b.xlsx", None).unwrap();
    assert_eq!(
        read.recognised.notes[0],
        "row 1 above the header (row 2) skipped"
    );
    let e = read_bytes(&zip_of("readme.txt", b"hello"), "b.xlsx", None).unwrap_err();
    assert!(
        e.starts_with("b.xlsx: the file is a ZIP archive but not an XLSX workbook ("),
        "{e}"
    );
    let whole = book(&[("X axis", wide_rows(&data))]);
    let e = read_bytes(&whole[..whole.len() / 2], "b.xlsx", None).unwrap_err();
    assert!(e.contains("not an XLSX workbook"), "{e}");
    let e = read_bytes(&book(&[("Empty", Vec::new())]), "b.xlsx", None).unwrap_err();
    assert!(
        e.starts_with("b.xlsx, sheet \"Empty\": the sheet is empty"),
        "{e}"
    );
}

#[test]
fn a_campaign_reads_sheets_and_one_broken_axis_fails_alone() {
    let dir = scratch("layouts-campaign");
    let long = table2();
    let bytes = book(&[
        ("long", long_rows(&long.data)),
        ("X axis", wide_rows(&long.data)),
    ]);
    std::fs::write(dir.join("data/book.xlsx"), &bytes).unwrap();
    let wide = csv_text(&wide_rows(&long.data), ",", false);
    std::fs::write(dir.join("data/wide.csv"), &wide).unwrap();
    std::fs::write(
        dir.join("data/broken.csv"),
        wide.replace("down_2_um", "down_7_um"),
    )
    .unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        [
            "campaign: {name: Layouts, spec: general}",
            "machines:",
            "  - id: M",
            "    axes:",
            "      - {name: W, kind: linear, data: data/wide.csv}",
            "      - {name: S, kind: linear, data: {file: data/book.xlsx, sheet: X axis}}",
            "      - {name: F, kind: linear, data: {file: data/book.xlsx}}",
            "      - {name: BAD, kind: linear, data: data/broken.csv}",
            "      - {name: NOSHEET, kind: linear, data: {file: data/book.xlsx, sheet: Y axis}}",
            "      - {name: TYPO, kind: linear, data: {file: data/book.xlsx, shet: X axis}}",
        ]
        .join("\n"),
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-diagnose",
    ]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let results: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let axes = results["axes"].as_array().unwrap();
    let axis = |name: &str| axes.iter().find(|a| a["axis"] == name).unwrap();
    for (name, layout) in [("W", "wide-csv"), ("S", "xlsx"), ("F", "xlsx")] {
        assert_eq!(axis(name)["verdict"], "pass", "{name}");
        assert_eq!(axis(name)["recognised"]["layout"], layout, "{name}");
        assert_eq!(axis(name)["parameters"], axis("W")["parameters"], "{name}");
    }
    assert_eq!(axis("S")["recognised"]["sheet"], "X axis");
    assert_eq!(axis("F")["recognised"]["sheet"], "long");
    let error = |name: &str| axis(name)["error"].as_str().unwrap().to_string();
    assert!(error("BAD").contains("broken.csv:1:"), "{}", error("BAD"));
    assert!(error("NOSHEET").contains("no sheet named \"Y axis\""));
    assert!(
        error("TYPO").contains(
            "campaign.yaml:10:65: machines[0].axes[5].data.shet: unknown key `shet` (did you mean `sheet`?)"
        ),
        "{}",
        error("TYPO")
    );
    assert_eq!(results["counts"]["error"], 3);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_real_files_are_recognised_as_before() {
    for (name, layout) in [
        ("ess_bifrost_slit_axis1.csv", Layout::LongCsv),
        ("ess_bifrost_slit_axis1.dat", Layout::KeyValue),
        ("ess_muts_target_x.csv", Layout::LongCsv),
        ("ess_muts_target_x.dat", Layout::KeyValue),
        ("gost27843_example.csv", Layout::LongCsv),
    ] {
        let read = measurement::read_file(&data_path(name), None).unwrap();
        assert_eq!(read.recognised.layout, layout, "{name}");
    }
}

/// Writes the XLSX fuzz seeds: `cargo test --release --test it -- --ignored
/// write_xlsx_fuzz_seeds`.
#[test]
#[ignore]
fn write_xlsx_fuzz_seeds() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus/xlsx");
    std::fs::create_dir_all(&dir).unwrap();
    let small =
        "target_mm,direction,run,deviation_um\n0,up,1,1\n0,down,1,2\n10,up,1,3\n10,down,1,4\n";
    let data = measurement::read(small.as_bytes(), "s.csv").unwrap().data;
    let seeds = [
        ("long.xlsx", book(&[("long", long_rows(&data))])),
        ("wide.xlsx", book(&[("X", wide_rows(&data))])),
        (
            "two-sheets.xlsx",
            book(&[("a", vec![vec![s("title")]]), ("X", wide_rows(&data))]),
        ),
    ];
    for (name, bytes) in seeds {
        std::fs::write(dir.join(name), bytes).unwrap();
    }
}
