//! Machines and axes of a campaign, loaded one by one: a broken one becomes an entry
//! with its error (file, line, column), and the rest of the campaign is still evaluated.

use super::data::DataSource;
use super::{
    AxisEntry, AxisRaw, AxisSpec, CampaignInfo, Machine, MachineInfo, Place, model, parse_standard,
};
use crate::evaluate::StandardId;
use crate::units::{AxisKind, Travel};
use crate::yaml::{self, Located, LocationIndex, YamlError, deserialize_at};
use serde_norway::Value;
use std::sync::Arc;

/// The machine at `base` with its axes; a machine that cannot be read fails each of its
/// axes with its error.
pub(super) fn machine(
    value: &Value,
    base: &str,
    index: &Arc<LocationIndex>,
    file: &str,
    campaign: &CampaignInfo,
    standard: StandardId,
) -> Machine {
    let info = match deserialize_at::<MachineInfo>(value, base, index) {
        Ok(info) => info,
        Err(e) => return broken_machine(value, base, e.in_file(file)),
    };
    if let Some(name) = &info.controller
        && crate::compensate::controllers::find(name).is_none()
    {
        let names = crate::compensate::controllers::names();
        let hint = crate::suggest::hint(name, &names);
        let path = format!("{base}.controller");
        let message = format!("{path}: unknown controller `{name}`{hint}");
        let located = Located::new(index.value(&path), message);
        return broken_machine(value, base, located.in_file(file));
    }
    if let Some(c) = &info.certificate {
        let path = format!("{base}.certificate");
        if let Err(located) = super::certificate::check(c, &path, campaign.date.as_deref(), index) {
            return broken_machine(value, base, located.in_file(file));
        }
    }
    let axes = match value.get("axes") {
        Some(Value::Sequence(items)) => items
            .iter()
            .enumerate()
            .map(|(a, v)| {
                let base = format!("{base}.axes[{a}]");
                let entry = axis(v, a, &base, index, file, campaign, standard);
                comp_file_type_fits(entry, info.controller.as_deref(), &base, index, file)
            })
            .collect(),
        None | Some(Value::Null) => Vec::new(),
        Some(other) => vec![AxisEntry {
            name: "axes".into(),
            spec: Err(Located::new(
                index.value(&format!("{base}.axes")),
                format!(
                    "{base}.axes: expected a list of axes, got {}",
                    yaml::describe(other)
                ),
            )
            .in_file(file)),
        }],
    };
    let squareness = super::squareness::entries(value.get("squareness"), base, index, file, &axes);
    Machine {
        info,
        axes,
        squareness,
    }
}

/// An axis that asks for a LinuxCNC comp file type on a machine whose controller is not
/// LinuxCNC fails with where it asks.
fn comp_file_type_fits(
    entry: AxisEntry,
    controller: Option<&str>,
    base: &str,
    index: &LocationIndex,
    file: &str,
) -> AxisEntry {
    let asks = entry.spec.as_ref().is_ok_and(|s| {
        s.raw
            .compensation
            .as_ref()
            .is_some_and(|c| c.comp_file_type.is_some())
    });
    use crate::compensate::controllers::{Controller, linuxcnc::LinuxCnc};
    let linuxcnc = LinuxCnc::TYPE_0.name();
    if !asks || controller == Some(linuxcnc) {
        return entry;
    }
    let path = format!("{base}.compensation.comp_file_type");
    let has = controller.map_or("names no controller".to_string(), |c| {
        format!("has controller {c}")
    });
    let message = format!("{path}: LinuxCNC's COMP_FILE_TYPE, but the machine {has}");
    AxisEntry {
        spec: Err(Located::new(index.key(&path), message).in_file(file)),
        ..entry
    }
}

/// A machine that cannot be read: each of its axes reports why (or one entry if none).
fn broken_machine(value: &Value, base: &str, error: YamlError) -> Machine {
    let id = value
        .get("id")
        .and_then(|v| v.as_str())
        .map_or_else(|| base.to_string(), str::to_string);
    let mut names: Vec<String> = match value.get("axes") {
        Some(Value::Sequence(items)) => items
            .iter()
            .enumerate()
            .map(|(a, v)| axis_name(v, a))
            .collect(),
        _ => Vec::new(),
    };
    if names.is_empty() {
        names.push("(all axes)".to_string());
    }
    Machine {
        info: MachineInfo {
            id,
            ..MachineInfo::default()
        },
        axes: names
            .into_iter()
            .map(|name| AxisEntry {
                name,
                spec: Err(error.clone()),
            })
            .collect(),
        squareness: Vec::new(),
    }
}

/// The axis's name as written, or `axis N` (1-based) when it has none that reads.
fn axis_name(value: &Value, a: usize) -> String {
    value
        .get("name")
        .and_then(|v| {
            v.as_str()
                .map(str::to_string)
                .or_else(|| v.as_i64().map(|n| n.to_string()))
        })
        .unwrap_or_else(|| format!("axis {}", a + 1))
}

