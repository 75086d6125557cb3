//! `axcheck._axcheck`: the evaluation core for Python. Each function returns the JSON the
//! command line prints for the same request (`eval --json`, `diagnose --json`,
//! `compensate --json`, `verify --json`), written by the same serialisers, so that a
//! notebook and a campaign give the same numbers bit for bit; `axcheck/__init__.py` turns
//! it into dicts and DataFrames. The work runs with the GIL released, so that a thread pool
//! of Python workers scales.

use axcheck_campaign::batch::{self, BatchOptions};
use axcheck_campaign::campaign::Campaign;
use axcheck_campaign::campaign::stages::compensate as tables;
use axcheck_campaign::measurement::{self, ReadError, ReadOptions, ReadTest, Recognised};
use axcheck_campaign::one_file::{Applied, EvalJson, WithFile};
use axcheck_campaign::table::{self, Cell};
use axcheck_core::compensate::json::TableJson;
use axcheck_core::compensate::{self, Settings, TableSlot, controllers};
use axcheck_core::evaluate::gost27843::SMethod;
use axcheck_core::evaluate::{Evaluation, StandardId};
use axcheck_core::measurement::AxisData;
use axcheck_core::uncertainty::{self, InstrumentKind, Setup};
use axcheck_core::verify;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use serde::Serialize;
use std::path::Path;

mod other_tests;

/// A positioning test as read: the readings and what the file was recognised as.
#[pyclass(frozen, module = "axcheck._axcheck")]
struct Measurement {
    data: AxisData,
    recognised: Recognised,
    /// The file's name as given (`<frame>` for a DataFrame).
    file: String,
}

#[pymethods]
impl Measurement {
    /// The file's name as given.
    #[getter]
    fn file(&self) -> &str {
        &self.file
    }

    /// `linear` or `rotary`.
    #[getter]
    fn kind(&self) -> String {
        self.data.kind.to_string()
    }

    /// What the file was read as: `{"layout", "name", "notes", …}` as JSON.
    fn recognised_json(&self) -> PyResult<String> {
        to_json(&self.recognised)
    }

    /// The readings in the long layout, one tuple per reading: target position (mm or
    /// deg), direction (`up`/`down`), run label, deviation (µm or arcsec), time (s or None).
    fn readings(&self) -> Vec<(f64, &'static str, u32, f64, Option<f64>)> {
        let d = &self.data;
        (d.readings.iter())
            .map(|r| {
                let direction = match r.direction {
                    axcheck_core::units::Direction::Up => "up",
                    axcheck_core::units::Direction::Down => "down",
                };
                let run = d.run_labels[r.run];
                (d.targets[r.target], direction, run, r.deviation, r.time_s)
            })
            .collect()
    }
}

/// A failure the Python side shows as `axcheck.ReadError` (path, line, column, sheet,
/// field), built by `axcheck._errors` so that its type is a plain Python class.
fn read_error(py: Python<'_>, e: &ReadError) -> PyErr {
    let l = &e.location;
    let args = (
        e.to_string(),
        l.file.clone(),
        l.line,
        l.column,
        l.sheet.clone(),
        e.kind.field(),
    );
    let made = py
        .import("axcheck._errors")
        .and_then(|m| m.getattr("ReadError"))
        .and_then(|class| class.call1(args));
    match made {
        Ok(error) => PyErr::from_value(error),
        Err(e) => e,
    }
}

fn to_json<T: Serialize>(value: &T) -> PyResult<String> {
    serde_json::to_string_pretty(value).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// `value`'s JSON and the measurement's `file` after it, as the command line prints
/// `diagnose --json` and `verify --json`.
fn json_with_file<T: Serialize>(value: T, file: &str) -> PyResult<String> {
    to_json(&WithFile { value, file })
}

fn standard(text: &str) -> PyResult<StandardId> {
    StandardId::parse(text).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown standard `{text}`; expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba"
        ))
    })
}

/// Reads a measurement file in any layout the command line reads; `sheet` names a
/// workbook's sheet, `reference` an ecmc ISO 230 app file's reference (1 to 5, `rbv`).
#[pyfunction]
#[pyo3(signature = (path, sheet=None, reference=None, angular=false))]
fn read(
    py: Python<'_>,
    path: &str,
    sheet: Option<&str>,
    reference: Option<&str>,
    angular: bool,
) -> PyResult<Measurement> {
    let source = reference
        .map(measurement::Source::parse)
        .transpose()
        .map_err(|e| PyValueError::new_err(format!("reference: {e}")))?;
    let options = ReadOptions {
        sheet,
        source,
        angular,
    };
    let read = py.detach(|| measurement::read_file_with(Path::new(path), &options));
    let ReadTest { data, recognised } = read.map_err(|e| read_error(py, &e))?;
    Ok(Measurement {
        data,
        recognised,
        file: path.to_string(),
    })
}

