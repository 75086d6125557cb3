//! ReadAs `%_N_AX_EEC_INI` as the NC runs it: a part program of assignments, the last one
//! to a variable standing. Comments after `;`, block numbers (`N10`), the `%` line,
//! `CHANDATA(n)` and the end (`M17`, `M30`, `M2`) are skipped; names are read in any case.
//! A file may hold several axes and both measuring systems: the axis is the one named
//! (`--axis`, `compensation.axis`), else the only one. The points are `MIN + N·STEP` for N
//! = 0 … (MAX − MIN)/STEP; values beyond MAX are not used by the NC (an archive holds all
//! of MD38000's points) and are not read.

use super::super::controller::{ReadAs, Unreadable};
use super::super::reading::{self, Points, numbered};
use crate::compensate::grid::REVOLUTION_DEG;
use crate::compensate::{Interpolation, Table, TableSlot};
use std::collections::BTreeMap;

/// One axis's table variables, each with the line that set it last.
#[derive(Default)]
struct Variables {
    values: BTreeMap<usize, (f64, usize)>,
    step: Option<(f64, usize)>,
    min: Option<(f64, usize)>,
    max: Option<(f64, usize)>,
    modulo: Option<(f64, usize)>,
}

/// The tables of a file by (measuring system, axis name as written).
type Tables = BTreeMap<(u8, String), Variables>;

/// The table of the axis `reading` names (or the file's only one).
pub fn read(text: &str, reading: ReadAs) -> Result<Table, Unreadable> {
    let tables = assignments(text)?;
    let ((system, axis), vars) = choose(&tables, reading.axis)?;
    let line_of = |v: Option<(f64, usize)>, name: &str| {
        v.ok_or_else(|| {
            Unreadable::file(format!(
                "no `$AA_ENC_COMP_{name}[{system},{axis}]`: the NC places the points at MIN + N·STEP up to MAX"
            ))
        })
    };
    let (step, step_line) = line_of(vars.step, "STEP")?;
    let (min, _) = line_of(vars.min, "MIN")?;
    let (max, max_line) = line_of(vars.max, "MAX")?;
    let last = point_count(step, step_line, min, max, max_line)?;
    // Not reserved ahead: MAX may claim far more points than the file holds.
    let mut points = Points::empty(reading.kind);
    let per_unit = reading.kind.deviation_units_per_position_unit();
    for n in 0..=last {
        let Some((value, _)) = vars.values.get(&n) else {
            return Err(Unreadable::file(format!(
                "no `$AA_ENC_COMP[{system},{n},{axis}]`: the table runs from point 0 to {last} (MIN to MAX)"
            )));
        };
        // The file holds the error (the NC subtracts it): the correction is minus it.
        let correction = -value * per_unit;
        // MIN + N·STEP, with the STEP that MAX gives (the file's STEP rounds it).
        points
            .positions
            .push(min + n as f64 * (max - min) / last.max(1) as f64);
        points.up.push(correction);
        points.down.push(correction);
    }
    let modulo = modulo(vars.modulo, min, max)?;
    let place = TableSlot {
        // A file still holding the placeholder names no axis: the next one written says so.
        axis: (axis != super::super::AXIS_PLACEHOLDER).then(|| axis.clone()),
        measuring_system: Some(*system),
        number: None,
    };
    Ok(points.table(None, modulo, place, Interpolation::Linear))
}

/// The index of the last point, (MAX − MIN)/STEP, when it is a whole number.
fn point_count(
    step: f64,
    step_line: usize,
    min: f64,
    max: f64,
    max_line: usize,
) -> Result<usize, Unreadable> {
    if step <= 0.0 {
        return Err(Unreadable::field(
            step_line,
            "$AA_ENC_COMP_STEP",
            format!("expected an interval > 0, got {step}"),
        ));
    }
    let count = (max - min) / step;
    if max <= min || (count - count.round()).abs() > 1e-6 * count.max(1.0) || count > 1e6 {
        return Err(Unreadable::field(
            max_line,
            "$AA_ENC_COMP_MAX",
            format!("MAX {max} is not MIN {min} plus a whole number of STEP {step}"),
        ));
    }
    Ok(count.round() as usize)
}

/// Whether the table wraps (`_IS_MODULO` = 1), over 0…360°.
fn modulo(flag: Option<(f64, usize)>, min: f64, max: f64) -> Result<bool, Unreadable> {
    match flag {
        None | Some((0.0, _)) => Ok(false),
        Some((1.0, _)) if min == 0.0 && (max - REVOLUTION_DEG).abs() < 1e-9 => Ok(true),
        Some((1.0, line)) => Err(Unreadable::field(
            line,
            "$AA_ENC_COMP_IS_MODULO",
            format!("a modulo table over {min}…{max}: axcheck reads modulo tables of 0…360° only"),
        )),
        Some((v, line)) => Err(Unreadable::field(
            line,
            "$AA_ENC_COMP_IS_MODULO",
            format!("expected 0 or 1, got {v}"),
        )),
    }
}

