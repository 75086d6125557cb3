//! The inspection history: `run --history` / `campaign.history` append one Parquet file per
//! campaign run; reruns replace it byte for byte; `read` and `series` give it back; readers
//! in another process never see a torn file.

use crate::common::{axcheck, copy_data, scratch};
use axcheck::history::{self, HistoryError, Record};
use serde_json::Value;
use std::path::{Path, PathBuf};

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A campaign in `dir`: M1 X with two tests (ISO 230-2 Table 2, then the GOST example),
/// M2 Z with one, and M3 Y whose file is missing (an error: no rows). `extra` goes into the
/// `campaign:` block.
fn campaign(dir: &Path, name: &str, date: Option<&str>, extra: &str) -> PathBuf {
    copy_data(dir, "iso230-2_table2.csv");
    copy_data(dir, "gost27843_example.csv");
    let date = date.map(|d| format!(", date: {d}")).unwrap_or_default();
    let path = dir.join("campaign.yaml");
    std::fs::write(
        &path,
        format!(
            "campaign: {{name: {name}{date}, spec: general{extra}}}
machines:
  - id: M1
    serial: S-1
    axes:
      - {{name: X, kind: linear, data: [data/iso230-2_table2.csv, data/gost27843_example.csv]}}
  - id: M2
    axes:
      - {{name: Z, kind: linear, data: data/gost27843_example.csv}}
  - id: M3
    axes:
      - {{name: Y, kind: linear, data: data/missing.csv}}
"
        ),
    )
    .unwrap();
    path
}

/// `axcheck run CAMPAIGN --out OUT --no-pdf EXTRA…`: (exit code, stdout + stderr).
fn run(campaign: &Path, out: &Path, extra: &[&str]) -> (i32, String) {
    let mut args = vec!["run", s(campaign), "--out", s(out), "--no-pdf"];
    args.extend_from_slice(extra);
    let (code, stdout, stderr) = axcheck(&args);
    (code, format!("{stdout}{stderr}"))
}

/// Every file under `dir`, relative, sorted, `/`-separated.
fn files(dir: &Path) -> Vec<String> {
    let mut files: Vec<String> = walkdir::WalkDir::new(dir)
        .into_iter()
        .map(Result::unwrap)
        .filter(|e| e.file_type().is_file())
        .map(|e| {
            let rel = e.path().strip_prefix(dir).unwrap();
            rel.to_string_lossy().replace('\\', "/")
        })
        .collect();
    files.sort();
    files
}

fn find<'a>(records: &'a [Record], machine: &str, test: u32, parameter: &str) -> &'a Record {
    records
        .iter()
        .find(|r| &*r.machine == machine && r.test == test && &*r.parameter == parameter)
        .unwrap_or_else(|| panic!("no row {machine} test {test} {parameter}"))
}

/// Every parameter of every test in results.json is one row, with its limit and U.
fn assert_rows_match_results(records: &[Record], results: &Value) {
    let mut expected = 0;
    for axis in results["axes"].as_array().unwrap() {
        let Some(parameters) = axis["parameters"].as_object() else {
            assert_eq!(axis["verdict"], "error");
            continue;
        };
        let machine = axis["machine"].as_str().unwrap();
        let test = u32::try_from(axis["test"].as_u64().unwrap()).unwrap();
        for (key, value) in parameters {
            let Some(value) = value.as_f64() else {
                continue;
            };
            expected += 1;
            let row = find(records, machine, test, key);
            assert_eq!(&*row.axis, axis["axis"].as_str().unwrap());
            assert_eq!(row.value, value, "{machine} {test} {key}");
            assert_eq!(&*row.verdict, axis["verdict"].as_str().unwrap());
            assert_eq!(&*row.unit, axis["unit"].as_str().unwrap());
            assert_eq!(&*row.standard, axis["standard"].as_str().unwrap());
            assert_eq!(row.limit, axis["limits"][key].as_f64(), "limit of {key}");
            assert_eq!(
                row.uncertainty,
                axis["uncertainty"]["U"][key].as_f64(),
                "U of {key}"
            );
        }
    }
    assert_eq!(records.len(), expected);
}

