//! The simulation file (YAML): unit-carrying keys, chosen by the axis kind.
//!
//! A linear model writes `reversal_um`, `pitch_mm`; a rotary one `reversal_arcsec`,
//! `pitch_deg`. Keys are checked against the kind (a `_um` key in a rotary model is an
//! error, as is a key without its unit) before the typed parse, which reports line and
//! column of bad values.

use crate::axis_model::Cycle;
use crate::units::{AxisKind, Direction};
use crate::yaml::{Located, LocationIndex, describe, join, names_of, or_list};
use serde_norway::{Mapping, Value};

/// Where a key lives.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Ctx {
    Top,
    Model,
    Periodic,
    Outlier,
    Plan,
    Spacing,
}

/// How the file spells a field: (serde's name of the field, linear spelling, rotary
/// spelling).
type Key = (&'static str, &'static str, &'static str);

/// A field without a unit, spelled as its name.
const fn plain(field: &'static str) -> Key {
    (field, field, field)
}

/// The fields of `ctx`'s struct in its order, by serde's names, each in each of its
/// spellings (the first is the one written; a unit test checks the table against the
/// names serde reads, so that a field added to a struct cannot miss it).
fn keys(ctx: Ctx) -> &'static [Key] {
    match ctx {
        Ctx::Top => TOP,
        Ctx::Model => MODEL,
        Ctx::Periodic => PERIODIC,
        Ctx::Outlier => OUTLIER,
        Ctx::Plan => PLAN,
        Ctx::Spacing => SPACING,
    }
}

/// The simulation file's top level ([`crate::axis_model::Simulation`]).
const TOP: &[Key] = &[
    plain("kind"),
    plain("seed"),
    plain("description"),
    plain("model"),
    plain("plan"),
];

/// `model` ([`crate::axis_model::ErrorModel`]).
const MODEL: &[Key] = &[
    plain("scale_ppm"),
    ("scale_ppm", "scale_um_per_m", "scale_ppm"),
    plain("shape"),
    plain("periodic"),
    ("reversal", "reversal_um", "reversal_arcsec"),
    ("reversal_end", "reversal_end_um", "reversal_end_arcsec"),
    (
        "reversal_knots",
        "reversal_knots_um",
        "reversal_knots_arcsec",
    ),
    ("drift_per_h", "drift_um_per_h", "drift_arcsec_per_h"),
    plain("thermal_growth_ppm_per_h"),
    (
        "thermal_growth_ppm_per_h",
        "thermal_growth_um_per_m_per_h",
        "thermal_growth_ppm_per_h",
    ),
    ("thermal_origin", "thermal_origin_mm", "thermal_origin_deg"),
    ("warm_up", "warm_up_um", "warm_up_arcsec"),
    plain("warm_up_ppm"),
    ("warm_up_ppm", "warm_up_um_per_m", "warm_up_ppm"),
    plain("warm_up_tau_min"),
    ("run_offsets", "run_offsets_um", "run_offsets_arcsec"),
    ("run_offset_sd", "run_offset_sd_um", "run_offset_sd_arcsec"),
    ("scatter", "scatter_um", "scatter_arcsec"),
    ("scatter_end", "scatter_end_um", "scatter_end_arcsec"),
    ("scatter_knots", "scatter_knots_um", "scatter_knots_arcsec"),
    plain("outliers"),
    plain("outlier_rate"),
    ("outlier_size", "outlier_size_um", "outlier_size_arcsec"),
    ("resolution", "resolution_um", "resolution_arcsec"),
    plain("geometry"),
];

/// An entry of `model.periodic` ([`crate::axis_model::PeriodicTerm`]).
const PERIODIC: &[Key] = &[
    ("pitch", "pitch_mm", "pitch_deg"),
    ("amplitude", "amplitude_um", "amplitude_arcsec"),
    plain("phase_deg"),
];

/// An entry of `model.outliers` ([`crate::axis_model::PlantedOutlier`]).
const OUTLIER: &[Key] = &[
    plain("run"),
    plain("direction"),
    plain("target"),
    ("size", "size_um", "size_arcsec"),
];

