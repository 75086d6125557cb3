//! Issue 42's surface: bounded work on oversized input, what cannot be right refused, and
//! messages that name file, line and field and say what to do.

use crate::common::{axcheck, copy_data, run_campaign, scratch};
use std::path::Path;

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A campaign in `dir` with `axes` (YAML flow mappings, one a line) on machine `M`.
fn campaign(dir: &Path, head: &str, axes: &[&str]) -> std::path::PathBuf {
    let mut text = format!("campaign: {{{head}}}\nmachines:\n  - id: M\n    axes:\n");
    for axis in axes {
        text += &format!("      - {axis}\n");
    }
    let path = dir.join("c.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

const TABLE2: &str = "data: data/iso230-2_table2.csv";

#[test]
fn deep_brackets_are_refused_at_once() {
    let dir = scratch("deep-brackets");
    let path = dir.join("c.yaml");
    let text = format!("campaign: {{name: C}}\nmachines: {}\n", "[".repeat(200_000));
    std::fs::write(&path, text).unwrap();
    let start = std::time::Instant::now();
    let (code, _, stderr) = axcheck(&["check", s(&path)]);
    let took = start.elapsed();
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("c.yaml:2:139: the values nest deeper than 128 levels of `[` and `{`"),
        "{stderr}"
    );
    // The bound is 0.5 s (20 s before); ten times that under a loaded test run.
    assert!(took.as_secs_f64() < 5.0, "took {took:?}");
}

#[test]
fn jobs_are_capped_at_the_machines_threads() {
    let dir = scratch("jobs-cap");
    copy_data(&dir, "iso230-2_table2.csv");
    let path = campaign(
        &dir,
        "name: C",
        &[&format!("{{name: X, kind: linear, {TABLE2}}}")],
    );
    let (code, stdout, stderr) = axcheck(&["check", s(&path), "--jobs", "100000"]);
    assert_ne!(code, 2, "{stdout}{stderr}");
    let threads = std::thread::available_parallelism().unwrap().get();
    assert!(
        stderr.contains(&format!(
            "note: --jobs 100000 is more than the machine's {threads} threads; using {threads}"
        )),
        "{stderr}"
    );
}

#[test]
fn a_fleet_and_a_plan_are_bounded() {
    let dir = scratch("fleet-bound");
    let (code, _, stderr) = axcheck(&[
        "simulate",
        "--fleet",
        "99999999999",
        "--out",
        s(&dir.join("fleet")),
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("--fleet 99999999999: a fleet has 1 to 100000 axes"),
        "{stderr}"
    );
    assert!(!dir.join("fleet/campaign.yaml").exists());
    let (code, stdout, stderr) = axcheck(&["plan", "--kind", "linear", "--travel", "1e9"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stdout.is_empty());
    assert!(
        stderr.contains(
            "needs 4000001 targets under ISO 230-2:1997, more than the 10000 a plan holds"
        ),
        "{stderr}"
    );
}

/// Ten tests of one axis: each is predicted by the eight nearest in file order, not by
/// the nine others (the work and `results.json` grew with the square of the files).
#[test]
fn many_files_of_an_axis_are_predicted_by_their_neighbours() {
    let dir = scratch("many-files");
    let table = crate::common::data_path("iso230-2_table2.csv");
    for k in 0..10 {
        std::fs::copy(&table, dir.join(format!("data/t{k:02}.csv"))).unwrap();
    }
    let path = campaign(
        &dir,
        "name: C",
        &["{name: X, kind: linear, data: {dir: data, glob: \"t*.csv\"}}"],
    );
    let result = run_campaign(&path, true);
    assert_eq!(result.tests.len(), 10);
    let from = |k: usize| -> Vec<usize> {
        let e = result.tests[k].evaluated().expect("evaluated");
        e.out_of_test.iter().map(|o| o.from_test).collect()
    };
    assert_eq!(from(0), [2, 3, 4, 5, 6, 7, 8, 9]);
    assert_eq!(from(5), [2, 3, 4, 5, 7, 8, 9, 10]);
    assert_eq!(from(9), [2, 3, 4, 5, 6, 7, 8, 9]);
}

#[test]
fn empty_and_twice_given_axis_names_are_refused() {
    let dir = scratch("axis-names");
    copy_data(&dir, "iso230-2_table2.csv");
    let path = campaign(
        &dir,
        "name: C",
        &[&format!("{{name: \"\", kind: linear, {TABLE2}}}")],
    );
    let (code, stdout, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        (stdout.clone() + &stderr).contains(
            "c.yaml:5:16: machines[0].axes[0].name: the axis name is empty; name the axis as the machine does"
        ),
        "{stdout}{stderr}"
    );
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis, &axis]);
    let (code, _, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("c.yaml:6:16: machines[0].axes[1].name: axis `X` of machine `M` is named twice (axes[0] and axes[1])"),
        "{stderr}"
    );
}

#[test]
fn an_impossible_date_is_refused_by_check_and_run() {
    let dir = scratch("impossible-date");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C, date: 2026-02-30", &[&axis]);
    let want = "c.yaml:1:27: campaign.date: `2026-02-30` is not a day of the calendar: February 2026 has 28 days";
    let (code, _, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains(want), "{stderr}");
    let out = dir.join("out");
    let (code, _, stderr) = axcheck(&["run", s(&path), "--out", s(&out), "--no-pdf"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains(want), "{stderr}");
    assert!(!out.join("results.json").exists());
    let path = campaign(&dir, "name: C, date: 2028-02-29", &[&axis]);
    let (code, _, stderr) = axcheck(&["check", s(&path)]);
    assert_ne!(code, 2, "a leap day is a day: {stderr}");
}

#[test]
fn a_history_in_the_output_folder_is_refused() {
    let dir = scratch("history-in-out");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C, date: 2026-11-20", &[&axis]);
    let out = dir.join("out");
    for (history, how) in [
        (out.clone(), "is"),
        (out.join("history"), "is inside"),
        (dir.clone(), "holds"),
    ] {
        let (code, _, stderr) = axcheck(&[
            "run",
            s(&path),
            "--out",
            s(&out),
            "--history",
            s(&history),
            "--no-pdf",
        ]);
        assert_eq!(code, 2, "{stderr}");
        assert!(
            stderr.contains(&format!(
                "the history folder {} {how} the output folder {}",
                history.display(),
                out.display()
            )),
            "{stderr}"
        );
        assert!(!out.join("results.json").exists());
    }
}

#[test]
fn a_history_name_too_long_is_refused_before_the_evaluation() {
    let dir = scratch("history-long-name");
    copy_data(&dir, "iso230-2_table2.csv");
    let name = "Inspection ".repeat(30);
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, &format!("name: {name}, date: 2026-11-20"), &[&axis]);
    let out = dir.join("out");
    let args = ["run", s(&path), "--out", s(&out), "--no-pdf"];
    let (code, _, stderr) = axcheck(&[&args[..], &["--history", s(&dir.join("h"))]].concat());
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains(
            "campaign.name: the campaign's history file name would be 348 bytes, more than the 230"
        ),
        "{stderr}"
    );
    assert!(!out.join("results.json").exists(), "nothing is written");
}

