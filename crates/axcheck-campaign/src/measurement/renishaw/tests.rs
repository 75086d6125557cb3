//! Constructed `.rtl` and `.rta` files (no real file is public; these follow the layout the
//! module documents) read to exactly the same test as the same readings in the long CSV.
// The whole file is test code: the attribute below marks it so for tests/it/architecture.rs.
use super::*;
#[cfg(test)]
use crate::evaluate::ParamKey;
use crate::evaluate::{StandardId, evaluate};
use crate::measurement::csv;
use crate::units::Direction;

/// A test written as a Renishaw file: `passes[r][i]` is the deviation of pass r + 1 at
/// target i + 1 in the file's unit (µm or mrad).
pub(super) struct Rtl {
    pub targets: Vec<f64>,
    pub passes: Vec<Vec<f64>>,
    pub(crate) eol: &'static str,
    pub(crate) per_line: usize,
    pub file_type: &'static str,
    /// USER-TEXT:: lines as bytes (Windows-1252 or UTF-8).
    pub(crate) user_text: Vec<Vec<u8>>,
    /// Sections between DEVIATIONS:: and EOF::, LF line ends.
    pub(crate) after_deviations: &'static str,
    /// Even runs listed from the last target down, as the laser software writes them.
    pub(crate) even_runs_reversed: bool,
}

/// ENVIRONMENT:: of an older file (the values quoted by a third-party reader from a real
/// file of 12 Dec 2016).
pub(super) const ENVIRONMENT: &str = "ENVIRONMENT::
Air temp   : 20.337280 20.384956 0
Air press  : 99.039005 99.049346 1
Air humid  : 46.954897 46.893887
Mat temp 1 : 20.203292 20.321342 0
Mat temp 2 : -10.000000 -10.000000 0
Mat temp 3 : -10.000000 -10.000000 0
Env factor : 0.31641096 0.31641067
Exp coeff  : 8.000000 8.000000 0
Date Time  : \"10:46 Dec 12 2016\" \"11:01 Dec 12 2016\"
Final Data : 1 0
";

/// EQUIPMENT:: of a newer file (content constructed: nobody documents it).
pub(super) const EQUIPMENT: &str = "EQUIPMENT::
Laser      : Renishaw XL-80 S/N 123456
Compensator: XC-80 S/N 654321
";

impl Rtl {
    /// The readings of `data` (a test read from the long CSV), passes up then down.
    pub fn of(data: &AxisData) -> Rtl {
        let mut passes = Vec::new();
        for j in 0..data.runs() {
            for d in Direction::BOTH {
                passes.push(
                    (0..data.target_count())
                        .map(|i| data.deviation(i, d, j))
                        .collect(),
                );
            }
        }
        Rtl {
            targets: data.targets.clone(),
            passes,
            eol: "\r\n",
            per_line: 5,
            file_type: "rtl",
            user_text: vec![b"Machine: M1".to_vec(), b"Axis: X".to_vec()],
            after_deviations: ENVIRONMENT,
            even_runs_reversed: true,
        }
    }

    /// The file's lines; `bytes` joins them.
    pub fn lines(&self) -> Vec<Vec<u8>> {
        let mut out: Vec<Vec<u8>> = Vec::new();
        let mut push = |s: &str| out.push(s.as_bytes().to_vec());
        push("HEADER::");
        push(&format!("File type  : {}", self.file_type));
        push("Owner      : Linear");
        push("Version no : V20.02.02");
        push("");
        push("TARGET DATA::");
        push("Filetype  : ISO");
        push(&format!("Target-count: {}", self.targets.len()));
        push("Targets :");
        for chunk in self.targets.chunks(self.per_line) {
            let values: Vec<String> = chunk.iter().map(|t| format!("{t:.6}")).collect();
            push(&format!("{} ", values.join("  ")));
        }
        push("Flags: 0 0 2 0");
        push("");
        push("USER-TEXT::");
        out.extend(self.user_text.iter().cloned());
        let mut push = |s: &str| out.push(s.as_bytes().to_vec());
        push("");
        push("RUNS::");
        push(&format!("Run-count:{}", self.passes.len()));
        push("");
        push("DEVIATIONS::");
        push("Run Target Data: ");
        for (r, pass) in self.passes.iter().enumerate() {
            let mut order: Vec<usize> = (0..pass.len()).collect();
            if r % 2 == 1 && self.even_runs_reversed {
                order.reverse();
            }
            for i in order {
                push(&format!("{:<7}{:<5}{:>10.3}", r + 1, i + 1, pass[i]));
            }
        }
        push("");
        for line in self.after_deviations.lines() {
            push(line);
        }
        push("");
        push("EOF::");
        out
    }