/// `plan` ([`crate::axis_model::TestPlan`]).
const PLAN: &[Key] = &[
    plain("targets"),
    ("target_list", "targets_mm", "targets_deg"),
    plain("runs"),
    plain("cycle"),
    ("feed_per_min", "feed_mm_per_min", "feed_deg_per_min"),
    plain("dwell_s"),
    ("overrun", "overrun_mm", "overrun_deg"),
];

/// `plan.targets` ([`crate::axis_model::TargetSpacing`]).
const SPACING: &[Key] = &[
    ("start", "start_mm", "start_deg"),
    ("end", "end_mm", "end_deg"),
    plain("count"),
    ("jitter", "jitter_mm", "jitter_deg"),
];

/// The mapping the field `field` of `ctx` holds, for those that hold one.
fn child(ctx: Ctx, field: &str) -> Option<Ctx> {
    match (ctx, field) {
        (Ctx::Top, "model") => Some(Ctx::Model),
        (Ctx::Top, "plan") => Some(Ctx::Plan),
        (Ctx::Model, "periodic") => Some(Ctx::Periodic),
        (Ctx::Model, "outliers") => Some(Ctx::Outlier),
        (Ctx::Plan, "targets") => Some(Ctx::Spacing),
        _ => None,
    }
}

fn spelling(key: &Key, kind: AxisKind) -> &'static str {
    match kind {
        AxisKind::Linear => key.1,
        AxisKind::Rotary => key.2,
    }
}

/// The axis kind the file declares, read first: it decides how every other key is spelled.
pub(crate) fn kind(value: &Value, index: &LocationIndex) -> Result<AxisKind, Located> {
    let root = index.value("");
    let expected = "expected a mapping with kind, model and plan";
    match value {
        Value::Mapping(_) => {}
        Value::Null => return Err(Located::new(root, format!("{expected}, got an empty file"))),
        other => {
            return Err(Located::new(
                root,
                format!("{expected}, got {}", describe(other)),
            ));
        }
    }
    if value.get("kind").is_none() {
        return Err(Located::new(
            root,
            "missing `kind: linear` or `kind: rotary`",
        ));
    }
    /// Only the kind, through the same reader as [`super::Simulation`]'s.
    #[derive(serde::Deserialize)]
    struct KindOnly {
        #[serde(deserialize_with = "crate::yaml::keyword")]
        kind: AxisKind,
    }
    crate::yaml::deserialize_at::<KindOnly>(value, "", index).map(|k| k.kind)
}

/// Checks every key against the kind, and that names (`cycle`, `direction`) are text;
/// the error names the key's path and location.
pub(crate) fn check_keys(
    value: &Value,
    kind: AxisKind,
    index: &LocationIndex,
) -> Result<(), Located> {
    check(value, Ctx::Top, kind, "", index)
}

/// The names a key that holds a name (`cycle: step`) may have.
fn keyword_names(ctx: Ctx, internal: &str) -> Option<String> {
    match (ctx, internal) {
        (Ctx::Plan, "cycle") => Some(or_list(&names_of::<Cycle>())),
        (Ctx::Outlier, "direction") => Some(or_list(&names_of::<Direction>())),
        _ => None,
    }
}

