//! Each controller reads back what it writes, to its unit, and builds a table on an active
//! one: measured with a known table active, the table written with `--active` is the one
//! written from the same axis measured with nothing active.

use axcheck::compensate::controllers::{CONTROLLERS, Controller, ReadAs, Refused, Spacing};
use axcheck::compensate::{self, Active, Settings, Table};
use axcheck::evaluate::ParamKey;
use axcheck::evaluate::{StandardId, evaluate};
use axcheck::measurement::{AxisData, RawReading};
use axcheck::simulate::Simulation;
use axcheck::simulate::SimulationFile as _;
use axcheck::units::{AxisKind, Direction};
use proptest::prelude::*;

/// A random axis: its kind, targets (ascending) and a mean deviation per target and
/// direction (the same on both runs).
#[derive(Debug, Clone)]
struct RandomAxis {
    kind: AxisKind,
    targets: Vec<f64>,
    up: Vec<f64>,
    down: Vec<f64>,
    /// Grid step for an equidistant controller, as a multiple of the mean spacing.
    interval_factor: f64,
    /// Where the reference point lies, as a fraction of the grid points (None: none).
    reference: Option<f64>,
}

/// Linear axes with irregular targets anywhere; rotary ones over part of a turn or, every
/// third, a whole turn in equal steps (a modulo table where the controller holds one).
fn random_axis() -> impl Strategy<Value = RandomAxis> {
    (0usize..3, 3usize..25).prop_flat_map(|(shape, m)| {
        let kind = if shape == 0 {
            AxisKind::Linear
        } else {
            AxisKind::Rotary
        };
        (
            Just((kind, shape)),
            proptest::collection::vec(1.0f64..60.0, m),
            -500.0f64..500.0,
            proptest::collection::vec((-40.0f64..40.0, -8.0f64..8.0), m),
            0.5f64..2.0,
            proptest::option::of(0.0f64..1.0),
        )
            .prop_map(
                move |((kind, shape), gaps, start, values, factor, reference)| {
                    let targets: Vec<f64> = match shape {
                        0 => steps(start, &gaps),
                        1 => {
                            let total: f64 = gaps.iter().sum();
                            let scaled: Vec<f64> = gaps.iter().map(|g| g * 300.0 / total).collect();
                            steps(0.0, &scaled)
                        }
                        _ => (0..gaps.len())
                            .map(|k| k as f64 * 360.0 / (gaps.len() - 1) as f64)
                            .collect(),
                    };
                    let factor = if shape == 2 { 1.0 } else { factor };
                    RandomAxis {
                        kind,
                        up: values.iter().map(|(e, _)| *e).collect(),
                        down: values.iter().map(|(e, b)| e + b).collect(),
                        targets,
                        interval_factor: factor,
                        reference,
                    }
                },
            )
    })
}

fn data_of(a: &RandomAxis) -> AxisData {
    let mut raw = Vec::new();
    for run in 1..=2 {
        for (direction, values) in [(Direction::Up, &a.up), (Direction::Down, &a.down)] {
            for (t, v) in a.targets.iter().zip(values) {
                raw.push(RawReading {
                    target: *t,
                    direction,
                    run,
                    deviation: *v,
                    time_s: None,
                    temps_c: vec![],
                    line: 0,
                });
            }
        }
    }
    AxisData::from_raw(a.kind, raw, vec![], "random").unwrap()
}

/// The settings of `a` for `controller`: an interval (rounded to 0.001) for equidistant
/// controllers, the reference on a target.
fn settings_of(a: &RandomAxis, controller: &dyn Controller) -> Settings {
    let (first, last) = (a.targets[0], a.targets[a.targets.len() - 1]);
    let mean = (last - first) / (a.targets.len() - 1) as f64;
    let whole_turn = a.kind == AxisKind::Rotary && last - first >= 360.0;
    let interval = match controller.format().spacing {
        Spacing::Equidistant if !whole_turn => {
            Some(((mean * a.interval_factor) * 1000.0).round().max(1.0) / 1000.0)
        }
        _ => None,
    };
    let reference = a
        .reference
        .map(|f| a.targets[((a.targets.len() - 1) as f64 * f).round() as usize]);
    Settings {
        interval,
        reference,
        active: Some(Active::default()),
        ..Default::default()
    }
}

