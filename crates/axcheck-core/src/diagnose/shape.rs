//! The shapes a term along the axis may take (issue 43): a reversal value that changes
//! along the axis may do so on a straight line (a screw worn evenly, a preload that
//! changes with the travel), on a smooth curve, or target by target (a worn or damaged
//! section) — which is the standard's own Bi per target (ISO 230-2 2.12) kept as measured.
//! Hemingray et al. 1971, §5.2 measure lost motion at every position for that reason.
//!
//! Each shape is offered when the plan can tell it from the simpler ones, and the one with
//! the smallest held-out error wins ([`super::select`]); a shape with more parameters
//! pays for them there, since the values it fits to the scatter of the training readings
//! miss the readings held out.

use super::maths::linalg::least_squares;
use serde::Serialize;

/// The shape of a term along the targets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Shape {
    /// A straight line along the axis (2 parameters).
    #[default]
    Line,
    /// A quadratic along the axis (3 parameters).
    Curve,
    /// One value per target (as many parameters as targets).
    PerTarget,
}

impl Shape {
    /// Every shape, the simplest first.
    pub const ALL: [Shape; 3] = [Shape::Line, Shape::Curve, Shape::PerTarget];

    /// The stable name (`line`, `curve`, `per_target`).
    pub fn name(self) -> &'static str {
        match self {
            Shape::Line => "line",
            Shape::Curve => "curve",
            Shape::PerTarget => "per_target",
        }
    }

    /// How a value in this shape changes, in a finding's words.
    pub(crate) fn changes(self) -> &'static str {
        match self {
            Shape::Line => "along the axis",
            Shape::Curve => "along the axis on a curve",
            Shape::PerTarget => "from target to target",
        }
    }

    /// Parameters of the shape over `m` targets.
    pub fn parameters(self, m: usize) -> usize {
        match self {
            Shape::Line => 2,
            Shape::Curve => 3,
            Shape::PerTarget => m,
        }
    }

    /// Whether the shape is offered on `m` targets: only where it differs from the
    /// simpler ones (a curve through 3 or 4 targets is nearly one value per target).
    pub(crate) fn offered(self, m: usize) -> bool {
        match self {
            Shape::Line => m >= 2,
            Shape::Curve => m >= 6,
            Shape::PerTarget => m >= 3,
        }
    }

    /// The shapes offered on `m` targets, the simplest first.
    pub(crate) fn offered_on(m: usize) -> Vec<Shape> {
        Shape::ALL.into_iter().filter(|s| s.offered(m)).collect()
    }

    /// The shape fitted by least squares to the finite values `b` at `along` (one per
    /// target), at every target; a target without a value gets the fit's value there
    /// (per target: the mean of the others).
    pub fn fit(self, b: &[f64], along: &[f64]) -> Vec<f64> {
        let finite: Vec<usize> = (0..b.len()).filter(|&i| b[i].is_finite()).collect();
        let n = finite.len() as f64;
        let mean = finite.iter().map(|&i| b[i]).sum::<f64>() / n.max(1.0);
        if finite.len() < 2 {
            return vec![mean; b.len()];
        }
        match self {
            Shape::PerTarget => (0..b.len())
                .map(|i| if b[i].is_finite() { b[i] } else { mean })
                .collect(),
            Shape::Line | Shape::Curve => {
                let degree = if self == Shape::Line { 1 } else { 2 };
                polynomial(b, along, &finite, degree)
            }
        }
    }
}

/// The least-squares polynomial of `degree` through the values `b` of the rows `finite`,
/// at every `along` (positions centred and scaled for the conditioning).
fn polynomial(b: &[f64], along: &[f64], finite: &[usize], degree: i32) -> Vec<f64> {
    let n = finite.len() as f64;
    let centre = finite.iter().map(|&i| along[i]).sum::<f64>() / n;
    let scale = (finite.iter())
        .map(|&i| (along[i] - centre).abs())
        .fold(0.0, f64::max);
    let u = |p: f64| {
        if scale > 0.0 {
            (p - centre) / scale
        } else {
            0.0
        }
    };
    let cols: Vec<Vec<f64>> = (0..=degree)
        .map(|d| finite.iter().map(|&i| u(along[i]).powi(d)).collect())
        .collect();
    let y: Vec<f64> = finite.iter().map(|&i| b[i]).collect();
    let fit = least_squares(&cols, &y);
    along
        .iter()
        .map(|&p| {
            (0..=degree)
                .map(|d| fit.coef[d as usize] * u(p).powi(d))
                .sum()
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each shape reproduces data of its own form exactly, and a line is fitted to a
    /// quadratic by least squares.
    #[test]
    fn shapes_fit_their_own_form() {
        let along = [0.0, 100.0, 200.0, 300.0, 400.0, 500.0];
        let line: Vec<f64> = along.iter().map(|p| 2.0 + 0.01 * p).collect();
        let curve: Vec<f64> = along
            .iter()
            .map(|p| 1.0 + 1e-5 * (p - 250.0f64).powi(2))
            .collect();
        for (got, want) in Shape::Line.fit(&line, &along).iter().zip(&line) {
            assert!((got - want).abs() < 1e-12);
        }
        for (got, want) in Shape::Curve.fit(&curve, &along).iter().zip(&curve) {
            assert!((got - want).abs() < 1e-12);
        }
        let worn = [1.24, 4.37, -7.28, -2.31, -13.43];
        assert_eq!(Shape::PerTarget.fit(&worn, &along[..5]), worn);
        // The symmetric curve has no slope: its line is flat at its mean.
        let flat = Shape::Line.fit(&curve, &along);
        let mean = curve.iter().sum::<f64>() / 6.0;
        assert!(flat.iter().all(|v| (v - mean).abs() < 1e-12), "{flat:?}");
        // A missing value takes the fit's.
        let gap = [1.0, f64::NAN, 3.0];
        assert_eq!(Shape::Line.fit(&gap, &[0.0, 1.0, 2.0])[1], 2.0);
        assert_eq!(Shape::PerTarget.fit(&gap, &[0.0, 1.0, 2.0])[1], 2.0);
    }

    #[test]
    fn shapes_offered_by_the_plan() {
        assert_eq!(Shape::offered_on(2), [Shape::Line]);
        assert_eq!(Shape::offered_on(5), [Shape::Line, Shape::PerTarget]);
        assert_eq!(Shape::offered_on(11), Shape::ALL);
    }
}