/// The axis `a` of a machine, at `base` in the document.
fn axis(
    value: &Value,
    a: usize,
    base: &str,
    index: &Arc<LocationIndex>,
    file: &str,
    campaign: &CampaignInfo,
    default_standard: StandardId,
) -> AxisEntry {
    let spec = validated_axis(value, base, index, default_standard).map(|(raw, standard, data)| {
        AxisSpec {
            standard,
            // `spec: none` opts an axis out of the campaign's default spec.
            spec: match raw.spec.as_deref() {
                // The other tests' limits are their own `tolerance:` (no spec holds them).
                _ if raw.test != crate::geometry::TestKind::Positioning => None,
                Some("none") => None,
                Some(name) => Some(name.to_string()),
                None => campaign.spec.clone().filter(|s| s != "none"),
            },
            data,
            at: Place::new(index, base),
            raw,
        }
    });
    AxisEntry {
        name: axis_name(value, a),
        spec: spec.map(Arc::new).map_err(|e| e.in_file(file)),
    }
}

/// The axis as written, its standard and its data source, each value checked.
fn validated_axis(
    value: &Value,
    base: &str,
    index: &LocationIndex,
    default_standard: StandardId,
) -> Result<(AxisRaw, StandardId, DataSource), Located> {
    let mut raw: AxisRaw = deserialize_at(value, base, index)?;
    check_name(&raw, base, index)?;
    let standard = match &raw.standard {
        None => default_standard,
        Some(s) => parse_standard(s, &format!("{base}.standard"), index)?,
    };
    let data = DataSource::from_value(&raw.data).map_err(|bad| {
        let path = format!("{base}.data{}", bad.path);
        let at = if bad.at_key {
            index.key_or_value(&path)
        } else {
            index.value(&path)
        };
        Located::new(at, format!("{path}: {}", bad.message))
    })?;
    check_travels(&raw, base, index)?;
    check_pitch(&raw, base, index)?;
    check_thermal_origin(&raw, base, index)?;
    check_compensation(&raw, base, index)?;
    check_plan(&raw, base, index)?;
    check_tolerances(&mut raw, base, index)?;
    super::geometry::check(&mut raw, base, index)?;
    check_instrument(&raw, base, index)?;
    Ok((raw, standard, data))
}

/// An axis has a name: it names the axis in every output and, with the machine's id, its
/// series in the history.
fn check_name(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    if !raw.name.trim().is_empty() {
        return Ok(());
    }
    let path = format!("{base}.name");
    Err(Located::new(
        index.value(&path),
        format!(
            "{path}: the axis name is empty; name the axis as the machine does (X, Y, Z, A, B, C …)"
        ),
    ))
}

/// The instrument's stated accuracy, resolution, dead path and beam walk are numbers ≥ 0
/// (a coverage factor > 0): they enter the uncertainty budget.
fn check_instrument(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let Some(i) = &raw.conditions.instrument else {
        return Ok(());
    };
    let unit = raw.kind.deviation_unit();
    let (accuracy, resolution) = (format!("accuracy_{unit}"), format!("resolution_{unit}"));
    let fields = [
        (accuracy.as_str(), i.accuracy_fixed, false),
        ("accuracy_ppm", i.accuracy_ppm, false),
        ("accuracy_k", i.accuracy_k, true),
        (resolution.as_str(), i.resolution, false),
        ("dead_path_mm", i.dead_path_mm, false),
        ("beam_walk_mm", i.beam_walk_mm, false),
    ];
    if let Some(c) = &i.calibration
        && let (Some(on), Some(due)) = (&c.calibrated_on, &c.due)
        && due < on
    {
        let path = format!("{base}.conditions.instrument.calibration.due");
        return Err(Located::new(
            index.value(&path),
            format!("{path}: {due} is before the calibration on {on}"),
        ));
    }
    for (key, value, positive) in fields {
        let Some(v) = value else { continue };
        let ok = v.is_finite() && if positive { v > 0.0 } else { v >= 0.0 };
        if !ok {
            let path = format!("{base}.conditions.instrument.{key}");
            let want = if positive { "> 0" } else { "≥ 0" };
            return Err(Located::new(
                index.value(&path),
                format!("{path}: expected a number {want}, got {v}"),
            ));
        }
    }
    Ok(())
}