    pub fn bytes(&self) -> Vec<u8> {
        let mut out = self.lines().join(self.eol.as_bytes());
        out.extend(self.eol.as_bytes());
        out
    }
}

/// 1-based number of the first line of `bytes` that contains `needle`.
pub(super) fn line_of(bytes: &[u8], needle: &str) -> usize {
    String::from_utf8_lossy(bytes)
        .lines()
        .position(|l| l.contains(needle))
        .unwrap_or_else(|| panic!("no line with {needle:?}"))
        + 1
}

pub(super) fn table2() -> AxisData {
    let text = include_str!("../../../../../tests/data/iso230-2_table2.csv");
    csv::parse(text.as_bytes(), "iso230-2_table2.csv").unwrap()
}

/// Same targets, runs, readings in the same order with the same deviations, and the same
/// ISO 230-2 evaluation; only the line numbers differ.
fn assert_same_test(got: &AxisData, expected: &AxisData) {
    assert_eq!(got.kind, expected.kind);
    assert_eq!(got.targets, expected.targets);
    assert_eq!(got.run_labels, expected.run_labels);
    let strip = |d: &AxisData| {
        d.readings
            .iter()
            .map(|r| (r.target, r.direction, r.run, r.deviation))
            .collect::<Vec<_>>()
    };
    assert_eq!(strip(got), strip(expected));
    for i in 0..expected.target_count() {
        for d in Direction::BOTH {
            assert_eq!(got.deviations(i, d), expected.deviations(i, d));
        }
    }
    for standard in StandardId::ALL {
        assert_eq!(evaluate(got, standard), evaluate(expected, standard));
    }
}

#[test]
fn linear_rtl_with_crlf_windows_1252_and_environment_equals_the_long_csv() {
    let csv = table2();
    let mut rtl = Rtl::of(&csv);
    rtl.user_text = vec![
        b"Machine: M\xFChle 3".to_vec(),
        b"Serial No: 4711".to_vec(),
        b"Date: 12/12/2016 10:46:00".to_vec(),
        b"By: J. M\xFCller".to_vec(),
        b"Axis: X".to_vec(),
        b"Location: Halle 2, 20\xB0C".to_vec(),
        b"TITLE:".to_vec(),
    ];
    let bytes = rtl.bytes();
    assert!(looks_like(&bytes));
    let test = parse(&bytes, "table2.rtl").unwrap();
    assert_same_test(&test.data, &csv);
    assert!(!test.rotary);
    let e = evaluate(&test.data, StandardId::Iso230_2);
    assert!((e.value(ParamKey::A).unwrap() - 9.586).abs() < 0.001);

    let u = &test.user_text;
    assert_eq!(u.machine.as_deref(), Some("Mühle 3"));
    assert_eq!(u.serial.as_deref(), Some("4711"));
    assert_eq!(u.date.as_deref(), Some("12/12/2016 10:46:00"));
    assert_eq!(u.operator.as_deref(), Some("J. Müller"));
    assert_eq!(u.axis.as_deref(), Some("X"));
    assert_eq!(u.location.as_deref(), Some("Halle 2, 20°C"));
    assert_eq!(u.title, None);

    let env = test.environment.as_ref().unwrap();
    assert_eq!(env.air_temp_c.start, Some(20.33728));
    assert_eq!(env.air_temp_c.end, Some(20.384956));
    assert!((env.air_pressure_hpa.start.unwrap() - 990.39005).abs() < 1e-9);
    assert_eq!(env.air_humidity_percent.end, Some(46.893887));
    assert_eq!(env.material_temps_c.len(), 1);
    assert_eq!(env.material_temps_c[0].sensor, 1);
    assert!((env.material_temp_c().unwrap() - 20.262317).abs() < 1e-9);
    assert_eq!(env.expansion_ppm_per_c, Some(8.0));
    assert_eq!(env.date_time_start.as_deref(), Some("10:46 Dec 12 2016"));
    assert_eq!(env.date_time_end.as_deref(), Some("11:01 Dec 12 2016"));
    assert_eq!(env.other.len(), 2, "Env factor, Final Data");

    assert_eq!(test.header.file_type.as_deref(), Some("rtl"));
    assert_eq!(test.header.owner.as_deref(), Some("Linear"));
    assert_eq!(test.header.version.as_deref(), Some("V20.02.02"));
    assert_eq!(test.header.test_type.as_deref(), Some("ISO"));
    assert_eq!(test.header.flags.as_deref(), Some("0 0 2 0"));
    assert!(test.other_sections.is_empty());
    assert_eq!(
        test.notes,
        [
            "targets in mm, deviations in µm; 11 targets listed 5 per line; 10 runs read as 5 cycles, odd runs up (↑) and even runs down (↓)",
            "ENVIRONMENT:: states no units: read as °C, kPa (converted to hPa), % relative humidity and ppm/°C",
            "ENVIRONMENT:: Mat temp 2, 3 read −10 °C at start and end: taken as no sensor fitted",
            "the text is not UTF-8: read as Windows-1252 (letters in the user text may be wrong if the laser PC used another code page)",
        ]
    );
    // Line numbers point into the file.
    let first = &test.data.readings[0];
    assert_eq!(first.line, line_of(&bytes, "Run Target Data") + 1);
}

