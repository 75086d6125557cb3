//! The other tests of a linear axis in the model: its straightness across the axis, its
//! rotations (roll, pitch, yaw) and where the positioning test's laser beam is from the
//! tool point. The rotations put an Abbe error into the positioning readings at the beam
//! (the offset times the angle's tangent, HP 5528A User's Guide Appendix B), which
//! `geometry::abbe` takes out again at the tool point.
//!
//! Straightness in µm, rotations in arcsec, positions in mm; the axes by their letters
//! (for an X axis: straightness along Y and Z, rotations about A, B and C).

use crate::units::{ARCSEC_PER_RAD, Direction};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A straightness or a rotation along the travel.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Profile {
    /// In the middle of the travel, above the line through its ends (a parabola), µm or
    /// arcsec.
    #[serde(alias = "bow_um", alias = "bow_arcsec")]
    pub bow: f64,
    /// Slope along the travel, µm or arcsec per metre.
    #[serde(alias = "slope_um_per_m", alias = "slope_arcsec_per_m")]
    pub slope_per_m: f64,
    /// Upward minus downward, µm or arcsec.
    #[serde(alias = "reversal_um", alias = "reversal_arcsec")]
    pub reversal: f64,
    /// Standard deviation of each reading, µm or arcsec.
    #[serde(alias = "scatter_um", alias = "scatter_arcsec")]
    pub scatter: f64,
}

impl Profile {
    /// The profile's value at `position` in `direction`, without scatter.
    pub fn at(&self, position: f64, direction: Direction, travel: (f64, f64)) -> f64 {
        let length = travel.1 - travel.0;
        let u = match length > 0.0 {
            true => (position - travel.0) / length,
            false => 0.0,
        };
        let half = match direction {
            Direction::Up => 0.5,
            Direction::Down => -0.5,
        };
        4.0 * self.bow * u * (1.0 - u)
            + self.slope_per_m * (position - travel.0) / 1000.0
            + half * self.reversal
    }
}

/// The axis's geometry beyond positioning.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GeometryModel {
    /// The moving axis: X, Y or Z (names the others).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub axis: Option<char>,
    /// Straightness along the other linear axes, µm: `{Y: {bow_um: 8}}` for EYX.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub straightness: BTreeMap<char, Profile>,
    /// Rotations about A, B and C, arcsec: `{B: {slope_arcsec_per_m: 20}}` for EBX.
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub angular: BTreeMap<char, Profile>,
    /// Where the positioning test's laser beam is from the tool point across the axis,
    /// mm by axis letter (`{Z: -150}`: 150 mm below it).
    #[serde(skip_serializing_if = "BTreeMap::is_empty")]
    pub beam_mm: BTreeMap<char, f64>,
}

/// The two linear axes across `axis` in ISO 841's cyclic order and the rotations about
/// them: X → (Y, Z, B, C), Y → (Z, X, C, A), Z → (X, Y, A, B); the roll's letter last.
pub fn across(axis: char) -> Option<[char; 5]> {
    match axis {
        'X' => Some(['Y', 'Z', 'B', 'C', 'A']),
        'Y' => Some(['Z', 'X', 'C', 'A', 'B']),
        'Z' => Some(['X', 'Y', 'A', 'B', 'C']),
        _ => None,
    }
}

impl GeometryModel {
    pub fn is_empty(&self) -> bool {
        self.straightness.is_empty() && self.angular.is_empty() && self.beam_mm.is_empty()
    }

    /// What a model cannot use: terms without the axis, letters that are not across it.
    pub fn validate(&self) -> Result<(), String> {
        if self.is_empty() {
            return Ok(());
        }
        let Some(axis) = self.axis else {
            return Err("model.geometry.axis: give the moving axis (X, Y or Z) that names the straightness, angular and beam letters".into());
        };
        let Some([v, w, about_v, about_w, roll]) = across(axis) else {
            return Err(format!("model.geometry.axis: `{axis}` is not X, Y or Z"));
        };
        let check = |key: &str, letters: Vec<char>, allowed: &[char]| match letters
            .into_iter()
            .find(|l| !allowed.contains(l))
        {
            Some(l) => Err(format!(
                "model.geometry.{key}: `{l}` is not across the {axis} axis (expected {})",
                allowed
                    .iter()
                    .map(char::to_string)
                    .collect::<Vec<_>>()
                    .join(" or ")
            )),
            None => Ok(()),
        };
        check(
            "straightness",
            self.straightness.keys().copied().collect(),
            &[v, w],
        )?;
        check(
            "angular",
            self.angular.keys().copied().collect(),
            &[about_v, about_w, roll],
        )?;
        check("beam_mm", self.beam_mm.keys().copied().collect(), &[v, w])?;
        let values = (self.straightness.values().chain(self.angular.values()))
            .flat_map(|p| [p.bow, p.slope_per_m, p.reversal, p.scatter])
            .chain(self.beam_mm.values().copied());
        match values.into_iter().all(f64::is_finite) {
            true => Ok(()),
            false => Err("model.geometry: every value must be a finite number".into()),
        }
    }

    /// The Abbe error the rotations put into a positioning reading at the beam, µm: the
    /// beam at r = (r_v, r_w) from the tool point reads the tool point's deviation plus
    /// εᵥ·r_w − ε_w·r_v (the rigid-body rule of `geometry::abbe`).
    pub fn abbe_at_beam(&self, position: f64, direction: Direction, travel: (f64, f64)) -> f64 {
        let Some([v, w, about_v, about_w, _]) = self.axis.and_then(across) else {
            return 0.0;
        };
        let angle = |letter: char| {
            (self.angular.get(&letter))
                .map_or(0.0, |p| p.at(position, direction, travel) / ARCSEC_PER_RAD)
        };
        let r = |letter: char| self.beam_mm.get(&letter).copied().unwrap_or(0.0);
        (angle(about_v).tan() * r(w) - angle(about_w).tan() * r(v)) * 1000.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_profile_by_hand() {
        let p = Profile {
            bow: 8.0,
            slope_per_m: 15.0,
            reversal: 2.0,
            scatter: 0.0,
        };
        // At 250 of 0..1000 mm: 4·8·0.25·0.75 + 15·0.25 ± 1 = 6 + 3.75 ± 1.
        assert!((p.at(250.0, Direction::Up, (0.0, 1000.0)) - 10.75).abs() < 1e-12);
        assert!((p.at(250.0, Direction::Down, (0.0, 1000.0)) - 8.75).abs() < 1e-12);
    }

    #[test]
    fn letters_must_be_across_the_axis() {
        let mut g = GeometryModel {
            axis: Some('X'),
            ..Default::default()
        };
        g.straightness.insert('X', Profile::default());
        let e = g.validate().unwrap_err();
        assert!(
            e.contains("`X` is not across the X axis (expected Y or Z)"),
            "{e}"
        );
        g.straightness.clear();
        g.angular.insert('B', Profile::default());
        g.beam_mm.insert('Z', -150.0);
        assert_eq!(g.validate(), Ok(()));
        g.axis = None;
        assert!(g.validate().unwrap_err().contains("give the moving axis"));
        // 20″ about B with the beam 150 mm below the tool point (r_w = −150): the beam
        // reads tan(20″)·(−150 mm) = −14.544 µm more than the tool point.
        g.axis = Some('X');
        g.angular.insert(
            'B',
            Profile {
                slope_per_m: 20.0,
                ..Default::default()
            },
        );
        let at_end = g.abbe_at_beam(1000.0, Direction::Up, (0.0, 1000.0));
        assert_eq!(format!("{at_end:.3}"), "-14.544");
    }
}
