//! What each fuzz target does with its input, in one place: the cargo-fuzz targets in
//! `fuzz_targets/` call these functions, and `tests/fuzz_corpus.rs` (which includes this
//! file with `#[path]`) replays the committed corpus through them under `cargo test`.
//!
//! Every function takes arbitrary bytes and must return without panicking, overflowing,
//! hanging or allocating without bound: an error from axcheck is a fine outcome, a panic is
//! a bug. The parsed values are then pushed through everything downstream that reads them
//! (evaluation by every standard, the test-plan rules, judging, the JSON and CSV writers),
//! because values that parse are exactly the ones that reach those functions.
//!
//! Uses only the library without its default features (no Typst, no polars).

use axcheck_campaign::campaign::Campaign;
use axcheck_campaign::judge::{self, Spec};
use axcheck_campaign::measurement::{self, AxisData};
use axcheck_campaign::simulate::SimulationFile as _;
use axcheck_core::evaluate::gost27843::{Gost27843, SMethod};
use axcheck_core::evaluate::{self, Standard, StandardId};
use axcheck_core::nde;
use axcheck_core::rules::{self, PlanContext};
use axcheck_core::units::{AxisKind, Travel};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The long CSV reader, as a positioning test and as an angular test (angles at targets
/// in mm), each evaluated by the other tests of a linear axis too.
pub fn csv(data: &[u8]) {
    if let Ok(axis) = measurement::csv::parse(data, "fuzz.csv") {
        check_data(&axis);
        check_geometry(&axis);
    }
    if let Ok(test) = measurement::read_with(data, "fuzz.csv", &angular()) {
        check_geometry(&test.data);
    }
}

/// Straightness by both lines (with a local length), the angular deviation, a squareness
/// with itself and the tool point through its own angles: finite numbers or `None`, no
/// panic.
fn check_geometry(data: &AxisData) {
    use axcheck_core::geometry::{abbe, angular, line::ReferenceLine, squareness, straightness};
    for line in [ReferenceLine::LeastSquares, ReferenceLine::EndPoint] {
        let options = straightness::Options {
            line,
            local_length_mm: Some(100.0),
        };
        if let Some(s) = straightness::evaluate(data, &options) {
            let _ = serde_json::to_vec(&s);
            let sq = squareness::evaluate(&s.up.line, &s.down.line, 1.0, Default::default());
            let _ = serde_json::to_vec(&sq);
        }
    }
    if let Some(a) = angular::evaluate(data) {
        let _ = serde_json::to_vec(&a);
    }
    let trace = angular::Trace::of(data);
    let rotations = abbe::Rotations {
        about_v: Some(&trace),
        about_w: Some(&trace),
    };
    let offset = abbe::Offset {
        v_mm: 120.0,
        w_mm: -80.0,
    };
    if let Ok(at_tool) = abbe::to_tool_point(data, rotations, offset) {
        check_data(&at_tool);
    }
}

/// The ecmc ISO 230 app's report and raw-points CSV, through the dispatch (recognised by
/// content), with every source the files may name; the app's own results compared.
pub fn ecmc_app(data: &[u8]) {
    use measurement::{ReadOptions, Source};
    let sources = [None, Some(Source::Reference(2)), Some(Source::Readback)];
    for source in sources {
        let options = ReadOptions {
            source,
            ..ReadOptions::default()
        };
        let Ok(test) = measurement::read_with(data, "fuzz.md", &options) else {
            continue;
        };
        check_data(&test.data);
        if let Some(reported) = &test.recognised.reported {
            let compared = axcheck_core::crosscheck::compare(reported, &test.data);
            let _ = serde_json::to_vec(&compared);
        }
    }
}

/// The wide CSV reader, as a positioning test and as an angular test (angles at targets
/// in mm), each evaluated by the other tests of a linear axis too.
pub fn wide(data: &[u8]) {
    if let Ok(axis) = measurement::wide::parse(data, "fuzz.csv") {
        check_data(&axis);
        check_geometry(&axis);
    }
    if let Ok(test) = measurement::read_with(data, "fuzz.csv", &angular()) {
        check_geometry(&test.data);
    }
}

/// The options that read an angular test of a linear axis.
fn angular() -> measurement::ReadOptions<'static> {
    measurement::ReadOptions {
        angular: true,
        ..Default::default()
    }
}

