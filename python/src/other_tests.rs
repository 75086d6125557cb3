//! The other tests of a linear axis for Python: straightness, angular deviation and
//! squareness (ISO 230-1), each returning the JSON `eval --test … --json` prints.

use super::{Measurement, to_json};
use axcheck_campaign::one_file;
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

/// `eval --test straightness --json`: the straightness (ISO 230-1) by `line`
/// (`least_squares` or `end_point`), with the local straightness over `local` mm.
#[pyfunction]
#[pyo3(signature = (m, line="least_squares", local=None, direction=None))]
pub fn straightness(
    py: Python<'_>,
    m: &Measurement,
    line: &str,
    local: Option<f64>,
    direction: Option<&str>,
) -> PyResult<String> {
    linear(m, TestKind::Straightness)?;
    let direction = direction_letter(direction, "XYZ")?;
    let options = geometry::straightness::Options {
        line: reference_line(line)?,
        local_length_mm: local,
    };
    py.detach(|| {
        let s = geometry::straightness::evaluate(&m.data, &options).ok_or_else(|| {
            PyValueError::new_err(format!(
                "{}: a straightness needs two targets or more",
                m.file
            ))
        })?;
        let test = TestKind::Straightness;
        one_file::geometry_json(test, direction, &m.data, &s, &m.file, &m.recognised)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    })
}

/// `eval --test angular --json`: the angular deviation of a test read with
/// `read(path, angular=True)`.
#[pyfunction]
#[pyo3(signature = (m, direction=None))]
pub fn angular(py: Python<'_>, m: &Measurement, direction: Option<&str>) -> PyResult<String> {
    linear(m, TestKind::Angular)?;
    let direction = direction_letter(direction, "ABC")?;
    py.detach(|| {
        let a = geometry::angular::evaluate(&m.data)
            .ok_or_else(|| PyValueError::new_err("no target"))?;
        let test = TestKind::Angular;
        one_file::geometry_json(test, direction, &m.data, &a, &m.file, &m.recognised)
            .map_err(|e| PyValueError::new_err(e.to_string()))
    })
}

/// `eval --test squareness --json`: the squareness of two axes from their straightness
/// tests, θ₂ − θ₁ + the square's error (HP 5528A §21), stated positive when the included
/// angle is larger than 90° (`over_90`) or smaller (`under_90`).
#[pyfunction]
#[pyo3(signature = (first, second, line="least_squares", square_error=0.0, convention="over_90"))]
pub fn squareness(
    first: &Measurement,
    second: &Measurement,
    line: &str,
    square_error: f64,
    convention: &str,
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
    let method = reference_line(line)?;
    let trace = |m: &Measurement| -> PyResult<geometry::straightness::Trace> {
        linear(m, TestKind::Straightness)?;
        let options = geometry::straightness::Options {
            line: method,
            local_length_mm: None,
        };
        geometry::straightness::evaluate(&m.data, &options)
            .map(|s| s.bidirectional)
            .ok_or_else(|| {
                PyValueError::new_err(format!(
                    "{}: a straightness needs two targets or more",
                    m.file
                ))
            })
    };
    let (a, b) = (trace(first)?, trace(second)?);
    let sq = geometry::squareness::evaluate(&a.line, &b.line, square_error, convention);
    to_json(&one_file::SquarenessJson {
        test: TestKind::Squareness,
        line: method,
        squareness: &sq,
        first: one_file::SquarenessSide {
            file: &first.file,
            recognised: &first.recognised,
            straightness: &a,
        },
        second: one_file::SquarenessSide {
            file: &second.file,
            recognised: &second.recognised,
            straightness: &b,
        },
    })
}
