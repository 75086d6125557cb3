//! The laser optics' published accuracy specifications, as named presets of
//! [`Accuracy`], each with the test kinds it is stated for and its source.
//!
//! Only what a maker's document states, legibly, is a preset (docs/optics-specifications.md
//! holds what was searched and found). Each value is converted to the result's unit
//! (µm for straightness, arcsec for angular and squareness): the presets here are all
//! stated in arcsec by their source, so none is converted. A specification of another
//! form is stated with [`Accuracy`]'s four terms (`fraction`, `fixed`, `per_m`,
//! `per_m2`).

use super::TestKind;
use serde::Serialize;

/// An optics' accuracy as a laser specification states it: ±(fraction·|value| + fixed +
/// per_m·M + per_m2·M²), M the travel in metres, in the result's unit (µm or arcsec).
/// The presets are below.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Accuracy {
    pub fraction: f64,
    pub fixed: f64,
    pub per_m: f64,
    /// A part per square metre of travel (straightness specifications are of that form).
    #[serde(skip_serializing_if = "is_zero")]
    pub per_m2: f64,
}

fn is_zero(v: &f64) -> bool {
    *v == 0.0
}

impl Accuracy {
    /// The bound for a result `value` over `travel_mm`.
    pub fn bound(&self, value: f64, travel_mm: f64) -> f64 {
        let m = travel_mm / 1000.0;
        self.fraction * value.abs() + self.fixed + self.per_m * m + self.per_m2 * m * m
    }

    /// `±(1 % of the value + 0.5 + 0.1·M) arcsec, M the travel in m`: the terms as stated.
    pub fn formula(&self, unit: &str) -> String {
        let mut terms = Vec::new();
        if self.fraction != 0.0 {
            terms.push(format!("{} % of the value", fmt_g(self.fraction * 100.0)));
        }
        if self.fixed != 0.0 || (self.per_m == 0.0 && self.per_m2 == 0.0) {
            terms.push(fmt_g(self.fixed));
        }
        if self.per_m != 0.0 {
            terms.push(format!("{}·M", fmt_g(self.per_m)));
        }
        if self.per_m2 != 0.0 {
            terms.push(format!("{}·M²", fmt_g(self.per_m2)));
        }
        let unit = if unit == "um" { "µm" } else { unit };
        let m = if self.per_m != 0.0 || self.per_m2 != 0.0 {
            ", M the travel in m"
        } else {
            ""
        };
        format!("±({}) {unit}{m}", terms.join(" + "))
    }
}

/// A stated number as written (`0.5`, `2.5`, `0.015`).
fn fmt_g(v: f64) -> String {
    let text = format!("{v:.6}");
    text.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A named accuracy specification of a laser's optics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Preset {
    /// The name `--optics` and a campaign's `optics:` take.
    pub name: &'static str,
    /// Earlier names still accepted.
    pub aliases: &'static [&'static str],
    /// What the optics are, as a report line says it.
    pub label: &'static str,
    pub accuracy: Accuracy,
    /// The tests the specification is stated for.
    pub tests: &'static [TestKind],
    /// The document, section and statement it is taken from.
    pub source: &'static str,
}

impl Accuracy {
    /// HP 5528A squareness, short-range optics: "±(0.5 + 0.1M) arc-sec ± 1% of θ" (metric
    /// units mode; θ the calculated out-of-squareness angle in arc-sec, M the distance of
    /// travel of the moving optic in metres). HP 5528A Laser Measurement System User's
    /// Guide, section 13 "Squareness Measurements (In a Vertical Plane)", Operating
    /// Specifications, Accuracy (page 13-1). Stated in arcsec: not converted.
    pub const HP_5528A_SQUARENESS_SHORT: Accuracy = Accuracy {
        fraction: 0.01,
        fixed: 0.5,
        per_m: 0.1,
        per_m2: 0.0,
    };

    /// HP 5528A squareness, long-range optics: "±(0.5 + 0.01M) arc-sec ± 2.5% of θ"
    /// (metric units mode; θ and M as for the short-range optics). HP 5528A Laser
    /// Measurement System User's Guide, section 13 "Squareness Measurements (In a Vertical
    /// Plane)", Operating Specifications, Accuracy (page 13-1). Stated in arcsec: not
    /// converted.
    pub const HP_5528A_SQUARENESS_LONG: Accuracy = Accuracy {
        fraction: 0.025,
        fixed: 0.5,
        per_m: 0.01,
        per_m2: 0.0,
    };

    /// The preset named `name` (or an earlier name of it): its accuracy and the tests it
    /// is stated for.
    pub fn preset(name: &str) -> Option<(Accuracy, &'static [TestKind])> {
        Preset::find(name).map(|p| (p.accuracy, p.tests))
    }

    /// The presets' names, for messages.
    pub fn preset_names() -> Vec<&'static str> {
        PRESETS.iter().map(|p| p.name).collect()
    }
}

const SQUARENESS: &[TestKind] = &[TestKind::Squareness];

const HP_5528A_SECTION_13: &str = "HP 5528A Laser Measurement System User's Guide, section 13 \"Squareness Measurements (In a Vertical Plane)\", Operating Specifications, Accuracy";

