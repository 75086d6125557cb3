//! Acceptance specs (`specs/*.yaml`): limits per parameter in bands of measurement travel.

use super::{LimitSource, Limits, Tolerances};
use crate::evaluate::catalogue;
use crate::units::AxisKind;
use crate::yaml::{self, Located, LocationIndex, YamlError, deserialize_at};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// The specs that ship inside the binary (`specs/*.yaml` of the source tree).
pub const BUILTIN_SPECS: &[(&str, &str)] = &[
    ("general", include_str!("../../../../specs/general.yaml")),
    (
        "precision",
        include_str!("../../../../specs/precision.yaml"),
    ),
];

/// One band of a spec: limits for axes whose measurement travel is up to `up_to`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Band {
    /// Upper end of the band's measurement travel, mm or deg; absent: no upper end.
    #[serde(
        default,
        alias = "up_to_mm",
        alias = "up_to_deg",
        skip_serializing_if = "Option::is_none"
    )]
    pub up_to: Option<f64>,
    /// The limits as the file writes them: read by serde, then checked and moved into
    /// `tolerances` by [`Spec::from_yaml`] (empty after it).
    #[serde(rename = "tolerances", skip_serializing)]
    written: BTreeMap<String, f64>,
    /// Limits per parameter, µm (linear) or arcsec (rotary).
    #[serde(skip_deserializing)]
    pub tolerances: Tolerances,
}

/// An acceptance spec.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spec {
    pub name: String,
    #[serde(default)]
    pub title: String,
    #[serde(default)]
    pub note: String,
    /// The limits are examples, quoted from no standard (`example: true`): every report,
    /// summary and console line judged by them says [`super::EXAMPLE_LIMITS`].
    #[serde(default)]
    pub example: bool,
    /// The standard whose parameters the limits name.
    #[serde(default)]
    pub standard: Option<String>,
    /// Decision rule of the agreement (ISO 14253-1): overrides the campaign's, not an
    /// axis's own.
    #[serde(default, deserialize_with = "crate::yaml::optional_keyword")]
    pub decision_rule: Option<super::DecisionRule>,
    #[serde(default)]
    pub linear: Vec<Band>,
    #[serde(default)]
    pub rotary: Vec<Band>,
    /// Where the spec was read (`specs/general.yaml`, `built-in spec general`) and the
    /// lines of its `linear` and `rotary` keys: a test no band covers is told where to
    /// add one.
    #[serde(skip)]
    pub origin: SpecOrigin,
}

/// Where a spec and its band lists are written.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SpecOrigin {
    pub file: String,
    pub(crate) linear_line: Option<usize>,
    pub(crate) rotary_line: Option<usize>,
}

impl SpecOrigin {
    /// `specs/house.yaml:4` (the `linear:`/`rotary:` line), or the file alone.
    pub fn at(&self, kind: AxisKind) -> String {
        let line = match kind {
            AxisKind::Linear => self.linear_line,
            AxisKind::Rotary => self.rotary_line,
        };
        match line {
            Some(line) => format!("{}:{line}", self.file),
            None => self.file.clone(),
        }
    }
}

impl Spec {
    /// Parses a spec; `file` names it in errors.
    pub fn from_yaml(text: &str, file: &str) -> Result<Spec, YamlError> {
        let (value, index) = yaml::parse(text, file)?;
        let mut spec: Spec = deserialize_at(&value, "", &index).map_err(|e| e.in_file(file))?;
        for (group, bands) in [("linear", &mut spec.linear), ("rotary", &mut spec.rotary)] {
            check_bands(group, bands, &index).map_err(|e| e.in_file(file))?;
        }
        spec.origin = SpecOrigin {
            file: file.to_string(),
            linear_line: index.key("linear").map(|(line, _)| line),
            rotary_line: index.key("rotary").map(|(line, _)| line),
        };
        Ok(spec)
    }

    /// The band for an axis of `kind` whose measurement travel is `travel`.
    pub fn band(&self, kind: AxisKind, travel: f64) -> Option<&Band> {
        let bands = match kind {
            AxisKind::Linear => &self.linear,
            AxisKind::Rotary => &self.rotary,
        };
        bands
            .iter()
            .find(|b| b.up_to.is_none_or(|u| travel <= u + 1e-9))
    }
}

