//! Broken and hostile `.rtl` files: each is refused with words that say what is wrong and
//! where.
// The whole file is test code: the attribute below marks it so for tests/it/architecture.rs.
#[cfg(test)]
use super::parse;
use super::tests::{ENVIRONMENT, Rtl, line_of, table2};
use crate::measurement::MAX_LINE_BYTES;

/// The lines of the ISO 230-2 Table 2 test as an `.rtl`.
fn lines() -> Vec<Vec<u8>> {
    Rtl::of(&table2()).lines()
}

fn join(lines: &[Vec<u8>]) -> Vec<u8> {
    lines.join(&b"\r\n"[..])
}

/// Index of the first line equal to `text`.
fn index(lines: &[Vec<u8>], text: &str) -> usize {
    lines
        .iter()
        .position(|l| l == text.as_bytes())
        .unwrap_or_else(|| panic!("no line {text:?}"))
}

/// The error for `bytes` read as `t.rtl`.
fn error(bytes: &[u8]) -> String {
    parse(bytes, "t.rtl").unwrap_err().to_string()
}

/// Deviation line of run `run`, target `target` as the builder writes it (prefix).
fn deviation_line(lines: &[Vec<u8>], run: usize, target: usize) -> usize {
    let prefix = format!("{run:<7}{target:<5}");
    lines
        .iter()
        .position(|l| l.starts_with(prefix.as_bytes()))
        .unwrap()
}

#[test]
fn no_eof_says_the_file_was_cut_short() {
    let mut l = lines();
    l.pop();
    let bytes = join(&l);
    let last = line_of(&bytes, "Final Data");
    assert_eq!(
        error(&bytes),
        format!(
            "t.rtl:{last}: the file ends inside `ENVIRONMENT::` without `EOF::`: it looks cut short; copy the file again from the laser PC"
        )
    );
}

#[test]
fn a_file_cut_mid_deviations_is_refused() {
    let mut l = lines();
    let cut = deviation_line(&l, 7, 3);
    l.truncate(cut);
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{cut}: the file ends inside `DEVIATIONS::` without `EOF::`: it looks cut short; copy the file again from the laser PC"
        )
    );
    // Cut, then closed by hand: the runs that are there are named.
    l.push(b"EOF::".to_vec());
    let runs = index(&l, "Run-count:10") + 1;
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{runs}: Run-count says 10 but DEVIATIONS:: holds runs 1,2,3,4,5,6,7 only (68 readings; expected 10 × 11 = 110)"
        )
    );
}

#[test]
fn target_count_that_disagrees_with_the_targets() {
    let mut l = lines();
    let k = index(&l, "Target-count: 11");
    l[k] = b"Target-count: 12".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: Target-count says 12 but 11 targets follow `Targets :`",
            k + 1
        )
    );
}

#[test]
fn a_run_missing_a_target() {
    let mut l = lines();
    let k = deviation_line(&l, 3, 7);
    l.remove(k);
    let last = index(&l, "ENVIRONMENT::") - 1; // the blank line before it
    assert_eq!(
        error(&join(&l)),
        format!("t.rtl:{last}: run 3 has no reading at target 7 (1055.89 mm)")
    );
}

#[test]
fn a_duplicated_run_and_target() {
    let mut l = lines();
    let first = deviation_line(&l, 2, 4);
    let k = deviation_line(&l, 2, 5);
    l[k] = l[first].clone();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: run 2 lists target 4 (525.668 mm) twice (first on line {})",
            k.max(first) + 1,
            k.min(first) + 1
        )
    );
}

#[test]
fn binary_junk_with_the_right_extension() {
    let junk = b"MZ\x90\x00\x03\x00\x00\x00\x04\x00\x00\x00\xFF\xFF\x00\x00\n\x00PE";
    assert_eq!(
        error(junk),
        "t.rtl:1: not a Renishaw .rtl/.rta file: line 1 is `MZ\\u{90}\\u{0}\\u{3}\\u{0}\\u{0}\\u{0}\\u{4}\\u{0}\\u{0}\\u{0}ÿÿ\\u{0}\\u{0}`; such a file starts with `HEADER::`, then `TARGET DATA::`, `RUNS::`, `DEVIATIONS::` … `EOF::`"
    );
}