/// Positions from `start` by `gaps`, each to 0.001.
fn steps(start: f64, gaps: &[f64]) -> Vec<f64> {
    let mut p = start;
    gaps.iter()
        .map(|g| {
            let t = (p * 1000.0).round() / 1000.0;
            p += g;
            t
        })
        .collect()
}

/// What a one-table controller holds in both directions: the mean.
fn as_loaded(controller: &dyn Controller, table: &Table) -> (Vec<f64>, Vec<f64>) {
    match controller.format().directions {
        compensate::controllers::Directions::Bidirectional => {
            (table.up.clone(), table.down.clone())
        }
        _ => (table.mean(), table.mean()),
    }
}

/// Written and read back, a held table gives its points and values to the controller's
/// unit (half a step of rounding when the file prints in a coarser unit than it holds).
/// `Ok(false)`: the controller cannot hold this table (too many points, too steep for
/// FANUC, outside HEIDENHAIN's 0…360°), so there is nothing to read back.
fn round_trip(controller: &dyn Controller, a: &RandomAxis) -> Result<bool, TestCaseError> {
    let data = data_of(a);
    let held = match compensate::held_table(controller, &data, &settings_of(a, controller)) {
        Ok(t) => t,
        Err(Refused::Grid(_) | Refused::Range(_)) => return Ok(false),
        Err(e) => return Err(TestCaseError::fail(e.to_string())),
    };
    let file = controller
        .write(&held, &["a note".to_string()])
        .map_err(|e| {
            TestCaseError::fail(format!("{}: a held table refused: {e}", controller.name()))
        })?;
    let reading = ReadAs {
        kind: a.kind,
        axis: None,
    };
    let back = controller
        .read(&file, reading)
        .map_err(|e| TestCaseError::fail(format!("{}: {e}\n{file}", controller.name())))?;
    let unit = controller.format().quantum(a.kind);
    let (up, down) = as_loaded(controller, &held);
    prop_assert_eq!(back.positions.len(), held.positions.len());
    for k in 0..up.len() {
        let close = |x: f64, y: f64, tol: f64| (x - y).abs() <= tol + 1e-9 * y.abs().max(1.0);
        prop_assert!(
            close(back.positions[k], held.positions[k], 5e-5),
            "{} position {k}: {} vs {}",
            controller.name(),
            back.positions[k],
            held.positions[k]
        );
        prop_assert!(
            close(back.up[k], up[k], unit / 2.0) && close(back.down[k], down[k], unit / 2.0),
            "{} point {k}: read ↑ {} ↓ {}, held ↑ {} ↓ {} (unit {unit})\n{file}",
            controller.name(),
            back.up[k],
            back.down[k],
            up[k],
            down[k]
        );
    }
    prop_assert_eq!(back.modulo_deg, held.modulo_deg);
    Ok(true)
}

/// Every controller (and LinuxCNC's type 1 beside its type 0): a thousand random tables
/// it can hold, written and read back (the axes it refuses are drawn again, at most one
/// in two).
#[test]
fn every_controller_reads_back_a_thousand_random_tables() {
    use proptest::strategy::ValueTree;
    let strategy = random_axis();
    let type_1: &dyn Controller = &compensate::controllers::linuxcnc::LinuxCnc::TYPE_1;
    for controller in CONTROLLERS.iter().chain([&type_1]) {
        let mut runner = proptest::test_runner::TestRunner::deterministic();
        let (mut read, mut drawn) = (0, 0);
        while read < 1000 {
            drawn += 1;
            assert!(
                drawn <= 2000,
                "{}: refused {} of {drawn}",
                controller.name(),
                drawn - read
            );
            let a = strategy.new_tree(&mut runner).unwrap().current();
            match round_trip(*controller, &a) {
                Ok(true) => read += 1,
                Ok(false) => {}
                Err(e) => panic!("{e}\n{a:?}"),
            }
        }
        eprintln!("{}: {read} read back of {drawn} drawn", controller.name());
    }
}