/// Reads a measurement from its text (a long or wide CSV), `name` for messages.
#[pyfunction]
fn read_text(py: Python<'_>, text: &str, name: &str) -> PyResult<Measurement> {
    let read = py.detach(|| measurement::read(text.as_bytes(), name));
    let ReadTest { data, recognised } = read.map_err(|e| read_error(py, &e))?;
    Ok(Measurement {
        data,
        recognised,
        file: name.to_string(),
    })
}

/// One test's parameters and their U. The values are handed over as they are asked for,
/// the whole JSON only when it is (it is most of the cost of a small file).
#[pyclass(frozen, module = "axcheck._axcheck")]
struct Evaluated {
    evaluation: Evaluation,
    uncertainty: uncertainty::Uncertainty,
    other_tool: Option<axcheck_core::crosscheck::OtherTool>,
    recognised: Recognised,
    file: String,
}

#[pymethods]
impl Evaluated {
    /// Each parameter's key and value, in the catalogue's order.
    fn values(&self) -> Vec<(&'static str, f64)> {
        (self.evaluation.parameters.iter())
            .map(|p| (p.key(), p.value))
            .collect()
    }

    /// Each parameter's key and its expanded uncertainty U (k = 2).
    fn expanded(&self) -> Vec<(String, f64)> {
        (self.uncertainty.expanded.iter())
            .map(|(k, u)| (k.clone(), *u))
            .collect()
    }

    /// ISO 230-2 Fig. 2a (bidirectional) and Fig. 2b (unidirectional) as SVG: the scenes
    /// the axis report and `summary.html` draw, texts in `family`.
    #[pyo3(signature = (family="sans-serif"))]
    fn figures(&self, family: &str) -> (String, String) {
        let [both, each] = axcheck_charts::figures::iso_charts(&self.evaluation);
        (both.svg(family), each.svg(family))
    }

    /// The whole of `eval --json`, and `uncertainty`.
    fn json(&self, py: Python<'_>) -> PyResult<String> {
        py.detach(|| {
            to_json(&EvalJson {
                evaluation: self.evaluation.json(),
                applied: &Applied::default(),
                file: &self.file,
                recognised: &self.recognised,
                other_tool: self.other_tool.as_ref(),
                uncertainty: Some(&self.uncertainty),
            })
        })
    }
}

/// What to evaluate by: the standard, GOST 27843's S and the instrument for U.
struct Request {
    standard: StandardId,
    method: SMethod,
    setup: Option<Setup>,
}

impl Request {
    fn parse(standard_key: &str, s_from_ranges: bool, instrument: Option<&str>) -> PyResult<Self> {
        let standard = standard(standard_key)?;
        if s_from_ranges && standard != StandardId::Gost27843 {
            return Err(PyValueError::new_err(
                "s_from_ranges applies to the standard gost27843 only",
            ));
        }
        let setup = (instrument.map(|name| {
            InstrumentKind::from_name(name)
                .map(Setup::for_instrument)
                .ok_or_else(|| PyValueError::new_err(format!("instrument: unknown kind `{name}`")))
        }))
        .transpose()?;
        let method = match s_from_ranges {
            true => SMethod::Ranges,
            false => SMethod::Formula5,
        };
        Ok(Request {
            standard,
            method,
            setup,
        })
    }

    /// The evaluation of one test (no GIL needed).
    fn evaluate(&self, data: &AxisData, recognised: Recognised, file: &str) -> Evaluated {
        let evaluation = axcheck_core::evaluate::evaluate_by(data, self.standard, self.method);
        let setup = (self.setup.clone()).unwrap_or_else(|| Setup::for_axis(data.kind));
        let reported = recognised.reported.as_ref();
        Evaluated {
            uncertainty: uncertainty::evaluate(&setup, &evaluation),
            evaluation,
            other_tool: reported.map(|r| axcheck_core::crosscheck::compare(r, data)),
            recognised,
            file: file.to_string(),
        }
    }
}

