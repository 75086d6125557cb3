//! Options that two meanings shared (issue 41): `compensate --reference POS` is the table's
//! reference point, the ecmc position source is `--ecmc-reference N|rbv` (`--reference` on
//! `eval` and `diagnose`, which have no reference point, as before).

use crate::common::{axcheck, data_path};

/// LATHE-5's Z axis of the example campaign, 0…800 mm.
const LATHE_Z: &str = "example-campaign/data/lathe5-z.csv";

/// The ecmc ISO 230 app's raw points: the laser (the reference the app evaluated) and the
/// motor's readback.
fn ecmc_raw() -> String {
    data_path("ecmc_app/demo_iso230_raw.csv")
        .display()
        .to_string()
}

/// The value of FANUC parameter `number` in a set-up sheet (`  3620   = 7        …`).
fn parameter(sheet: &str, number: &str) -> i64 {
    let line = sheet
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{number} ")))
        .unwrap_or_else(|| panic!("no parameter {number}:\n{sheet}"));
    let value = line.split('=').nth(1).unwrap().split_whitespace().next();
    value.unwrap().parse().unwrap()
}

/// `--reference 490` from the command line anchors a FANUC table at 490 mm: 3620, the
/// reference position's number, is the grid point at 490 mm. The grid runs every
/// interval from the point numbered 3621 − 1 (the start, at the sheet's first position),
/// so 490 mm is number 3621 − 1 + (490 − start) / interval.
#[test]
fn compensate_reference_sets_the_fanuc_reference_point() {
    let (code, sheet, stderr) = axcheck(&[
        "compensate",
        LATHE_Z,
        "--controller",
        "fanuc",
        "--reference",
        "490",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        sheet.contains(", reference position 490.000 mm\n"),
        "{sheet}"
    );
    let axis = sheet.lines().find(|l| l.starts_with("Axis: ")).unwrap();
    // `Axis: linear, 10 points every 95.823 mm from 10.885 to 873.292 mm, …`: the mean
    // target spacing through 490 mm, which is 10.885 + 5 × 95.823, number 1 − 1 + 5.
    let words: Vec<&str> = axis.split_whitespace().collect();
    let interval: f64 = words[5].parse().unwrap();
    let start: f64 = words[8].parse().unwrap();
    let steps = (490.0 - start) / interval;
    assert!((steps - steps.round()).abs() < 1e-9, "{axis}");
    let want = parameter(&sheet, "3621") - 1 + steps.round() as i64;
    assert_eq!(want, 5, "{sheet}");
    assert_eq!(parameter(&sheet, "3620"), want, "{sheet}");
    assert!(
        sheet.contains(&format!(
            "3620   = {want:<8} point number of the reference position, 490.000 mm"
        )),
        "{sheet}"
    );
    // Without it the table is anchored at its first point: 3620 is another number.
    let (_, first, _) = axcheck(&["compensate", LATHE_Z, "--controller", "fanuc"]);
    assert_ne!(parameter(&first, "3620"), want, "{first}");
}

/// Both options on one command line: the readback of an ecmc file, a table zero at 0 mm.
#[test]
fn compensate_takes_the_ecmc_reference_and_the_reference_point_together() {
    let file = ecmc_raw();
    let run = |extra: &[&str]| {
        let mut args = vec!["compensate", &file, "--controller", "csv"];
        args.extend_from_slice(extra);
        let (code, table, stderr) = axcheck(&args);
        assert_eq!(code, 0, "{extra:?}: {stderr}");
        (table, stderr)
    };
    let (laser, _) = run(&[]);
    let (readback, _) = run(&["--ecmc-reference", "rbv"]);
    let (both, stderr) = run(&["--ecmc-reference", "rbv", "--reference", "0"]);
    assert_ne!(laser, readback);
    assert!(!stderr.contains("note"), "{stderr}");
    // The csv table's first row is 0 mm; zero ↑ correction there with --reference 0.
    let row = |table: &str| {
        table
            .lines()
            .find(|l| l.starts_with("0.0000,"))
            .unwrap_or_else(|| panic!("{table}"))
            .to_string()
    };
    assert!(!row(&readback).starts_with("0.0000,0.0000,"), "{readback}");
    assert!(row(&both).starts_with("0.0000,0.0000,"), "{both}");
}

/// `--reference 2` was the ecmc option's name on `compensate` too: on an ecmc app file
/// it is now the reference point, and a note says how to read reference 2.
#[test]
fn compensate_reference_on_an_ecmc_file_says_what_it_is() {
    let file = ecmc_raw();
    let (code, _, stderr) = axcheck(&[
        "compensate",
        &file,
        "--controller",
        "csv",
        "--reference",
        "2",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("axcheck: note: --reference 2 is the table's reference point (2 on the axis); the file's reference 2 is read with --ecmc-reference 2\n"),
        "{stderr}"
    );
    // A position no reference number could be: no note.
    let (_, _, stderr) = axcheck(&[
        "compensate",
        &file,
        "--controller",
        "csv",
        "--reference",
        "248.325",
    ]);
    assert!(!stderr.contains("note"), "{stderr}");
}

/// `eval` and `diagnose` read the readback by either name.
#[test]
fn eval_and_diagnose_take_the_ecmc_reference_by_both_names() {
    let file = ecmc_raw();
    for command in ["eval", "diagnose"] {
        let (code, new, stderr) = axcheck(&[command, &file, "--ecmc-reference", "rbv"]);
        assert_eq!(code, 0, "{command}: {stderr}");
        let (code, old, _) = axcheck(&[command, &file, "--reference", "rbv"]);
        assert_eq!(code, 0);
        assert_eq!(new, old, "{command}");
        let (_, laser, _) = axcheck(&[command, &file]);
        assert_ne!(new, laser, "{command}");
    }
    let (_, text, _) = axcheck(&["eval", &file, "--ecmc-reference", "rbv"]);
    assert!(
        text.contains("deviations from the readback (RBV)"),
        "{text}"
    );
}
