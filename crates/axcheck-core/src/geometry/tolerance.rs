//! Tolerances of the other tests, in the forms acceptance standards write them: a length
//! over the whole travel (`0.015`, in mm as ISO 230 writes them, or `15 µm`), a length per
//! measuring length (`0.020 per 1000`: straightness, squareness), a length over any
//! stretch of the travel (`0.010 over any 300`: local straightness) and an angle (`30″`,
//! `30 arcsec`, `145 µrad`: angular deviations, squareness).
//!
//! A tolerance per measuring length is read proportionally: for a travel of L mm,
//! `0.020 per 1000` allows 0.020 × L / 1000 mm (and for squareness, a slope of 20 µm/m).
//! ISO 230-1 words this rule (and a minimum tolerance) in its clause on tolerances, which
//! the project could not consult; axcheck applies the proportion only, and says so.

use crate::units::ARCSEC_PER_RAD;
use serde::Serialize;

/// A tolerance as written.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "form", rename_all = "snake_case")]
pub enum Tolerance {
    /// The whole travel's, µm.
    Length { um: f64 },
    /// In proportion to the travel: `um` per `per_mm` of it.
    PerLength { um: f64, per_mm: f64 },
    /// Over any stretch of `over_mm` (judged on the local straightness), µm.
    Local { um: f64, over_mm: f64 },
    /// An angle, arcsec.
    Angle { arcsec: f64 },
}

/// A tolerance that cannot be read: the text and what was expected.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "tolerance `{text}`: {why}; write e.g. `0.015` (mm), `15 µm`, `0.020 per 1000`, `0.010 over any 300` or `30″`"
)]
pub struct ToleranceError {
    pub text: String,
    pub why: String,
}

impl Tolerance {
    /// Reads a tolerance; decimal commas are accepted (`0,020 per 1 000`).
    pub fn parse(text: &str) -> Result<Tolerance, ToleranceError> {
        let error = |why: &str| ToleranceError {
            text: text.to_string(),
            why: why.to_string(),
        };
        let t = text.trim().to_lowercase().replace(',', ".");
        let (value, rest) = number(&t).ok_or_else(|| error("it does not start with a number"))?;
        let (unit, rest) = unit(rest);
        let rest = rest.trim();
        let tolerance = match (unit, rest) {
            (Unit::Angle(factor), "") => Tolerance::Angle {
                arcsec: value * factor,
            },
            (Unit::Angle(_), _) => return Err(error("an angle takes nothing after its unit")),
            (Unit::Length(factor), "") => Tolerance::Length { um: value * factor },
            (Unit::Length(factor), rest) => {
                let (local, after) = match strip_any(rest, &["over any", "for any", "over"]) {
                    Some(after) => (true, after),
                    None => match strip_any(rest, &["per", "for", "/"]) {
                        Some(after) => (false, after),
                        None => {
                            return Err(error(
                                "expected `per L`, `over any L` or nothing after the value",
                            ));
                        }
                    },
                };
                let (length, tail) = number(after.trim_start())
                    .ok_or_else(|| error("expected a length in mm after `per` or `over any`"))?;
                if !matches!(tail.trim(), "" | "mm") {
                    return Err(error("the length after `per` or `over any` is in mm"));
                }
                if length <= 0.0 {
                    return Err(error("the length must be more than 0"));
                }
                let um = value * factor;
                match local {
                    true => Tolerance::Local {
                        um,
                        over_mm: length,
                    },
                    false => Tolerance::PerLength { um, per_mm: length },
                }
            }
        };
        match tolerance.value() >= 0.0 && tolerance.value().is_finite() {
            true => Ok(tolerance),
            false => Err(error("a tolerance is a finite number ≥ 0")),
        }
    }

    fn value(&self) -> f64 {
        match *self {
            Tolerance::Length { um } | Tolerance::PerLength { um, .. } => um,
            Tolerance::Local { um, .. } => um,
            Tolerance::Angle { arcsec } => arcsec,
        }
    }

    /// The limit of a straightness over a travel of `length_mm`, µm; `None` for an angle
    /// or a local tolerance (judged on the local straightness, [`Tolerance::local`]).
    pub fn straightness_um(&self, length_mm: f64) -> Option<f64> {
        match *self {
            Tolerance::Length { um } => Some(um),
            Tolerance::PerLength { um, per_mm } => Some(um * length_mm / per_mm),
            _ => None,
        }
    }

    /// The local tolerance: (µm, over mm).
    pub fn local(&self) -> Option<(f64, f64)> {
        match *self {
            Tolerance::Local { um, over_mm } => Some((um, over_mm)),
            _ => None,
        }
    }

    /// The limit of an angle (angular deviation, squareness), arcsec: an angle as given,
    /// a length per length as its slope (20 µm per 1000 mm is arctan(2·10⁻⁵)).
    pub fn angle_arcsec(&self) -> Option<f64> {
        match *self {
            Tolerance::Angle { arcsec } => Some(arcsec),
            Tolerance::PerLength { um, per_mm } => {
                Some((um / 1000.0 / per_mm).atan() * ARCSEC_PER_RAD)
            }
            _ => None,
        }
    }
}

