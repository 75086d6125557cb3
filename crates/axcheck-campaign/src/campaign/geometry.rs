//! An axis entry's other laser test (`test: straightness|angular`, ISO 230-1): its keys
//! checked where they are written, so that a wrong letter or a tolerance of the wrong
//! form stops at its line and not after the measurement is read.

use super::AxisRaw;
use super::model::OpticsStatedRaw;
use crate::geometry::TestKind;
use crate::geometry::judge::limits;
use crate::geometry::optics::{Optics, OpticsError, Preset};
use crate::geometry::tolerance::Tolerance;
use crate::geometry::uncertainty::Accuracy;
use crate::units::AxisKind;
use crate::yaml::{self, Located, LocationIndex, deserialize_at};
use serde_norway::Value;

/// The keys of a positioning test that the other tests do not take, with what they are.
const POSITIONING_ONLY: [&str; 7] = [
    "tolerances",
    "compensation",
    "plan",
    "pitch",
    "thermal_origin",
    "s_from_ranges",
    "spec",
];

/// Checks the test's keys and reads its tolerances into `raw.tolerance`.
pub(super) fn check(raw: &mut AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let at = |key: &str| {
        let path = format!("{base}.{key}");
        (index.key(&path).or_else(|| index.value(&path)), path)
    };
    let refuse = |key: &str, why: String| {
        let (place, path) = at(key);
        Err(Located::new(place, format!("{path}: {why}")))
    };
    let test = raw.test;
    check_tool_point(raw, base, index)?;
    super::cross::check(raw, base, index)?;
    if test == TestKind::Positioning {
        for (key, given) in geometry_keys(raw) {
            if given {
                return refuse(
                    key,
                    format!(
                        "`{key}` belongs to a straightness or angular test; add `test: straightness` or `test: angular`"
                    ),
                );
            }
        }
        return Ok(());
    }
    if test == TestKind::Squareness {
        return refuse(
            "test",
            "a squareness is two straightness tests of two axes; evaluate it with `axcheck eval --test squareness` (a campaign does not hold squareness pairs yet)".into(),
        );
    }
    if raw.kind != AxisKind::Linear {
        return refuse(
            "test",
            format!(
                "a {} test is of a linear axis; this axis is rotary",
                test.key()
            ),
        );
    }
    for key in POSITIONING_ONLY {
        // A straightness's table is the cross table (checked by `super::cross`).
        let cross = key == "compensation" && test == TestKind::Straightness;
        if index.key(&format!("{base}.{key}")).is_some() && !cross {
            return refuse(
                key,
                format!(
                    "`{key}` belongs to a positioning test; a {} test takes `tolerance:` (e.g. `0.020 per 1000`)",
                    test.key()
                ),
            );
        }
    }
    check_letters(raw, base, index)?;
    if let Some(l) = raw.local_mm
        && !(l > 0.0 && l.is_finite())
    {
        return refuse("local_mm", format!("expected a length > 0 (mm), got {l}"));
    }
    let written = std::mem::take(&mut raw.written_tolerance);
    let mut read = Vec::with_capacity(written.len());
    for text in written {
        match Tolerance::parse(&text) {
            Ok(t) => read.push((text, t)),
            Err(e) => return refuse("tolerance", e.to_string()),
        }
    }
    // The form of each (the length does not change which value a form limits).
    if let Err(e) = limits(test, &read, 1.0) {
        return refuse("tolerance", e.to_string());
    }
    let local = read.iter().find_map(|(_, t)| t.local());
    if let (Some(l), Some((_, over))) = (raw.local_mm, local)
        && (l - over).abs() > 1e-9
    {
        return refuse(
            "local_mm",
            format!(
                "the local straightness is over {l} mm but its tolerance is over any {over} mm; write one length"
            ),
        );
    }
    raw.tolerance = read;
    raw.optics = optics(raw.written_optics.take(), test, base, index)?;
    Ok(())
}

