//! Every kind of bad measurement file gets an error naming the file, line and what to change.
use axcheck::measurement;
use axcheck::simulate::SimulationFile as _;
use proptest::prelude::*;

fn error(text: &str) -> String {
    match measurement::read(text.as_bytes(), "bad.csv") {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(e) => e.to_string(),
    }
}

fn expect(text: &str, location: &str, words: &[&str]) {
    let e = error(text);
    assert!(
        e.starts_with(location),
        "`{e}` should start with `{location}`"
    );
    for w in words {
        assert!(e.contains(w), "`{e}` should contain `{w}`");
    }
}

const HEADER: &str = "target_mm,direction,run,deviation_um\n";

fn with_rows(rows: &str) -> String {
    format!("{HEADER}{rows}")
}

#[test]
fn unknown_column_suggests_the_right_name() {
    expect(
        "target_mm,direction,run,deviaton_um\n0,up,1,1\n",
        "bad.csv:1:25:",
        &[
            "unknown column `deviaton_um`",
            "did you mean `deviation_um`",
        ],
    );
    expect(
        "target_mm,direction,run,deviation_um,colour\n",
        "bad.csv:1:38:",
        &["unknown column `colour`"],
    );
}

#[test]
fn missing_unit() {
    expect(
        "target,direction,run,deviation_um\n",
        "bad.csv:1:1:",
        &["`target` has no unit", "target_mm"],
    );
    expect(
        "target_mm,direction,run,deviation\n",
        "bad.csv:1:25:",
        &["`deviation` has no unit", "deviation_um"],
    );
    expect(
        "# c\ntarget_mm,direction,run,deviation_um,temp_table\n",
        "bad.csv:2:38:",
        &["temp_table_c"],
    );
}

#[test]
fn missing_and_duplicate_columns() {
    expect(
        "target_mm,run,deviation_um\n",
        "bad.csv:1:",
        &["missing column `direction`"],
    );
    expect(
        "target_mm,direction,run,deviation_um,run\n",
        "bad.csv:1:38:",
        &["`run` appears twice"],
    );
    expect(
        "target_mm,direction,run,deviation_um,actual_mm\n",
        "bad.csv:1:",
        &["keep one"],
    );
    expect(
        "target_mm,direction,run,deviation_arcsec\n",
        "bad.csv:1:25:",
        &["looks like an angular test", "--test angular"],
    );
    expect(
        "target_deg,direction,run,deviation_um\n",
        "bad.csv:1:26:",
        &["an angle", "a length"],
    );
}

#[test]
fn values_that_are_not_numbers() {
    expect(
        &with_rows("0,up,1,1.0\n0,down,1,abc\n"),
        "bad.csv:3:10:",
        &["deviation_um", "expected a number, found `abc`"],
    );
    expect(
        &with_rows("0,up,1,NaN\n"),
        "bad.csv:2:8:",
        &["expected a finite number, found `NaN`"],
    );
    expect(&with_rows("0,up,1,inf\n"), "bad.csv:2:8:", &["finite"]);
    expect(
        &with_rows("x,up,1,1\n"),
        "bad.csv:2:1:",
        &["target_mm", "expected a number"],
    );
    expect(
        &with_rows("0,up,1\n"),
        "bad.csv:2:1:",
        &["expected 4 fields", "found 3"],
    );
}

#[test]
fn directions_and_runs() {
    expect(
        &with_rows("0,up,1,1\n0,sideways,1,2\n"),
        "bad.csv:3:3:",
        &["unknown direction `sideways`", "up/down"],
    );
    expect(
        &with_rows("0,up,0,1\n"),
        "bad.csv:2:6:",
        &["run number", "found `0`"],
    );
    expect(&with_rows("0,up,-2,1\n"), "bad.csv:2:6:", &["found `-2`"]);
    expect(&with_rows("0,up,1.5,1\n"), "bad.csv:2:6:", &["found `1.5`"]);
}

#[test]
fn duplicate_reading_names_both_lines() {
    expect(
        &with_rows("0,up,1,1\n0,down,1,2\n0,up,1,1.5\n"),
        "bad.csv:4:",
        &[
            "duplicate reading",
            "target 0 mm, direction up, run 1",
            "line 2",
        ],
    );
}

#[test]
fn one_direction_only() {
    expect(
        &with_rows("0,up,1,1\n0,down,1,2\n50,up,1,3\n"),
        "bad.csv:4:",
        &["target 50 mm has readings in direction up only"],
    );
}