/// A linear axis of 1 000 mm measured every 50 mm (21 targets, on every controller's
/// grid): 30 ppm of scale error, a 4 µm sine of 400 mm, a reversal of 5 µm, 0.3 µm scatter.
const AXIS: &str = "kind: linear\nseed: 11\nmodel:\n  scale_um_per_m: 30\n  periodic: [{pitch_mm: 400, amplitude_um: 4, phase_deg: 30}]\n  reversal_um: 5\n  scatter_um: 0.3\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21}\n  runs: 5\n";

/// The table already active: another error (−12 ppm, a 2 µm sine of 250 mm, 3 µm of
/// reversal) as the controller holds it on the same grid, written to its file.
const ACTIVE: &str = "kind: linear\nseed: 5\nmodel:\n  scale_um_per_m: -12\n  periodic: [{pitch_mm: 250, amplitude_um: 2}]\n  reversal_um: 3\n  scatter_um: 0.2\nplan:\n  targets: {start_mm: 0, end_mm: 1000, count: 21}\n  runs: 5\n";

/// The settings both tables are written with: every 50 mm where the controller wants an
/// interval, the machine axis named (TwinCAT names it by its logical number).
fn grid_settings(controller: &dyn Controller) -> Settings {
    let axis = if controller.name() == "twincat" {
        "1"
    } else {
        "X1"
    };
    Settings {
        interval: (controller.format().spacing == Spacing::Equidistant).then_some(50.0),
        place: compensate::TableSlot {
            axis: Some(axis.into()),
            ..Default::default()
        },
        active: Some(Active::default()),
        ..Default::default()
    }
}

/// The backlash parameter set during the second measurement, where it acts on the
/// readings and the new table or parameter takes it over (µm).
fn active_backlash(controller: &dyn Controller) -> Option<f64> {
    use compensate::controllers::Backlash;
    match controller.backlash() {
        Backlash::Stated | Backlash::Cleared => Some(4.0),
        Backlash::UnusedWithTable | Backlash::Kept | Backlash::Absent => None,
    }
}

/// Measured with nothing active, and again (the same readings) with a known table and
/// backlash active: the table written from the second with the active one stated is the
/// table written from the first, to the file's last digit, for every controller; applied
/// in place of the active one it leaves E below a quarter of the uncompensated E.
#[test]
fn a_table_built_on_the_active_one_is_the_table_measured_without_it() {
    let plain = Simulation::from_yaml(AXIS, "axis.yaml").unwrap().run(11);
    let other = Simulation::from_yaml(ACTIVE, "active.yaml").unwrap().run(5);
    let e_plain = evaluate(&plain, StandardId::Iso230_2)
        .parameter(ParamKey::E)
        .unwrap()
        .value;
    assert!(e_plain > 30.0, "E = {e_plain}");
    for controller in CONTROLLERS {
        let settings = grid_settings(*controller);
        let known = compensate::held_table(*controller, &other, &settings).unwrap();
        let file = controller.write(&known, &[]).unwrap();
        let reading = ReadAs {
            kind: AxisKind::Linear,
            axis: Some("X1"),
        };
        let active = Active {
            table: Some(controller.read(&file, reading).unwrap()),
            file: Some("active".into()),
            backlash: active_backlash(*controller),
        };
        let total = active
            .total(controller.backlash(), AxisKind::Linear)
            .unwrap();
        let with_active = compensate::apply(&total, &plain);
        let from_plain = compensate::held_table(*controller, &plain, &settings).unwrap();
        let stated = Settings {
            active: Some(active),
            ..settings
        };
        let built = compensate::held_table(*controller, &with_active, &stated).unwrap();
        let name = controller.name();
        assert_eq!(
            controller.write(&built, &[]).unwrap(),
            controller.write(&from_plain, &[]).unwrap(),
            "{name}"
        );
        let after = compensate::apply_change(&built, Some(&total), &with_active);
        let e_after = evaluate(&after, StandardId::Iso230_2)
            .parameter(ParamKey::E)
            .unwrap()
            .value;
        assert!(e_after < e_plain / 4.0, "{name}: E {e_plain} -> {e_after}");
    }
}

