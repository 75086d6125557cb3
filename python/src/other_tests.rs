//! The other tests of a linear axis for Python: straightness, angular deviation and
//! squareness (ISO 230-1), each returning the JSON `eval --test … --json` prints.

use super::Measurement;
use axcheck_campaign::one_file::{self, OtherOptions};
use axcheck_core::geometry::optics;
use axcheck_core::geometry::uncertainty::Accuracy;
use axcheck_core::geometry::{self, TestKind, line::ReferenceLine};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

/// A straightness or angular test must be of a linear axis.
fn linear(m: &Measurement, test: TestKind) -> PyResult<()> {
    match m.data.kind {
        axcheck_core::units::AxisKind::Linear => Ok(()),
        _ => Err(PyValueError::new_err(format!(
            "{}: a {} test is of a linear axis (targets in mm); this file's targets are in degrees",
            m.file,
            test.key()
        ))),
    }
}

fn reference_line(key: &str) -> PyResult<ReferenceLine> {
    ReferenceLine::parse(key).ok_or_else(|| {
        PyValueError::new_err(format!(
            "line: unknown `{key}`; expected least_squares or end_point"
        ))
    })
}

fn direction_letter(direction: Option<&str>, allowed: &str) -> PyResult<Option<char>> {
    let Some(text) = direction else {
        return Ok(None);
    };
    let upper = text.to_ascii_uppercase();
    match upper.len() == 1 && allowed.contains(upper.as_str()) {
        true => Ok(upper.chars().next()),
        false => Err(PyValueError::new_err(format!(
            "direction: `{text}`; expected one of {allowed}"
        ))),
    }
}

/// The optics' accuracy: (percent, fixed, per metre[, per square metre]) or a preset's
/// name (`"hp5528a_squareness_short"`, `"hp5528a_squareness_long"`; `"hp5528a_short"` as
/// before).
#[derive(FromPyObject)]
pub enum Optics {
    Spec4(f64, f64, f64, f64),
    Spec(f64, f64, f64),
    Preset(String),
}

fn optics(given: Option<Optics>, test: TestKind) -> PyResult<Option<optics::Optics>> {
    let terms =
        |percent: f64, fixed: f64, per_m: f64, per_m2: f64| match [percent, fixed, per_m, per_m2]
            .iter()
            .all(|v| v.is_finite() && *v >= 0.0)
        {
            true => Ok(Some(
                Accuracy {
                    fraction: percent / 100.0,
                    fixed,
                    per_m,
                    per_m2,
                }
                .into(),
            )),
            false => Err(PyValueError::new_err("optics: three or four numbers ≥ 0")),
        };
    match given {
        None => Ok(None),
        Some(Optics::Spec(percent, fixed, per_m)) => terms(percent, fixed, per_m, 0.0),
        Some(Optics::Spec4(percent, fixed, per_m, per_m2)) => terms(percent, fixed, per_m, per_m2),
        Some(Optics::Preset(name)) => optics::Preset::for_test(&name.replace('_', "-"), test)
            .map(|p| Some(p.into()))
            .map_err(|e| {
                PyValueError::new_err(format!("optics: {e}; or (percent, fixed, per_m[, per_m2])"))
            }),
    }
}

/// A straightness or angular test with U, as `eval --test … --json` prints it.
fn other(
    py: Python<'_>,
    m: &Measurement,
    test: TestKind,
    direction: Option<char>,
    options: OtherOptions,
) -> PyResult<String> {
    linear(m, test)?;
    py.detach(|| {
        let done = one_file::evaluate_other(&m.data, test, &options).ok_or_else(|| {
            PyValueError::new_err(format!("{}: the test needs two targets or more", m.file))
        })?;
        one_file::geometry_json(test, direction, &m.data, &done, &m.file, &m.recognised)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    })
}

/// `eval --test straightness --json`: the straightness (ISO 230-1) by `line`
/// (`least_squares` or `end_point`), with the local straightness over `local` mm and U
/// (with the optics' accuracy `optics` when given).
#[pyfunction]
#[pyo3(signature = (m, line="least_squares", local=None, direction=None, optics=None))]
pub fn straightness(
    py: Python<'_>,
    m: &Measurement,
    line: &str,
    local: Option<f64>,
    direction: Option<&str>,
    optics: Option<Optics>,
) -> PyResult<String> {
    let options = OtherOptions {
        straightness: geometry::straightness::Options {
            line: reference_line(line)?,
            local_length_mm: local,
        },
        optics: self::optics(optics, TestKind::Straightness)?,
    };
    let direction = direction_letter(direction, "XYZ")?;
    other(py, m, TestKind::Straightness, direction, options)
}

/// `eval --test angular --json`: the angular deviation of a test read with
/// `read(path, angular=True)`, with U.
#[pyfunction]
#[pyo3(signature = (m, direction=None, optics=None))]
pub fn angular(
    py: Python<'_>,
    m: &Measurement,
    direction: Option<&str>,
    optics: Option<Optics>,
) -> PyResult<String> {
    let options = OtherOptions {
        optics: self::optics(optics, TestKind::Angular)?,
        ..OtherOptions::default()
    };
    let direction = direction_letter(direction, "ABC")?;
    other(py, m, TestKind::Angular, direction, options)
}

/// `eval --test squareness --json`: the squareness of two axes from their straightness
/// tests, θ₂ − θ₁ + the square's error (HP 5528A §21), stated positive when the included
/// angle is larger than 90° (`over_90`) or smaller (`under_90`), with U.
#[pyfunction]
#[pyo3(signature = (first, second, line="least_squares", square_error=0.0, convention="over_90", square_u=None, optics=None))]
#[allow(clippy::too_many_arguments)]
pub fn squareness(
    first: &Measurement,
    second: &Measurement,
    line: &str,
    square_error: f64,
    convention: &str,
    square_u: Option<f64>,
    optics: Option<Optics>,
) -> PyResult<String> {
    use geometry::squareness::Convention;
    let convention = match convention.replace('-', "_").as_str() {
        "over_90" => Convention::OverNinetyPositive,
        "under_90" => Convention::UnderNinetyPositive,
        _ => {
            return Err(PyValueError::new_err(format!(
                "convention: `{convention}`; expected over_90 or under_90"
            )));
        }
    };
    linear(first, TestKind::Straightness)?;
    linear(second, TestKind::Straightness)?;
    let options = one_file::SquarenessOptions {
        line: reference_line(line)?,
        square_error_arcsec: square_error,
        square_u_arcsec: square_u,
        convention,
        optics: self::optics(optics, TestKind::Squareness)?,
    };
    let done = one_file::evaluate_squareness(&first.data, &second.data, &options).map_err(|k| {
        let file = [&first.file, &second.file][k - 1];
        PyValueError::new_err(format!("{file}: a straightness needs two targets or more"))
    })?;
    done.json(
        (&first.file, &first.recognised),
        (&second.file, &second.recognised),
    )
    .map_err(|e| PyValueError::new_err(e.to_string()))
}