/// Bands in order of `up_to` (only the last open-ended), each limit known and ≥ 0; the
/// limits of each band typed by [`check_limits`].
fn check_bands(group: &str, bands: &mut [Band], index: &LocationIndex) -> Result<(), Located> {
    let mut last = f64::NEG_INFINITY;
    let count = bands.len();
    for (k, band) in bands.iter_mut().enumerate() {
        let here = format!("{group}[{k}]");
        match band.up_to {
            Some(u) if u > last => last = u,
            Some(_) => {
                let message = format!("{here}: bands must have increasing up_to");
                return Err(Located::new(index.value(&here), message));
            }
            None if k + 1 == count => last = f64::INFINITY,
            None => {
                let message = format!("{here}: only the last band may omit up_to");
                return Err(Located::new(index.value(&here), message));
            }
        }
        check_limits(&here, band, index)?;
    }
    Ok(())
}

/// Every limit of a band names a parameter that can be limited, and is a number ≥ 0: the
/// written limits become the band's typed `tolerances`.
fn check_limits(here: &str, band: &mut Band, index: &LocationIndex) -> Result<(), Located> {
    band.tolerances = check_tolerances(here, &std::mem::take(&mut band.written), index)?;
    Ok(())
}

/// Every limit of `written` (at `here` in the file: a spec's band or a campaign's axis)
/// names a parameter that can be limited, and is a number ≥ 0: the limits keyed by their
/// parameters. The one check of limits, for specs and campaigns alike; the first bad
/// limit in the order of the written keys is the one reported.
pub fn check_tolerances<'a>(
    here: &str,
    written: impl IntoIterator<Item = (&'a String, &'a f64)>,
    index: &LocationIndex,
) -> Result<Tolerances, Located> {
    let mut tolerances = Tolerances::new();
    for (key, &limit) in written {
        let path = format!("{here}.tolerances.{key}");
        let Some(parameter) = catalogue::limitable(key) else {
            let hint = crate::suggest::hint(key, catalogue::limitable_keys());
            let message = format!("{here}.tolerances: unknown parameter `{key}`{hint}");
            return Err(Located::new(index.key_or_value(&path), message));
        };
        if !(limit >= 0.0 && limit.is_finite()) {
            let message = format!("{path}: expected a limit ≥ 0");
            return Err(Located::new(index.value(&path), message));
        }
        tolerances.insert(parameter, limit);
    }
    Ok(tolerances)
}

/// A spec without a band for the test's measurement travel: `specs/house.yaml:3: spec
/// `house` has no linear band for a measurement travel of 1200 mm (its last ends at 1000
/// mm): add one …`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "{at}: spec `{spec}` has no {kind} band for a measurement travel of {travel} {unit}{last}: add a `{kind}` band with `up_to` of at least {travel} (or none) to the spec, or give the axis its own `tolerances`",
    unit = kind.position_unit(),
    last = last_band(*kind, *last_up_to)
)]
pub struct NoBand {
    /// Where the spec's bands of this kind are written (`specs/house.yaml:3`).
    pub at: String,
    pub spec: String,
    pub kind: AxisKind,
    /// The test's measurement travel, mm or deg.
    pub travel: f64,
    /// Where the spec's last band of this kind ends; `None`: it has none, or its last
    /// has no end.
    pub(crate) last_up_to: Option<f64>,
}

/// ` (its last ends at 1000 mm)`, or ` (it has no `linear` bands)`.
fn last_band(kind: AxisKind, last_up_to: Option<f64>) -> String {
    match last_up_to {
        Some(u) => format!(" (its last ends at {u} {})", kind.position_unit()),
        None => format!(" (it has no `{kind}` bands)"),
    }
}

fn no_band(spec: &Spec, kind: AxisKind, travel: f64) -> NoBand {
    let bands = match kind {
        AxisKind::Linear => &spec.linear,
        AxisKind::Rotary => &spec.rotary,
    };
    NoBand {
        at: spec.origin.at(kind),
        spec: spec.name.clone(),
        kind,
        travel,
        last_up_to: bands.last().and_then(|b| b.up_to),
    }
}

