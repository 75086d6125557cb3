//! Compensation tables: the table cancels a known error, read back from its file it gives
//! what the prediction says, and the CLI writes it.

use crate::common::{axcheck, scratch};
use axcheck::compensate::{self, Table};
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{self, StandardId};
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use axcheck::units::AxisKind;

/// A scale error of 15 ppm, a slow sine (period 600 mm, 3 µm) and a reversal of 5 µm over
/// 1000 mm, 21 targets, scatter 0.3 µm.
const AXIS: &str = "kind: linear\nseed: 3\nmodel:\n  scale_um_per_m: 15\n  periodic: [{pitch_mm: 600, amplitude_um: 3, phase_deg: 20}]\n  reversal_um: 5\n  scatter_um: 0.3\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21, jitter_mm: 8}\n  runs: 5\n";

/// The generic CSV read back: position, correction ↑, correction ↓.
fn read_back(text: &str) -> Table {
    let mut table = Table {
        kind: AxisKind::Linear,
        positions: Vec::new(),
        up: Vec::new(),
        down: Vec::new(),
        reference: 0.0,
        modulo_deg: None,
        place: Default::default(),
        interpolation: Default::default(),
    };
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("position_mm,correction_up_um,correction_down_um")
    );
    for line in lines {
        let v: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        table.positions.push(v[0]);
        table.up.push(v[1]);
        table.down.push(v[2]);
    }
    table
}

#[test]
fn the_table_read_back_cancels_a_known_error_as_predicted() {
    let data = Simulation::from_yaml(AXIS, "axis.yaml").unwrap().run(3);
    let measured = evaluate::evaluate(&data, StandardId::Iso230_2);
    let e = measured.parameter(ParamKey::E).unwrap().value;
    assert!(e > 10.0, "the error is there to cancel: E = {e}");
    for interval in [None, Some(50.0)] {
        let settings = compensate::Settings {
            interval,
            reference: None,
            ..Default::default()
        };
        // Every controller holds and writes it (none refuses 21 targets or 20 mm steps).
        for c in compensate::controllers::CONTROLLERS {
            let held = compensate::held_table(*c, &data, &settings).unwrap();
            let file = c.write(&held, &[]).unwrap();
            assert!(file.lines().count() >= held.positions.len(), "{}", c.name());
        }
        let csv = compensate::controllers::find("csv").unwrap();
        let table = compensate::held_table(csv, &data, &settings).unwrap();
        let file = csv.write(&table, &[]).unwrap();
        let back = read_back(&file);
        let after = evaluate::evaluate(&compensate::apply(&back, &data), StandardId::Iso230_2);
        let e_after = after.parameter(ParamKey::E).unwrap().value;
        assert!(e_after < e / 4.0, "{interval:?}: E {e} -> {e_after}");
        // The prediction is what the file does (to its 4 decimals).
        let diagnosis = axcheck::diagnose::diagnose(&data, &Default::default());
        let compensation =
            compensate::compensation(csv, &data, StandardId::Iso230_2, &settings, &diagnosis);
        let predicted = compensation.outcome.unwrap().predicted;
        for p in &after.parameters {
            let q = predicted.parameter(p.def.key).unwrap().value;
            assert!(
                (p.value - q).abs() < 1e-3,
                "{interval:?} {}: {} vs {q}",
                p.key(),
                p.value
            );
        }
        // The repeatability is the floor: a table leaves R as it was.
        let r = |e: &evaluate::Evaluation| e.parameter(ParamKey::RUp).unwrap().value;
        assert!((r(&after) - r(&measured)).abs() < 1e-9);
    }
}