fn check(
    value: &Value,
    ctx: Ctx,
    kind: AxisKind,
    path: &str,
    index: &LocationIndex,
) -> Result<(), Located> {
    match value {
        Value::Sequence(items) => {
            for (k, item) in items.iter().enumerate() {
                check(item, ctx, kind, &format!("{path}[{k}]"), index)?;
            }
            Ok(())
        }
        Value::Mapping(map) => {
            for (k, v) in map {
                let Some(name) = k.as_str() else {
                    let message = format!("keys are names, got {} as a key", describe(k));
                    let message = match path {
                        "" => message,
                        _ => format!("{path}: {message}"),
                    };
                    return Err(Located::new(index.value(path), message));
                };
                let here = join(path, name);
                let entry = spelled(ctx, kind, name).ok_or_else(|| {
                    Located::new(index.key_or_value(&here), misspelt(ctx, kind, name, &here))
                })?;
                if let Some(names) = keyword_names(ctx, entry.0)
                    && !v.is_string()
                {
                    let message = format!("{here}: expected {names}, got {}", describe(v));
                    return Err(Located::new(index.value(&here), message));
                }
                if let Some(inner) = child(ctx, entry.0) {
                    check(v, inner, kind, &here, index)?;
                }
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// The entry of `ctx` that `kind` spells `name`.
fn spelled(ctx: Ctx, kind: AxisKind, name: &str) -> Option<&'static Key> {
    keys(ctx).iter().find(|e| spelling(e, kind) == name)
}

/// Why `name` is not a key of `ctx` for `kind`: the other kind's unit, no unit, or unknown.
fn misspelt(ctx: Ctx, kind: AxisKind, name: &str, here: &str) -> String {
    let table = keys(ctx);
    let other = match kind {
        AxisKind::Linear => AxisKind::Rotary,
        AxisKind::Rotary => AxisKind::Linear,
    };
    if let Some(entry) = table.iter().find(|e| spelling(e, other) == name) {
        return format!(
            "`{here}` has a {other} unit, but this is a {kind} model; write `{}`",
            spelling(entry, kind)
        );
    }
    if let Some(e) = table
        .iter()
        .find(|e| e.0 == name && spelling(e, kind) != name)
    {
        return format!("`{here}` has no unit; write `{}`", spelling(e, kind));
    }
    let names: Vec<&str> = table.iter().map(|e| spelling(e, kind)).collect();
    let hint = crate::suggest::hint(name, &names);
    format!(
        "unknown key `{here}`{hint}; expected one of {}",
        names.join(", ")
    )
}

/// The context of the mapping at `path` (`plan.targets` → the target spacing), following
/// the keys as the file spells them.
fn context_at(path: &str, kind: AxisKind) -> Option<Ctx> {
    let mut ctx = Ctx::Top;
    for segment in path.split('.').filter(|s| !s.is_empty()) {
        let name = segment.split('[').next().unwrap_or(segment);
        ctx = child(ctx, spelled(ctx, kind, name)?.0)?;
    }
    Some(ctx)
}

/// The field `field` of the mapping at `path` as the file spells it (`pitch` →
/// `pitch_mm`), for messages about a missing key.
pub(crate) fn spell(path: &str, field: &str, kind: AxisKind) -> String {
    context_at(path, kind)
        .and_then(|ctx| keys(ctx).iter().find(|e| e.0 == field))
        .map_or_else(|| field.to_string(), |e| spelling(e, kind).to_string())
}

/// A check's message (which names keys by their internal names, `model.scatter`) with
/// the keys as the file spells them (`model.scatter_um`), at the first key's location.
pub(crate) fn locate(message: &str, kind: AxisKind, index: &LocationIndex) -> Located {
    let (out, first) = respell(message, kind);
    let at = first.and_then(|p| index.value(&p)).or(index.value(""));
    Located::new(at, out)
}

/// A check's message with the keys as the file spells them, and the first key's path.
pub(crate) fn respell(message: &str, kind: AxisKind) -> (String, Option<String>) {
    let mut out = String::new();
    let mut first = None;
    let mut rest = message;
    while let Some(start) = rest.find(['m', 'p']) {
        let boundary =
            start == 0 || !rest[..start].ends_with(|c: char| c.is_alphanumeric() || c == '_');
        let len = rest[start..]
            .find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '.' || c == '[' || c == ']'))
            .unwrap_or(rest.len() - start);
        let token = rest[start..start + len].trim_end_matches('.');
        out.push_str(&rest[..start]);
        let path = boundary.then(|| spelled_path(token, kind)).flatten();
        out.push_str(path.as_deref().unwrap_or(token));
        if first.is_none() {
            first = path;
        }
        rest = &rest[start + token.len()..];
    }
    out.push_str(rest);
    (out, first)
}

/// `model.scatter` as `model.scatter_um`: each internal name (or a name it starts with,
/// `plan.feed` for `feed_per_min`) spelled for the kind; `None` if `token` is no path.
fn spelled_path(token: &str, kind: AxisKind) -> Option<String> {
    if !(token == "model"
        || token == "plan"
        || token.starts_with("model.")
        || token.starts_with("plan."))
    {
        return None;
    }
    let mut ctx = Some(Ctx::Top);
    let mut out = String::new();
    for segment in token.split('.') {
        let (name, subscript) = segment.split_at(segment.find('[').unwrap_or(segment.len()));
        let here = ctx?;
        let table = keys(here);
        let entry = table.iter().find(|e| e.0 == name).or_else(|| {
            table
                .iter()
                .find(|e| !name.is_empty() && e.0.starts_with(name))
        })?;
        out = join(&out, &format!("{}{subscript}", spelling(entry, kind)));
        ctx = child(here, entry.0);
    }
    Some(out)
}

/// Renames internal keys to the kind's spellings, for writing a model file.
pub(crate) fn externalize(value: Value, kind: AxisKind) -> Value {
    rename(value, Ctx::Top, kind)
}

fn rename(value: Value, ctx: Ctx, kind: AxisKind) -> Value {
    match value {
        Value::Sequence(items) => {
            Value::Sequence(items.into_iter().map(|v| rename(v, ctx, kind)).collect())
        }
        Value::Mapping(map) => {
            let mut out = Mapping::new();
            for (k, v) in map {
                let entry = k
                    .as_str()
                    .and_then(|name| keys(ctx).iter().find(|e| e.0 == name));
                match entry {
                    Some(e) => {
                        let v = match child(ctx, e.0) {
                            Some(inner) => rename(v, inner, kind),
                            None => v,
                        };
                        out.insert(Value::String(spelling(e, kind).to_string()), v);
                    }
                    None => {
                        out.insert(k, v);
                    }
                }
            }
            Value::Mapping(out)
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::axis_model::{
        ErrorModel, PeriodicTerm, PlantedOutlier, Simulation, TargetSpacing, TestPlan,
    };
    use crate::yaml::field_names;

    const CONTEXTS: [Ctx; 6] = [
        Ctx::Top,
        Ctx::Model,
        Ctx::Periodic,
        Ctx::Outlier,
        Ctx::Plan,
        Ctx::Spacing,
    ];

    /// Every name serde reads for the struct of `ctx`: each field's name and its aliases.
    fn serde_names(ctx: Ctx) -> &'static [&'static str] {
        match ctx {
            Ctx::Top => field_names::<Simulation>(),
            Ctx::Model => field_names::<ErrorModel>(),
            Ctx::Periodic => field_names::<PeriodicTerm>(),
            Ctx::Outlier => field_names::<PlantedOutlier>(),
            Ctx::Plan => field_names::<TestPlan>(),
            Ctx::Spacing => field_names::<TargetSpacing>(),
        }
    }

    /// The table's names as serde lists them: field by field in the table's order, each
    /// field's name with its spellings, sorted.
    fn table_names(ctx: Ctx) -> Vec<&'static str> {
        let mut fields: Vec<&str> = keys(ctx).iter().map(|k| k.0).collect();
        fields.dedup();
        let mut out = Vec::new();
        for field in fields {
            let rows = keys(ctx).iter().filter(|k| k.0 == field);
            let mut names: Vec<&str> = rows.flat_map(|k| [k.0, k.1, k.2]).collect();
            names.sort_unstable();
            names.dedup();
            out.extend(names);
        }
        out
    }

    /// The table spells every field serde reads, by serde's name, in the struct's order,
    /// and each spelling is an alias serde accepts for that field: a field added to a
    /// struct (or an alias) without its spellings fails here.
    #[test]
    fn the_table_spells_every_field_of_the_structs() {
        for ctx in CONTEXTS {
            assert!(!serde_names(ctx).is_empty(), "{ctx:?}");
            assert_eq!(table_names(ctx), serde_names(ctx), "{ctx:?}");
        }
    }
}