/// The `optics:` at `base` of a test of kind `test`: a preset's name stated for that kind
/// of test, or the specification's terms (`{percent, fixed, per_m, per_m2}`, each ≥ 0, in
/// the result's unit).
pub(super) fn optics(
    written: Option<Value>,
    test: TestKind,
    base: &str,
    index: &LocationIndex,
) -> Result<Option<Optics>, Located> {
    let path = format!("{base}.optics");
    let refuse = |at: &str, why: String| {
        Located::new(
            index.value(at).or_else(|| index.key(&path)),
            format!("{at}: {why}"),
        )
    };
    let unit = match test {
        TestKind::Straightness => "µm",
        _ => "arcsec",
    };
    let form = format!("{{percent: , fixed: , per_m: , per_m2: }} (in {unit})");
    let Some(value) = written else {
        return Ok(None);
    };
    match value {
        Value::Null => Ok(None),
        Value::String(name) => match Preset::for_test(&name, test) {
            Ok(p) => Ok(Some(p.into())),
            Err(e @ OpticsError::Unknown(_)) => Err(refuse(
                &path,
                format!("{e}; or state the specification as {form}"),
            )),
            Err(e) => Err(refuse(&path, e.to_string())),
        },
        Value::Mapping(_) => {
            let stated: OpticsStatedRaw = deserialize_at(&value, &path, index)?;
            let terms = [
                ("percent", stated.percent),
                ("fixed", stated.fixed),
                ("per_m", stated.per_m),
                ("per_m2", stated.per_m2),
            ];
            if terms.iter().all(|(_, v)| v.is_none()) {
                return Err(refuse(
                    &path,
                    format!("state the optics' accuracy as {form}, or a preset's name"),
                ));
            }
            for (key, v) in terms {
                if let Some(v) = v
                    && !(v >= 0.0 && v.is_finite())
                {
                    return Err(refuse(
                        &format!("{path}.{key}"),
                        format!("expected a number ≥ 0, got {v}"),
                    ));
                }
            }
            Ok(Some(
                Accuracy {
                    fraction: stated.percent.unwrap_or(0.0) / 100.0,
                    fixed: stated.fixed.unwrap_or(0.0),
                    per_m: stated.per_m.unwrap_or(0.0),
                    per_m2: stated.per_m2.unwrap_or(0.0),
                }
                .into(),
            ))
        }
        other => Err(refuse(
            &path,
            format!(
                "expected a preset's name ({}) or {form}, got {}",
                Accuracy::preset_names().join(", "),
                yaml::describe(&other)
            ),
        )),
    }
}

/// A tool point is of a positioning test of a linear axis X, Y or Z, offset across it by
/// finite distances.
fn check_tool_point(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let Some(tool) = &raw.tool_point else {
        return Ok(());
    };
    let path = format!("{base}.tool_point");
    let refuse = |why: String| Err(Located::new(index.key(&path), format!("{path}: {why}")));
    if raw.test != TestKind::Positioning || raw.kind != AxisKind::Linear {
        return refuse("a tool point is of a positioning test of a linear axis".into());
    }
    let Some(own) = axis_letter(&raw.name) else {
        return refuse(format!(
            "the axis `{}` is not named X, Y or Z: which offsets are across it is not known",
            raw.name
        ));
    };
    let given = [('X', tool.x_mm), ('Y', tool.y_mm), ('Z', tool.z_mm)];
    for (letter, value) in given {
        match value {
            Some(_) if letter == own => {
                return refuse(format!(
                    "`{}_mm` is along the axis itself; give the offsets across it ({})",
                    letter.to_ascii_lowercase(),
                    across(own)
                        .map(|c| format!("{}_mm", c.to_ascii_lowercase()))
                        .join(", ")
                ));
            }
            Some(v) if !v.is_finite() => {
                return refuse(format!("expected a distance in mm, got {v}"));
            }
            _ => {}
        }
    }
    if given.iter().all(|(_, v)| v.is_none()) {
        return refuse(
            "give the offsets of the tool point from the beam, e.g. {y_mm: 0, z_mm: 150}".into(),
        );
    }
    Ok(())
}