/// The limits of a test of `kind` over `travel`: the spec's band (if any) overridden by
/// the axis's own tolerances.
pub fn limits(
    spec: Option<&Spec>,
    overrides: &Tolerances,
    kind: AxisKind,
    travel: f64,
) -> Result<Limits, NoBand> {
    let mut limits = Limits::default();
    if let Some(spec) = spec {
        let band = spec
            .band(kind, travel)
            .ok_or_else(|| no_band(spec, kind, travel))?;
        let range = match band.up_to {
            Some(u) => format!("≤ {u} {}", kind.position_unit()),
            None => "all travels".to_string(),
        };
        limits.spec = Some(format!("{} ({kind} {range})", spec.name));
        for (k, v) in &band.tolerances {
            limits.values.insert(*k, (*v, LimitSource::Spec));
        }
    }
    for (k, v) in overrides {
        limits.values.insert(*k, (*v, LimitSource::Axis));
    }
    limits.example = spec.is_some_and(|s| s.example)
        && (limits.values.values()).any(|(_, s)| *s == LimitSource::Spec);
    Ok(limits)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate::ParamKey;

    #[test]
    fn builtin_specs_parse_and_say_they_are_examples() {
        for (name, text) in BUILTIN_SPECS {
            let spec = Spec::from_yaml(text, name).unwrap();
            assert_eq!(&spec.name, name);
            assert!(spec.note.to_lowercase().contains("example"), "{name}");
            assert!(spec.band(AxisKind::Linear, 1000.0).is_some());
            assert!(spec.band(AxisKind::Linear, 9000.0).is_some());
            assert!(spec.band(AxisKind::Rotary, 360.0).is_some());
        }
    }

    #[test]
    fn bands_and_overrides() {
        let spec = Spec::from_yaml(
            "name: t\nlinear:\n  - {up_to_mm: 1000, tolerances: {A: 10, R: 5}}\n  - {tolerances: {A: 20}}\n",
            "t.yaml",
        )
        .unwrap();
        let over = Tolerances::from([(ParamKey::R, 4.0)]);
        let l = limits(Some(&spec), &over, AxisKind::Linear, 1000.0).unwrap();
        assert_eq!(l.values[&ParamKey::A], (10.0, LimitSource::Spec));
        assert_eq!(l.values[&ParamKey::R], (4.0, LimitSource::Axis));
        let l = limits(Some(&spec), &BTreeMap::new(), AxisKind::Linear, 1000.5).unwrap();
        assert_eq!(l.values[&ParamKey::A].0, 20.0);
        assert!(limits(Some(&spec), &BTreeMap::new(), AxisKind::Rotary, 90.0).is_err());
        let e = Spec::from_yaml(
            "name: t\nlinear:\n  - {up_to_mm: 1000, tolerances: {AA: 1}}\n",
            "t.yaml",
        )
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "t.yaml:3:35: linear[0].tolerances: unknown parameter `AA` (did you mean `A`?)"
        );
    }

    /// Issue 42: an example spec's limits say so wherever the spec is described; an axis's
    /// own limits alone do not.
    #[test]
    fn example_limits_are_labelled() {
        let spec = Spec::from_yaml(BUILTIN_SPECS[0].1, "general").unwrap();
        assert!(spec.example, "specs/general.yaml carries example: true");
        let example = limits(Some(&spec), &Tolerances::new(), AxisKind::Linear, 500.0).unwrap();
        assert!(example.example);
        assert_eq!(
            example.describe_labelled(),
            "general (linear ≤ 1000 mm) — example limits, not from a standard"
        );
        assert_eq!(example.describe(), "general (linear ≤ 1000 mm)");
        let own = Tolerances::from([(ParamKey::A, 5.0)]);
        let axis_only = limits(None, &own, AxisKind::Linear, 500.0).unwrap();
        assert!(!axis_only.example);
        assert_eq!(axis_only.describe_labelled(), "axis tolerances");
    }
}