#[test]
fn an_empty_file() {
    for empty in [&b""[..], b"\r\n  \r\n", b"\xEF\xBB\xBF"] {
        assert_eq!(
            error(empty),
            "t.rtl: not a Renishaw .rtl/.rta file: the file is empty; such a file starts with `HEADER::`, then `TARGET DATA::`, `RUNS::`, `DEVIATIONS::` … `EOF::`"
        );
    }
}

#[test]
fn a_huge_line() {
    let mut l = lines();
    let k = index(&l, "Machine: M1");
    l[k] = format!("Machine: {}", "x".repeat(MAX_LINE_BYTES)).into_bytes();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: the line is longer than {MAX_LINE_BYTES} bytes; a measurement file has short lines (is this the right file?)",
            k + 1
        )
    );
}

#[test]
fn a_non_numeric_deviation() {
    let mut l = lines();
    let k = deviation_line(&l, 2, 3);
    l[k] = b"2      3         1.2x".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}:18: run 2 target 3 (353.834 mm): the deviation `1.2x` is not a number; expected e.g. `-0.250`",
            k + 1
        )
    );
}

#[test]
fn a_run_count_larger_than_the_deviations_hold() {
    let mut l = lines();
    let k = index(&l, "Run-count:10");
    l[k] = b"Run-count:12".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: Run-count says 12 but DEVIATIONS:: holds runs 1,2,3,4,5,6,7,8,9,10 only (110 readings; expected 12 × 11 = 132)",
            k + 1
        )
    );
}

#[test]
fn a_run_count_smaller_than_the_deviations_hold() {
    let mut l = lines();
    let k = index(&l, "Run-count:10");
    l[k] = b"Run-count:8".to_vec();
    let first = deviation_line(&l, 9, 1);
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}:1: Run-count says 8 but this line is of run 9 (Run-count is on line {})",
            first + 1,
            k + 1
        )
    );
}

#[test]
fn an_odd_run_count() {
    let mut l = lines();
    let k = index(&l, "Run-count:10");
    l[k] = b"Run-count:9".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}:11: Run-count is 9: a bidirectional test has an even number of passes (2 per cycle, one out and one back), at least 2",
            k + 1
        )
    );
}

#[test]
fn a_missing_section() {
    let mut l = lines();
    let k = index(&l, "RUNS::");
    l.drain(k..k + 2);
    assert_eq!(
        error(&join(&l)),
        "t.rtl: no `RUNS::` section; expected `Run-count:N`"
    );
}

#[test]
fn a_section_twice() {
    let mut l = lines();
    let first = index(&l, "USER-TEXT::");
    let k = index(&l, "RUNS::");
    l.insert(k, b"USER-TEXT::".to_vec());
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: section `USER-TEXT::` appears twice (first on line {}); a Renishaw file has each section once",
            k + 1,
            first + 1
        )
    );
}

#[test]
fn a_dynamic_capture_is_named() {
    let rtx = b"HEADER::\r\nOwner : CARTO-Dynamic\r\nSample rate : 1000\r\nData:\r\n\x00\x01\x02\x03\xFF\r\nEOF::\r\n";
    assert_eq!(
        error(rtx),
        "t.rtl:4: this is a Renishaw dynamic capture (.rtx: a `Data:` block of samples over time), not a positioning test; export the test as .rtl (linear) or .rta (rotary)"
    );
}

#[test]
fn return_runs_all_zero_are_a_one_direction_test() {
    let data = table2();
    let mut rtl = Rtl::of(&data);
    for pass in rtl.passes.iter_mut().skip(1).step_by(2) {
        pass.iter_mut().for_each(|v| *v = 0.0);
    }
    let bytes = rtl.bytes();
    let first = line_of(&bytes, "2      11 ");
    assert_eq!(
        error(&bytes),
        format!(
            "t.rtl:{first}: every return run (2,4,6,8,10) reads 0 at every target (Flags: 0 0 2 0): this looks like a one-direction test; every target must be approached from both directions (ISO 230-2 clause 2.2, 4.3)"
        )
    );
    // One such run only: read, with a note.
    let mut rtl = Rtl::of(&data);
    rtl.passes[3].iter_mut().for_each(|v| *v = 0.0);
    let test = parse(&rtl.bytes(), "t.rtl").unwrap();
    assert!(test.notes.contains(
        &"run(s) 4 read exactly 0 at every target; check that they were measured".to_string()
    ));
}

