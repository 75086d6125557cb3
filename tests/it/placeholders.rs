//! Placeholders fail safe (issue 41): a compensation file whose axis was not given names it
//! by something the control cannot load, never a valid axis (SINUMERIK's old `AX1` is its
//! machine axis 1, TwinCAT's old `kopf.achs_nr 1` its axis 1), and the console of
//! `compensate` and `run` says what to replace and that `--axis` or `compensation: {axis}`
//! fills it.

use crate::common::{axcheck, scratch};

const DATA: &str = "tests/data/iso230-2_table2.csv";

/// Whether `name` could be a SINUMERIK axis identifier: letters, digits and underscores,
/// starting with a letter or an underscore, at most 8 characters (SINUMERIK 840D
/// Programming Manual Fundamentals, 10.2004, p. 2-14: identifiers are letters, digits and
/// underscores; axis identifiers at most 8 characters; X1-style names are an address
/// letter and a number). Wider than the NC's rule, so a name it refuses is refused.
fn could_be_sinumerik_axis(name: &str) -> bool {
    let first = name.chars().next();
    (1..=8).contains(&name.len())
        && first.is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// The axis index of each `$AA_ENC_COMP…[…]` line: the last one inside the brackets.
fn siemens_axes(file: &str) -> Vec<&str> {
    file.lines()
        .filter(|l| l.starts_with("$AA_ENC_COMP"))
        .map(|l| {
            let inside = &l[l.find('[').unwrap() + 1..l.find(']').unwrap()];
            inside.rsplit(',').next().unwrap()
        })
        .collect()
}

/// Whether `name` is a file name a TNC accepts: letters, digits, `.`, `_`, `-` (TNC 640
/// User's Manual 1/2015, "File names"; the TNC 620 manual forbids `< > ?` by name).
fn tnc_file_name(name: &str) -> bool {
    !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-'))
}

/// `compensate DATA --controller NAME extra…`: the file (standard output) and standard
/// error.
fn compensate(controller: &str, extra: &[&str]) -> (String, String) {
    let mut args = vec!["compensate", DATA, "--controller", controller];
    args.extend_from_slice(extra);
    let (code, file, stderr) = axcheck(&args);
    assert_eq!(code, 0, "{controller} {extra:?}: {stderr}");
    (file, stderr)
}

#[test]
fn siemens_without_an_axis_names_none_the_nc_can_run() {
    let (file, stderr) = compensate("siemens-840d", &[]);
    let axes = siemens_axes(&file);
    // 11 points, then STEP, MIN, MAX and IS_MODULO.
    assert_eq!(axes.len(), 11 + 4, "{file}");
    for axis in &axes {
        assert!(
            !could_be_sinumerik_axis(axis),
            "`{axis}` names an axis:\n{file}"
        );
        assert_eq!(*axis, "<AXIS?>");
    }
    assert!(
        file.contains("; Replace <AXIS?> by the machine axis name (X1, Y1, ...) in every line before loading: the NC cannot run it as written.\n"),
        "{file}"
    );
    assert!(
        stderr.contains("axcheck: warning: the file names no machine axis: replace <AXIS?> in every line by the machine axis name (X1, Y1, ...; the NC cannot run the file as written), or give it with --axis (compensation: {axis} in a campaign)\n"),
        "{stderr}"
    );
    // --axis fills it, in every line, and nothing is left to replace.
    let (file, stderr) = compensate("siemens-840d", &["--axis", "X1"]);
    let axes = siemens_axes(&file);
    assert!(axes.iter().all(|a| *a == "X1"), "{file}");
    assert!(
        !file.contains("<AXIS?>") && !file.contains("Replace"),
        "{file}"
    );
    assert!(!stderr.contains("--axis"), "{stderr}");
}

#[test]
fn heidenhain_without_an_axis_names_no_table_the_control_holds() {
    let (file, stderr) = compensate("heidenhain", &[]);
    let name = file
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("BEGIN "))
        .and_then(|l| l.strip_suffix(" MM"))
        .unwrap_or_else(|| panic!("{file}"));
    assert!(!tnc_file_name(name), "`{name}` is a file name:\n{file}");
    assert_eq!(name, "<AXIS?>.COM");
    let header: Vec<&str> = file.lines().nth(1).unwrap().split_whitespace().collect();
    assert_eq!(header, ["NR", "AXISPOS", "<AXIS?>", "BACKLASH"]);
    assert!(
        stderr.contains("axcheck: warning: the table names no axis: replace <AXIS?> in its BEGIN line and its value column by the axis key from CfgAxes/axisList"),
        "{stderr}"
    );
    assert!(stderr.contains("or give the key with --axis"), "{stderr}");
    let (file, stderr) = compensate("heidenhain", &["--axis", "X"]);
    assert!(
        file.starts_with("BEGIN X.COM MM\nNR    AXISPOS       X    "),
        "{file}"
    );
    assert!(!stderr.contains("--axis"), "{stderr}");
}