/// `name`'s reading of `text` for a linear axis (`axis`: the axis to pick).
fn read(name: &str, text: &str, axis: Option<&str>) -> Result<Table, String> {
    let controller = compensate::controllers::find(name).unwrap();
    let reading = ReadAs {
        kind: AxisKind::Linear,
        axis,
    };
    controller.read(text, reading).map_err(|e| e.to_string())
}

fn close(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
}

/// LinuxCNC reads `nominal forward reverse` until a line is not three numbers. A type 0
/// file (actual positions, with leading blanks, as LinuxCNC's own sample) gives the trims
/// nominal − actual; a type 1 file the trims themselves, text after the third number
/// ignored; what LinuxCNC would not load is refused.
#[test]
fn linuxcnc_reads_type_0_and_1_as_its_loader_does() {
    let type0 = " -10  -10.001  -9.999\n  0   -0.003   0.002\n 10    9.999  10.000\n";
    let t = read("linuxcnc", type0, None).unwrap();
    assert!(close(&t.positions, &[-10.0, 0.0, 10.0]));
    // Trim = nominal − actual, mm → µm: 1, 3, 1 forward; −1, −2, 0 reverse.
    assert!(close(&t.up, &[1.0, 3.0, 1.0]), "{:?}", t.up);
    assert!(close(&t.down, &[-1.0, -2.0, 0.0]), "{:?}", t.down);
    let type1 = "0 0.0010 -0.0020 # a note\n100 0.0005 0.0\n200 0 0\n\n# written by hand\n";
    let t = read("linuxcnc", type1, None).unwrap();
    assert!(close(&t.up, &[1.0, 0.5, 0.0]) && close(&t.down, &[-2.0, 0.0, 0.0]));
    for (text, message) in [
        (
            "# nominal fwd rev\n0 0 0\n",
            "line 1: `# nominal fwd rev` is not three numbers (nominal, forward, reverse): LinuxCNC stops reading here and would load no table",
        ),
        (
            "0 0 0\n\n100 0.001 0\n",
            "line 3: a point after line 2 (``), where LinuxCNC stops reading: it would not be loaded; remove line 2 or move it below the points",
        ),
        (
            "0 0 0\n100 0.001 0\n100 0.002 0\n",
            "line 3, field `nominal`: the positions must increase: 100 follows 100",
        ),
        (
            "0 nan 0\n",
            "line 1: `0 nan 0` is not three numbers (nominal, forward, reverse): LinuxCNC stops reading here and would load no table",
        ),
    ] {
        assert_eq!(read("linuxcnc", text, None).unwrap_err(), message);
    }
}

