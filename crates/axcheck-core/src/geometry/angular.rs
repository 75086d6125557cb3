//! Angular deviations of a linear axis: roll, pitch and yaw (ISO 230-1 EAX, EBX, ECX for
//! an X axis), measured with angular optics at the targets of the travel, in arcseconds
//! (1″ = π/648 000 rad ≈ 4.848 µrad).
//!
//! The angular error of the travel is the largest minus the smallest mean angular reading,
//! not referred to any line: an angle is measured from the start's, and only its
//! variation along the travel moves a point off the beam (the laser packages report this
//! range; ISO 230-1's own wording was not available to the project). Per direction and
//! both directions together, as [`super::straightness`]; the repeatability as ISO 230-2
//! 2.20 gives it for positioning (4sᵢ, the largest over targets and directions).

use crate::evaluate::stats::{range, sample_sd};
use crate::measurement::AxisData;
use crate::units::Direction;
use serde::Serialize;

/// An angular test evaluated, arcsec.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Angular {
    /// Largest minus smallest of both directions' mean readings.
    pub deviation_arcsec: f64,
    pub up_arcsec: f64,
    pub down_arcsec: f64,
    /// The largest 4sᵢ over targets and directions; `None` for one run.
    pub repeatability_arcsec: Option<f64>,
    /// The largest |x̄ᵢ↑ − x̄ᵢ↓|.
    pub reversal_arcsec: f64,
}

/// The angular error of `data` (arcsec at targets in mm); `None` for no target.
pub fn evaluate(data: &AxisData) -> Option<Angular> {
    let up = super::means(data, Direction::Up);
    let down = super::means(data, Direction::Down);
    let both: Vec<f64> = up.iter().chain(&down).copied().collect();
    let repeatability_arcsec = (0..data.target_count())
        .flat_map(|i| [Direction::Up, Direction::Down].map(|d| sample_sd(data.deviations(i, d))))
        .map(|s| s.map(|s| 4.0 * s))
        .collect::<Option<Vec<f64>>>()
        .and_then(|r| r.into_iter().reduce(f64::max));
    Some(Angular {
        deviation_arcsec: range(&both)?,
        up_arcsec: range(&up).unwrap_or(0.0),
        down_arcsec: range(&down).unwrap_or(0.0),
        repeatability_arcsec,
        reversal_arcsec: (up.iter().zip(&down))
            .map(|(u, d)| (u - d).abs())
            .fold(0.0, f64::max),
    })
}

/// An angular test's mean reading in each direction along the travel, to be read at any
/// position between its first and last target (linear between targets).
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    targets_mm: Vec<f64>,
    up: Vec<f64>,
    down: Vec<f64>,
}

impl Trace {
    pub fn of(data: &AxisData) -> Trace {
        Trace {
            targets_mm: data.targets.clone(),
            up: super::means(data, Direction::Up),
            down: super::means(data, Direction::Down),
        }
    }

    /// The first and last target, mm.
    pub fn travel_mm(&self) -> (f64, f64) {
        let t = &self.targets_mm;
        (t[0], t[t.len() - 1])
    }

    /// The mean angle in `direction` at `position_mm`, arcsec; `None` outside the travel.
    pub fn at(&self, position_mm: f64, direction: Direction) -> Option<f64> {
        let t = &self.targets_mm;
        let values = match direction {
            Direction::Up => &self.up,
            Direction::Down => &self.down,
        };
        let slack = 1e-6;
        let (first, last) = self.travel_mm();
        if position_mm < first - slack || position_mm > last + slack {
            return None;
        }
        let k = t.partition_point(|&x| x < position_mm);
        Some(match k {
            0 => values[0],
            k if k >= t.len() => values[t.len() - 1],
            k => {
                let u = (position_mm - t[k - 1]) / (t[k] - t[k - 1]);
                values[k - 1] + u * (values[k] - values[k - 1])
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::straightness::tests::test;

    #[test]
    fn a_pitch_of_20_arcsec_along_the_travel() {
        let targets: Vec<f64> = (0..=8).map(|k| k as f64 * 125.0).collect();
        let data = test(&targets, 5, |x| 0.02 * x, 1.0);
        let a = evaluate(&data).unwrap();
        // Means up 0.02x + 0.5, down 0.02x − 0.5 over 0..1000 mm: 20 each, 21 together.
        assert!((a.up_arcsec - 20.0).abs() < 1e-9 && (a.down_arcsec - 20.0).abs() < 1e-9);
        assert!((a.deviation_arcsec - 21.0).abs() < 1e-9);
        assert!((a.reversal_arcsec - 1.0).abs() < 1e-9);
        assert_eq!(a.repeatability_arcsec, Some(0.0));
        let t = Trace::of(&data);
        assert!((t.at(62.5, Direction::Up).unwrap() - 1.75).abs() < 1e-12);
        assert!((t.at(1000.0, Direction::Down).unwrap() - 19.5).abs() < 1e-12);
        assert_eq!(t.at(1000.1, Direction::Up), None);
    }
}