/// The parameters of `standard` (ISO 230-2 clause 2; GOST 27843 with S from ranges when
/// asked) as `eval` computes them, with U per parameter.
#[pyfunction]
#[pyo3(signature = (m, standard_key="iso230-2", s_from_ranges=false, instrument=None))]
fn evaluate(
    py: Python<'_>,
    m: &Measurement,
    standard_key: &str,
    s_from_ranges: bool,
    instrument: Option<&str>,
) -> PyResult<Evaluated> {
    let request = Request::parse(standard_key, s_from_ranges, instrument)?;
    Ok(py.detach(|| request.evaluate(&m.data, m.recognised.clone(), &m.file)))
}

/// Each file read and evaluated as `read` and `evaluate` would, in Rust's thread pool
/// (`jobs` threads, default one per core) with the GIL released once for them all: the
/// Python around one call per small file costs more than its evaluation. In the paths'
/// order, each an `Evaluated` or the `axcheck.ReadError` its file raised.
#[pyfunction]
#[pyo3(signature = (paths, standard_key="iso230-2", s_from_ranges=false, instrument=None, jobs=None))]
fn evaluate_files(
    py: Python<'_>,
    paths: Vec<String>,
    standard_key: &str,
    s_from_ranges: bool,
    instrument: Option<&str>,
    jobs: Option<usize>,
) -> PyResult<Vec<Py<PyAny>>> {
    use rayon::prelude::*;
    let request = Request::parse(standard_key, s_from_ranges, instrument)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(jobs.unwrap_or(0))
        .build()
        .map_err(|e| PyValueError::new_err(format!("jobs: {e}")))?;
    let one = |path: &String| {
        let read = measurement::read_file_with(Path::new(path), &ReadOptions::default());
        read.map(|t| request.evaluate(&t.data, t.recognised, path))
    };
    let done: Vec<_> = py.detach(|| pool.install(|| paths.par_iter().map(one).collect()));
    (done.into_iter())
        .map(|r| match r {
            Ok(evaluated) => Ok(Py::new(py, evaluated)?.into_any()),
            Err(e) => Ok(read_error(py, &e).into_value(py).into_any()),
        })
        .collect()
}

/// `diagnose --json` of the measurement: what the standard's model gets wrong, and why.
#[pyfunction]
#[pyo3(signature = (m, standard_key="iso230-2", pitch=None))]
fn diagnose(
    py: Python<'_>,
    m: &Measurement,
    standard_key: &str,
    pitch: Option<f64>,
) -> PyResult<String> {
    let options = axcheck_core::diagnose::Options {
        pitch,
        standard: standard(standard_key)?,
        ..Default::default()
    };
    py.detach(|| {
        let d = axcheck_core::diagnose::diagnose(&m.data, &options);
        json_with_file(d.json(axcheck_campaign::simulate::model_text), &m.file)
    })
}

/// The controller called `name`, or the error that lists the known ones.
fn controller(name: &str) -> PyResult<&'static dyn controllers::Controller> {
    controllers::find(name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown controller `{name}`; known: {}",
            controllers::names().join(", ")
        ))
    })
}

/// A table file read as the controller reads it, the errors as the command line's.
fn table_file(
    path: &str,
    key: &'static str,
    c: &dyn controllers::Controller,
    m: &Measurement,
    axis: Option<&str>,
) -> PyResult<compensate::Table> {
    let at = tables::TableFile::Given {
        path: Path::new(path),
        key,
    };
    tables::read_table(at, c, m.data.kind, axis).map_err(|e| PyValueError::new_err(e.to_string()))
}

/// `compensate --json` with the table file's text (`file_text`): the controller's table
/// for the measurement, on the active table when given (`active`, `"none"` or None for
/// unknown, with `active_backlash`).
#[pyfunction]
#[pyo3(name = "compensate", signature = (m, controller_name, active=None, active_backlash=None, interval=None, reference=None, pitch=None, axis=None, standard_key="iso230-2"))]
#[allow(clippy::too_many_arguments)]
fn compensate_table(
    py: Python<'_>,
    m: &Measurement,
    controller_name: &str,
    active: Option<&str>,
    active_backlash: Option<f64>,
    interval: Option<f64>,
    reference: Option<f64>,
    pitch: Option<f64>,
    axis: Option<&str>,
    standard_key: &str,
) -> PyResult<String> {
    let c = controller(controller_name)?;
    let standard = standard(standard_key)?;
    let state = tables::given_active_state(active, active_backlash, "active", c, m.data.kind, axis)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let settings = Settings {
        interval,
        reference,
        pitch,
        place: TableSlot {
            axis: axis.map(str::to_string),
            measuring_system: None,
            number: None,
        },
        active: state,
        conditions: None,
    };
    py.detach(|| compensation_json(c, m, standard, &settings))
}