/// The workbook reader: the first sheet, then a named one (the name from the input's
/// last bytes, so both the found and the not-found paths run).
pub fn xlsx(data: &[u8]) {
    if let Ok(axis) = measurement::xlsx::parse(data, "fuzz.xlsx", None) {
        check_data(&axis);
    }
    let name = String::from_utf8_lossy(&data[data.len().saturating_sub(8)..]);
    if let Ok(axis) = measurement::xlsx::parse(data, "fuzz.xlsx", Some(&name)) {
        check_data(&axis);
    }
    if let Ok(test) = measurement::read_with(data, "fuzz.xlsx", &angular()) {
        check_geometry(&test.data);
    }
}

/// The ecmc key=value reader.
pub fn keyvalue(data: &[u8]) {
    if let Ok(axis) = measurement::keyvalue::parse(data, "fuzz.dat") {
        check_data(&axis);
    }
}

/// The Renishaw `.rtl`/`.rta` reader, as linear and as rotary, then each standard's
/// evaluation and, with the file's own material temperature and expansion coefficient,
/// the NDE correction.
pub fn renishaw(data: &[u8]) {
    let _ = measurement::renishaw::looks_like(data);
    for file in ["fuzz.rtl", "fuzz.rta"] {
        let Ok(test) = measurement::renishaw::parse(data, file) else {
            continue;
        };
        check_data(&test.data);
        for standard in StandardId::ALL {
            let _ = serde_json::to_vec(&evaluate::evaluate(&test.data, standard).json());
        }
        if let Some(env) = &test.environment
            && let (Some(t), Some(k)) = (env.material_temp_c(), env.expansion_ppm_per_c)
        {
            let _ = nde::correct(&test.data, k, nde::Temperature::Constant(t));
        }
    }
}

/// The layout-detecting reader, then everything that consumes a test: each standard's
/// evaluation and JSON, the rules, judging against the built-in specs, the NDE correction
/// and the CSV writer (whose output is read again).
pub fn evaluate(data: &[u8]) {
    let Ok(axis) = measurement::read(data, "fuzz").map(|t| t.data) else {
        return;
    };
    check_data(&axis);
    for standard in StandardId::ALL {
        let e = evaluate::evaluate(&axis, standard);
        let _ = serde_json::to_vec(&e.json());
        let (first, last) = axis.measurement_travel();
        for (_, spec) in builtin_specs() {
            let limits = judge::limits(Some(spec), &BTreeMap::new(), axis.kind, last - first);
            if let Ok(limits) = limits {
                let j = judge::judge(&e, limits, &judge::Decision::default());
                let _ = j.worst();
            }
        }
        let ctx = PlanContext {
            kind: axis.kind,
            standard,
            axis_travel: Some(Travel::Range([first - 1.0, last + 1.0])),
            measurement_travel: Some([first, last]),
            pitch: Some(5.0),
            planned: None,
            unstated: None,
            calibration: None,
        };
        let _ = rules::check(&ctx, &axis);
    }
    let _ = Gost27843 {
        s_method: SMethod::Ranges,
    }
    .evaluate(&axis);
    let _ = nde::correct(&axis, 11.5, nde::Temperature::PerReading);
    let _ = nde::correct(&axis, 11.5, nde::Temperature::Constant(23.0));
    let text = measurement::csv::write(&axis, &["written by the fuzz target".into()]);
    // Rounding in the writer may merge targets, so the copy need not be valid; it must not
    // panic either way.
    let _ = measurement::read(text.as_bytes(), "fuzz-copy.csv");
}

/// Cheap checks of any test a reader accepted: the invariants the evaluation relies on.
fn check_data(axis: &AxisData) {
    let m = axis.target_count();
    let n = axis.runs();
    assert!(m >= 1 && n >= 1, "an accepted test has targets and runs");
    assert_eq!(
        axis.readings.len(),
        2 * m * n,
        "dense: both directions, every run"
    );
    assert!(
        axis.targets.windows(2).all(|w| w[0] < w[1]),
        "targets ascend"
    );
    for r in &axis.readings {
        assert!(r.deviation.is_finite());
        assert_eq!(axis.deviation(r.target, r.direction, r.run), r.deviation);
    }
}