#[test]
fn links_and_folders_named_as_inspections_stop_trend() {
    let dir = scratch("history-links");
    let history = dir.join("h");
    std::fs::create_dir_all(history.join("year=2026/inspection_2026-01-01.parquet")).unwrap();
    let (code, _, stderr) = axcheck(&["trend", s(&history)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("inspection_2026-01-01.parquet: it is a folder, named as an inspection"),
        "{stderr}"
    );
    std::fs::remove_dir(history.join("year=2026/inspection_2026-01-01.parquet")).unwrap();
    #[cfg(unix)]
    {
        let target = dir.join("elsewhere.parquet");
        std::fs::write(&target, b"PAR1").unwrap();
        let link = history.join("year=2026/c_2026-11-20.parquet");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        let (code, _, stderr) = axcheck(&["trend", s(&history)]);
        assert_eq!(code, 2, "{stderr}");
        assert!(
            stderr.contains("c_2026-11-20.parquet: it is a symbolic link, named as an inspection"),
            "{stderr}"
        );
    }
}

#[test]
fn a_campaign_with_a_byte_order_mark_is_read_and_utf16_is_named() {
    let dir = scratch("bom");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis]);
    let text = std::fs::read_to_string(&path).unwrap();
    std::fs::write(&path, format!("\u{feff}{text}")).unwrap();
    let (code, stdout, stderr) = axcheck(&["check", s(&path)]);
    assert_ne!(code, 2, "{stdout}{stderr}");
    assert!(stdout.contains("1 test"), "{stdout}{stderr}");
    let utf16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain(text.encode_utf16().flat_map(u16::to_le_bytes))
        .collect();
    std::fs::write(&path, utf16).unwrap();
    let (code, _, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("it is UTF-16 little-endian text; axcheck reads UTF-8: save it as UTF-8"),
        "{stderr}"
    );
    let csv = std::fs::read_to_string(crate::common::data_path("iso230-2_table2.csv")).unwrap();
    let data = dir.join("data/utf16.csv");
    let utf16: Vec<u8> = csv.encode_utf16().flat_map(u16::to_le_bytes).collect();
    std::fs::write(&data, utf16).unwrap();
    let (code, _, stderr) = axcheck(&["eval", s(&data)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("utf16.csv: the file is UTF-16 little-endian text; axcheck reads UTF-8"),
        "{stderr}"
    );
    assert!(stderr.len() < 400, "{stderr}");
}

