//! A machine's `squareness:` pairs: each read and checked where it is written (its
//! tolerances' form, its two straightness tests among the machine's axis entries), so
//! that a pair that names a test the campaign does not hold stops at its line and the
//! machine's other tests still run.

use super::geometry::axis_letter;
use super::model::SquarenessRaw;
use super::{AxisEntry, AxisSpec};
use crate::geometry::TestKind;
use crate::geometry::judge::limits;
use crate::geometry::tolerance::Tolerance;
use crate::yaml::{self, Located, LocationIndex, YamlError, deserialize_at};
use serde_norway::Value;
use std::sync::Arc;

/// A squareness as loaded: its two axes (`X-Y`) and its spec, or why it cannot be.
#[derive(Debug, Clone)]
pub struct SquarenessEntry {
    pub axes: String,
    pub spec: Result<Arc<SquarenessSpec>, YamlError>,
}

/// A squareness ready to evaluate: as written, and its two straightness tests.
#[derive(Debug, Clone)]
pub struct SquarenessSpec {
    pub raw: SquarenessRaw,
    /// The axis entries of the first axis's straightness along the second, and the other.
    pub tests: [Arc<AxisSpec>; 2],
}

/// The machine's `squareness:` list at `base`.
pub(super) fn entries(
    value: Option<&Value>,
    base: &str,
    index: &LocationIndex,
    file: &str,
    axes: &[AxisEntry],
) -> Vec<SquarenessEntry> {
    let path = format!("{base}.squareness");
    match value {
        None | Some(Value::Null) => Vec::new(),
        Some(Value::Sequence(items)) => (items.iter().enumerate())
            .map(|(k, v)| {
                let base = format!("{path}[{k}]");
                let axes_label = label(v);
                SquarenessEntry {
                    axes: axes_label,
                    spec: entry(v, &base, index, axes)
                        .map(Arc::new)
                        .map_err(|e| e.in_file(file)),
                }
            })
            .collect(),
        Some(other) => vec![SquarenessEntry {
            axes: "squareness".into(),
            spec: Err(Located::new(
                index.value(&path),
                format!(
                    "{path}: expected a list of {{axes: [X, Y], …}}, got {}",
                    yaml::describe(other)
                ),
            )
            .in_file(file)),
        }],
    }
}

/// `X-Y` from `axes: [X, Y]` (as far as it can be read).
fn label(v: &Value) -> String {
    let names: Vec<String> = (v
        .get("axes")
        .and_then(Value::as_sequence)
        .into_iter()
        .flatten())
    .map(|n| n.as_str().map_or_else(|| format!("{n:?}"), str::to_string))
    .collect();
    match names.is_empty() {
        true => "squareness".into(),
        false => names.join("-"),
    }
}

fn entry(
    value: &Value,
    base: &str,
    index: &LocationIndex,
    axes: &[AxisEntry],
) -> Result<SquarenessSpec, Located> {
    let mut raw: SquarenessRaw = deserialize_at(value, base, index)?;
    let refuse = |key: &str, why: String| {
        let path = format!("{base}.{key}");
        Located::new(
            index.value(&path).or_else(|| index.key(base)),
            format!("{path}: {why}"),
        )
    };
    let written = std::mem::take(&mut raw.written_tolerance);
    let mut read = Vec::with_capacity(written.len());
    for text in written {
        match Tolerance::parse(&text) {
            Ok(t) => read.push((text, t)),
            Err(e) => return Err(refuse("tolerance", e.to_string())),
        }
    }
    limits(TestKind::Squareness, &read, 1.0).map_err(|e| refuse("tolerance", e.to_string()))?;
    raw.tolerance = read;
    raw.optics =
        super::geometry::optics(raw.written_optics.take(), TestKind::Squareness, base, index)?;
    if let Some(u) = raw.square_u_arcsec
        && !(u >= 0.0 && u.is_finite())
    {
        return Err(refuse(
            "square_u_arcsec",
            format!("expected a standard uncertainty ≥ 0 (arcsec), got {u}"),
        ));
    }
    if !raw.square_error_arcsec.is_finite() {
        return Err(refuse(
            "square_error_arcsec",
            "expected an angle in arcsec".into(),
        ));
    }
    let [a, b] = &raw.axes;
    let (Some(la), Some(lb)) = (axis_letter(a), axis_letter(b)) else {
        return Err(refuse(
            "axes",
            format!("expected two linear axes named X, Y or Z, got `{a}` and `{b}`"),
        ));
    };
    if la == lb {
        return Err(refuse(
            "axes",
            format!("a squareness is of two axes; `{a}` and `{b}` are along one"),
        ));
    }
    let find = |name: &str, along: char| {
        straightness_of(axes, name, along).ok_or_else(|| {
            refuse(
                "axes",
                format!(
                    "the squareness of {a} and {b} takes the straightness of {name} along {along} (E{along}{name}): no axis entry `{name}` with `test: straightness` and `direction: {along}` in this machine"
                ),
            )
        })
    };
    let tests = [find(a, lb)?, find(b, la)?];
    Ok(SquarenessSpec { raw, tests })
}

/// The machine's straightness test of axis `name` along `along`.
fn straightness_of(axes: &[AxisEntry], name: &str, along: char) -> Option<Arc<AxisSpec>> {
    (axes.iter().filter_map(|e| e.spec.as_ref().ok()))
        .find(|s| {
            s.raw.name == name
                && s.raw.test == TestKind::Straightness
                && s.raw.direction.map(|c| c.to_ascii_uppercase()) == Some(along)
        })
        .cloned()
}
