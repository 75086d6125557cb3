//! The simulation file (YAML): unit-carrying keys, chosen by the axis kind.
//!
//! A linear model writes `reversal_um`, `pitch_mm`; a rotary one `reversal_arcsec`,
//! `pitch_deg`. Keys are checked against the kind (a `_um` key in a rotary model is an
//! error, as is a key without its unit) before the typed parse, which reports line and
//! column of bad values.

use crate::units::AxisKind;
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

/// (internal name, linear spelling, rotary spelling, child context).
type Key = (&'static str, &'static str, &'static str, Option<Ctx>);

fn keys(ctx: Ctx) -> &'static [Key] {
    match ctx {
        Ctx::Top => &[
            ("kind", "kind", "kind", None),
            ("seed", "seed", "seed", None),
            ("description", "description", "description", None),
            ("model", "model", "model", Some(Ctx::Model)),
            ("plan", "plan", "plan", Some(Ctx::Plan)),
        ],
        Ctx::Model => &[
            ("scale_ppm", "scale_ppm", "scale_ppm", None),
            ("scale_ppm", "scale_um_per_m", "scale_ppm", None),
            ("shape", "shape", "shape", None),
            ("periodic", "periodic", "periodic", Some(Ctx::Periodic)),
            ("reversal", "reversal_um", "reversal_arcsec", None),
            (
                "reversal_end",
                "reversal_end_um",
                "reversal_end_arcsec",
                None,
            ),
            ("drift_per_h", "drift_um_per_h", "drift_arcsec_per_h", None),
            (
                "thermal_growth_ppm_per_h",
                "thermal_growth_ppm_per_h",
                "thermal_growth_ppm_per_h",
                None,
            ),
            (
                "thermal_growth_ppm_per_h",
                "thermal_growth_um_per_m_per_h",
                "thermal_growth_ppm_per_h",
                None,
            ),
            (
                "thermal_origin",
                "thermal_origin_mm",
                "thermal_origin_deg",
                None,
            ),
            ("run_offsets", "run_offsets_um", "run_offsets_arcsec", None),
            (
                "run_offset_sd",
                "run_offset_sd_um",
                "run_offset_sd_arcsec",
                None,
            ),
            ("scatter", "scatter_um", "scatter_arcsec", None),
            ("scatter_end", "scatter_end_um", "scatter_end_arcsec", None),
            ("outliers", "outliers", "outliers", Some(Ctx::Outlier)),
            ("outlier_rate", "outlier_rate", "outlier_rate", None),
            (
                "outlier_size",
                "outlier_size_um",
                "outlier_size_arcsec",
                None,
            ),
            ("resolution", "resolution_um", "resolution_arcsec", None),
        ],
        Ctx::Periodic => &[
            ("pitch", "pitch_mm", "pitch_deg", None),
            ("amplitude", "amplitude_um", "amplitude_arcsec", None),
            ("phase_deg", "phase_deg", "phase_deg", None),
        ],
        Ctx::Outlier => &[
            ("run", "run", "run", None),
            ("direction", "direction", "direction", None),
            ("target", "target", "target", None),
            ("size", "size_um", "size_arcsec", None),
        ],
        Ctx::Plan => &[
            ("targets", "targets", "targets", Some(Ctx::Spacing)),
            ("target_list", "targets_mm", "targets_deg", None),
            ("runs", "runs", "runs", None),
            ("cycle", "cycle", "cycle", None),
            ("feed_per_min", "feed_mm_per_min", "feed_deg_per_min", None),
            ("dwell_s", "dwell_s", "dwell_s", None),
            ("overrun", "overrun_mm", "overrun_deg", None),
        ],
        Ctx::Spacing => &[
            ("start", "start_mm", "start_deg", None),
            ("end", "end_mm", "end_deg", None),
            ("count", "count", "count", None),
            ("jitter", "jitter_mm", "jitter_deg", None),
        ],
    }
}

fn spelling(key: &Key, kind: AxisKind) -> &'static str {
    match kind {
        AxisKind::Linear => key.1,
        AxisKind::Rotary => key.2,
    }
}

/// Checks every key against the kind; returns a message naming the key's path.
pub(crate) fn check_keys(value: &Value, kind: AxisKind) -> Result<(), String> {
    check(value, Ctx::Top, kind, "")
}

fn check(value: &Value, ctx: Ctx, kind: AxisKind, path: &str) -> Result<(), String> {
    match value {
        Value::Sequence(items) => {
            for (k, item) in items.iter().enumerate() {
                check(item, ctx, kind, &format!("{path}[{k}]"))?;
            }
            Ok(())
        }
        Value::Mapping(map) => {
            let table = keys(ctx);
            for (k, v) in map {
                let Some(name) = k.as_str() else {
                    return Err(format!("{path}: keys must be text"));
                };
                let here = if path.is_empty() {
                    name.to_string()
                } else {
                    format!("{path}.{name}")
                };
                if let Some(entry) = table.iter().find(|e| spelling(e, kind) == name) {
                    if let Some(child) = entry.3 {
                        check(v, child, kind, &here)?;
                    }
                    continue;
                }
                let other = match kind {
                    AxisKind::Linear => AxisKind::Rotary,
                    AxisKind::Rotary => AxisKind::Linear,
                };
                if let Some(entry) = table.iter().find(|e| spelling(e, other) == name) {
                    return Err(format!(
                        "`{here}` has a {other} unit, but this is a {kind} model; write `{}`",
                        spelling(entry, kind)
                    ));
                }
                let names: Vec<&str> = table.iter().map(|e| spelling(e, kind)).collect();
                let hint = crate::suggest::hint(name, &names);
                let unitless = table
                    .iter()
                    .find(|e| e.0 == name && spelling(e, kind) != name);
                return Err(match unitless {
                    Some(e) => format!("`{here}` has no unit; write `{}`", spelling(e, kind)),
                    None => format!(
                        "unknown key `{here}`{hint}; expected one of {}",
                        names.join(", ")
                    ),
                });
            }
            Ok(())
        }
        _ => Ok(()),
    }
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
                        let v = match e.3 {
                            Some(child) => rename(v, child, kind),
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
