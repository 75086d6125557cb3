//! Renishaw `.rtl` files end to end (constructed after the layout of the module docs: no
//! real file is public): a campaign reads one as it reads the long CSV, and what the file
//! says of itself (USER-TEXT, ENVIRONMENT) reaches the report, `results.json` and, where
//! the campaign asks for it, the correction to 20 °C (ISO 230-2 clause 3.1).

use crate::common::{axcheck, data_path, pdf_text, scratch};
use axcheck::measurement::{self, AxisData};
use axcheck::units::Direction;

/// `data` written as a Renishaw `.rtl`: CRLF, Windows-1252 USER-TEXT, targets 5 per line
/// with trailing spaces, even runs listed from the last target down, and ENVIRONMENT with
/// one material sensor at 20.203292 → 20.321342 °C and an expansion coefficient of 8.
fn rtl(data: &AxisData) -> Vec<u8> {
    let mut lines: Vec<Vec<u8>> = Vec::new();
    let mut push = |s: &str| lines.push(s.as_bytes().to_vec());
    for l in ["HEADER::", "File type  : rtl", "Owner      : Linear", ""] {
        push(l);
    }
    push("TARGET DATA::");
    push(&format!("Target-count: {}", data.targets.len()));
    push("Targets :");
    for chunk in data.targets.chunks(5) {
        let values: Vec<String> = chunk.iter().map(|t| format!("{t:.6}")).collect();
        push(&format!("{}  ", values.join("  ")));
    }
    push("Flags: 0 0 2 0");
    push("");
    push("USER-TEXT::");
    lines.push(b"Machine: M\xFChle 3".to_vec()); // "Mühle" in Windows-1252
    let mut push = |s: &str| lines.push(s.as_bytes().to_vec());
    for l in [
        "SerialNo: SN-77",
        "Date: 12/12/2016",
        "By: J. Smith",
        "Axis: X1",
        "Location: Hall B",
        "",
        "RUNS::",
    ] {
        push(l);
    }
    push(&format!("Run-count:{}", 2 * data.runs()));
    push("");
    push("DEVIATIONS::");
    push("Run Target Data: ");
    let mut pass = 0;
    for j in 0..data.runs() {
        for d in Direction::BOTH {
            pass += 1;
            let mut order: Vec<usize> = (0..data.target_count()).collect();
            if pass % 2 == 0 {
                order.reverse();
            }
            for i in order {
                let x = data.deviation(i, d, j);
                push(&format!("{:<7}{:<5}{:>10.3}", pass, i + 1, x));
            }
        }
    }
    push("");
    for l in [
        "ENVIRONMENT::",
        "Air temp   : 20.337280 20.384956 0",
        "Air press  : 99.039005 99.049346 1",
        "Air humid  : 46.954897 46.893887",
        "Mat temp 1 : 20.203292 20.321342 0",
        "Mat temp 2 : -10.000000 -10.000000 0",
        "Exp coeff  : 8.000000 8.000000 0",
        "Date Time  : \"10:46 Dec 12 2016\" \"11:01 Dec 12 2016\"",
        "",
        "EOF::",
    ] {
        push(l);
    }
    let mut bytes = lines.join(&b"\r\n"[..]);
    bytes.extend(b"\r\n");
    bytes
}

#[test]
fn a_campaign_reads_a_renishaw_file_as_the_long_csv_and_keeps_what_it_says() {
    let table2 = measurement::read_file(&data_path("iso230-2_table2.csv"), None).unwrap();
    let dir = scratch("renishaw-campaign");
    std::fs::create_dir_all(dir.join("data")).unwrap();
    std::fs::copy(data_path("iso230-2_table2.csv"), dir.join("data/x.csv")).unwrap();
    std::fs::write(dir.join("data/x.rtl"), rtl(&table2.data)).unwrap();
    std::fs::write(
        dir.join("campaign.yaml"),
        "campaign: {name: lab files, date: 2026-11-23, unjudged: allowed}\nmachines:\n  - id: M1\n    axes:\n      - {name: X, kind: linear, data: data/x.csv}\n      - {name: X1, kind: linear, data: data/x.rtl}\n      - {name: X2, kind: linear, data: data/x.rtl, conditions: {nde: {}}}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, err) = axcheck(&[
        "run",
        dir.join("campaign.yaml").to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-diagnose",
    ]);
    assert_eq!(code, 0, "{stdout}{err}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    let tests = json["axes"].as_array().unwrap();
    let by_axis = |a: &str| tests.iter().find(|t| t["axis"] == a).unwrap();
    let (csv, rtl, nde) = (by_axis("X"), by_axis("X1"), by_axis("X2"));
    // The same readings: the same parameters, to the last digit.
    assert_eq!(csv["parameters"], rtl["parameters"]);
    assert_eq!(rtl["recognised"]["layout"], "renishaw-rtl");
    assert_eq!(csv["recognised"]["layout"], "long-csv");
    let info = &rtl["recognised"]["file_info"];
    assert_eq!(info["machine"], "Mühle 3");
    assert_eq!(info["serial"], "SN-77");
    assert_eq!(info["operator"], "J. Smith");
    // 99.039005 and 99.049346 kPa: their mean 99.0441755 to 0.01 kPa; 46.924392 %RH to 0.1.
    assert_eq!(info["air_pressure_kpa"], 99.04);
    assert_eq!(info["air_humidity_pct"], 46.9);
    assert_eq!(info["expansion_um_per_m_c"], 8.0);
    // Only X2 asks for the correction; it takes the file's coefficient and its sensor's
    // mean temperature (20.203292 + 20.321342) / 2 = 20.262317 °C.
    assert!(rtl["nde"].is_null(), "{}", rtl["nde"]);
    assert_eq!(nde["nde"]["coefficient_um_per_m_c"], 8.0);
    let t = nde["nde"]["mean_temperature_c"].as_f64().unwrap();
    assert!((t - 20.262317).abs() < 1e-9, "{t}");
    assert_ne!(nde["parameters"], rtl["parameters"]);

    let report = pdf_text(&out.join("reports/M1/X1.pdf"));
    for words in [
        "Renishaw .rtl (linear)",
        "SN-77 (measurement file)",
        "J. Smith (measurement file)",
        "Mühle 3",
        "Hall B (measurement file)",
        "Taken from the measurement file",
        "air temperature, pressure and humidity, material temperatures",
    ] {
        assert!(
            report.contains(words),
            "{words} missing from the report:\n{report}"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn eval_names_the_renishaw_layout_and_what_it_assumed() {
    let table2 = measurement::read_file(&data_path("iso230-2_table2.csv"), None).unwrap();
    let dir = scratch("renishaw-eval");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("test.rtl");
    std::fs::write(&file, rtl(&table2.data)).unwrap();
    let (code, stdout, err) = axcheck(&["eval", file.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(stdout.contains("Renishaw .rtl (linear)"), "{stdout}");
    assert!(stdout.contains("10 runs read as 5 cycles"), "{stdout}");
    assert!(stdout.contains("Windows-1252"), "{stdout}");
    // --sheet names a workbook's sheet: refused for a Renishaw file.
    let (code, _, err) = axcheck(&["eval", file.to_str().unwrap(), "--sheet", "X"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("Renishaw"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