/// An EEC file of two axes as a control archives it: block numbers, lower case, STEP, MIN
/// and MAX before the points, measuring system 1 for X1, points beyond MAX (the rest of
/// MD38000's) that the NC does not use. The axis is picked by name; the values are the
/// error, so the corrections are minus them.
#[test]
fn siemens_reads_the_named_axis_of_an_archive() {
    let text = "%_N_AX_EEC_INI\nCHANDATA(1)\nN10 $AA_ENC_COMP_STEP[1,X1]=50 ; mm\nN20 $aa_enc_comp_min[1,X1]=-50\nN30 $AA_ENC_COMP_MAX[1,X1]=50\n\
N40 $AA_ENC_COMP[1,0,X1]=0.002\nN50 $AA_ENC_COMP[1,1,X1] = -0.0015\nN60 $AA_ENC_COMP[1,2,X1]=0.0\nN70 $AA_ENC_COMP[1,3,X1]=0.0\n\
$AA_ENC_COMP[0,0,Y1]=0.001\n$AA_ENC_COMP[0,1,Y1]=0.001\n$AA_ENC_COMP_STEP[0,Y1]=10\n$AA_ENC_COMP_MIN[0,Y1]=0\n$AA_ENC_COMP_MAX[0,Y1]=10\nM17\n";
    let x = read("siemens-840d", text, Some("X1")).unwrap();
    assert!(close(&x.positions, &[-50.0, 0.0, 50.0]));
    assert!(close(&x.up, &[-2.0, 1.5, 0.0]) && x.up == x.down);
    assert_eq!(x.place.measuring_system, Some(1));
    assert_eq!(x.place.axis.as_deref(), Some("X1"));
    let y = read("siemens-840d", text, Some("y1")).unwrap();
    assert!(close(&y.up, &[-1.0, -1.0]));
    assert_eq!(
        read("siemens-840d", text, None).unwrap_err(),
        "the file holds 2 tables ([0,…,Y1], [1,…,X1]): name the axis (--axis, or compensation: {axis}) and keep one measuring system"
    );
    assert_eq!(
        read("siemens-840d", text, Some("Z1")).unwrap_err(),
        "no table of axis Z1; the file has [0,…,Y1], [1,…,X1]"
    );
    let gap = text.replace("N60 $AA_ENC_COMP[1,2,X1]=0.0\n", "");
    assert_eq!(
        read("siemens-840d", &gap, Some("X1")).unwrap_err(),
        "no `$AA_ENC_COMP[1,2,X1]`: the table runs from point 0 to 2 (MIN to MAX)"
    );
    let bad = text.replace("= -0.0015", "=-0,0015");
    assert_eq!(
        read("siemens-840d", &bad, Some("X1")).unwrap_err(),
        "line 7, field `$AA_ENC_COMP`: expected a number, got `-0,0015`"
    );
}

/// A unilateral SSFK list with comments after the values, blanks inside the brackets and
/// no `End`; a list of setpoints (interval 0).
#[test]
fn twincat_reads_unilateral_lists_and_setpoints() {
    let text = "#TC_AXIS_COMP_DESC: X\n# ****\nkopf.achs_nr 3\nkopf.log_achs_name X_ACHSE\nkw.ssfk.unit 1 /* metric */\n\
kw.ssfk.interval 500000\nkw.ssfk.kw_startpos 0\nkw.ssfk.kw_nr_max 3\nkw.ssfk.bilateral 0\nkw.ssfk.res1 0\n\
kw.ssfk.table[ 0].pos 10   ( 1 um )\nkw.ssfk.table[1].pos -5\nkw.ssfk.table[2].pos 0\n";
    let t = read("twincat", text, None).unwrap();
    assert!(close(&t.positions, &[0.0, 50.0, 100.0]));
    assert!(
        close(&t.up, &[-1.0, 0.5, 0.0]) && t.up == t.down,
        "{:?}",
        t.up
    );
    assert_eq!(t.place.number, Some(3));
    let setpoints = text
        .replace("kw.ssfk.interval 500000", "kw.ssfk.interval 0")
        .replace("kw.ssfk.table[2].pos 0", "kw.ssfk.table[2].pos 0\nkw.ssfk.table[0].setpoint 0\nkw.ssfk.table[1].setpoint 300000\nkw.ssfk.table[2].setpoint 1000000");
    assert!(close(
        &read("twincat", &setpoints, None).unwrap().positions,
        &[0.0, 30.0, 100.0]
    ));
    for (from, to, message) in [
        (
            "kw.ssfk.unit 1",
            "kw.ssfk.unit 0",
            "line 5, field `kw.ssfk.unit`: 0: axcheck reads metric lists (1: 0.1 um and 0.0001 deg) only; increments need the axis's resolution",
        ),
        (
            "kw.ssfk.table[2].pos 0",
            "kw.ssfk.table[3].pos 0",
            "line 13, field `kw.ssfk.table[3].pos`: entry 3 is beyond kw.ssfk.kw_nr_max = 3",
        ),
        (
            "kw.ssfk.table[1].pos -5",
            "kw.ssfk.table[1].pos -5\nkw.ssfk.table[1].neg 7",
            "line 13, field `kw.ssfk.table[1].neg`: differs from .pos in a unilateral list (kw.ssfk.bilateral 0): set bilateral 1 if the list holds both directions",
        ),
        (
            "kw.ssfk.table[1].pos -5",
            "kw.ssfk.table[1].pos -5.5",
            "line 12, field `kw.ssfk.table[1].pos`: expected an integer, got `-5.5`",
        ),
    ] {
        assert_eq!(
            read("twincat", &text.replace(from, to), None).unwrap_err(),
            message
        );
    }
}