/// Every preset.
pub const PRESETS: [Preset; 2] = [
    Preset {
        name: "hp5528a-squareness-short",
        aliases: &["hp5528a-short"],
        label: "HP 5528A squareness, short-range optics: ±(0.5 + 0.1·M)″ ± 1 % of θ",
        accuracy: Accuracy::HP_5528A_SQUARENESS_SHORT,
        tests: SQUARENESS,
        source: HP_5528A_SECTION_13,
    },
    Preset {
        name: "hp5528a-squareness-long",
        aliases: &["hp5528a-long"],
        label: "HP 5528A squareness, long-range optics: ±(0.5 + 0.01·M)″ ± 2.5 % of θ",
        accuracy: Accuracy::HP_5528A_SQUARENESS_LONG,
        tests: SQUARENESS,
        source: HP_5528A_SECTION_13,
    },
];

impl Preset {
    /// The preset named `name` or by an earlier name.
    pub fn find(name: &str) -> Option<&'static Preset> {
        let name = name.trim();
        PRESETS
            .iter()
            .find(|p| p.name.eq_ignore_ascii_case(name) || p.aliases.contains(&name))
    }

    /// The preset named `name`, for a test of kind `test`.
    pub fn for_test(name: &str, test: TestKind) -> Result<&'static Preset, OpticsError> {
        let preset = Preset::find(name).ok_or_else(|| OpticsError::Unknown(name.to_string()))?;
        if !preset.tests.contains(&test) {
            return Err(OpticsError::WrongTest { preset, test });
        }
        Ok(preset)
    }

    fn kinds(&self) -> String {
        let names: Vec<&str> = self.tests.iter().map(|t| t.key()).collect();
        names.join(" or ")
    }
}

/// Why a preset's name is not taken.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OpticsError {
    #[error("unknown optics `{0}`: the presets are {names}", names = Accuracy::preset_names().join(", "))]
    Unknown(String),
    #[error(
        "`{name}` is the {label} (stated for {kinds}), not for this {test} test",
        name = preset.name,
        label = preset.label,
        kinds = preset.kinds(),
        test = test.key()
    )]
    WrongTest {
        preset: &'static Preset,
        test: TestKind,
    },
}

/// The optics' accuracy as stated for a test: a preset, or numbers.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Optics {
    #[serde(flatten)]
    pub accuracy: Accuracy,
    /// The preset's name, when one was named.
    #[serde(
        rename = "preset",
        skip_serializing_if = "Option::is_none",
        serialize_with = "preset_name"
    )]
    pub preset: Option<&'static Preset>,
}

fn preset_name<S: serde::Serializer>(p: &Option<&'static Preset>, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(p.map_or("", |p| p.name))
}

impl From<Accuracy> for Optics {
    fn from(accuracy: Accuracy) -> Optics {
        Optics {
            accuracy,
            preset: None,
        }
    }
}

impl From<&'static Preset> for Optics {
    fn from(preset: &'static Preset) -> Optics {
        Optics {
            accuracy: preset.accuracy,
            preset: Some(preset),
        }
    }
}

impl Optics {
    /// What the budget's optics line stands for, as a note: the preset and its source, or
    /// the numbers as stated.
    pub fn describe(&self, unit: &str) -> String {
        match self.preset {
            Some(p) => format!("the optics: {} ({})", p.label, p.source),
            None => format!("the optics as stated: {}", self.accuracy.formula(unit)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_by_name_and_alias() {
        let (a, tests) = Accuracy::preset("hp5528a-squareness-long").unwrap();
        assert_eq!(a, Accuracy::HP_5528A_SQUARENESS_LONG);
        assert_eq!(tests, &[TestKind::Squareness]);
        assert_eq!(
            Accuracy::preset("hp5528a-short").unwrap().0,
            Accuracy::HP_5528A_SQUARENESS_SHORT
        );
        assert!(Accuracy::preset("xl80-straightness-short").is_none());
        assert_eq!(
            Accuracy::preset_names(),
            ["hp5528a-squareness-short", "hp5528a-squareness-long"]
        );
    }

    #[test]
    fn a_preset_of_another_test_is_refused_naming_both() {
        let e = Preset::for_test("hp5528a-squareness-short", TestKind::Angular).unwrap_err();
        let text = e.to_string();
        assert!(text.contains("hp5528a-squareness-short"), "{text}");
        assert!(text.contains("stated for squareness"), "{text}");
        assert!(text.contains("not for this angular test"), "{text}");
        let e = Preset::for_test("hp5528b", TestKind::Squareness).unwrap_err();
        assert!(e.to_string().contains("hp5528a-squareness-long"), "{e}");
        assert!(Preset::for_test("HP5528A-Squareness-Long", TestKind::Squareness).is_ok());
    }

    #[test]
    fn the_long_range_bound_by_hand() {
        // θ = −4″ over 2.5 m: 2.5 % of 4 = 0.1, 0.5, 0.01 · 2.5 = 0.025: 0.625″.
        let b = Accuracy::HP_5528A_SQUARENESS_LONG.bound(-4.0, 2500.0);
        assert!((b - 0.625).abs() < 1e-12, "{b}");
    }
}
