//! Every kind of bad measurement file gets an error naming the file, line and what to change.
use axcheck::measurement;
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
        "bad.csv:1:",
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

    /// Specs too.
    #[test]
    fn mutated_specs_never_panic(pos in 0usize..5_000, byte in any::<u8>()) {
        let mut bytes = include_bytes!("../../specs/general.yaml").to_vec();
        let k = pos % bytes.len();
        bytes[k] = byte;
        let _ = axcheck::judge::Spec::from_yaml(&String::from_utf8_lossy(&bytes), "fuzz.yaml");
    }
}