/// The number at the start of `text` (a space between digit groups of three allowed:
/// `1 000`) and the rest.
fn number(text: &str) -> Option<(f64, &str)> {
    let b = text.as_bytes();
    let digit = |k: usize| b.get(k).is_some_and(u8::is_ascii_digit);
    let mut end = 0;
    let mut digits = String::new();
    while end < b.len() {
        let c = b[end];
        let grouped = c == b' '
            && !digits.is_empty()
            && !digits.contains('.')
            && (1..=3).all(|k| digit(end + k))
            && !digit(end + 4);
        match c {
            b'0'..=b'9' | b'.' => digits.push(c as char),
            b'+' | b'-' if end == 0 => digits.push(c as char),
            _ if grouped => {}
            _ => break,
        }
        end += 1;
    }
    Some((digits.parse::<f64>().ok()?, &text[end..]))
}

enum Unit {
    /// Factor to µm.
    Length(f64),
    /// Factor to arcsec.
    Angle(f64),
}

/// The unit after a value (mm when none), and the rest.
fn unit(text: &str) -> (Unit, &str) {
    let t = text.trim_start();
    let units: [(&str, Unit); 9] = [
        ("µrad", Unit::Angle(0.648 / std::f64::consts::PI)),
        ("urad", Unit::Angle(0.648 / std::f64::consts::PI)),
        ("arcsec", Unit::Angle(1.0)),
        ("″", Unit::Angle(1.0)),
        ("\"", Unit::Angle(1.0)),
        ("µm", Unit::Length(1.0)),
        ("um", Unit::Length(1.0)),
        ("mm", Unit::Length(1000.0)),
        ("", Unit::Length(1000.0)),
    ];
    for (name, unit) in units {
        if let Some(rest) = t.strip_prefix(name) {
            return (unit, rest);
        }
    }
    unreachable!("the empty unit matches every text")
}

fn strip_any<'a>(text: &'a str, words: &[&str]) -> Option<&'a str> {
    words.iter().find_map(|w| text.strip_prefix(w))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_forms_acceptance_standards_write() {
        let p = |t: &str| Tolerance::parse(t).unwrap();
        assert_eq!(p("0.015"), Tolerance::Length { um: 15.0 });
        assert_eq!(p("15 µm"), Tolerance::Length { um: 15.0 });
        assert_eq!(
            p("0.020 per 1000"),
            Tolerance::PerLength {
                um: 20.0,
                per_mm: 1000.0
            }
        );
        assert_eq!(
            p("0,020 for 1 000 mm"),
            Tolerance::PerLength {
                um: 20.0,
                per_mm: 1000.0
            }
        );
        assert_eq!(
            p("0.02/1000"),
            Tolerance::PerLength {
                um: 20.0,
                per_mm: 1000.0
            }
        );
        assert_eq!(
            p("0.010 over any 300"),
            Tolerance::Local {
                um: 10.0,
                over_mm: 300.0
            }
        );
        assert_eq!(
            p("10 um for any 300 mm"),
            Tolerance::Local {
                um: 10.0,
                over_mm: 300.0
            }
        );
        assert_eq!(p("30″"), Tolerance::Angle { arcsec: 30.0 });
        assert_eq!(p("30 arcsec"), Tolerance::Angle { arcsec: 30.0 });
        // 145 µrad = 145 × 0.206265″ = 29.908″.
        let Tolerance::Angle { arcsec } = p("145 µrad") else {
            panic!()
        };
        assert_eq!(format!("{arcsec:.3}"), "29.908");
    }

    #[test]
    fn limits_by_hand() {
        let per = Tolerance::parse("0.020 per 1000").unwrap();
        // A travel of 600 mm: 0.020 × 600 / 1000 mm = 12 µm.
        assert!((per.straightness_um(600.0).unwrap() - 12.0).abs() < 1e-12);
        // As a squareness: arctan(20 µm / 1000 mm) = 4.125″.
        assert_eq!(format!("{:.3}", per.angle_arcsec().unwrap()), "4.125");
        let local = Tolerance::parse("0.010 over any 300").unwrap();
        assert_eq!(local.local(), Some((10.0, 300.0)));
        assert_eq!(local.straightness_um(600.0), None);
        assert_eq!(
            Tolerance::parse("30″").unwrap().straightness_um(600.0),
            None
        );
    }

    #[test]
    fn what_is_refused_says_why() {
        for (text, why) in [
            ("per 1000", "does not start with a number"),
            ("0.020 each 1000", "expected `per L`"),
            ("0.020 per 1000 inch", "is in mm"),
            ("0.020 per 0", "more than 0"),
            ("-0.020", "finite number ≥ 0"),
            ("30″ per 1000", "nothing after its unit"),
        ] {
            let e = Tolerance::parse(text).unwrap_err();
            assert!(e.to_string().contains(why), "{text}: {e}");
        }
    }
}
