//! A real LinuxCNC applies the compensation tables axcheck writes as axcheck predicts.
//!
//! `linuxcnc -r machine.ini` (Debian's `linuxcnc-uspace`, installed by `.ci/test`) runs a
//! simulated machine of four joints (tests/data/linuxcnc: trivkins X Y A B, each joint's
//! motor command fed back as its position), X and A loading axcheck's type 0 tables and Y
//! and B its type 1 tables (`COMP_FILE`, `COMP_FILE_TYPE`), X and Y of a linear axis of
//! 1190 mm, A and B of a rotary one over 0…360°, written by `axcheck compensate` from
//! simulated measurements. Its `[DISPLAY]` is no display but `probe.py`, which drives the
//! machine through LinuxCNC's Python interface: it moves all four joints at once (`G53 G0`)
//! to 12 positions from below (forward: from 5 mm or 5° under the position) and 12 from
//! above (reverse), among them points of the tables, positions between them and positions
//! beyond both ends (400°: LinuxCNC's lookup does not wrap), waits until the joints stand
//! and the compensation filter has reached its value, and reads each joint's `pos-cmd`,
//! `motor-pos-cmd` and `motor-offset` with the `hal` module's `get_value`, as doubles
//! (halcmd prints about 7 significant digits, 0.1 µm at 1190 mm).
//!
//! The correction LinuxCNC applied, `motor-pos-cmd − pos-cmd − motor-offset`, must equal
//! the correction axcheck predicts (its table's `correction` at `pos-cmd` in the probe's
//! direction, from `compensate --json`) to 0.2 µm on the linear joints and 0.05″ on the
//! rotary ones at every probed position, and the value LinuxCNC looked up in the table
//! (`backlash-corr`, before it ramps it in) to 1e-4 µm or ″. That settles the sign by the
//! controller: the trim is added to the commanded position. LinuxCNC holds trims as
//! `float` (about 7 significant digits): the looked-up value differs by about 1e-6.
//!
//! LinuxCNC ramps the correction in (`compute_screw_comp` in `control.c`) and the ramp can
//! stop short of it by up to `MAX_ACCELERATION` × servo period² / 2 (from rest, a step
//! between ¼ and ½ of that is not ramped at all: with no ramp speed its "constant
//! velocity" branch moves by 0). The machine's period of 0.25 ms and accelerations of
//! 3200 mm/s² and 400 °/s² bound that to 0.1 µm and 0.045″, within the tolerances; at
//! 20000 mm/s² and 1 ms a reversal of 6 µm stayed unapplied.
//!
//! The sign is also measured: the slope of the applied correction on the predicted one
//! over every probe of a joint is +1 (the trim added; −1 if LinuxCNC subtracted it).
//!
//! As root, `rtapi_app` runs only with `RTAPI_UID` (an unprivileged uid, 65534) and a
//! `RTAPI_FIFO_PATH` (its socket) in a folder that uid can write; everything runs in a
//! temporary folder, `HOME` included (LinuxCNC writes its logs there), and the run is
//! serialized by a lock (LinuxCNC's script stops any other instance it finds).

use crate::common::{axcheck, data_path, scratch};
use axcheck::compensate::Table;
use axcheck::units::{AxisKind, Direction};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Probed positions of the linear joints (mm): before the table, on and between its
/// points (0, 97.3, …, 1190), beyond its end.
const LINEAR_MM: [f64; 12] = [
    -20.0, 0.0, 50.5, 97.3, 150.25, 333.3, 555.55, 777.7, 950.0, 1144.4, 1190.0, 1200.0,
];
/// Probed positions of the rotary joints (deg): before 0, on and between the table's
/// points (every 30°), and beyond 360°, where the end values hold (no modulo).
const ROTARY_DEG: [f64; 12] = [
    -30.0, 0.0, 15.0, 30.0, 47.5, 100.0, 180.0, 222.2, 300.0, 359.0, 360.0, 400.0,
];
/// How far below (forward) or above (reverse) each position a probe starts, mm or deg.
const APPROACH: f64 = 5.0;
/// The joints, their axis letters, table files and what they hold.
const JOINTS: [(&str, &str, AxisKind, u8); 4] = [
    ("X", "x.txt", AxisKind::Linear, 0),
    ("Y", "y.txt", AxisKind::Linear, 1),
    ("A", "a.txt", AxisKind::Rotary, 0),
    ("B", "b.txt", AxisKind::Rotary, 1),
];