/// ecmc reads comments in the first column, `PREC=`, empty lines and commas; it refuses an
/// indented comment, a line of blanks, and what it would read otherwise than it looks
/// (decimal commas); 9.6.x refuses empty lines and commas, and adds the table (the file
/// holds minus the correction there).
#[test]
fn ecmc_reads_what_its_loader_reads() {
    let text = "# table\nPREC=5\n0 0.001\n\n50,-0.002\n100\t0.0 extra\n";
    let t = read("ecmc", text, None).unwrap();
    assert!(close(&t.positions, &[0.0, 50.0, 100.0]));
    assert!(close(&t.up, &[1.0, -2.0, 0.0]) && t.up == t.down);
    let old = "# table\n0 0.001\n50 -0.002\n100 0.0\n";
    assert!(close(
        &read("ecmc-9.6", old, None).unwrap().up,
        &[-1.0, 2.0, 0.0]
    ));
    for (name, text, message) in [
        (
            "ecmc",
            "  # note\n0 0\n1 0\n2 0\n",
            "line 1: a comment must start in the first column: ecmc refuses `#` after a blank",
        ),
        (
            "ecmc",
            "0 0\n  \n1 0\n2 0\n",
            "line 2: a line of blanks only (or a `\\r`): ecmc refuses it; leave it empty or remove it",
        ),
        (
            "ecmc",
            "0 0\n1,5 2,3\n2 0\n",
            "line 2: `1 5 2 3`: three numbers once commas are separators; decimal commas? ecmc would read the row 1, 5",
        ),
        (
            "ecmc",
            "0 0\nPREC 5\n1 0\n2 0\n",
            "line 2: `PREC 5` is not `PREC=n`: ecmc refuses it",
        ),
        (
            "ecmc",
            "0 0\n1 0\n",
            "2 rows: ecmc loads a lookup table of at least 3",
        ),
        (
            "ecmc",
            "0 0\n1 0\n1 0.1\n",
            "line 3, field `position`: the positions must increase: 1 follows 1",
        ),
        (
            "ecmc-9.6",
            "0 0\n\n1 0\n2 0\n",
            "line 2: an empty line: ECMC 9.6.x and earlier refuses it",
        ),
        (
            "ecmc-9.6",
            "0 0\n1,0\n2 0\n",
            "line 2: a comma: ECMC 9.6.x and earlier separates numbers by blanks only",
        ),
    ] {
        assert_eq!(
            read(name, text, None).unwrap_err(),
            message,
            "{name} {text:?}"
        );
    }
}

/// A `.COM` table with a `#STRUCTBEGIN` block, the axis column named `X` beside another
/// axis's column, INCH units; the columns are cut at the header's positions.
#[test]
fn heidenhain_reads_columns_at_their_positions() {
    let text = "BEGIN X.COM INCH\n#STRUCTBEGIN\n   NAME = X\n#STRUCTEND\nNR    AXISPOS   X         Z         BACKLASH\n\
0     +0.0000   +0.0001   +0.0009   +0.0002\n1     +1.0000   -0.0001   +0.0000   +0.0000\n[END]\n";
    let t = read("heidenhain", text, Some("X")).unwrap();
    assert!(close(&t.positions, &[0.0, 25.4]));
    // Error 0.0001 in = 2.54 µm; the correction is minus the error.
    assert!(
        close(&t.up, &[-2.54, 2.54]) && close(&t.down, &[-5.08, 0.0]),
        "{:?} {:?}",
        t.up,
        t.down
    );
    assert_eq!(t.place.axis.as_deref(), Some("X"));
    for (from, to, axis, message) in [
        (
            "",
            "",
            None,
            "line 5: several axis columns (X, Z): name the axis (--axis, or compensation: {axis})",
        ),
        (
            "[END]\n",
            "",
            Some("X"),
            "no `[END]` line: the table may be cut short",
        ),
        (
            "-0.0001   +0.0000",
            "-0,0001   +0.0000",
            Some("X"),
            "line 7, field `X`: `-0,0001`: a decimal comma; write the number with a point",
        ),
        (
            "INCH",
            "FEET",
            Some("X"),
            "line 1: unknown unit `FEET` (MM or INCH)",
        ),
    ] {
        let changed = if from.is_empty() {
            text.to_string()
        } else {
            text.replace(from, to)
        };
        assert_eq!(read("heidenhain", &changed, axis).unwrap_err(), message);
    }
}