/// The axis letter `X`, `Y` or `Z` an axis's name starts with (`X`, `x`, `X1`).
pub fn axis_letter(name: &str) -> Option<char> {
    let c = name.trim().chars().next()?.to_ascii_uppercase();
    matches!(c, 'X' | 'Y' | 'Z').then_some(c)
}

/// The two axes across `letter`, in ISO 841's cyclic order (X: Y, Z; Y: Z, X; Z: X, Y),
/// as `geometry::abbe` takes them.
pub fn across(letter: char) -> [char; 2] {
    match letter {
        'X' => ['Y', 'Z'],
        'Y' => ['Z', 'X'],
        _ => ['X', 'Y'],
    }
}

/// The rotation about `letter`: A about X, B about Y, C about Z.
pub fn rotation_about(letter: char) -> char {
    match letter {
        'X' => 'A',
        'Y' => 'B',
        _ => 'C',
    }
}

/// The other tests' keys and whether each is written.
fn geometry_keys(raw: &AxisRaw) -> [(&'static str, bool); 6] {
    [
        ("direction", raw.direction.is_some()),
        ("about", raw.about.is_some()),
        ("line", raw.line.is_some()),
        ("local_mm", raw.local_mm.is_some()),
        ("tolerance", !raw.written_tolerance.is_empty()),
        ("optics", raw.written_optics.is_some()),
    ]
}

/// A straightness names the axis its deviation is along (`X`, `Y`, `Z`, not the axis's
/// own), an angular test the axis its rotation is about (`A`, `B`, `C`); neither takes
/// the other's key.
fn check_letters(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let located = |key: &str, why: String| {
        let path = format!("{base}.{key}");
        let place = index.value(&path).or_else(|| index.key(base));
        Located::new(place, format!("{path}: {why}"))
    };
    let own = raw
        .name
        .trim()
        .chars()
        .next()
        .map(|c| c.to_ascii_uppercase());
    match raw.test {
        TestKind::Straightness => {
            if raw.about.is_some() {
                return Err(located(
                    "about",
                    "a straightness test takes `direction:`, not `about:`".into(),
                ));
            }
            match raw.direction.map(|c| c.to_ascii_uppercase()) {
                None => Err(located(
                    "direction",
                    "a straightness test states the direction of its deviation: `direction: Y` or `Z` for an X axis (EYX, EZX)".into(),
                )),
                Some(d) if !matches!(d, 'X' | 'Y' | 'Z') => Err(located(
                    "direction",
                    format!("expected X, Y or Z (the axis the deviation is along), got `{d}`"),
                )),
                Some(d) if Some(d) == own && raw.name.trim().len() == 1 => Err(located(
                    "direction",
                    format!("a straightness of axis {d} is across it: Y or Z for X, X or Z for Y, X or Y for Z"),
                )),
                Some(_) => Ok(()),
            }
        }
        _ => {
            for key in ["direction", "line", "local_mm"] {
                let given = geometry_keys(raw).iter().any(|(k, g)| *k == key && *g);
                if given {
                    return Err(located(
                        key,
                        format!("`{key}` belongs to a straightness test, not an angular one"),
                    ));
                }
            }
            match raw.about.map(|c| c.to_ascii_uppercase()) {
                None => Err(located(
                    "about",
                    "an angular test states the axis its rotation is about: `about: A` (roll), `B` (pitch) or `C` (yaw) of an X axis".into(),
                )),
                Some('A' | 'B' | 'C') => Ok(()),
                Some(c) => Err(located(
                    "about",
                    format!("expected A, B or C (rotation about X, Y or Z), got `{c}`"),
                )),
            }
        }
    }
}

/// ISO 230-1's symbol of the test of axis `axis`: `EYX` for a straightness in Y of X,
/// `EBX` for a rotation about Y of X; the axis's name when it is not one letter.
pub fn symbol(raw: &AxisRaw) -> Option<String> {
    let letter = match raw.test {
        TestKind::Straightness => raw.direction?,
        TestKind::Angular => raw.about?,
        _ => return None,
    };
    Some(format!(
        "E{}{}",
        letter.to_ascii_uppercase(),
        raw.name.trim()
    ))
}