#[test]
fn an_implausible_deviation() {
    let mut l = lines();
    let k = deviation_line(&l, 1, 2);
    l[k] = b"1      2    250000.000".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}:13: run 1 target 2 (175.077 mm): a deviation of 250000 µm is not plausible (more than 100000 µm); the file may be corrupt",
            k + 1
        )
    );
}

#[test]
fn targets_that_do_not_rise_or_fall() {
    let mut l = lines();
    let k = index(&l, "Targets :") + 1;
    l[k] = b"6.711000  175.077000  100.000000  525.668000  704.175000 ".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: target 3 (100 mm) comes after target 2 (175.077 mm) in a rising list; the targets must rise along the whole list",
            k + 1
        )
    );
    l[k] = b"6.711000  175.077000  175.077000  525.668000  704.175000 ".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: targets 2 and 3 are both 175.077 mm; every target of the list must differ",
            k + 1
        )
    );
}

#[test]
fn a_non_numeric_target() {
    let mut l = lines();
    let k = index(&l, "Targets :") + 2;
    l[k] = b"881.868000  1055.89O000 ".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}:13: `Targets`: expected target positions in mm such as `550.000000`, found `1055.89O000`",
            k + 1
        )
    );
}

#[test]
fn too_many_readings_are_refused_before_reading_them() {
    let runs = |count: &str| {
        format!(
            "HEADER::\nTARGET DATA::\nTarget-count: 2\nTargets :\n0 1\nRUNS::\nRun-count:{count}\nDEVIATIONS::\nEOF::\n"
        )
    };
    assert_eq!(
        error(runs("99999999999999999999").as_bytes()),
        "t.rtl:7:11: `Run-count`: expected the number of one-direction passes, a whole number such as 10, found `99999999999999999999`"
    );
    assert_eq!(
        error(runs(&(usize::MAX - 1).to_string()).as_bytes()),
        "t.rtl:7:11: the file holds more than 100000 readings; split it into one file per test"
    );
    let text = "HEADER::\nTARGET DATA::\nTarget-count: 50000\nTargets :\n0 1\nRUNS::\nRun-count:4\nDEVIATIONS::\nEOF::\n";
    assert_eq!(
        error(text.as_bytes()),
        "t.rtl:3: Target-count says 50000 but 2 targets follow `Targets :`"
    );
    let mut big = String::from("HEADER::\nTARGET DATA::\nTarget-count: 30000\nTargets :\n");
    for k in 0..30_000 {
        big.push_str(&format!("{k}\n"));
    }
    big.push_str("RUNS::\nRun-count:4\nDEVIATIONS::\nEOF::\n");
    let line = line_of(big.as_bytes(), "Run-count");
    assert_eq!(
        error(big.as_bytes()),
        format!(
            "t.rtl:{line}:11: the file holds more than 100000 readings; split it into one file per test"
        )
    );
}

#[test]
fn a_file_too_large() {
    let big = vec![b' '; super::MAX_FILE_BYTES + 1];
    assert_eq!(
        error(&big),
        format!(
            "t.rtl: the file holds more than {} bytes; a Renishaw positioning test is far smaller (is this the right file?)",
            super::MAX_FILE_BYTES
        )
    );
}

#[test]
fn a_deviation_line_of_the_wrong_shape() {
    let mut l = lines();
    let k = deviation_line(&l, 4, 6);
    l[k] = b"4      6".to_vec();
    assert_eq!(
        error(&join(&l)),
        format!(
            "t.rtl:{}: expected a deviation line `run target deviation` such as `1  3  -0.250`, found `4      6`",
            k + 1
        )
    );
}

#[test]
fn environment_values_that_make_no_sense_are_left_out_with_a_note() {
    let mut rtl = Rtl::of(&table2());
    rtl.after_deviations = "ENVIRONMENT::\nAir temp   : 2033.7 x 0\nAir press  : 990.4 990.5 1\n";
    let bytes = rtl.bytes();
    let test = parse(&bytes, "t.rtl").unwrap();
    let env = test.environment.unwrap();
    assert_eq!(env.air_temp_c.mean(), None);
    assert_eq!(env.air_pressure_hpa.mean(), None);
    let line = line_of(&bytes, "Air temp");
    assert!(test.notes.contains(&format!(
        "ENVIRONMENT:: `Air temp` start value `2033.7` (line {line}) is not a number between -20 and 60; left out"
    )));
    assert_eq!(ENVIRONMENT.lines().count(), 11);
}