fn compensation_json(
    c: &'static dyn controllers::Controller,
    m: &Measurement,
    standard: StandardId,
    settings: &Settings,
) -> PyResult<String> {
    let (done, measured) = compensate::of_measurement(c, &m.data, standard, settings);
    let table = done
        .outcome
        .as_ref()
        .map_err(|refused| PyValueError::new_err(refused.to_string()))?;
    let unit = m.data.kind.deviation_unit();
    /// `compensate --json` and the text of the file it would write.
    #[derive(Serialize)]
    struct WithText<'a> {
        #[serde(flatten)]
        table: TableJson<'a>,
        file_text: &'a str,
    }
    to_json(&WithText {
        table: TableJson::new(&done, table, &measured, unit, None),
        file_text: &table.file,
    })
}

/// `verify --json`: whether the table loaded between `before` and `after` did what it
/// predicted, and if not what went wrong.
#[pyfunction]
#[pyo3(name = "verify", signature = (before, after, controller_name, table, active=None, active_backlash=None, backlash=None, axis=None, standard_key="iso230-2", others=Vec::new()))]
#[allow(clippy::too_many_arguments)]
fn verify_table(
    py: Python<'_>,
    before: &Measurement,
    after: &Measurement,
    controller_name: &str,
    table: &str,
    active: Option<&str>,
    active_backlash: Option<f64>,
    backlash: Option<f64>,
    axis: Option<&str>,
    standard_key: &str,
    others: Vec<(String, String)>,
) -> PyResult<String> {
    let c = controller(controller_name)?;
    let standard = standard(standard_key)?;
    let kind = after.data.kind;
    let others = (others.iter())
        .map(|(axis, path)| tables::other_table(axis, Path::new(path), "others", c, kind))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    let old = tables::given_active_state(active, active_backlash, "active", c, kind, axis)
        .map_err(|e| PyValueError::new_err(e.to_string()))?
        .unwrap_or_default();
    let new = table_file(table, "table", c, after, axis)?;
    let compared = tables::compared_tables(&old, new, table, backlash, c, kind)
        .map_err(|e| PyValueError::new_err(e.to_string()))?;
    py.detach(|| {
        let input = verify::VerifyInput {
            before: &before.data,
            after: &after.data,
            old: compared.old.as_ref(),
            new: &compared.new,
            others: &others,
            controller: Some(c),
            standard,
        };
        let mut v = verify::verify(&input).map_err(|e| PyValueError::new_err(e.to_string()))?;
        v.notes.extend(compared.notes.iter().cloned());
        json_with_file(v.json(), &after.file)
    })
}

/// A test plan before the laser is set up (`axcheck plan`): the standard's targets on the
/// axis, spaced as ISO 230-2 4.2 asks with offsets that sample the declared pitches, or the
/// `targets` given, checked by the test-plan rules; as JSON with the plan file's YAML
/// (`plan -o`).
#[pyfunction]
#[pyo3(signature = (kind, travel, standard_key="iso230-2", pitch=None, scale_pitch=None, runs=None, overrun=5.0, dwell_s=4.0, feed=1000.0, seed=1, targets=None, continuous=false))]
#[allow(clippy::too_many_arguments)]
fn plan(
    kind: &str,
    travel: Vec<f64>,
    standard_key: &str,
    pitch: Option<f64>,
    scale_pitch: Option<f64>,
    runs: Option<usize>,
    overrun: f64,
    dwell_s: f64,
    feed: f64,
    seed: u64,
    targets: Option<Vec<f64>>,
    continuous: bool,
) -> PyResult<String> {
    use axcheck_core::plan::{self, Axis, Motion};
    use axcheck_core::units::{AxisKind, Travel};
    let kind = match kind {
        "linear" => AxisKind::Linear,
        "rotary" => AxisKind::Rotary,
        other => {
            let e = format!("kind: expected linear or rotary, got `{other}`");
            return Err(PyValueError::new_err(e));
        }
    };
    let travel = match travel[..] {
        [l] if l > 0.0 => Travel::Length(l),
        [a, b] if b > a => Travel::Range([a, b]),
        _ => {
            let e = "travel: expected a length > 0 or (start, end) with end > start";
            return Err(PyValueError::new_err(e));
        }
    };
    let axis = Axis {
        kind,
        standard: standard(standard_key)?,
        travel,
        continuous,
        measurement_travel: None,
        pitch,
        scale_pitch,
    };
    let motion = Motion {
        runs,
        overrun,
        dwell_s,
        feed,
        ..Motion::default()
    };
    let made = match targets {
        Some(t) => plan::with_targets(&axis, &motion, t),
        None => plan::plan(&axis, &motion, seed),
    };
    let made = made.map_err(|e| PyValueError::new_err(e.to_string()))?;
    let json = serde_json::json!({
        "targets": made.targets,
        "runs": made.runs,
        "measurement_travel": made.measurement_travel,
        "seed": made.seed,
        "findings": made.findings,
        "yaml": axcheck_campaign::plan::file::to_yaml(&made),
    });
    to_json(&json)
}