#[test]
fn linear_rtl_with_lf_utf8_and_equipment_equals_the_long_csv() {
    let csv = table2();
    let mut rtl = Rtl::of(&csv);
    rtl.eol = "\n";
    rtl.per_line = 4;
    rtl.after_deviations = EQUIPMENT;
    rtl.user_text = vec!["Machine: Mühle".as_bytes().to_vec()];
    let test = parse(&rtl.bytes(), "table2.rtl").unwrap();
    assert_same_test(&test.data, &csv);
    assert_eq!(test.user_text.machine.as_deref(), Some("Mühle"));
    assert_eq!(test.environment, None);
    assert_eq!(test.other_sections.len(), 1);
    assert_eq!(test.other_sections[0].name, "EQUIPMENT");
    assert_eq!(
        test.other_sections[0].lines[0],
        "Laser      : Renishaw XL-80 S/N 123456"
    );
    assert_eq!(
        test.notes,
        [
            "targets in mm, deviations in µm; 11 targets listed 4 per line; 10 runs read as 5 cycles, odd runs up (↑) and even runs down (↓)",
            &format!(
                "section EQUIPMENT:: (line {}, 2 lines) kept but not used",
                line_of(&rtl.bytes(), "EQUIPMENT::")
            ),
        ]
    );
}

/// Even runs listed in target order (not from the last target down) are read by their
/// target column: the same test, with a note. The readings stay in measurement order.
#[test]
fn deviations_are_read_by_target_column_not_line_order() {
    let csv = table2();
    let mut rtl = Rtl::of(&csv);
    rtl.even_runs_reversed = false;
    let test = parse(&rtl.bytes(), "table2.rtl").unwrap();
    assert_same_test(&test.data, &csv);
    assert!(test.notes.contains(
        &"run(s) 2,4,6,8,10 not listed in the order of the pass (odd runs from target 1, even runs from the last target down); read by their target column".to_string()
    ));
}

/// A rotary table, 5 targets, 3 cycles, deviations in mrad.
fn rotary_rta() -> Rtl {
    let passes = (0..6)
        .map(|r| {
            (0..5)
                .map(|i| f64::from(r * 5 + i) / 1000.0 - 0.012)
                .collect()
        })
        .collect();
    Rtl {
        targets: vec![0.0, 90.0, 180.0, 270.0, 360.0],
        passes,
        eol: "\r\n",
        per_line: 5,
        file_type: "rta",
        user_text: vec![b"Machine: Rundtisch".to_vec(), b"Axis: C".to_vec()],
        after_deviations: EQUIPMENT,
        even_runs_reversed: true,
    }
}

