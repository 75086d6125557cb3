//! What `run` and `check` print for a plant: the first axes that need attention, not one
//! line per axis, and progress at every tenth of the campaign when stderr is not a
//! terminal (a CI log).

use crate::common::{axcheck, scratch};

/// A 200-axis fleet (seed 1) has 25 failing axes.
fn fleet() -> std::path::PathBuf {
    let dir = scratch("console-fleet");
    let (code, _, stderr) = axcheck(&[
        "simulate",
        "--fleet",
        "200",
        "--seed",
        "1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    dir
}

#[test]
fn a_fleet_prints_twenty_problems_and_a_count_of_the_rest() {
    let dir = fleet();
    let campaign = dir.join("campaign.yaml");
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--no-pdf",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stdout.contains("200 tests: 175 pass, 25 fail"), "{stdout}");
    let fails = stdout.lines().filter(|l| l.starts_with("  FAIL ")).count();
    assert_eq!(fails, 20, "{stdout}");
    assert!(
        stdout.contains("  … and 5 more (all in summary.md)"),
        "{stdout}"
    );
    let summary = std::fs::read_to_string(out.join("summary.md")).unwrap();
    let listed = summary.lines().filter(|l| l.contains("| **fail**")).count();
    assert_eq!(listed, 25, "summary.md lists every failing axis");
    // Not a terminal: a progress line at every tenth, not one per axis.
    let progress: Vec<&str> = stderr.lines().filter(|l| l.contains(" % (")).collect();
    assert_eq!(progress.len(), 10, "{stderr}");
    assert_eq!(
        progress[9],
        "axcheck: 100 % (200 of 200 axis entries evaluated)"
    );
    assert!(stderr.lines().count() <= 11, "{stderr}");

    let (code, stdout, stderr) = axcheck(&["check", campaign.to_str().unwrap(), "--progress"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stdout.contains("  … and 5 more (`axcheck run` lists them all in summary.md)"),
        "{stdout}"
    );
    let every: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("axcheck: ["))
        .collect();
    assert_eq!(every.len(), 200, "--progress: a line per test");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Progress counts axis entries: the example campaign has 31 entries and 33 tests (GANTRY-1
/// X has two data files; MILL-8's squareness is a test of no entry), and 100 % comes with
/// the last entry, not one test early.
#[test]
fn progress_counts_axes_when_an_axis_has_several_tests() {
    let (code, stdout, stderr) =
        axcheck(&["check", "example-campaign/campaign.yaml", "--jobs", "1"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stdout.contains("33 tests: 28 pass"), "{stdout}");
    let progress: Vec<&str> = stderr.lines().filter(|l| l.contains(" % (")).collect();
    assert_eq!(progress.len(), 10, "{stderr}");
    assert_eq!(
        progress[4],
        "axcheck: 50 % (16 of 31 axis entries evaluated)"
    );
    assert_eq!(
        progress[9],
        "axcheck: 100 % (31 of 31 axis entries evaluated)"
    );
}