#[test]
fn the_data_folder_message_names_machine_and_axis() {
    let dir = scratch("machine-and-axis");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: D, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis]);
    let (code, _, stderr) = axcheck(&["run", s(&path), "--out", s(&dir.join("data/out"))]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("of machine `M` axis `D`"), "{stderr}");
}

/// A folder that cannot be written is said so, with one OS error text (it was printed
/// twice, and the folder said to be "cannot lock").
#[cfg(target_os = "linux")]
#[test]
fn a_folder_that_cannot_be_written_is_said_so_once() {
    let out = Path::new("/sys/axcheck-surface-test");
    if std::fs::create_dir(out).is_ok() {
        let _ = std::fs::remove_dir(out);
        return; // /sys is writable here: nothing to test.
    }
    let dir = scratch("unwritable");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: X, kind: linear, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis]);
    let (code, _, stderr) = axcheck(&["run", s(&path), "--out", s(out), "--no-pdf"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("cannot write in /sys/axcheck-surface-test: "),
        "{stderr}"
    );
    assert!(
        stderr.contains("choose a folder you may write in"),
        "{stderr}"
    );
    assert_eq!(stderr.matches("(os error").count(), 1, "{stderr}");
}

#[test]
fn a_negative_pitch_is_refused_for_its_sign() {
    let data = crate::common::data_path("iso230-2_table2.csv");
    let (code, _, stderr) = axcheck(&["diagnose", s(&data), "--pitch", "-5"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(!stderr.contains("unexpected argument"), "{stderr}");
    assert!(
        stderr.contains("the pitch is -5; a pitch is a positive length"),
        "{stderr}"
    );
    let (code, _, stderr) = axcheck(&[
        "plan", "--kind", "linear", "--travel", "500", "--pitch", "-5",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("the pitch is -5"), "{stderr}");
}

#[test]
fn a_misspelt_spec_gets_its_line_and_a_suggestion() {
    let dir = scratch("spec-typo");
    copy_data(&dir, "iso230-2_table2.csv");
    let axis = format!("{{name: X, kind: linear, spec: precison, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis]);
    let (code, stdout, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let all = stdout + &stderr;
    assert!(
        all.contains("c.yaml:5: machines[0].axes[0].spec: spec `precison` not found (did you mean `precision`?)"),
        "{all}"
    );
}

/// Issue 42, item 8: a target beyond 1e6 mm (or °) is refused at its line by every reader
/// (they all build their data in one place), not evaluated into overflowing statistics.
#[test]
fn targets_beyond_the_bound_are_refused_at_their_line() {
    let dir = scratch("huge-target");
    let table2 = std::fs::read_to_string(crate::common::data_path("iso230-2_table2.csv")).unwrap();
    let long = dir.join("long.csv");
    std::fs::write(&long, table2.replacen("6.711,up,1", "1e300,up,1", 1)).unwrap();
    let (code, stdout, stderr) = axcheck(&["eval", s(&long)]);
    assert_eq!(code, 2, "{stdout}{stderr}");
    assert!(
        stderr.contains("long.csv:2: target 1e300 mm is not a plausible position (more than 1000000 mm from zero)"),
        "{stderr}"
    );
    let wide = dir.join("wide.csv");
    let text = "target_mm;up_1_um;down_1_um\n0;1;2\n500;1;2\n2000000;1;2\n";
    std::fs::write(&wide, text).unwrap();
    let (code, _, stderr) = axcheck(&["eval", s(&wide)]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("wide.csv:4: target 2000000 mm is not a plausible position"),
        "{stderr}"
    );
}

/// Issue 42, item 9: a spec without a band for the test's travel names its file and the
/// line of its band list, and says what to add.
#[test]
fn a_spec_without_a_band_names_its_file_and_line() {
    let dir = scratch("spec-band");
    copy_data(&dir, "iso230-2_table2.csv");
    std::fs::create_dir_all(dir.join("specs")).unwrap();
    let spec = "name: house\nlinear:\n  - {up_to: 500, tolerances: {A: 10}}\n";
    std::fs::write(dir.join("specs/house.yaml"), spec).unwrap();
    let axis = format!("{{name: X, kind: linear, spec: house, {TABLE2}}}");
    let path = campaign(&dir, "name: C", &[&axis]);
    let (code, stdout, stderr) = axcheck(&["check", s(&path)]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    let all = stdout + &stderr;
    let house = dir.join("specs").join("house.yaml");
    assert!(
        all.contains(&format!(
            "{}:2: spec `house` has no linear band for a measurement travel of 1744.209 mm (its last ends at 500 mm): add a `linear` band",
            house.display()
        )),
        "{all}"
    );
}