#[test]
fn linuxcnc_applies_each_table_as_axcheck_predicts() {
    let _lock = lock();
    require_linuxcnc();
    let dir = scratch("linuxcnc-sim");
    for file in ["machine.ini", "machine.hal", "probe.py"] {
        std::fs::copy(data_path("linuxcnc").join(file), dir.join(file)).unwrap();
    }
    set_mode(&dir.join("probe.py"), 0o755);
    std::fs::write(dir.join("tool.tbl"), "").unwrap();
    std::fs::write(dir.join("sim.var"), "").unwrap();
    let tables: Vec<Table> = JOINTS
        .iter()
        .map(|(_, file, kind, file_type)| write_table(&dir, file, *kind, *file_type))
        .collect();
    let probes = probe_plan();
    std::fs::write(
        dir.join("probes.json"),
        serde_json::to_string(&probes.iter().map(|p| &p.commands).collect::<Vec<_>>()).unwrap(),
    )
    .unwrap();
    let results = run_linuxcnc(&dir);
    let mut worst = [0.0f64; 4];
    let mut worst_looked_up = [0.0f64; 4];
    // Σ applied·predicted and Σ predicted², per joint: the slope of one on the other.
    let mut products = [(0.0f64, 0.0f64); 4];
    for (probe, joints) in probes.iter().zip(results) {
        for (j, (axis, _, kind, _)) in JOINTS.iter().enumerate() {
            let pins = &joints[j];
            let pos = pins["pos-cmd"].as_f64().unwrap();
            let applied = pins["motor-pos-cmd"].as_f64().unwrap()
                - pos
                - pins["motor-offset"].as_f64().unwrap();
            let per_unit = kind.deviation_units_per_position_unit();
            let applied = applied * per_unit;
            let predicted = tables[j].correction(pos, probe.direction);
            // The correction looked up before LinuxCNC's ramp: the table's own value.
            let looked_up = pins["backlash-corr"].as_f64().unwrap() * per_unit;
            assert!(
                (looked_up - predicted).abs() < 1e-4,
                "joint {axis} at {pos} {}: LinuxCNC looked up {looked_up}, axcheck predicts {predicted}",
                probe.direction.arrow()
            );
            let difference = applied - predicted;
            worst[j] = worst[j].max(difference.abs());
            worst_looked_up[j] = worst_looked_up[j].max((looked_up - predicted).abs());
            products[j].0 += applied * predicted;
            products[j].1 += predicted * predicted;
            let tolerance = match kind {
                AxisKind::Linear => 0.2,
                AxisKind::Rotary => 0.05,
            };
            assert!(
                difference.abs() <= tolerance,
                "joint {axis} at {pos} {} {}: LinuxCNC applied {applied} {unit}, axcheck predicts {predicted} {unit}",
                kind.position_unit(),
                probe.direction.arrow(),
                unit = kind.deviation_unit()
            );
        }
    }
    for (j, (axis, _, kind, file_type)) in JOINTS.iter().enumerate() {
        let slope = products[j].0 / products[j].1;
        assert!((slope - 1.0).abs() < 1e-3, "joint {axis}: slope {slope}");
        eprintln!(
            "LinuxCNC joint {axis} ({kind}, type {file_type}): sign (slope of applied on predicted) {slope:+.5}, max |applied − predicted| = {:.2e} {unit}, max |looked up − predicted| = {:.2e} {unit}",
            worst[j],
            worst_looked_up[j],
            unit = kind.deviation_unit()
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A probe: the MDI commands that end at the position from one side, and that side.
struct Probe {
    commands: Vec<String>,
    direction: Direction,
}

/// Every position from below, then from above: the four joints move together, X and Y to
/// the linear positions, A and B to the rotary ones.
fn probe_plan() -> Vec<Probe> {
    let mut probes = Vec::new();
    for direction in [Direction::Up, Direction::Down] {
        let from = -direction.sign() * APPROACH;
        for (l, r) in LINEAR_MM.iter().zip(ROTARY_DEG) {
            let line = |d: f64| {
                format!(
                    "G53 G0 X{:.4} Y{:.4} A{:.4} B{:.4}",
                    l + d,
                    l + d,
                    r + d,
                    r + d
                )
            };
            probes.push(Probe {
                commands: vec![line(from), line(0.0)],
                direction,
            });
        }
    }
    probes
}

/// Writes the table of `kind` and `file_type` to `dir/file` with `axcheck compensate`
/// and returns the table it predicts with (`--json`), checking that the file states its
/// type and reads back as that table.
fn write_table(dir: &Path, file: &str, kind: AxisKind, file_type: u8) -> Table {
    let model = match kind {
        AxisKind::Linear => "linear",
        AxisKind::Rotary => "rotary",
    };
    let data = dir.join(format!("data/{model}.csv"));
    if !data.exists() {
        let model = data_path(&format!("linuxcnc/{model}.yaml"));
        let (code, out, err) = axcheck(&[
            "simulate",
            model.to_str().unwrap(),
            "-o",
            data.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{out}{err}");
    }
    let path = dir.join(file);
    let file_type = file_type.to_string();
    let (code, out, err) = axcheck(&[
        "compensate",
        data.to_str().unwrap(),
        "--controller",
        "linuxcnc",
        "--comp-file-type",
        &file_type,
        "--active",
        "none",
        "-o",
        path.to_str().unwrap(),
        "--json",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    let json: Value = serde_json::from_str(&out).unwrap();
    let table = table_of(&json["table"], kind);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.contains(&format!("\n# COMP_FILE_TYPE = {file_type}: ")),
        "{text}"
    );
    let controller = axcheck::compensate::controllers::find("linuxcnc").unwrap();
    let reading = axcheck::compensate::controllers::ReadAs { kind, axis: None };
    let back = controller.read(&text, reading).unwrap();
    let values = |t: &Table| [t.positions.clone(), t.up.clone(), t.down.clone()].concat();
    for (b, t) in values(&back).iter().zip(values(&table)) {
        assert!((b - t).abs() < 1e-6, "{file}: read {b}, predicted with {t}");
    }
    table
}

/// The table of `compensate --json`.
fn table_of(json: &Value, kind: AxisKind) -> Table {
    let numbers = |key: &str| -> Vec<f64> {
        json[key]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    assert!(
        json["modulo_deg"].is_null(),
        "LinuxCNC holds no modulo table"
    );
    Table {
        kind,
        positions: numbers("positions"),
        up: numbers("up"),
        down: numbers("down"),
        reference: json["reference"].as_f64().unwrap(),
        modulo_deg: None,
        place: Default::default(),
        interpolation: Default::default(),
    }
}

/// Runs LinuxCNC on `dir/machine.ini` until its display program exits (at most two
/// minutes) and returns, per probe, each joint's pins.
fn run_linuxcnc(dir: &Path) -> Vec<Vec<serde_json::Map<String, Value>>> {
    let fifo = dir.join("rtapi");
    std::fs::create_dir_all(&fifo).unwrap();
    if is_root(dir) {
        std::os::unix::fs::chown(&fifo, Some(UNPRIVILEGED_UID), None).unwrap();
    }
    let mut child = Command::new("linuxcnc")
        .args(["-r", "machine.ini"])
        .current_dir(dir)
        .env_remove("DISPLAY")
        .env("HOME", dir)
        .env("RTAPI_UID", UNPRIVILEGED_UID.to_string())
        .env("RTAPI_FIFO_PATH", fifo.join("socket"))
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(dir.join("linuxcnc.log")).unwrap())
        .stderr(Stdio::from(
            std::fs::File::options()
                .append(true)
                .open(dir.join("linuxcnc.log"))
                .unwrap(),
        ))
        .process_group(0)
        .spawn()
        .expect("linuxcnc starts");
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(120) {
            let _ = Command::new("kill")
                .args(["-TERM", "--", &format!("-{}", child.id())])
                .status();
            let _ = child.wait();
            panic!("LinuxCNC ran over two minutes:\n{}", log(dir));
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    let text = std::fs::read_to_string(dir.join("results.json"))
        .unwrap_or_else(|e| panic!("no results.json ({e}):\n{}", log(dir)));
    let results: Value = serde_json::from_str(&text).unwrap();
    assert!(
        results["failure"].is_null(),
        "probe.py failed: {}\n{}",
        results["failure"].as_str().unwrap_or(""),
        log(dir)
    );
    let errors = results["errors"].as_array().unwrap();
    assert!(errors.is_empty(), "LinuxCNC reported {errors:?}");
    results["probes"]
        .as_array()
        .unwrap()
        .iter()
        .map(|probe| {
            let joints = probe.as_array().unwrap();
            joints
                .iter()
                .map(|j| j.as_object().unwrap().clone())
                .collect()
        })
        .collect()
}

use std::os::unix::fs::MetadataExt;
use std::os::unix::process::CommandExt;

/// The uid `rtapi_app` runs as when started by root ("nobody").
const UNPRIVILEGED_UID: u32 = 65534;

/// Whether the test runs as root: the folder it made belongs to uid 0.
fn is_root(dir: &Path) -> bool {
    std::fs::metadata(dir).unwrap().uid() == 0
}

/// The log of the LinuxCNC run, for a failure's message.
fn log(dir: &Path) -> String {
    std::fs::read_to_string(dir.join("linuxcnc.log")).unwrap_or_default()
}

fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// One LinuxCNC at a time on this machine: its start script stops any other it finds.
fn lock() -> std::fs::File {
    let path = std::env::temp_dir().join("axcheck-linuxcnc.lock");
    let file = std::fs::File::create(path).unwrap();
    file.lock().unwrap();
    file
}

/// `linuxcnc` on the PATH, or a failure that says how to install it.
fn require_linuxcnc() {
    let found = std::env::var_os("PATH").is_some_and(|paths| {
        std::env::split_paths(&paths).any(|p: PathBuf| p.join("linuxcnc").is_file())
    });
    assert!(
        found,
        "linuxcnc is not installed: this test runs a real LinuxCNC (Debian: apt-get install linuxcnc-uspace, as .ci/test does)"
    );
}