#[test]
fn the_cli_writes_the_table_and_refuses_an_unknown_controller() {
    let dir = scratch("compensate-cli");
    let out = dir.join("x.csv");
    let (code, stdout, stderr) = axcheck(&[
        "compensate",
        "tests/data/iso230-2_table2.csv",
        "--controller",
        "csv",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("E                       7.70               0.00"),
        "{stdout}"
    );
    let table = std::fs::read_to_string(&out).unwrap();
    // ISO 230-2 Table 2, target 1: x̄↑ = −1.60 µm, x̄↓ = 2.26 µm: corrections 1.6, −2.26.
    assert!(table.contains("\n6.7110,1.6000,-2.2600\n"), "{table}");
    // Nothing said of the compensation active during the test: the file, the console say so.
    let unknown = "the compensation active during the test was not stated: these values are this measurement's correction alone";
    assert!(
        table.starts_with(&format!("# Warning: {unknown}")),
        "{table}"
    );
    assert!(
        stdout.contains(&format!("\nWarning: {unknown}")),
        "{stdout}"
    );
    assert!(stdout.starts_with("csv table written to "), "{stdout}");
    assert!(
        stdout.contains("(absolute: this measurement's correction alone)\n"),
        "{stdout}"
    );
    // Stated: measured with nothing active.
    let (code, stdout, _) = axcheck(&[
        "compensate",
        "tests/data/iso230-2_table2.csv",
        "--controller",
        "csv",
        "--active",
        "none",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0);
    assert!(!stdout.contains("Warning"), "{stdout}");
    let table = std::fs::read_to_string(&out).unwrap();
    assert!(
        table.starts_with("# Absolute: measured with no compensation active (as stated); load it as the whole table.\nposition_mm,"),
        "{table}"
    );
    let (code, _, stderr) = axcheck(&[
        "compensate",
        "tests/data/iso230-2_table2.csv",
        "--controller",
        "fanuc-0i",
    ]);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("unknown controller `fanuc-0i`; known: csv, linuxcnc, siemens-840d, fanuc, heidenhain, twincat, ecmc, ecmc-9.6\n"),
        "{stderr}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A machine that names its controller gets a table per evaluated axis from `run`, and
/// results.json its path and the parameters predicted; a misspelt controller fails that
/// machine's axes with the names.
#[test]
fn a_campaign_machine_with_a_controller_gets_its_tables() {
    let dir = scratch("compensate-campaign");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    let write = |controller: &str| {
        std::fs::write(
            &campaign,
            format!("campaign: {{name: comp, unjudged: allowed}}\nmachines:\n  - id: M\n    controller: {controller}\n    axes:\n      - {{name: X, kind: linear, data: data/x.csv}}\n"),
        )
        .unwrap();
    };
    write("csv");
    let out = dir.join("out");
    let run = [
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ];
    let (code, stdout, stderr) = axcheck(&run);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let table = std::fs::read_to_string(out.join("compensation/M/X.csv")).unwrap();
    assert!(table.contains("\n6.7110,1.6000,-2.2600\n"), "{table}");
    let json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("results.json")).unwrap()).unwrap();
    let c = &json["axes"][0]["compensation"];
    assert_eq!(c["controller"], "csv");
    assert_eq!(c["file"], "compensation/M/X.csv");
    // On the measured targets the table cancels every mean: E and B go to 0; the
    // unidirectional repeatabilities stay (R itself loses the reversal it held).
    let predicted = &c["predicted"]["parameters"];
    assert!(predicted["E"].as_f64().unwrap().abs() < 1e-9);
    assert!(predicted["B"].as_f64().unwrap().abs() < 1e-9);
    let measured = &json["axes"][0]["parameters"];
    assert_eq!(predicted["R_up"], measured["R_up"]);
    assert!(predicted["R"].as_f64().unwrap() < measured["R"].as_f64().unwrap());

    write("cvs");
    let (code, stdout, _) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        stdout.contains("machines[0].controller: unknown controller `cvs` (did you mean `csv`?)"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// When not to compensate: each simulated axis carries one thing a static table cannot
/// fix or would bake in, and gets that warning and no other; a clean axis gets none.
#[test]
fn the_diagnosis_warns_when_a_table_will_not_hold() {
    use axcheck::diagnose::{Options, diagnose};
    let cases = [
        ("warn-drift.yaml", None, vec!["time_effect"]),
        ("warn-single-run.yaml", None, vec!["single_run"]),
        ("warn-outlier.yaml", None, vec!["outliers"]),
        // A 40 mm period: 20 mm between points cannot follow it; 5 mm can.
        ("warn-periodic.yaml", Some(20.0), vec!["aliased_periodic"]),
        ("warn-periodic.yaml", Some(5.0), vec![]),
    ];
    let csv = compensate::controllers::find("csv").unwrap();
    for (file, interval, expected) in cases {
        let text = std::fs::read_to_string(format!("tests/data/compensation/{file}")).unwrap();
        let data = Simulation::from_yaml(&text, file).unwrap().run(5);
        let diagnosis = diagnose(&data, &Options::default());
        let settings = compensate::Settings {
            interval,
            active: Some(compensate::Active::default()),
            ..Default::default()
        };
        let c = compensate::compensation(csv, &data, StandardId::Iso230_2, &settings, &diagnosis);
        let keys: Vec<&str> = c.warnings.iter().map(|w| w.key).collect();
        assert_eq!(keys, expected, "{file} {interval:?}: {:?}", c.warnings);
    }
    // A declared pitch of 5 mm cannot be followed by points 20 mm apart, found or not.
    let data = Simulation::from_yaml(AXIS, "axis.yaml").unwrap().run(3);
    let settings = compensate::Settings {
        interval: Some(20.0),
        pitch: Some(5.0),
        active: Some(compensate::Active::default()),
        ..Default::default()
    };
    let diagnosis = diagnose(&data, &Options::default());
    let c = compensate::compensation(csv, &data, StandardId::Iso230_2, &settings, &diagnosis);
    assert_eq!(c.warnings.len(), 1, "{:?}", c.warnings);
    assert!(c.warnings[0].message.starts_with(
        "the declared pitch 5.000 mm is shorter than four table intervals (80.000 mm)"
    ));
}

/// An axis's `compensation: {interval, reference}` sets its table's grid: every 20 mm
/// through 0, zero ↑ correction at 0; a misspelt key is named with the right one.
#[test]
fn a_campaign_axis_sets_its_table_grid() {
    let dir = scratch("compensate-grid");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    let write = |keys: &str| {
        std::fs::write(
            &campaign,
            format!("campaign: {{name: comp, unjudged: allowed}}\nmachines:\n  - id: M\n    controller: linuxcnc\n    axes:\n      - {{name: X, kind: linear, data: data/x.csv, compensation: {{{keys}}}}}\n"),
        )
        .unwrap();
    };
    write("interval: 20, reference: 0");
    let out = dir.join("out");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains(", compensation/MACHINE/AXIS.*"), "{stdout}");
    let table = std::fs::read_to_string(out.join("compensation/M/X.txt")).unwrap();
    let first: Vec<&str> = table.lines().take(2).collect();
    // Table 2's targets run from 6.711 mm: the grid starts at 0 (at or before the first
    // target) and the ↑ trim is 0 there; ↓ keeps the reversal −(x̄↓ − x̄↑) = −3.86 µm,
    // written as the actual position 0 − (−0.00386) mm (type 0).
    assert_eq!(first[0], "0.000000 0.0000000 0.0038600");
    assert!(first[1].starts_with("20.000000 "), "{table}");
    assert!(
        stdout.contains("  M X: COMP_FILE_TYPE = 0: nominal, forward actual and reverse actual position (mm); LinuxCNC corrects by nominal − actual. In the joint's `[JOINT_n]` section of the INI: `COMP_FILE = compensation/MACHINE/AXIS.txt` and `COMP_FILE_TYPE = 0`;"),
        "{stdout}"
    );
    // Asked for type 1, the trims themselves.
    write("interval: 20, reference: 0, comp_file_type: 1");
    let (code, stdout, stderr) = axcheck(&[
        "run",
        campaign.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--no-pdf",
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("  M X: COMP_FILE_TYPE = 1: "), "{stdout}");
    let table = std::fs::read_to_string(out.join("compensation/M/X.txt")).unwrap();
    assert!(
        table.starts_with("0.000000 0.0000000 -0.0038600\n"),
        "{table}"
    );
    write("interval: 20, refrence: 0");
    let (code, stdout, _) = axcheck(&["check", campaign.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        stdout
            .contains("compensation.refrence: unknown key `refrence` (did you mean `reference`?)"),
        "{stdout}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A rotary axis measured over three turns (0…1080° every 40°): every controller with
/// modulo tables gets one revolution, 0…360° every 40°, the ends one value, the modulo
/// flag in its file; the others get the whole travel. The table looked up at 1000° is the
/// one at 280°.
#[test]
fn a_rotary_axis_over_a_turn_gets_a_modulo_table() {
    let data = axcheck::measurement::read_file(
        std::path::Path::new("tests/data/compensation/rotary-three-turns.csv"),
        None,
    )
    .unwrap()
    .data;
    assert_eq!(data.measurement_travel(), (0.0, 1080.0));
    let flags = [
        ("siemens-840d", "$AA_ENC_COMP_IS_MODULO[0,<AXIS?>]=1"),
        ("fanuc", "3625   = 360000"),
        ("heidenhain", "\n9     +360.0000 "),
        ("twincat", "kw.ssfk.modulo               1"),
        (
            "ecmc",
            "Cfg.SetAxisEncLookupTableRange(${ECMC_AXIS_NO},360)",
        ),
        (
            "ecmc-9.6",
            "Cfg.SetAxisEncLookupTableRange(${ECMC_AXIS_NO},360)",
        ),
    ];
    for c in compensate::controllers::CONTROLLERS {
        let table = compensate::held_table(*c, &data, &Default::default()).unwrap();
        let file = c.write(&table, &[]).unwrap();
        let flag = flags.iter().find(|(name, _)| *name == c.name());
        if table.modulo_deg.is_none() {
            assert!(flag.is_none(), "{} should wrap", c.name());
            assert_eq!(table.positions.last(), Some(&1080.0), "{}", c.name());
            continue;
        }
        let (_, flag) = flag.unwrap_or_else(|| panic!("{} wraps", c.name()));
        assert!(file.contains(flag), "{}:\n{file}", c.name());
        let expected: Vec<f64> = (0..=9).map(|k| k as f64 * 40.0).collect();
        assert_eq!(table.positions, expected, "{}", c.name());
        assert_eq!(table.up[0], table.up[9], "{}", c.name());
        assert_eq!(table.down[0], table.down[9], "{}", c.name());
        let at = |p| table.correction(p, axcheck::units::Direction::Up);
        assert_eq!(at(1000.0), at(280.0), "{}", c.name());
    }
}

/// A LinuxCNC file is of type 0 unless type 1 is asked for (`--comp-file-type`,
/// `compensation: {comp_file_type}`), and says so after its points (never before: the
/// loader would stop there and load nothing), as does the console with the INI lines;
/// a rotary joint's file and console say that the lookup does not wrap. The type is
/// LinuxCNC's alone.
#[test]
fn linuxcnc_files_state_their_type_and_ini_lines() {
    let dir = scratch("linuxcnc-type");
    let out = dir.join("x.txt");
    let out_arg = out.to_str().unwrap();
    let data = "tests/data/iso230-2_table2.csv";
    let run = |extra: &[&str]| {
        let mut args = vec![
            "compensate",
            data,
            "--controller",
            "linuxcnc",
            "-o",
            out_arg,
        ];
        args.extend(extra);
        let (code, stdout, stderr) = axcheck(&args);
        assert_eq!(code, 0, "{stdout}{stderr}");
        (stdout, std::fs::read_to_string(&out).unwrap())
    };
    let (stdout, file) = run(&[]);
    // Table 2's first target 6.711 mm: x̄↑ = −1.6 µm, x̄↓ = 2.26 µm (the means of its five
    // runs), trims 0.0016 and −0.00226 mm: actual positions 6.711 − 0.0016 and
    // 6.711 + 0.00226 mm in type 0.
    assert!(file.starts_with("6.711000 6.7094000 6.7132600\n"), "{file}");
    let points = file.lines().take_while(|l| !l.starts_with('#')).count();
    let notes: Vec<&str> = file.lines().skip(points).collect();
    assert!(notes.iter().all(|l| l.starts_with("# ")), "{file}");
    assert!(
        notes[0].starts_with(
            "# COMP_FILE_TYPE = 0: nominal, forward actual and reverse actual position (mm)"
        ),
        "{file}"
    );
    assert!(
        notes[0].contains("`COMP_FILE = <file>` and `COMP_FILE_TYPE = 0`"),
        "{file}"
    );
    assert!(!file.contains("does not wrap"));
    assert!(
        stdout.contains(&format!("`COMP_FILE = {out_arg}` and `COMP_FILE_TYPE = 0`; read as type 1, each correction would be about the nominal position.\n")),
        "{stdout}"
    );
    let (stdout, file) = run(&["--comp-file-type", "1"]);
    assert!(
        file.starts_with("6.711000 0.0016000 -0.0022600\n"),
        "{file}"
    );
    assert!(file.contains("\n# COMP_FILE_TYPE = 1: nominal, forward trim and reverse trim (mm)"));
    assert!(
        stdout.contains(
            "`COMP_FILE_TYPE = 1`; read as type 0 (LinuxCNC's default when the key is missing)"
        ),
        "{stdout}"
    );
    // A rotary joint: no modulo, over the positions measured (three turns here).
    let rotary = "tests/data/compensation/rotary-three-turns.csv";
    let (code, stdout, stderr) = axcheck(&[
        "compensate",
        rotary,
        "--controller",
        "linuxcnc",
        "-o",
        out_arg,
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let file = std::fs::read_to_string(&out).unwrap();
    assert!(file.contains("\n# Rotary joint: LinuxCNC's comp lookup does not wrap (no modulo): the table covers joint positions 0 to 1080 deg; beyond them its end values are held.\n"), "{file}");
    assert!(stdout.contains("Rotary joint: LinuxCNC's comp lookup does not wrap (no modulo): the table covers the joint positions it lists; beyond them its end values are held.\n"), "{stdout}");
    for (extra, message) in [
        (
            ["--controller", "fanuc", "--comp-file-type", "1"],
            "--comp-file-type: the comp file type is LinuxCNC's COMP_FILE_TYPE, not a setting of fanuc",
        ),
        (
            ["--controller", "linuxcnc", "--comp-file-type", "2"],
            "2 is not in 0..=1",
        ),
    ] {
        let mut args = vec!["compensate", data];
        args.extend(extra);
        let (code, _, stderr) = axcheck(&args);
        assert_ne!(code, 0);
        assert!(stderr.contains(message), "{stderr}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `compensation: {comp_file_type}` is 0 or 1, and only where the machine's controller is
/// LinuxCNC: `check` names the key.
#[test]
fn a_campaign_asks_for_a_comp_file_type_only_of_linuxcnc() {
    let dir = scratch("comp-file-type");
    std::fs::copy("tests/data/iso230-2_table2.csv", dir.join("data/x.csv")).unwrap();
    let campaign = dir.join("campaign.yaml");
    for (controller, value, message) in [
        (
            "fanuc",
            "1",
            "machines[0].axes[0].compensation.comp_file_type: LinuxCNC's COMP_FILE_TYPE, but the machine has controller fanuc",
        ),
        (
            "linuxcnc",
            "2",
            "machines[0].axes[0].compensation.comp_file_type: expected LinuxCNC's COMP_FILE_TYPE, 0 (actual positions) or 1 (trims)",
        ),
    ] {
        std::fs::write(
            &campaign,
            format!("campaign: {{name: comp}}\nmachines:\n  - id: M\n    controller: {controller}\n    axes:\n      - {{name: X, kind: linear, data: data/x.csv, compensation: {{comp_file_type: {value}}}}}\n"),
        )
        .unwrap();
        let (code, stdout, _) = axcheck(&["check", campaign.to_str().unwrap()]);
        assert_eq!(code, 1, "{stdout}");
        assert!(stdout.contains(message), "{stdout}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