#[test]
fn rotary_rta_in_mrad_equals_the_long_csv_in_arcsec() {
    let rta = rotary_rta();
    let mut csv_text = String::from("target_deg,direction,run,deviation_arcsec\n");
    for (r, pass) in rta.passes.iter().enumerate() {
        let direction = if r % 2 == 0 { "up" } else { "down" };
        let mut order: Vec<usize> = (0..pass.len()).collect();
        if r % 2 == 1 {
            order.reverse();
        }
        for i in order {
            let mrad: f64 = format!("{:.3}", pass[i]).parse().unwrap();
            let arcsec = mrad * ARCSEC_PER_MRAD;
            let line = format!("{},{direction},{},{arcsec}\n", rta.targets[i], r / 2 + 1);
            csv_text.push_str(&line);
        }
    }
    let csv = csv::parse(csv_text.as_bytes(), "c.csv").unwrap();
    let test = parse(&rta.bytes(), "table-c.rta").unwrap();
    assert!(test.rotary);
    assert_eq!(test.data.kind, AxisKind::Rotary);
    assert_same_test(&test.data, &csv);
    // −0.012 mrad at target 1, run 1: −0.012 × 206.264806… = −2.4752″.
    assert!((test.data.deviation(0, Direction::Up, 0) - -2.475_177_675).abs() < 1e-9);
    assert!(test.notes[0].starts_with(
        "targets in degrees, deviations in mrad converted to arcsec (1 mrad = 206.265″;"
    ));
    assert!(
        test.notes[0].ends_with(
            "5 targets; 6 runs read as 3 cycles, odd runs up (↑) and even runs down (↓)"
        )
    );
}

#[test]
fn arcsec_per_mrad_is_180_times_3600_over_1000_pi() {
    assert!((ARCSEC_PER_MRAD - 206.264_806_247_096_36).abs() < 1e-12);
}

/// A list from the far end down: odd runs move down. Same test as the CSV.
#[test]
fn falling_target_list_makes_odd_runs_down() {
    let csv = table2();
    let mut rtl = Rtl::of(&csv);
    rtl.targets.reverse();
    let mut passes = Vec::new();
    for j in 0..csv.runs() {
        for d in [Direction::Down, Direction::Up] {
            passes.push(
                (0..csv.target_count())
                    .rev()
                    .map(|i| csv.deviation(i, d, j))
                    .collect(),
            );
        }
    }
    rtl.passes = passes;
    let test = parse(&rtl.bytes(), "table2.rtl").unwrap();
    assert!(test.notes[0].ends_with("odd runs down (↓) and even runs up (↑)"));
    for i in 0..csv.target_count() {
        for d in Direction::BOTH {
            assert_eq!(test.data.deviations(i, d), csv.deviations(i, d));
        }
    }
    assert_eq!(
        evaluate(&test.data, StandardId::Iso230_2),
        evaluate(&csv, StandardId::Iso230_2)
    );
}

#[test]
fn unknown_sections_are_kept_and_named() {
    let mut rtl = rotary_rta();
    rtl.after_deviations =
        "CALIBRATION::\nLaser cal : 2024-01-01\n\nENVIRONMENT::\nAir temp : 20.1 20.2 0\n";
    let bytes = rtl.bytes();
    let test = parse(&bytes, "c.rta").unwrap();
    assert_eq!(test.other_sections[0].name, "CALIBRATION");
    assert_eq!(test.other_sections[0].lines, ["Laser cal : 2024-01-01"]);
    let line = line_of(&bytes, "CALIBRATION::");
    assert!(test.notes.contains(&format!(
        "section CALIBRATION:: (line {line}, 1 lines) kept but not used"
    )));
    assert_eq!(test.environment.unwrap().air_temp_c.mean(), Some(20.15));
}