#[test]
fn ragged_runs() {
    expect(
        &with_rows(
            "0,up,1,1\n0,down,1,2\n0,up,2,1\n0,down,2,2\n50,up,1,3\n50,down,1,3\n50,down,2,3\n",
        ),
        "bad.csv:6:",
        &[
            "ragged runs",
            "target 50 mm direction up has runs 1",
            "runs 1,2",
        ],
    );
}

#[test]
fn empty_header_only_and_garbage() {
    expect("", "bad.csv:", &["empty"]);
    expect("# only a comment\n\n", "bad.csv:", &["empty"]);
    expect(HEADER, "bad.csv:1:", &["no readings"]);
    let mut bytes = HEADER.as_bytes().to_vec();
    bytes.extend_from_slice(b"0,up,1,\xff\xfe\n");
    let e = measurement::read(bytes.as_slice(), "bad.csv")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("bad.csv:2:") && e.contains("UTF-8"), "{e}");
    let long = format!("{HEADER}{}\n", "1".repeat(70_000));
    let e = measurement::read(long.as_bytes(), "bad.csv")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("bad.csv:2:") && e.contains("longer than"),
        "{e}"
    );
}

#[test]
fn key_value_layout_errors() {
    let e = measurement::read(
        "UNIT=mm\nTGT_DATA[1]=1\nREF_DATA_FWD[1,1]=oops\n".as_bytes(),
        "k.dat",
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.starts_with("k.dat:3:19:") && e.contains("expected a finite number"),
        "{e}"
    );
    let e = measurement::read("UNIT=mm\nCYCLES=5\n".as_bytes(), "k.dat")
        .unwrap_err()
        .to_string();
    assert!(e.contains("no TGT_DATA"), "{e}");
    let e = measurement::read(
        "UNIT=mm\nTGT_DATA[1]=1\nREF_DATA_FWD[1,1]=1.001\n".as_bytes(),
        "k.dat",
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("direction up only"), "{e}");
    let e = measurement::read("UNIT=mm\nPOSITIONS=3\nTGT_DATA[1]=1\n".as_bytes(), "k.dat")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("k.dat:2:") && e.contains("POSITIONS=3"),
        "{e}"
    );
}

#[test]
fn direction_typos_get_a_suggestion() {
    expect(
        &with_rows("0,up,1,1\n0,dwon,1,2\n"),
        "bad.csv:3:3:",
        &["unknown direction `dwon` (did you mean `down`?)"],
    );
}

#[test]
fn implausible_values_are_refused() {
    expect(
        &with_rows("0,up,1,1e308\n"),
        "bad.csv:2:8:",
        &[
            "1e308 is not a plausible deviation",
            "check the column's unit",
        ],
    );
    let e = measurement::read(
        "target_mm,direction,run,actual_mm\n0,up,1,250\n".as_bytes(),
        "bad.csv",
    )
    .unwrap_err();
    assert!(
        e.to_string().contains("250 is not a plausible deviation"),
        "{e}"
    );
}

#[test]
fn key_value_targets_must_increase_with_their_index() {
    let e = measurement::read("TGT_DATA[1]=20\nTGT_DATA[2]=10\n".as_bytes(), "k.dat")
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("k.dat:2:1:") && e.contains("does not increase"),
        "{e}"
    );
    let e = measurement::read("TGT_DATA[1]=20\nTGT_DATA[2]=20\n".as_bytes(), "k.dat")
        .unwrap_err()
        .to_string();
    assert!(e.contains("TGT_DATA[2] = 20 does not increase"), "{e}");
}

