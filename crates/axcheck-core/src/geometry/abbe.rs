//! The positioning deviation carried from the beam to the tool point (Abbe): a component
//! that tilts as it moves displaces a point off the measuring line by the offset times the
//! angle's tangent (HP 5528A User's Guide, Appendix B, p. B-4: "Offset distance × tangent
//! (offset angle)"; 20″ at 150 mm is 14.5 µm), which the laser on the beam does not see.
//!
//! The sign follows the small-angle rigid-body rule with right-handed rotations: for a
//! point at (v, w) from the beam across an axis u (X: v = Y, w = Z; Y: Z, X; Z: X, Y, ISO
//! 841's cyclic order) and rotations εᵥ, ε_w about v and w, the point moves along u by
//! εᵥ·w − ε_w·v. For an X axis: Δx = EBX·z − ECX·y (pitch with the vertical offset, yaw
//! with the horizontal). The angular tests must be of the component that carries the
//! tool point (or its opposite sign when it carries the workpiece: state the offset
//! negated). No source available to the project states this rule in words; it is the
//! cross product ε × r.

use super::ARCSEC_PER_RAD;
use super::angular::Trace;
use crate::measurement::AxisData;
use serde::Serialize;

/// Where the tool point is from the beam, across the axis, mm: `v_mm` and `w_mm` in the
/// cyclic order (for X: y and z; for Y: z and x; for Z: x and y).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Offset {
    pub v_mm: f64,
    pub w_mm: f64,
}

/// The angular tests of the moving component: about v (for X, EBX pitch) and about w
/// (for X, ECX yaw), arcsec; a rotation not measured is left out (and counted as none).
#[derive(Debug, Clone, Copy, Default)]
pub struct Rotations<'a> {
    pub about_v: Option<&'a Trace>,
    pub about_w: Option<&'a Trace>,
}

/// A positioning target the angular tests do not reach.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error(
    "the positioning target {position_mm} mm is outside the angular test's travel {from_mm}..{to_mm} mm: the angle there is not measured"
)]
pub struct OutsideTravel {
    pub position_mm: f64,
    pub from_mm: f64,
    pub to_mm: f64,
}

/// The positioning test as the tool point would have shown it: each reading plus
/// εᵥ·w − ε_w·v at its target and direction, µm (angles interpolated between the angular
/// tests' targets).
pub fn to_tool_point(
    positioning: &AxisData,
    rotations: Rotations<'_>,
    offset: Offset,
) -> Result<AxisData, OutsideTravel> {
    let angle =
        |trace: Option<&Trace>, position_mm: f64, direction| -> Result<f64, OutsideTravel> {
            let Some(trace) = trace else { return Ok(0.0) };
            trace.at(position_mm, direction).ok_or_else(|| {
                let (from_mm, to_mm) = trace.travel_mm();
                OutsideTravel {
                    position_mm,
                    from_mm,
                    to_mm,
                }
            })
        };
    let mut shift = Vec::with_capacity(positioning.readings.len());
    for r in &positioning.readings {
        let p = positioning.targets[r.target];
        let about_v = angle(rotations.about_v, p, r.direction)? / ARCSEC_PER_RAD;
        let about_w = angle(rotations.about_w, p, r.direction)? / ARCSEC_PER_RAD;
        shift.push((about_v.tan() * offset.w_mm - about_w.tan() * offset.v_mm) * 1000.0);
    }
    let mut k = 0;
    Ok(positioning.map_deviations(|r| {
        k += 1;
        r.deviation + shift[k - 1]
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate::{StandardId, evaluate_by, gost27843::SMethod};
    use crate::geometry::straightness::tests::test;

    fn e(data: &AxisData) -> f64 {
        let ev = evaluate_by(data, StandardId::Iso230_2, SMethod::Formula5);
        ev.parameters.iter().find(|p| p.key() == "E").unwrap().value
    }

    #[test]
    fn a_20_arcsec_pitch_150_mm_below_the_tool_point() {
        let targets: Vec<f64> = (0..=10).map(|k| k as f64 * 100.0).collect();
        // A perfect positioning test, and a pitch growing to 20″ over the travel.
        let positioning = test(&targets, 5, |_| 0.0, 0.0);
        let pitch = Trace::of(&test(&targets, 5, |x| 0.02 * x, 0.0));
        let rotations = Rotations {
            about_v: Some(&pitch),
            about_w: None,
        };
        let at_tool = to_tool_point(
            &positioning,
            rotations,
            Offset {
                v_mm: 0.0,
                w_mm: 150.0,
            },
        )
        .unwrap();
        // By hand: tan(20″) × 150 mm = tan(20 / 206 264.806 rad) × 150 000 µm = 14.544 µm.
        assert_eq!(format!("{:.3}", e(&at_tool)), "14.544");
        assert_eq!(e(&positioning), 0.0);
        // Yaw with a horizontal offset enters with the other sign: −ECX·y.
        let yaw = Rotations {
            about_v: None,
            about_w: Some(&pitch),
        };
        let left = to_tool_point(
            &positioning,
            yaw,
            Offset {
                v_mm: 150.0,
                w_mm: 0.0,
            },
        )
        .unwrap();
        let last = left.deviations(10, crate::units::Direction::Up)[0];
        assert_eq!(format!("{last:.3}"), "-14.544");
    }

    #[test]
    fn a_target_beyond_the_angular_test_is_refused() {
        let positioning = test(&[0.0, 500.0, 1000.0], 2, |_| 0.0, 0.0);
        let short = Trace::of(&test(&[0.0, 800.0], 2, |x| 0.01 * x, 0.0));
        let rotations = Rotations {
            about_v: Some(&short),
            about_w: None,
        };
        let e = to_tool_point(
            &positioning,
            rotations,
            Offset {
                v_mm: 0.0,
                w_mm: 100.0,
            },
        )
        .unwrap_err();
        assert_eq!(e.position_mm, 1000.0);
    }
}