#[test]
fn linear_or_rotary_from_the_header_when_the_name_does_not_say() {
    let rta = rotary_rta().bytes();
    assert!(parse(&rta, "stdin").unwrap().rotary);
    let test = parse(&rta, "c.rtl").unwrap();
    assert!(!test.rotary);
    assert!(test.notes.contains(
        &"the file is named .rtl but HEADER says `File type : rta`; read as linear from the name".to_string()
    ));
}

#[test]
fn targets_on_the_caption_line_and_lines_after_eof() {
    let text = "HEADER::\nTARGET DATA::\nTarget-count: 2\nTargets : 0 10\nFlags: 0 0 2 0\nRUNS::\nRun-count: 2\nDEVIATIONS::\n1 1 0.5\n1 2 1.5\n2 2 -1\n2 1 -0.5\nEOF::\ntrailing junk\n";
    let test = parse(text.as_bytes(), "x.rtl").unwrap();
    assert_eq!(test.data.targets, [0.0, 10.0]);
    assert_eq!(test.data.deviations(1, Direction::Down), [-1.0]);
    assert!(
        test.notes
            .contains(&"1 lines after EOF:: ignored".to_string())
    );
    assert!(test.notes.contains(
        &"no `Run Target Data:` line; every line of DEVIATIONS:: read as a reading".to_string()
    ));
    assert!(test.notes.contains(&"no USER-TEXT:: section: machine, serial number, operator and axis not given by the file".to_string()));
}

#[test]
fn detection_is_by_content() {
    assert!(looks_like(b"HEADER::\r\nFile type  : rtl\r\n"));
    assert!(looks_like(b"\xEF\xBB\xBF\r\n  HEADER::  \r\n"));
    assert!(looks_like(b"HEADER::"));
    assert!(!looks_like(b"target_mm,direction,run,deviation_um\n"));
    assert!(!looks_like(b"MZ\x90\x00\x03\x00\x00\x00"));
    assert!(!looks_like(b""));
    assert!(!looks_like(b"HEADER:: x\n"));
}

#[test]
fn the_dispatch_recognises_it_and_reads_it_from_a_reader() {
    let bytes = rotary_rta().bytes();
    let read = crate::measurement::read(&bytes[..], "c.rta").unwrap();
    assert_eq!(read.data, parse(&bytes, "c.rta").unwrap().data);
    assert_eq!(
        read.recognised.layout,
        crate::measurement::Layout::RenishawRta
    );
}

/// No header field says which test a file holds (the module's doc says what was
/// checked): an angular test is refused from an `.rtl` and an `.rta` alike, naming the
/// file; a straightness test reads an `.rtl`'s µm as asked, with a note.
#[test]
fn the_test_type_is_not_recorded_so_angular_is_refused_and_straightness_noted() {
    use crate::geometry::TestKind;
    use crate::measurement::{ReadOptions, read_with};
    use crate::one_file::note_test;
    let angular = ReadOptions {
        angular: true,
        ..ReadOptions::default()
    };
    let rtl = Rtl::of(&table2()).bytes();
    for (bytes, name) in [(&rtl, "x.rtl"), (&rotary_rta().bytes(), "c.rta")] {
        let e = read_with(&bytes[..], name, &angular).unwrap_err();
        assert_eq!(e.location, Location::file(name));
        assert!(
            matches!(*e.kind, ReadErrorKind::RenishawTestNotRecorded { .. }),
            "{e}"
        );
        let says = format!(
            "{name}: an angular test of a linear axis is not read from a Renishaw file: its header records no test type"
        );
        assert!(e.to_string().starts_with(&says), "{e}");
    }
    let positioning = crate::measurement::read(&rtl[..], "x.rtl").unwrap();
    let mut read = positioning.clone();
    note_test(&mut read, TestKind::Positioning);
    assert_eq!(read, positioning);
    note_test(&mut read, TestKind::Straightness);
    assert_eq!(read.data, positioning.data);
    assert_eq!(
        read.recognised.notes.last().map(String::as_str),
        Some(
            "a Renishaw file records no test type: its deviations (µm at targets in mm) are taken as the straightness test asked for"
        )
    );
}
