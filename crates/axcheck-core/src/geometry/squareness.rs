//! Squareness of two linear axes from two straightness tests and an optical square
//! (ISO 230-1:2012 3.6.7, as quoted in Renishaw TE328: the difference of the inclinations
//! of the two trajectories' reference straight lines).
//!
//! The method and sign are those of the HP 5528A User's Guide, §21, pp. 21-6 to 21-8:
//! each axis's misalignment angle θ = arctan(m) from its reference line's slope m
//! (dimensionless), the total angle between the axes = 90° + θ₂ − θ₁ + the optical
//! square's error, so "squareness = θ₂ − θ₁ + optical square error": **positive when the
//! included angle is larger than 90°**. The straightness readings must be signed as the
//! guide's Figure 21-2 draws them (into and out of the square); the other convention
//! (positive when the angle is smaller than 90°) is the same value negated.

use super::ARCSEC_PER_RAD;
use super::line::Line;
use serde::{Deserialize, Serialize};

/// Which sign the squareness error is stated with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Convention {
    /// Positive when the included angle is larger than 90° (HP 5528A §21).
    #[default]
    #[serde(alias = "over_90", alias = "over-90")]
    OverNinetyPositive,
    /// Positive when the included angle is smaller than 90°.
    #[serde(alias = "under_90", alias = "under-90")]
    UnderNinetyPositive,
}

/// The squareness of two axes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Squareness {
    /// The squareness error in `convention`'s sign, arcsec.
    pub error_arcsec: f64,
    /// The same, µm per metre (tan of the angle × 10⁶).
    pub error_um_per_m: f64,
    /// The included angle minus 90°, arcsec (positive: larger than 90°), whatever the
    /// convention.
    pub over_ninety_arcsec: f64,
    /// θ₁ and θ₂: each axis's misalignment from its reference line, arcsec.
    pub first_arcsec: f64,
    pub second_arcsec: f64,
    pub square_error_arcsec: f64,
    pub convention: Convention,
}

/// Each axis's misalignment angle from its reference line, arcsec (arctan of the slope).
pub fn misalignment_arcsec(line: &Line) -> f64 {
    (line.slope_um_per_m * 1e-6).atan() * ARCSEC_PER_RAD
}

/// The squareness from the first and second axis's reference lines and the optical
/// square's stated error (arcsec, as printed on it).
pub fn evaluate(
    first: &Line,
    second: &Line,
    square_error_arcsec: f64,
    convention: Convention,
) -> Squareness {
    let first_arcsec = misalignment_arcsec(first);
    let second_arcsec = misalignment_arcsec(second);
    let over_ninety_arcsec = second_arcsec - first_arcsec + square_error_arcsec;
    let error_arcsec = match convention {
        Convention::OverNinetyPositive => over_ninety_arcsec,
        Convention::UnderNinetyPositive => -over_ninety_arcsec,
    };
    Squareness {
        error_arcsec,
        error_um_per_m: (error_arcsec / ARCSEC_PER_RAD).tan() * 1e6,
        over_ninety_arcsec,
        first_arcsec,
        second_arcsec,
        square_error_arcsec,
        convention,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::line::tests::{hp_axis_1, hp_axis_2};
    use crate::geometry::line::{ReferenceLine, fit};

    /// HP 5528A User's Guide §21, pp. 21-4 to 21-7: the guide's two axes give −5.2″ by
    /// least squares and −5.5″ by end points, with an optical square of no error.
    #[test]
    fn the_hp_5528a_worked_example_in_both_conventions() {
        let (x1, y1) = hp_axis_1();
        let (x2, y2) = hp_axis_2();
        for (method, printed) in [
            (ReferenceLine::LeastSquares, "-5.2"),
            (ReferenceLine::EndPoint, "-5.5"),
        ] {
            let a = fit(method, &x1, &y1).unwrap();
            let b = fit(method, &x2, &y2).unwrap();
            let over = evaluate(&a, &b, 0.0, Convention::OverNinetyPositive);
            assert_eq!(format!("{:.1}", over.error_arcsec), printed);
            let under = evaluate(&a, &b, 0.0, Convention::UnderNinetyPositive);
            assert_eq!(under.error_arcsec, -over.error_arcsec);
            assert_eq!(under.over_ninety_arcsec, over.over_ninety_arcsec);
        }
        let a = fit(ReferenceLine::LeastSquares, &x1, &y1).unwrap();
        let b = fit(ReferenceLine::LeastSquares, &x2, &y2).unwrap();
        // The guide's θ₁ = 1.6″ and θ₂ = −3.6″; a square 2″ over 90° adds 2″.
        let s = evaluate(&a, &b, 2.0, Convention::OverNinetyPositive);
        assert_eq!(
            format!("{:.1} {:.1}", s.first_arcsec, s.second_arcsec),
            "1.6 -3.6"
        );
        assert_eq!(format!("{:.1}", s.error_arcsec), "-3.2");
    }

    #[test]
    fn forty_um_per_m() {
        let flat = Line {
            offset_um: 0.0,
            slope_um_per_m: 0.0,
        };
        let tilted = Line {
            offset_um: 3.0,
            slope_um_per_m: 40.0,
        };
        let s = evaluate(&flat, &tilted, 0.0, Convention::OverNinetyPositive);
        assert!((s.error_um_per_m - 40.0).abs() < 1e-9);
        // 40 µm/m = arctan(4e-5) rad = 8.2506″.
        assert_eq!(format!("{:.4}", s.error_arcsec), "8.2506");
    }
}