#[test]
fn a_run_appends_one_file_whose_rows_are_its_parameters_and_a_rerun_replaces_it() {
    let dir = scratch("history-run");
    let campaign = campaign(&dir, "Plant 2 annual inspection", Some("2026-11-20"), "");
    let (out, hist) = (dir.join("out"), dir.join("hist"));
    let (code, log) = run(&campaign, &out, &["--history", s(&hist)]);
    assert_eq!(code, 1, "{log}");
    let name = "year=2026/plant-2-annual-inspection_2026-11-20.parquet";
    assert!(log.contains("History: ") && log.contains(name), "{log}");
    assert_eq!(files(&hist), [name]);

    let records = history::read(&hist).unwrap();
    let results: Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    assert_rows_match_results(&records, &results);
    let e = find(&records, "M1", 1, "E");
    assert_eq!(&*e.campaign, "Plant 2 annual inspection");
    assert_eq!(e.date.to_string(), "2026-11-20");
    assert_eq!(e.serial.as_deref(), Some("S-1"));
    assert_eq!((&*e.kind, &*e.unit), ("linear", "um"));
    assert!(!e.effects.is_empty(), "diagnosed: effects or `none`");
    assert!(
        records.iter().all(|r| &*r.machine != "M3"),
        "errors have no rows"
    );
    assert!(find(&records, "M2", 1, "E").serial.is_none());

    let before = std::fs::read(hist.join(name)).unwrap();
    let (code, log) = run(&campaign, &out, &["--history", s(&hist)]);
    assert_eq!(code, 1, "{log}");
    assert_eq!(files(&hist), [name], "a rerun replaces, never duplicates");
    assert_eq!(
        std::fs::read(hist.join(name)).unwrap(),
        before,
        "same bytes"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn campaign_history_key_dates_in_year_folders_and_series() {
    let dir = scratch("history-key");
    let key = ", history: history";
    let out = dir.join("out");
    for date in ["2025-11-20", "2026-11-19"] {
        let campaign = campaign(&dir, "Plant 2", Some(date), key);
        let (code, log) = run(&campaign, &out, &["--no-diagnose"]);
        assert_eq!(code, 1, "{log}");
    }
    let hist = dir.join("history");
    assert_eq!(
        files(&hist),
        [
            "year=2025/plant-2_2025-11-20.parquet",
            "year=2026/plant-2_2026-11-19.parquet"
        ]
    );
    let records = history::read(&hist).unwrap();
    assert!(
        records.iter().all(|r| r.effects.is_empty()),
        "not diagnosed"
    );
    let series = history::series(&records);
    let e: Vec<_> = series.iter().filter(|s| s.parameter == "E").collect();
    assert_eq!(e.len(), 2, "M1 X and M2 Z");
    let (m1, m2) = (e[0], e[1]);
    assert_eq!((m1.machine.as_str(), m1.axis.as_str()), ("M1", "X"));
    assert_eq!(m1.serial.as_deref(), Some("S-1"));
    assert_eq!((m2.machine.as_str(), m2.axis.as_str()), ("M2", "Z"));
    let dates: Vec<String> = m1.points.iter().map(|p| p.date.to_string()).collect();
    assert_eq!(dates, ["2025-11-20", "2026-11-19"]);
    // Two tests of M1 X each date: the series follows test 1 (Table 2), not test 2.
    let test1 = find(&records, "M1", 1, "E");
    assert_ne!(test1.value, find(&records, "M1", 2, "E").value);
    assert!(m1.points.iter().all(|p| p.value == test1.value));
    assert_eq!(m1.limit, test1.limit);
    assert_eq!(m1.unit, "um");
    let mut sorted = series.clone();
    sorted.sort_by(|a, b| {
        (&a.machine, &a.serial, &a.axis, &a.parameter).cmp(&(
            &b.machine,
            &b.serial,
            &b.axis,
            &b.parameter,
        ))
    });
    assert_eq!(series, sorted, "sorted by machine, serial, axis, parameter");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_history_needs_the_campaigns_date_and_a_path_inside_its_folder() {
    let dir = scratch("history-date");
    let undated = campaign(&dir, "No date", None, "");
    let (out, hist) = (dir.join("out"), dir.join("hist"));
    let (code, log) = run(&undated, &out, &["--history", s(&hist)]);
    assert_eq!(code, 2, "{log}");
    let file = undated.display().to_string();
    assert!(
        log.contains(&format!("{file}: campaign.date: a history needs")),
        "{log}"
    );
    assert!(!out.exists() && !hist.exists(), "refused before anything");

    let away = campaign(&dir, "Away", Some("2026-11-20"), ", history: ../away");
    let (code, log) = run(&away, &out, &[]);
    assert_eq!(code, 2, "{log}");
    assert!(
        log.contains("campaign.history: path `../away` leaves the campaign's folder"),
        "{log}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

fn record(campaign: &str, schema_version: u32) -> Record {
    Record {
        schema_version,
        campaign: campaign.into(),
        date: chrono::NaiveDate::from_ymd_opt(2026, 11, 20).unwrap(),
        machine: "M1".into(),
        serial: None,
        axis: "X".into(),
        test: 1,
        kind: "linear".into(),
        standard: "iso230-2".into(),
        verdict: "pass".into(),
        parameter: "E".into(),
        unit: "um".into(),
        value: 4.5,
        limit: None,
        uncertainty: Some(1.2),
        effects: "none".into(),
    }
}

/// While a thread swaps the year folder of a history for a link to another folder (out
/// of the way, link in, link out, back), every read either gives the history's own rows,
/// misses the folder, or refuses a file it opened outside the history folder: the other
/// folder's rows (campaign `Away`) never come back.
#[cfg(unix)]
#[test]
fn a_year_folder_swapped_for_a_link_while_the_history_is_read_never_leaks() {
    let dir = scratch("history-race");
    let hist = dir.join("hist");
    let mine = history::append(&hist, &[record("Plant", 1)])
        .unwrap()
        .unwrap();
    let away = history::append(&dir.join("away"), &[record("Away", 1)])
        .unwrap()
        .unwrap();
    std::fs::rename(&away, away.with_file_name(mine.file_name().unwrap())).unwrap();
    let (year, aside) = (mine.parent().unwrap().to_path_buf(), dir.join("aside"));
    let away_year = away.parent().unwrap().to_path_buf();
    let swap = || {
        std::fs::rename(&year, &aside).unwrap();
        std::os::unix::fs::symlink(&away_year, &year).unwrap();
        std::fs::remove_file(&year).unwrap();
        std::fs::rename(&aside, &year).unwrap();
    };
    let (read, refused, missing) = crate::common::while_swapping(swap, || {
        // Until a few reads were refused at the open (without the check those are the reads
        // that leak), or for at most 10 s on a machine too busy to run both threads at once.
        let (mut read, mut refused, mut missing) = (0, 0, 0);
        let start = std::time::Instant::now();
        while refused < 5 && start.elapsed() < std::time::Duration::from_secs(10) {
            match history::read(&hist) {
                Ok(rows) => {
                    assert!(rows.iter().all(|r| &*r.campaign == "Plant"), "{rows:?}");
                    read += 1;
                }
                Err(e) if e.to_string().contains("nothing was read from it") => refused += 1,
                Err(e) => {
                    assert!(!e.to_string().contains("Away"), "{e}");
                    missing += 1;
                }
            }
        }
        (read, refused, missing)
    });
    eprintln!("swapped year folder: {read} read, {refused} refused when opened, {missing} missed");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn reading_checks_the_schema_and_skips_temporary_files() {
    let dir = scratch("history-schema");
    let hist = dir.join("hist");
    let written = history::append(&hist, &[record("Plant", 1)])
        .unwrap()
        .unwrap();
    let temp = written.with_file_name(".plant_2026-11-20.parquet.axcheck-tmp-4242");
    std::fs::write(&temp, b"PAR1 half a file").unwrap();
    assert_eq!(history::read(&hist).unwrap(), [record("Plant", 1)]);

    // Another campaign whose name gives the same file name is refused, not replaced.
    let clash = history::append(&hist, &[record("plant!", 1)]).unwrap_err();
    assert!(matches!(clash, HistoryError::NameClash { .. }), "{clash}");

    let newer = dir.join("newer");
    history::append(&newer, &[record("Plant", 2)]).unwrap();
    let e = history::read(&newer).unwrap_err().to_string();
    assert!(e.contains("schema_version 2 is unknown"), "{e}");
    assert!(e.contains("plant_2026-11-20.parquet"), "{e}");

    let broken = dir.join("broken");
    std::fs::create_dir_all(&broken).unwrap();
    std::fs::write(broken.join("junk.parquet"), b"not parquet").unwrap();
    let e = history::read(&broken).unwrap_err().to_string();
    assert!(
        e.contains("junk.parquet: not a readable Parquet file"),
        "{e}"
    );

    let foreign = dir.join("foreign");
    std::fs::create_dir_all(&foreign).unwrap();
    let mut df = polars::df!("schema_version" => [1u32], "campaign" => ["x"]).unwrap();
    let file = std::fs::File::create(foreign.join("other.parquet")).unwrap();
    polars::prelude::ParquetWriter::new(file)
        .finish(&mut df)
        .unwrap();
    let e = history::read(&foreign).unwrap_err().to_string();
    assert!(e.contains("other.parquet: no column `date`"), "{e}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// One process wrote the history; while another appends to it again and again (replacing
/// its own file and adding new dates), this process reads it: every read is complete.
#[test]
fn a_history_is_read_while_another_process_appends() {
    let dir = scratch("history-concurrent");
    let hist = dir.join("hist");
    let first = campaign(&dir, "Plant", Some("2024-11-20"), "");
    let (code, log) = run(
        &first,
        &dir.join("out"),
        &["--history", s(&hist), "--no-diagnose"],
    );
    assert_eq!(code, 1, "{log}");
    let rows_per_run = history::read(&hist).unwrap().len();
    assert!(rows_per_run > 0);

    // The appender: a shell loop of runs, dates 2025-01-01 … and reruns of each.
    let dates = ["2025-01-01", "2025-06-01", "2026-01-01", "2026-06-01"];
    let mut script = String::new();
    for date in dates {
        let campaign = dir.join(format!("campaign-{date}.yaml"));
        let text = std::fs::read_to_string(&first).unwrap();
        std::fs::write(&campaign, text.replace("2024-11-20", date)).unwrap();
        for _ in 0..2 {
            script.push_str(&format!(
                "'{}' run '{}' --out '{}' --no-pdf --no-diagnose --history '{}' >/dev/null 2>&1\n",
                env!("CARGO_BIN_EXE_axcheck"),
                s(&campaign),
                s(&dir.join("out2")),
                s(&hist)
            ));
        }
    }
    let mut appender = std::process::Command::new("sh")
        .arg("-c")
        .arg(script)
        .spawn()
        .unwrap();
    let mut reads = 0;
    loop {
        let done = appender.try_wait().unwrap().is_some();
        let records = history::read(&hist).unwrap_or_else(|e| panic!("torn read: {e}"));
        assert_eq!(records.len() % rows_per_run, 0, "whole runs only");
        reads += 1;
        if done {
            break;
        }
    }
    appender.wait().unwrap();
    let records = history::read(&hist).unwrap();
    assert_eq!(records.len(), rows_per_run * (1 + dates.len()));
    assert!(reads > 1, "read while appending");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A measurement, not a check: `AXCHECK_HISTORY=DIR cargo test --release history_read_time
/// -- --ignored --nocapture` prints the time to read a history and regroup it as series.
#[test]
#[ignore]
fn history_read_time() {
    let Some(dir) = std::env::var_os("AXCHECK_HISTORY") else {
        return;
    };
    let start = std::time::Instant::now();
    let records = history::read(Path::new(&dir)).unwrap();
    let read = start.elapsed().as_secs_f64();
    let series = history::series(&records);
    println!(
        "{} rows read in {read:.2} s; {} series in {:.2} s more",
        records.len(),
        series.len(),
        start.elapsed().as_secs_f64() - read
    );
}

/// `count` damaged copies of `bytes`, the same on every run: cut short, or 1 to 8 bytes
/// overwritten (a small linear congruential generator, so no seed can drift).
fn damaged_copies(bytes: &[u8], count: usize) -> Vec<Vec<u8>> {
    let mut state: u64 = 0x2026_1123;
    let mut next = |below: usize| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) as usize) % below
    };
    (0..count)
        .map(|k| {
            let mut copy = bytes.to_vec();
            if k % 3 == 0 {
                copy.truncate(next(bytes.len()));
            } else {
                for _ in 0..=next(8) {
                    let at = next(copy.len());
                    copy[at] = next(256) as u8;
                }
            }
            copy
        })
        .collect()
}

/// A history file of a few rows and the bytes of one damaged copy that polars' reader
/// panics on (found among the damaged copies; the test says so if none is any more).
fn history_file_and_a_damaged_copy(dir: &Path) -> (PathBuf, Vec<u8>) {
    let hist = dir.join("mutants");
    let rows: Vec<Record> = ["A", "E", "R", "B"]
        .iter()
        .map(|p| Record {
            parameter: (*p).into(),
            ..record("Other", 1)
        })
        .collect();
    let path = history::append(&hist, &rows).unwrap().unwrap();
    let good = std::fs::read(&path).unwrap();
    let (mut refused, mut panicked) = (0, None);
    let copies = damaged_copies(&good, 300);
    for copy in &copies {
        std::fs::write(&path, copy).unwrap();
        // A panic escaping here fails the test.
        let Err(e) = history::read(&hist) else {
            continue; // a changed value in a data page: Parquet pages carry no checksum here
        };
        let e = e.to_string();
        assert!(e.starts_with(&format!("{}: ", path.display())), "{e}");
        if e.contains("not a readable Parquet file") {
            assert!(e.contains("move it out of the history folder"), "{e}");
        }
        refused += 1;
        if e.contains("it is damaged (the Parquet reader failed: ") && panicked.is_none() {
            panicked = Some(copy.clone());
        }
    }
    assert!(refused >= 200, "{refused} of 300 damaged copies refused");
    let panicked = panicked.expect("no damaged copy makes polars panic now: pick other copies");
    (path, panicked)
}

/// A damaged file in a shared history is an error naming it, never a crash: `trend` stops
/// with exit 2 and says what to do; `run` still writes every output, its reports without
/// the history sections. A history that cannot be appended to fails the run only after
/// its outputs are written.
#[test]
fn a_damaged_history_file_is_named_and_loses_no_output() {
    let dir = scratch("history-damaged");
    let (_, damaged) = history_file_and_a_damaged_copy(&dir);
    let hist = dir.join("hist");
    let other = hist.join("year=2025/other_2025-11-20.parquet");
    std::fs::create_dir_all(other.parent().unwrap()).unwrap();
    std::fs::write(&other, &damaged).unwrap();

    let plant = campaign(&dir, "Plant", Some("2026-11-20"), "");
    let out = dir.join("out");
    let (code, log) = run(&plant, &out, &["--history", s(&hist), "--no-diagnose"]);
    assert_eq!(code, 1, "M3's file is missing: {log}");
    assert!(!log.contains("panicked"), "{log}");
    assert!(
        log.contains("no trends, as the history cannot be read: "),
        "{log}"
    );
    assert!(log.contains("other_2025-11-20.parquet"), "{log}");
    assert!(out.join("results.json").is_file(), "{log}");
    assert!(hist.join("year=2026/plant_2026-11-20.parquet").is_file());

    let (code, stdout, stderr) = axcheck(&["trend", s(&hist)]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let expected = format!(
        "{}: not a readable Parquet file of the history: it is damaged (the Parquet reader failed: ",
        other.display()
    );
    assert!(stderr.contains(&expected), "{stderr}");

    // A history whose year folder cannot be made: the outputs first, then exit 2.
    let blocked = dir.join("blocked");
    std::fs::create_dir_all(&blocked).unwrap();
    std::fs::write(blocked.join("year=2026"), b"a file where a folder goes").unwrap();
    let out2 = dir.join("out2");
    let (code, log) = run(&plant, &out2, &["--history", s(&blocked), "--no-diagnose"]);
    assert_eq!(code, 2, "{log}");
    assert!(
        log.contains(&format!(
            "the outputs are written, but the run is not in the history {}",
            blocked.display()
        )),
        "{log}"
    );
    assert!(out2.join("results.json").is_file(), "{log}");
    std::fs::remove_dir_all(&dir).unwrap();
}