/// The campaign loader: `Campaign::parse` of the text as `campaign.yaml` in a fixed
/// scratch folder, then for each axis that loaded: its data paths resolved in that folder
/// (a glob walks it), and its plan, tolerances, NDE settings and standard applied to a
/// fixed test of the axis's kind (the numbers of the YAML reach the rules and the judge).
///
/// Paths are always resolved with `allow_outside_paths` off, whatever the campaign says:
/// the fuzzer must not walk the machine's file system.
pub fn campaign(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return; // Campaign::load refuses files that are not UTF-8 before parsing
    };
    let dir = scratch();
    let Ok(campaign) = Campaign::parse(text, &dir.join("campaign.yaml")) else {
        return;
    };
    for (_, entry) in campaign.axes() {
        let Ok(axis) = &entry.spec else { continue };
        let _ = axis.data.resolve(&axcheck_campaign::files::Root::campaign(
            &campaign.dir,
            false,
        ));
        let data = match axis.raw.kind {
            AxisKind::Linear => &fixtures().0,
            AxisKind::Rotary => &fixtures().1,
        };
        // The campaign's NDE settings applied as `run` applies them (clause 3.1).
        let (data, _) = axcheck_campaign::campaign::stages::nde::apply(axis, data.clone());
        let data = &data;
        let _ = rules::check(
            &axcheck_campaign::campaign::stages::rules::context(axis),
            data,
        );
        let e = if axis.standard == StandardId::Gost27843 && axis.raw.s_from_ranges {
            Gost27843 {
                s_method: SMethod::Ranges,
            }
            .evaluate(data)
        } else {
            evaluate::evaluate(data, axis.standard)
        };
        let spec = axis
            .spec
            .as_deref()
            .and_then(|name| builtin_specs().iter().find(|(n, _)| *n == name))
            .map(|(_, s)| s);
        let (first, last) = data.measurement_travel();
        if let Ok(limits) = judge::limits(spec, &axis.raw.tolerances, axis.raw.kind, last - first) {
            let _ = judge::judge(&e, limits, &judge::Decision::default());
        }
    }
}

/// The simulation-file loader (`axcheck simulate MODEL.yaml`, `diagnose --write-model`):
/// a model that loads is simulated, written as CSV and read back and evaluated, and its
/// own YAML must load again (what `--write-model` writes, `simulate` reads).
pub fn model(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    plan_file(text);
    let Ok(sim) = axcheck_campaign::simulate::Simulation::from_yaml(text, "fuzz-model.yaml") else {
        return;
    };
    let again = axcheck_campaign::simulate::Simulation::from_yaml(&sim.to_yaml(), "again.yaml");
    assert!(again.is_ok(), "{again:?}\n{}", sim.to_yaml());
    let axis = sim.run(sim.seed);
    let csv = measurement::csv::write(&axis, &[]);
    if let Ok(read) = measurement::csv::parse(csv.as_bytes(), "simulated.csv") {
        check_data(&read);
    }
}

/// The plan file (`axcheck plan -o`): a plan that loads is written again and loads to the
/// same plan, and every control's part program and the laser's lists are written for it.
fn plan_file(text: &str) {
    use axcheck_campaign::plan::{self, laser, programs};
    let Ok(plan) = plan::file::from_yaml(text, "fuzz-plan.yaml") else {
        return;
    };
    let again = plan::file::from_yaml(&plan::file::to_yaml(&plan), "again.yaml");
    assert_eq!(
        again.as_ref().ok(),
        Some(&plan),
        "{again:?}\n{}",
        plan::file::to_yaml(&plan)
    );
    let axis = match plan.axis.kind {
        AxisKind::Linear => "X",
        AxisKind::Rotary => "C",
    };
    for dialect in programs::DIALECTS {
        for (coordinates, lathe) in [
            (programs::Coordinates::Machine, None),
            (programs::Coordinates::Work, Some(programs::GcodeSystem::A)),
        ] {
            let job = programs::Job {
                coordinates,
                lathe,
                ..programs::Job::new(&plan, axis, "FUZZ")
            };
            let _ = dialect.write(&job);
        }
    }
    let _ = (laser::readings_csv(&plan), laser::rtl_targets(&plan));
}

/// The acceptance-spec loader, then each band lookup and a judgement against it.
pub fn spec(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(spec) = Spec::from_yaml(text, "fuzz-spec.yaml") else {
        return;
    };
    let (linear, rotary) = fixtures();
    for (data, e) in [(linear, &evaluations().0), (rotary, &evaluations().1)] {
        for travel in [0.0, 1.0, 360.0, 999.9, 1000.0, 1e6, f64::INFINITY] {
            let _ = spec.band(data.kind, travel);
            if let Ok(limits) = judge::limits(Some(&spec), &BTreeMap::new(), data.kind, travel) {
                let _ = judge::judge(e, limits, &judge::Decision::default()).worst();
            }
        }
    }
}