/// The table the reading asks for: the named axis, or the only one; refused when the
/// file holds none of it or two measuring systems of it.
fn choose<'t>(
    tables: &'t Tables,
    axis: Option<&str>,
) -> Result<(&'t (u8, String), &'t Variables), Unreadable> {
    let names: Vec<String> = tables.keys().map(|(e, a)| format!("[{e},…,{a}]")).collect();
    let found: Vec<_> = tables
        .iter()
        .filter(|((_, a), _)| axis.is_none_or(|want| a.eq_ignore_ascii_case(want)))
        .collect();
    match (found.as_slice(), axis) {
        ([one], _) => Ok(*one),
        ([], _) if tables.is_empty() => Err(Unreadable::file(
            "no `$AA_ENC_COMP[...]` assignment: not an LEC table",
        )),
        ([], Some(want)) => Err(Unreadable::file(format!(
            "no table of axis {want}; the file has {}",
            names.join(", ")
        ))),
        (_, _) => Err(Unreadable::file(format!(
            "the file holds {} tables ({}): name the axis (--axis, or compensation: {{axis}}) and keep one measuring system",
            found.len(),
            names.join(", ")
        ))),
    }
}

/// Every table variable the file assigns.
fn assignments(text: &str) -> Result<Tables, Unreadable> {
    let mut tables = Tables::new();
    for (line, raw) in numbered(text) {
        let code = raw.split(';').next().unwrap_or("").trim();
        let code = without_block_number(code);
        if skipped(code) {
            continue;
        }
        let Some((name, indices, value)) = assignment(code) else {
            return Err(Unreadable::at(
                line,
                format!(
                    "`{}` is not an assignment `$AA_ENC_COMP...[...]=value`",
                    raw.trim()
                ),
            ));
        };
        set(&mut tables, line, &name, &indices, value)?;
    }
    Ok(tables)
}

/// `N10 $AA_...` → `$AA_...`.
fn without_block_number(code: &str) -> &str {
    let Some(rest) = code.strip_prefix(['N', 'n']) else {
        return code;
    };
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    if digits == 0 {
        return code;
    }
    rest[digits..].trim_start()
}

/// Lines the NC runs that set no table variable.
fn skipped(code: &str) -> bool {
    let upper = code.to_ascii_uppercase();
    upper.is_empty()
        || upper.starts_with('%')
        || upper.starts_with("CHANDATA")
        || matches!(upper.as_str(), "M17" | "M30" | "M2" | "M02")
}

/// `$NAME[i,j,...]=value` → (NAME in upper case, the indices, the value as written).
fn assignment(code: &str) -> Option<(String, Vec<String>, &str)> {
    let (left, value) = code.split_once('=')?;
    let left = left.trim();
    let open = left.find('[')?;
    let inside = left[open + 1..].strip_suffix(']')?;
    let name = left[..open].trim().to_ascii_uppercase();
    let indices = inside.split(',').map(|i| i.trim().to_string()).collect();
    Some((name, indices, value))
}

/// Records one assignment, its indices and value read.
fn set(
    tables: &mut Tables,
    line: usize,
    name: &str,
    indices: &[String],
    value: &str,
) -> Result<(), Unreadable> {
    let expected = if name == "$AA_ENC_COMP" { 3 } else { 2 };
    let known = [
        "$AA_ENC_COMP",
        "$AA_ENC_COMP_STEP",
        "$AA_ENC_COMP_MIN",
        "$AA_ENC_COMP_MAX",
        "$AA_ENC_COMP_IS_MODULO",
    ];
    if !known.contains(&name) {
        return Err(Unreadable::field(
            line,
            name,
            format!(
                "not a variable of an LEC table (known: {})",
                known.join(", ")
            ),
        ));
    }
    if indices.len() != expected {
        return Err(Unreadable::field(
            line,
            name,
            format!(
                "expected {expected} indices in [...], got {}",
                indices.len()
            ),
        ));
    }
    let system = match reading::whole(&indices[0], line, name)? {
        e @ 0..=1 => e as u8,
        e => {
            return Err(Unreadable::field(
                line,
                name,
                format!("measuring system {e}: expected 0 or 1"),
            ));
        }
    };
    let axis = indices[expected - 1].clone();
    let v = reading::number(value, line, name)?;
    let vars = tables.entry((system, axis)).or_default();
    let slot = match name {
        "$AA_ENC_COMP" => {
            let n = reading::whole(&indices[1], line, name)?;
            vars.values.insert(n, (v, line));
            return Ok(());
        }
        "$AA_ENC_COMP_STEP" => &mut vars.step,
        "$AA_ENC_COMP_MIN" => &mut vars.min,
        "$AA_ENC_COMP_MAX" => &mut vars.max,
        _ => &mut vars.modulo,
    };
    *slot = Some((v, line));
    Ok(())
}