#[test]
fn too_many_readings_stop_early() {
    let mut text = String::from(HEADER);
    for k in 0..=measurement::MAX_READINGS {
        text.push_str(&format!("{},up,1,0.5\n", k));
    }
    let e = measurement::read(text.as_bytes(), "big.csv")
        .unwrap_err()
        .to_string();
    assert!(e.contains("more than 100000 readings"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        let _ = measurement::read(bytes.as_slice(), "fuzz.csv");
    }

    #[test]
    fn mutated_valid_files_never_panic(pos in 0usize..2000, byte in any::<u8>(), kv in any::<bool>()) {
        let base: &[u8] = if kv {
            include_bytes!("../data/ess_bifrost_slit_axis1.dat")
        } else {
            include_bytes!("../data/iso230-2_table2.csv")
        };
        let mut bytes = base.to_vec();
        let k = pos % bytes.len();
        bytes[k] = byte;
        let _ = measurement::read(bytes.as_slice(), "fuzz");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// The campaign loader returns a campaign or an error for any mutation of a real
    /// campaign file, and never panics.
    #[test]
    fn mutated_campaigns_never_panic(pos in 0usize..20_000, byte in any::<u8>(), cut in any::<bool>()) {
        let text = include_str!("../../example-campaign/campaign.yaml");
        let mut bytes = text.as_bytes().to_vec();
        let k = pos % bytes.len();
        if cut {
            bytes.truncate(k);
        } else {
            bytes[k] = byte;
        }
        let text = String::from_utf8_lossy(&bytes);
        let _ = axcheck::campaign::Campaign::parse(&text, std::path::Path::new("fuzz.yaml"));
    }

    /// Simulation files too.
    #[test]
    fn mutated_simulations_never_panic(pos in 0usize..5_000, byte in any::<u8>(), cut in any::<bool>()) {
        let mut bytes = include_bytes!("../../example-campaign/models/hmc02-b.yaml").to_vec();
        let k = pos % bytes.len();
        if cut {
            bytes.truncate(k);
        } else {
            bytes[k] = byte;
        }
        let _ = axcheck::simulate::Simulation::from_yaml(&String::from_utf8_lossy(&bytes), "fuzz.yaml");
    }

    /// Specs too.
    #[test]
    fn mutated_specs_never_panic(pos in 0usize..5_000, byte in any::<u8>()) {
        let mut bytes = include_bytes!("../../specs/general.yaml").to_vec();
        let k = pos % bytes.len();
        bytes[k] = byte;
        let _ = axcheck::judge::Spec::from_yaml(&String::from_utf8_lossy(&bytes), "fuzz.yaml");
    }
}

/// The error of a campaign whose one axis is written `entry` (on line 5, from column 9).
fn axis_error(entry: &str) -> String {
    let text = format!("campaign: {{name: T}}\nmachines:\n  - id: M\n    axes:\n      - {entry}\n");
    let campaign = axcheck::campaign::Campaign::parse(&text, std::path::Path::new("c.yaml"))
        .unwrap_or_else(|e| panic!("{entry}: {e}"));
    let (_, axis) = campaign.axes().next().unwrap();
    axis.spec.clone().expect_err(entry).to_string()
}

/// Axis values of the wrong shape: each says what was expected and what the file has,
/// in the file's terms, at the value's line and column.
#[test]
fn campaign_axis_errors_in_the_users_words() {
    let base = "name: X, kind: linear, data: x.csv";
    let cases = [
        (
            format!("{{{base}, travel: [0, 1, 2, 3]}}"),
            "c.yaml:5:54: machines[0].axes[0].travel: expected a length (600) or its two ends ([0, 600]), got a list of 4 items",
        ),
        (
            format!("{{{base}, travel: long}}"),
            "c.yaml:5:54: machines[0].axes[0].travel: expected a length (600) or its two ends ([0, 600]), got the text `long`",
        ),
        (
            format!("{{{base}, travel: [0, x]}}"),
            "c.yaml:5:58: machines[0].axes[0].travel[1]: expected a number, got the text `x`",
        ),
        (
            "{name: X, kind: linar, data: x.csv}".into(),
            "c.yaml:5:25: machines[0].axes[0].kind: unknown kind `linar` (did you mean `linear`?); expected linear or rotary",
        ),
        (
            "{name: X, kind: 5, data: x.csv}".into(),
            "c.yaml:5:25: machines[0].axes[0].kind: expected linear or rotary, got the number 5",
        ),
        (
            "{name: X, data: x.csv}".into(),
            "c.yaml:5:9: machines[0].axes[0]: missing key `kind`",
        ),
        (
            "{name: [X], kind: linear, data: x.csv}".into(),
            "c.yaml:5:16: machines[0].axes[0].name: expected text, got a list of 1 item",
        ),
        (
            format!("{{{base}, measurement_travel: [1, 2, 3]}}"),
            "c.yaml:5:66: machines[0].axes[0].measurement_travel: expected [first, last], got a list of 3 items",
        ),
        (
            format!("{{{base}, measurement_travel: [a, 2]}}"),
            "c.yaml:5:67: machines[0].axes[0].measurement_travel[0]: expected a number, got the text `a`",
        ),
        (
            format!("{{{base}, tolerances: [1, 2]}}"),
            "c.yaml:5:58: machines[0].axes[0].tolerances: expected a mapping, got a list of 2 items",
        ),
        (
            format!("{{{base}, tolerances: {{A: abc}}}}"),
            "c.yaml:5:62: machines[0].axes[0].tolerances.A: expected a number, got the text `abc`",
        ),
        (
            format!("{{{base}, thermal_origin: far}}"),
            "c.yaml:5:62: machines[0].axes[0].thermal_origin: expected a number, got the text `far`",
        ),
        (
            format!("{{{base}, thermal_origin: .inf}}"),
            "c.yaml:5:62: machines[0].axes[0].thermal_origin: expected a position (mm or deg)",
        ),
        (
            format!("{{{base}, s_from_ranges: maybe}}"),
            "c.yaml:5:61: machines[0].axes[0].s_from_ranges: expected true or false, got the text `maybe`",
        ),
        (
            format!("{{{base}, standard: gost2784}}"),
            "c.yaml:5:56: machines[0].axes[0].standard: unknown standard `gost2784` (did you mean `gost27843`?); expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba",
        ),
        (
            format!("{{{base}, conditions: {{cycle: [step]}}}}"),
            "c.yaml:5:66: machines[0].axes[0].conditions.cycle: expected standard, step or pilgrim, got a list of 1 item",
        ),
        (
            format!("{{{base}, conditions: {{temperature_sensors: [{{name: s, kind: water}}]}}}}"),
            "c.yaml:5:97: machines[0].axes[0].conditions.temperature_sensors[0].kind: unknown kind `water`; expected material or air",
        ),
        (
            format!("{{{base}, conditions: {{instrument: laser}}}}"),
            "c.yaml:5:71: machines[0].axes[0].conditions.instrument: expected a mapping (key: value), got the text `laser`",
        ),
        (
            format!("{{{base}, conditions: {{feed_mm_per_min: 1, feed_deg_per_min: 2}}}}"),
            "c.yaml:5:58: machines[0].axes[0].conditions: `feed_mm_per_min` is given twice, under two of its spellings; keep one",
        ),
        (
            "{name: X, kind: linear, data: [x.csv, 7]}".into(),
            "c.yaml:5:47: machines[0].axes[0].data[1]: expected a file path, got the number 7",
        ),
        (
            "{name: X, kind: linear, data: []}".into(),
            "c.yaml:5:39: machines[0].axes[0].data: expected a file path, a list of paths, {dir: FOLDER, glob: PATTERN} or {file: BOOK, sheet: NAME} ({file: REPORT, reference: N} for an ecmc ISO 230 app file), got an empty list",
        ),
        (
            "{name: X, kind: linear, data: {dir: [d], glob: x}}".into(),
            "c.yaml:5:45: machines[0].axes[0].data.dir: expected a folder, got a list of 1 item",
        ),
        (
            "{name: X, kind: linear, data: {dir: d, glob: [x]}}".into(),
            "c.yaml:5:54: machines[0].axes[0].data.glob: expected a pattern such as \"*.csv\", got a list of 1 item",
        ),
        (
            "{name: X, kind: linear, data: {dir: d, glb: x}}".into(),
            "c.yaml:5:48: machines[0].axes[0].data.glb: unknown key `glb` (did you mean `glob`?); expected {dir: FOLDER, glob: PATTERN} or {file: BOOK, sheet: NAME}",
        ),
        (
            format!("{{{base}, 1: 2}}"),
            "c.yaml:5:9: machines[0].axes[0]: keys are names, got the number 1 as a key",
        ),
        (
            format!("{{{base}, tolerances: {{1: 2}}}}"),
            "c.yaml:5:58: machines[0].axes[0].tolerances: keys are names, got the number 1 as a key",
        ),
        (
            "[X, linear]".into(),
            "c.yaml:5:9: machines[0].axes[0]: expected a mapping (key: value), got a list of 2 items",
        ),
    ];
    for (entry, want) in cases {
        assert_eq!(axis_error(&entry), want, "{entry}");
    }
}

/// A campaign that cannot be read at all: the top level.
#[test]
fn campaign_top_level_errors_in_the_users_words() {
    let cases = [
        (
            "5: 1\ncampaign: {name: x}\nmachines: []\n",
            "c.yaml:1:1: unknown key `5`; expected campaign, machines",
        ),
        (
            "campaign: {name: x, 3: 4}\nmachines: []\n",
            "c.yaml:1:11: campaign: keys are names, got the number 3 as a key",
        ),
        (
            "campaign: {name: x, standard: vdi341}\nmachines: []\n",
            "c.yaml:1:31: campaign.standard: unknown standard `vdi341` (did you mean `vdi3441`?); expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba",
        ),
        (
            "campaign: {name: x, output: {pdf: maybe}}\nmachines: []\n",
            "c.yaml:1:35: campaign.output.pdf: expected true or false, got the text `maybe`",
        ),
        (
            "campaign: {name: x}\n",
            "c.yaml:1:1: missing the `machines:` list",
        ),
    ];
    for (text, want) in cases {
        let e = axcheck::campaign::Campaign::parse(text, std::path::Path::new("c.yaml"))
            .unwrap_err()
            .to_string();
        assert_eq!(e, want, "{text}");
    }
}

/// A machine's axes that are not a list fail the machine's one entry.
#[test]
fn campaign_machine_errors_in_the_users_words() {
    let text = "campaign: {name: T}\nmachines:\n  - {id: M, axes: 5}\n";
    let campaign =
        axcheck::campaign::Campaign::parse(text, std::path::Path::new("c.yaml")).unwrap();
    let (_, axis) = campaign.axes().next().unwrap();
    assert_eq!(
        axis.spec.as_ref().unwrap_err().to_string(),
        "c.yaml:3:19: machines[0].axes: expected a list of axes, got the number 5"
    );
}

fn spec_error(text: &str) -> String {
    axcheck::judge::Spec::from_yaml(text, "s.yaml")
        .unwrap_err()
        .to_string()
}

#[test]
fn spec_errors_in_the_users_words() {
    let cases = [
        ("", "s.yaml:1:1: missing key `name`"),
        (
            "- 1\n",
            "s.yaml:1:1: expected a mapping (key: value), got a list of 1 item",
        ),
        (
            "name: s\nlinear: 5\n",
            "s.yaml:2:9: linear: expected a list, got the number 5",
        ),
        (
            "name: s\nlinear: [{up_to_mm: x, tolerances: {A: 1}}]\n",
            "s.yaml:2:21: linear[0].up_to_mm: expected a number, got the text `x`",
        ),
        (
            "name: s\nlinear: [{up_to_mm: 1000, up_to_deg: 3, tolerances: {A: 1}}]\n",
            "s.yaml:2:10: linear[0]: `up_to` is given twice, under two of its spellings; keep one",
        ),
        (
            "name: s\nlinear: [{up_to_mm: 1000}]\n",
            "s.yaml:2:10: linear[0]: missing key `tolerances`",
        ),
        (
            "name: s\nlinear: [{up_to_mm: 1000, tolerances: {A: 1, A: 2}}]\n",
            "s.yaml:2:46: linear[0].tolerances: key `A` is given twice",
        ),
        (
            "name: s\nlinear: [{up_to_mm: 1000, tolerances: {A: 1}}\n",
            "s.yaml:3:1: did not find expected ',' or ']' (while parsing a flow sequence that starts at 2:9)",
        ),
    ];
    for (text, want) in cases {
        assert_eq!(spec_error(text), want, "{text}");
    }
}

fn simulation_error(text: &str) -> String {
    axcheck::simulate::Simulation::from_yaml(text, "m.yaml")
        .unwrap_err()
        .to_string()
}

/// Simulation files: keys spelled with the kind's units in every message, and every
/// error at its line and column (their key errors had none).
#[test]
fn simulation_errors_in_the_users_words() {
    let plan = "plan: {targets_mm: [0, 100]}\n";
    let cases = [
        (
            format!("kind: linar\n{plan}"),
            "m.yaml:1:7: kind: unknown kind `linar` (did you mean `linear`?); expected linear or rotary",
        ),
        (
            format!("kind: [1]\n{plan}"),
            "m.yaml:1:7: kind: expected linear or rotary, got a list of 1 item",
        ),
        (
            plan.to_string(),
            "m.yaml:1:1: missing `kind: linear` or `kind: rotary`",
        ),
        ("kind: linear\n".into(), "m.yaml:1:1: missing key `plan`"),
        (
            "- 1\n".into(),
            "m.yaml:1:1: expected a mapping with kind, model and plan, got a list of 1 item",
        ),
        (
            "kind: linear\nplan: {targets_mm: [0, 100], cycle: zigzag}\n".into(),
            "m.yaml:2:37: plan.cycle: unknown cycle `zigzag`; expected standard, step or pilgrim",
        ),
        (
            "kind: linear\nplan: {targets_mm: [0, 100], runs: -1}\n".into(),
            "m.yaml:2:36: plan.runs: expected a whole number ≥ 0, got the number -1",
        ),
        (
            "kind: linear\nplan: {targets_mm: 7}\n".into(),
            "m.yaml:2:20: plan.targets_mm: expected a list, got the number 7",
        ),
        (
            "kind: linear\nplan: {targets: [1, 2]}\n".into(),
            "m.yaml:2:17: plan.targets: expected a mapping (key: value), got a list of 2 items",
        ),
        (
            "kind: linear\nplan: {targets: {start_mm: 0, end_mm: 10}}\n".into(),
            "m.yaml:2:17: plan.targets: missing key `count`",
        ),
        (
            format!("kind: linear\nmodel: {{periodic: [{{amplitude_um: 1}}]}}\n{plan}"),
            "m.yaml:2:20: model.periodic[0]: missing key `pitch_mm`",
        ),
        (
            format!("kind: linear\nmodel: {{shape: [[0, 1, 2]]}}\n{plan}"),
            "m.yaml:2:17: model.shape[0]: expected a shorter list, got a list of 3 items",
        ),
        (
            format!(
                "kind: linear\nmodel: {{outliers: [{{run: 1, direction: 5, target: 1, size_um: 3}}]}}\n{plan}"
            ),
            "m.yaml:2:40: model.outliers[0].direction: expected up or down, got the number 5",
        ),
        (
            format!(
                "kind: linear\nmodel: {{outliers: [{{run: 1, direction: dwon, target: 1, size_um: 3}}]}}\n{plan}"
            ),
            "m.yaml:2:40: model.outliers[0].direction: unknown direction `dwon` (did you mean `down`?); expected up or down",
        ),
        (
            format!("kind: linear\nmodel: 5\n{plan}"),
            "m.yaml:2:8: model: expected a mapping (key: value), got the number 5",
        ),
        (
            format!("kind: linear\nseed: abc\n{plan}"),
            "m.yaml:2:7: seed: expected a whole number ≥ 0, got the text `abc`",
        ),
        (
            format!("kind: linear\nmodel: {{scale_ppm: 1, scale_um_per_m: 2}}\n{plan}"),
            "m.yaml:2:8: model: `scale_ppm` is given twice, under two of its spellings; keep one",
        ),
        (
            "kind: linear\nplan: {targets: {start_mm: 0, end_mm: 1000, count: 5001}, runs: 10}\n"
                .into(),
            "m.yaml:2:65: plan.runs: 10 runs × 5001 targets × 2 directions = 100020 readings; a measurement file holds at most 100000",
        ),
        (
            "kind: linear\nplan: {targets_mm: [0, 100], dwell_s: -1}\n".into(),
            "m.yaml:2:39: plan.dwell_s must be a finite number ≥ 0",
        ),
        (
            "kind: linear\nplan: {targets: {start_mm: 0, end_mm: 100, count: 3, jitter_mm: 80}}\n"
                .into(),
            "m.yaml:2:65: plan.targets.jitter_mm must be ≥ 0 and less than half the spacing (25.000)",
        ),
        (
            "kind: linear\nmodel: {run_offsets_um: [1, 2]}\nplan: {targets_mm: [0, 100], runs: 3}\n".into(),
            "m.yaml:2:25: model.run_offsets_um has 2 values but the plan has 3 runs",
        ),
        (
            format!("kind: linear\nmodel: {{1: 2}}\n{plan}"),
            "m.yaml:2:8: model: keys are names, got the number 1 as a key",
        ),
        (
            "kind: linear\nplan: {targets_mm: [0, 100]\n".into(),
            "m.yaml:3:1: did not find expected ',' or '}' (while parsing a flow mapping that starts at 2:7)",
        ),
    ];
    for (text, want) in cases {
        assert_eq!(simulation_error(&text), want, "{text}");
    }
}