/// The generic CSV: one correction column for both directions; a table of the other
/// kind of axis is refused by its header.
#[test]
fn csv_reads_one_or_two_correction_columns() {
    let t = read(
        "csv",
        "# note\nposition_mm,correction_um\n0,1.5\n10,-2\n",
        None,
    )
    .unwrap();
    assert!(close(&t.up, &[1.5, -2.0]) && t.up == t.down);
    assert_eq!(
        read(
            "csv",
            "position_deg,correction_up_arcsec,correction_down_arcsec\n0,1,1\n",
            None
        )
        .unwrap_err(),
        "line 1: `position_deg`: the table is for a rotary axis, but the axis is linear"
    );
    assert_eq!(
        read("csv", "position_mm,correction_um\n0,1.5\n10\n", None).unwrap_err(),
        "line 3: 1 field, but the header names 2"
    );
}

/// A FANUC sheet whose numbers were moved by an offset of 100 (another axis uses 1…): read
/// at its numbers, the table kept at them when written again; a parameter that disagrees
/// with the axis line is refused with its line.
#[test]
fn fanuc_reads_its_sheet_at_its_numbers() {
    let fanuc = compensate::controllers::find("fanuc").unwrap();
    let data = Simulation::from_yaml(AXIS, "axis.yaml").unwrap().run(11);
    let settings = Settings {
        interval: Some(100.0),
        reference: Some(0.0),
        place: compensate::TableSlot {
            number: Some(101),
            ..Default::default()
        },
        active: Some(Active::default()),
        ..Default::default()
    };
    let held = compensate::held_table(fanuc, &data, &settings).unwrap();
    let sheet = fanuc.write(&held, &[]).unwrap();
    assert!(sheet.contains("\n  3621   = 101 "), "{sheet}");
    assert!(sheet.contains("\nN10101P"), "{sheet}");
    let back = read("fanuc", &sheet, None).unwrap();
    assert_eq!(back.place.number, Some(101));
    assert!(close(&back.up, &held.up) && close(&back.down, &held.down));
    assert_eq!(fanuc.write(&back, &[]).unwrap(), sheet);
    let wrong = sheet.replace("\n  3620   = 100 ", "\n  3620   = 102 ");
    let line = 1 + sheet[..sheet.find("\n  3620 ").unwrap() + 1]
        .matches('\n')
        .count();
    assert_eq!(
        read("fanuc", &wrong, None).unwrap_err(),
        format!(
            "line {line}, field `3620`: 102 is not the number of the reference position 0 given on the axis line"
        )
    );
    assert_eq!(
        read("fanuc", "%\nN10001P1\n%\n", None).unwrap_err(),
        "no `Axis:` line: axcheck reads the set-up sheet it writes (the axis line gives the points' positions, which the control does not hold)"
    );
}

/// An axis name that would break the file's syntax (a blank, a bracket) is refused by the
/// formats that write it (found by fuzzing: a HEIDENHAIN column named with a blank).
#[test]
fn an_axis_name_the_file_cannot_hold_is_refused() {
    let data = Simulation::from_yaml(AXIS, "axis.yaml").unwrap().run(11);
    for name in ["siemens-840d", "heidenhain"] {
        let controller = compensate::controllers::find(name).unwrap();
        let mut settings = grid_settings(controller);
        settings.place.axis = Some("X 1]".into());
        let held = compensate::held_table(controller, &data, &settings).unwrap();
        assert_eq!(
            controller.write(&held, &[]).unwrap_err().to_string(),
            "the axis name `X 1]` is not a name the file can hold (letters, digits and _)"
        );
    }
}
