//! Axis kinds, approach directions and the unit conventions that follow from them.
//!
//! A linear axis has target positions in mm and deviations in µm; a rotary axis has
//! target positions in degrees and deviations in arcseconds (ISO 230-2:1997 clause 1:
//! "applies equally to linear and rotary axes"). Every deviation value inside axcheck is
//! in the axis's deviation unit; every position in its position unit.

use serde::{Deserialize, Serialize};
use std::fmt;

/// Linear or rotary axis (ISO 230-2 clause 2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum AxisKind {
    Linear,
    Rotary,
}

impl AxisKind {
    /// Unit of target positions: `mm` or `deg`.
    pub fn position_unit(self) -> &'static str {
        match self {
            AxisKind::Linear => "mm",
            AxisKind::Rotary => "deg",
        }
    }

    /// Unit of deviations: `um` (µm) or `arcsec`.
    pub fn deviation_unit(self) -> &'static str {
        match self {
            AxisKind::Linear => "um",
            AxisKind::Rotary => "arcsec",
        }
    }

    /// Deviation unit for people: `µm` or `″`-free `arcsec`.
    pub fn deviation_symbol(self) -> &'static str {
        match self {
            AxisKind::Linear => "µm",
            AxisKind::Rotary => "arcsec",
        }
    }

    /// Position unit for people: `mm` or `°`.
    pub fn position_symbol(self) -> &'static str {
        match self {
            AxisKind::Linear => "mm",
            AxisKind::Rotary => "°",
        }
    }

    /// How many deviation units one position unit holds (1 mm = 1000 µm, 1° = 3600″).
    pub fn deviation_units_per_position_unit(self) -> f64 {
        match self {
            AxisKind::Linear => 1000.0,
            AxisKind::Rotary => 3600.0,
        }
    }

    /// A relative (ppm) error at `position` expressed in deviation units: 1 ppm of 1 m is
    /// 1 µm; 1 ppm of 1° is 0.0036″.
    pub(crate) fn ppm_to_deviation(self, ppm: f64, position: f64) -> f64 {
        ppm * 1e-6 * position * self.deviation_units_per_position_unit()
    }
}

impl fmt::Display for AxisKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            AxisKind::Linear => "linear",
            AxisKind::Rotary => "rotary",
        })
    }
}

/// Approach direction (ISO 230-2 clause 2.6): `Up` (↑) is an approach moving in the
/// positive direction, i.e. from the negative side; `Down` (↓) the opposite.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Direction {
    Up,
    Down,
}

impl Direction {
    pub const BOTH: [Direction; 2] = [Direction::Up, Direction::Down];

    /// Parses the spellings found in measurement files: `up`/`down`, `+`/`-`, `↑`/`↓`,
    /// `fwd`/`bwd`, `forward`/`reverse`/`backward`, `pos`/`neg`, `positive`/`negative`.
    pub fn parse(text: &str) -> Option<Direction> {
        const UP: [&str; 7] = ["up", "+", "↑", "fwd", "forward", "pos", "positive"];
        const DOWN: [&str; 10] = [
            "down", "-", "−", "↓", "bwd", "backward", "reverse", "rev", "neg", "negative",
        ];
        // Compared without a lower-case copy: a reader calls this for every reading.
        let t = text.trim();
        let is = |names: &[&str]| names.iter().any(|n| n.eq_ignore_ascii_case(t));
        if is(&UP) {
            Some(Direction::Up)
        } else if is(&DOWN) {
            Some(Direction::Down)
        } else {
            None
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Direction::Up => "up",
            Direction::Down => "down",
        }
    }

    pub fn arrow(self) -> &'static str {
        match self {
            Direction::Up => "↑",
            Direction::Down => "↓",
        }
    }

    /// +1 for up, −1 for down.
    pub fn sign(self) -> f64 {
        match self {
            Direction::Up => 1.0,
            Direction::Down => -1.0,
        }
    }

    pub fn index(self) -> usize {
        match self {
            Direction::Up => 0,
            Direction::Down => 1,
        }
    }

    pub fn opposite(self) -> Direction {
        match self {
            Direction::Up => Direction::Down,
            Direction::Down => Direction::Up,
        }
    }
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Arcseconds in a radian (648 000 / π).
pub const ARCSEC_PER_RAD: f64 = 648_000.0 / std::f64::consts::PI;

/// Formats `value` with `decimals` places, never printing `-0.000`.
pub fn fmt_fixed(value: f64, decimals: usize) -> String {
    let s = format!("{value:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Formats a position without trailing zeros (at most 6 decimals): `6.711`, `0`, `-20`.
pub fn fmt_position(value: f64) -> String {
    let s = fmt_fixed(value, 6);
    if s.contains('.') {
        let t = s.trim_end_matches('0').trim_end_matches('.');
        t.to_string()
    } else {
        s
    }
}

/// Axis travel: a length (`1200`) or the coordinates of its ends (`[-600, 600]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Travel {
    Length(f64),
    Range([f64; 2]),
}

/// Reads either form, and says which two it accepts when given neither (an untagged
/// derive would only say that no variant matched).
impl<'de> Deserialize<'de> for Travel {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<Travel, D::Error> {
        struct TravelVisitor;

        impl<'de> serde::de::Visitor<'de> for TravelVisitor {
            type Value = Travel;

            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a length (600) or its two ends ([0, 600])")
            }

            fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Travel, E> {
                Ok(Travel::Length(v))
            }

            fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Travel, E> {
                Ok(Travel::Length(v as f64))
            }

            fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Travel, E> {
                Ok(Travel::Length(v as f64))
            }

            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<Travel, A::Error> {
                let mut ends = Vec::new();
                while let Some(end) = seq.next_element::<f64>()? {
                    ends.push(end);
                }
                match ends[..] {
                    [a, b] => Ok(Travel::Range([a, b])),
                    _ => Err(serde::de::Error::invalid_length(ends.len(), &self)),
                }
            }
        }

        deserializer.deserialize_any(TravelVisitor)
    }
}

impl Travel {
    pub fn length(self) -> f64 {
        match self {
            Travel::Length(l) => l,
            Travel::Range([a, b]) => (b - a).abs(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_direction_spellings() {
        for s in ["up", "UP", "+", "↑", "fwd", "Forward", "positive"] {
            assert_eq!(Direction::parse(s), Some(Direction::Up), "{s}");
        }
        for s in ["down", "-", "↓", "bwd", "reverse", "BACKWARD", "neg"] {
            assert_eq!(Direction::parse(s), Some(Direction::Down), "{s}");
        }
        assert_eq!(Direction::parse("dwon"), None);
    }

    #[test]
    fn fixed_format_has_no_negative_zero() {
        assert_eq!(fmt_fixed(-0.00001, 3), "0.000");
        assert_eq!(fmt_fixed(-1.23456, 3), "-1.235");
        assert_eq!(fmt_position(6.711), "6.711");
        assert_eq!(fmt_position(-20.0), "-20");
        assert_eq!(fmt_position(1750.92), "1750.92");
    }

    #[test]
    fn ppm_conversion() {
        assert!((AxisKind::Linear.ppm_to_deviation(10.0, 1000.0) - 10.0).abs() < 1e-12);
        assert!((AxisKind::Rotary.ppm_to_deviation(1.0, 360.0) - 1.296).abs() < 1e-12);
    }
}