/// A summary-table cell as Python sees it (an empty cell is None).
#[derive(IntoPyObject)]
enum CellValue {
    Text(String),
    Int(i64),
    Number(f64),
    Bool(bool),
}

fn cell_value(cell: Cell) -> Option<CellValue> {
    match cell {
        Cell::Text(t) => Some(CellValue::Text(t)),
        Cell::Int(i) => Some(CellValue::Int(i)),
        Cell::Number(x) => Some(CellValue::Number(x)),
        Cell::Bool(b) => Some(CellValue::Bool(b)),
        Cell::Empty => None,
    }
}

/// A campaign as `axcheck check` judges it: the rows of `summary.csv` and the gate.
#[pyclass(frozen, module = "axcheck._axcheck")]
struct Checked {
    rows: Vec<Vec<Cell>>,
    passed: bool,
    counts: String,
}

#[pymethods]
impl Checked {
    /// The columns of `summary.csv`, in order (a stable interface).
    fn columns(&self) -> Vec<String> {
        table::columns().into_iter().map(|(name, _)| name).collect()
    }

    /// One row per axis test, the cells in the columns' order.
    fn rows(&self) -> Vec<Vec<Option<CellValue>>> {
        (self.rows.iter())
            .map(|row| row.iter().cloned().map(cell_value).collect())
            .collect()
    }

    /// Whether every axis passes the gate (`check`'s exit status 0).
    #[getter]
    fn passed(&self) -> bool {
        self.passed
    }

    /// The verdicts counted, as the command line's summary line says them.
    #[getter]
    fn counts(&self) -> &str {
        &self.counts
    }
}

/// `axcheck check`: every axis of the campaign read, evaluated, rule-checked and judged
/// in parallel (with `diagnose`, diagnosed too); nothing written.
#[pyfunction]
#[pyo3(signature = (campaign, diagnose=false))]
fn check(py: Python<'_>, campaign: &str, diagnose: bool) -> PyResult<Checked> {
    py.detach(|| {
        let loaded = Campaign::load(Path::new(campaign))
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        // The readings kept: the table's `m` and `travel` come from them.
        let options = BatchOptions {
            diagnose,
            drop_data: false,
            compensate: false,
            record_inputs: false,
        };
        let result = batch::run(&loaded, options, &|_| {});
        Ok(Checked {
            rows: table::rows(&result),
            passed: result.passes_gate(),
            counts: result.counts_text(),
        })
    })
}

/// The parameters `standard` defines, in its order: key, symbol, name and the clause (and
/// formula) that defines it, as the reports and `eval --json`'s `details` name them.
#[pyfunction]
#[pyo3(signature = (standard_key="iso230-2"))]
fn parameters(
    standard_key: &str,
) -> PyResult<Vec<(&'static str, &'static str, &'static str, &'static str)>> {
    let standard = standard(standard_key)?;
    Ok(axcheck_core::evaluate::catalogue::of(standard)
        .map(|d| (d.key.as_str(), d.symbol, d.name, d.clause))
        .collect())
}

/// The controllers whose tables `compensate` writes.
#[pyfunction]
fn controller_names() -> Vec<&'static str> {
    controllers::names()
}

#[pymodule]
fn _axcheck(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Measurement>()?;
    m.add_class::<Evaluated>()?;
    m.add_class::<Checked>()?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(parameters, m)?)?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(read_text, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(evaluate_files, m)?)?;
    m.add_function(wrap_pyfunction!(diagnose, m)?)?;
    m.add_function(wrap_pyfunction!(other_tests::straightness, m)?)?;
    m.add_function(wrap_pyfunction!(other_tests::angular, m)?)?;
    m.add_function(wrap_pyfunction!(other_tests::squareness, m)?)?;
    m.add_function(wrap_pyfunction!(compensate_table, m)?)?;
    m.add_function(wrap_pyfunction!(verify_table, m)?)?;
    m.add_function(wrap_pyfunction!(controller_names, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