/// Axis travel: a length > 0 or two ends in order; measurement travel: first < last.
fn check_travels(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let at = |key: &str| index.value(&format!("{base}.{key}"));
    if let Some(t) = raw.travel {
        let ok = match t {
            Travel::Length(l) => l > 0.0 && l.is_finite(),
            Travel::Range([a, b]) => b > a && a.is_finite() && b.is_finite(),
        };
        if !ok {
            return Err(Located::new(
                at("travel"),
                format!("{base}.travel: expected a length > 0 or [start, end] with end > start"),
            ));
        }
    }
    if let Some([a, b]) = raw.measurement_travel
        && !(b > a && a.is_finite() && b.is_finite())
    {
        return Err(Located::new(
            at("measurement_travel"),
            format!("{base}.measurement_travel: expected [first, last] with last > first"),
        ));
    }
    Ok(())
}

fn check_pitch(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    match raw.pitch {
        Some(p) if !(p > 0.0 && p.is_finite()) => Err(Located::new(
            index.value(&format!("{base}.pitch")),
            format!("{base}.pitch: expected a pitch > 0"),
        )),
        _ => Ok(()),
    }
}

/// A thermal origin is a finite position.
fn check_thermal_origin(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    match raw.thermal_origin {
        Some(p) if !p.is_finite() => Err(Located::new(
            index.value(&format!("{base}.thermal_origin")),
            format!("{base}.thermal_origin: expected a position (mm or deg)"),
        )),
        _ => Ok(()),
    }
}

/// A plan's tolerance is a distance > 0.
fn check_plan(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    match raw.plan.as_ref().and_then(|p| p.tolerance) {
        Some(t) if !(t > 0.0 && t.is_finite()) => {
            let path = format!("{base}.plan.tolerance");
            Err(Located::new(
                index.value(&path),
                format!("{path}: expected a distance > 0"),
            ))
        }
        _ => Ok(()),
    }
}

/// The table's interval is > 0 and its reference a finite position.
fn check_compensation(raw: &AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let Some(c) = &raw.compensation else {
        return Ok(());
    };
    let bad = |key: &str, want: &str| {
        let path = format!("{base}.compensation.{key}");
        Err(Located::new(
            index.value(&path),
            format!("{path}: expected {want}"),
        ))
    };
    if let Some(i) = c.interval
        && !(i > 0.0 && i.is_finite())
    {
        return bad("interval", "an interval > 0");
    }
    if let Some(r) = c.reference
        && !r.is_finite()
    {
        return bad("reference", "a position");
    }
    if let Some(m) = c.measuring_system
        && m > 1
    {
        return bad(
            "measuring_system",
            "0 (the first encoder) or 1 (a direct measuring system)",
        );
    }
    if let Some(t) = c.comp_file_type
        && t > 1
    {
        return bad(
            "comp_file_type",
            "LinuxCNC's COMP_FILE_TYPE, 0 (actual positions) or 1 (trims)",
        );
    }
    let base = format!("{base}.compensation");
    if let Some(model::ActiveRaw::Stated(a)) = &c.active {
        check_backlash(
            raw.kind,
            a.backlash_um,
            a.backlash_arcsec,
            &format!("{base}.active"),
            index,
        )?;
    }
    if let Some(v) = &c.verifies {
        let at = format!("{base}.verifies");
        check_backlash(raw.kind, v.backlash_um, v.backlash_arcsec, &at, index)?;
        if let Some(model::ActiveRaw::Stated(a)) = &v.active {
            check_backlash(
                raw.kind,
                a.backlash_um,
                a.backlash_arcsec,
                &format!("{at}.active"),
                index,
            )?;
        }
    }
    Ok(())
}

/// A backlash in the axis's deviation unit (`backlash_um` on a linear axis,
/// `backlash_arcsec` on a rotary one), a finite number.
fn check_backlash(
    kind: AxisKind,
    um: Option<f64>,
    arcsec: Option<f64>,
    base: &str,
    index: &LocationIndex,
) -> Result<(), Located> {
    let (right, wrong, value, other) = match kind {
        AxisKind::Linear => ("backlash_um", "backlash_arcsec", um, arcsec),
        AxisKind::Rotary => ("backlash_arcsec", "backlash_um", arcsec, um),
    };
    if other.is_some() {
        let path = format!("{base}.{wrong}");
        return Err(Located::new(
            index.key(&path),
            format!("{path}: a {kind} axis states its backlash as {right}"),
        ));
    }
    match value {
        Some(v) if !v.is_finite() => {
            let path = format!("{base}.{right}");
            Err(Located::new(
                index.value(&path),
                format!("{path}: expected a number"),
            ))
        }
        _ => Ok(()),
    }
}

/// Every limit names a parameter that can be limited, and is a number ≥ 0 (the check
/// specs share: [`crate::judge::check_tolerances`]): the written limits become the axis's
/// typed `tolerances`.
fn check_tolerances(raw: &mut AxisRaw, base: &str, index: &LocationIndex) -> Result<(), Located> {
    let written = std::mem::take(&mut raw.written_tolerances);
    raw.tolerances = crate::judge::check_tolerances(base, &written, index)?;
    Ok(())
}