/// The value of `kopf.achs_nr`.
fn achs_nr(list: &str) -> &str {
    let line = list.lines().find(|l| l.starts_with("kopf.achs_nr"));
    line.and_then(|l| l.split_whitespace().nth(1))
        .unwrap_or_else(|| panic!("{list}"))
}

#[test]
fn twincat_without_an_axis_number_writes_one_the_cnc_refuses() {
    let (list, stderr) = compensate("twincat", &[]);
    // P-COMP-00001: 0 < achs_nr.
    assert_eq!(achs_nr(&list), "0", "{list}");
    assert!(
        stderr.contains("axcheck: warning: the list names no axis: replace 0 in kopf.achs_nr by the axis' logical number (achs_kw_log_ax_nr in [STUP]; the CNC allows no 0), or give it with --axis (compensation: {axis} in a campaign)\n"),
        "{stderr}"
    );
    let (list, stderr) = compensate("twincat", &["--axis", "3"]);
    assert_eq!(achs_nr(&list), "3", "{list}");
    assert!(!list.contains("Replace"), "{list}");
    assert!(!stderr.contains("--axis"), "{stderr}");
    // The list names its axis by number: a name is refused, not dropped.
    let (code, _, stderr) =
        axcheck(&["compensate", DATA, "--controller", "twincat", "--axis", "X"]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("twincat: the axis `X`: a TwinCAT list names its axis by the logical axis number (kopf.achs_nr, 1 to 65534), not by name"),
        "{stderr}"
    );
}

/// With `-o` the note is in the summary, with `--json` among the warnings; a table built
/// on an unedited one (read back as the active table) still names no axis.
#[test]
fn the_note_is_printed_and_kept_through_an_active_table() {
    let dir = scratch("placeholders-out");
    for (controller, ext, placeholder) in [
        ("siemens-840d", "ini", "[0,0,<AXIS?>]"),
        ("heidenhain", "com", "BEGIN <AXIS?>.COM"),
        ("twincat", "lis", "kopf.achs_nr                 0\n"),
    ] {
        let first = dir.join(format!("first.{ext}"));
        let first = first.to_str().unwrap();
        let (code, stdout, stderr) =
            axcheck(&["compensate", DATA, "--controller", controller, "-o", first]);
        assert_eq!(code, 0, "{stderr}");
        assert!(stdout.contains("\nWarning: the "), "{stdout}");
        assert!(
            stdout.contains("--axis (compensation: {axis} in a campaign)"),
            "{stdout}"
        );
        let second = dir.join(format!("second.{ext}"));
        let (code, json, stderr) = axcheck(&[
            "compensate",
            DATA,
            "--controller",
            controller,
            "--active",
            first,
            "-o",
            second.to_str().unwrap(),
            "--json",
        ]);
        assert_eq!(code, 0, "{controller}: {stderr}");
        let json: serde_json::Value = serde_json::from_str(&json).unwrap();
        let keys: Vec<&str> = json["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["key"].as_str().unwrap())
            .collect();
        assert!(keys.contains(&"axis_placeholder"), "{controller}: {keys:?}");
        let written = std::fs::read_to_string(&second).unwrap();
        assert!(written.contains(placeholder), "{controller}:\n{written}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `run` names the axes whose tables still need their axis, once per controller's
/// words, and not those whose campaign names it.
#[test]
fn run_says_which_tables_need_their_axis() {
    let dir = scratch("placeholders-run");
    std::fs::copy(DATA, dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    std::fs::write(
        &campaign,
        "campaign: {name: axes, unjudged: allowed}\nmachines:\n  - id: M\n    controller: siemens-840d\n    axes:\n      - {name: X, kind: linear, data: data/x.csv}\n      - {name: Y, kind: linear, data: data/x.csv, compensation: {axis: Y1}}\n  - id: T\n    controller: twincat\n    axes:\n      - {name: Z, kind: linear, data: data/x.csv}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
        "--no-html",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains("\n  M X (axis_placeholder): the file names no machine axis: replace <AXIS?> in every line by the machine axis name (X1, Y1, ...; the NC cannot run the file as written), or give it with --axis (compensation: {axis} in a campaign)\n"),
        "{stdout}"
    );
    assert!(
        stdout.contains(
            "\n  T Z (axis_placeholder): the list names no axis: replace 0 in kopf.achs_nr"
        ),
        "{stdout}"
    );
    assert!(!stdout.contains("M Y (axis_placeholder)"), "{stdout}");
    let x = std::fs::read_to_string(out.join("compensation/M/X.ini")).unwrap();
    let y = std::fs::read_to_string(out.join("compensation/M/Y.ini")).unwrap();
    assert!(siemens_axes(&x).iter().all(|a| *a == "<AXIS?>"), "{x}");
    assert!(siemens_axes(&y).iter().all(|a| *a == "Y1"), "{y}");
    std::fs::remove_dir_all(&dir).unwrap();
}