/// Every controller's table reader, for both kinds of axis. A table read is checked (points
/// in order, finite values), held and written by its controller, and what is written must
/// read again; then it is the active table of a compensation of a fixed test of its kind
/// (the incremental table and its prediction).
pub fn controllers(data: &[u8]) {
    use axcheck_core::compensate::controllers::{CONTROLLERS, ReadAs};
    use axcheck_core::compensate::{self, Active, Settings};
    let Ok(text) = std::str::from_utf8(data) else {
        return; // every table file is read as UTF-8 text
    };
    let (linear, rotary) = fixtures();
    for controller in CONTROLLERS {
        for (kind, axis) in [(AxisKind::Linear, linear), (AxisKind::Rotary, rotary)] {
            let reading = ReadAs { kind, axis: None };
            let Ok(table) = controller.read(text, reading) else {
                continue;
            };
            let n = table.positions.len();
            assert!(n >= 1 && table.up.len() == n && table.down.len() == n);
            assert!(
                table.positions.windows(2).all(|w| w[0] < w[1]),
                "points ascend"
            );
            let values = table.up.iter().chain(&table.down).chain(&table.positions);
            assert!(values.clone().all(|v| v.is_finite()), "finite values");
            if let Ok(held) = controller.hold(table.clone())
                && let Ok(file) = controller.write(&held, &["fuzz".to_string()])
            {
                let again = controller.read(&file, reading);
                assert!(again.is_ok(), "{}: {again:?}\n{file}", controller.name());
            }
            let active = Active {
                table: Some(table),
                file: None,
                backlash: None,
            };
            let settings = Settings {
                active: Some(active.clone()),
                ..Default::default()
            };
            if let Ok(built) = compensate::held_table(*controller, axis, &settings) {
                let total = active.total(controller.backlash(), kind);
                let after = compensate::apply_change(&built, total.as_ref(), axis);
                check_data(&after);
            }
        }
    }
}

/// A linear (ISO 230-2 Table 2) and a rotary test, read once.
fn fixtures() -> &'static (AxisData, AxisData) {
    static DATA: OnceLock<(AxisData, AxisData)> = OnceLock::new();
    DATA.get_or_init(|| {
        let read = |text: &str| {
            measurement::read(text.as_bytes(), "fixture.csv")
                .unwrap()
                .data
        };
        (read(LINEAR), read(ROTARY))
    })
}

fn evaluations() -> &'static (evaluate::Evaluation, evaluate::Evaluation) {
    static EVALUATIONS: OnceLock<(evaluate::Evaluation, evaluate::Evaluation)> = OnceLock::new();
    EVALUATIONS.get_or_init(|| {
        let (linear, rotary) = fixtures();
        (
            evaluate::evaluate(linear, StandardId::Iso230_2),
            evaluate::evaluate(rotary, StandardId::Iso230_2),
        )
    })
}

fn builtin_specs() -> &'static [(&'static str, Spec)] {
    static SPECS: OnceLock<Vec<(&'static str, Spec)>> = OnceLock::new();
    SPECS.get_or_init(|| {
        judge::BUILTIN_SPECS
            .iter()
            .map(|(name, text)| (*name, Spec::from_yaml(text, name).unwrap()))
            .collect()
    })
}

const LINEAR: &str = include_str!("../../tests/data/iso230-2_table2.csv");
const ROTARY: &str = include_str!("../../example-campaign/data/rotary-c.csv");

/// A fixed folder the campaign target resolves data paths in: `data/` with a few files
/// (one in a subfolder, one hidden) and `specs/`. Made once per process.
fn scratch() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = std::env::temp_dir().join(format!("axcheck-fuzz-{}", std::process::id()));
        for (path, text) in [
            ("data/x.csv", LINEAR),
            ("data/c.csv", ROTARY),
            ("data/sub/y.csv", LINEAR),
            ("data/.hidden.csv", LINEAR),
            ("specs/general.yaml", judge::BUILTIN_SPECS[0].1),
        ] {
            let file = dir.join(path);
            std::fs::create_dir_all(file.parent().unwrap()).unwrap();
            std::fs::write(file, text).unwrap();
        }
        dir
    })
}
