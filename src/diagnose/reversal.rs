//! Reversal value that changes along the axis (lost motion, Hemingray et al. 1971, §5.2;
//! ISO 230-2 2.12 defines Bi per target but reports one B and B̄ as if it were one number).
//!
//! The Bi = X̄i↑ − X̄i↓ of readings corrected for the time effects (in the standard cycle a
//! drift reaches the down approaches later than the up ones and would show as a reversal
//! growing along the axis) have the known standard error σ√(1/n↑ + 1/n↓). Two tests:
//! the slope of a weighted straight line through the Bi (t-test, df of σ), and what the
//! line leaves (χ²/(m − 2) against σ², an F-test) for a reversal whose shape is not a
//! line. With n = 1 the slope is tested against the line's own residuals (df = m − 2).

use super::maths::linalg::least_squares;
use super::maths::stats::{f_upper, t_two_sided};

/// The result of the reversal tests.
#[derive(Debug, Clone)]
pub(crate) struct ReversalTest {
    /// Slope of B along the axis (deviation per position unit).
    pub slope: f64,
    /// B of the line at the mean position of the targets used.
    pub at_center: f64,
    pub center: f64,
    pub t_slope: f64,
    pub p_slope: f64,
    pub df: f64,
    pub f_shape: Option<f64>,
    pub p_shape: Option<f64>,
}

impl ReversalTest {
    /// The fitted reversal value at `p`.
    pub fn at(&self, p: f64) -> f64 {
        self.at_center + self.slope * (p - self.center)
    }
}

/// Tests the per-target reversal values `b` at `positions` with variances `var` (None:
/// unknown scatter, n = 1) whose scatter estimate has `df_sigma` degrees of freedom.
pub(crate) fn test(
    positions: &[f64],
    b: &[f64],
    var: Option<&[f64]>,
    df_sigma: f64,
) -> Option<ReversalTest> {
    let idx: Vec<usize> = (0..b.len())
        .filter(|&i| b[i].is_finite() && var.is_none_or(|v| v[i] > 0.0 && v[i].is_finite()))
        .collect();
    let m = idx.len();
    let w: Vec<f64> = idx
        .iter()
        .map(|&i| var.map_or(1.0, |v| 1.0 / v[i]))
        .collect();
    let sw: f64 = w.iter().sum();
    if m < 2 || sw.is_nan() || sw <= 0.0 {
        return None;
    }
    let center = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi * positions[i])
        .sum::<f64>()
        / sw;
    let one: Vec<f64> = w.iter().map(|wi| wi.sqrt()).collect();
    let x: Vec<f64> = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi.sqrt() * (positions[i] - center))
        .collect();
    let y: Vec<f64> = idx
        .iter()
        .zip(&w)
        .map(|(&i, wi)| wi.sqrt() * b[i])
        .collect();
    let fit = least_squares(&[one, x], &y);
    if !fit.kept[1] {
        return None;
    }
    let slope = fit.coef[1];
    let at_center = fit.coef[0];
    match var {
        Some(_) => {
            if df_sigma.is_nan() || df_sigma < 1.0 {
                return None;
            }
            let t = slope / fit.cov[1][1].sqrt();
            let (f_shape, p_shape) = if m >= 3 {
                let f = fit.rss / (m - 2) as f64;
                (Some(f), Some(f_upper(f, (m - 2) as f64, df_sigma)))
            } else {
                (None, None)
            };
            Some(ReversalTest {
                slope,
                at_center,
                center,
                t_slope: t,
                p_slope: t_two_sided(t, df_sigma),
                df: df_sigma,
                f_shape,
                p_shape,
            })
        }
        None => {
            if m < 4 {
                return None;
            }
            let df = (m - 2) as f64;
            let s2 = fit.rss / df;
            if s2.is_nan() || s2 <= 0.0 {
                return None;
            }
            let t = slope / (s2 * fit.cov[1][1]).sqrt();
            Some(ReversalTest {
                slope,
                at_center,
                center,
                t_slope: t,
                p_slope: t_two_sided(t, df),
                df,
                f_shape: None,
                p_shape: None,
            })
        }
    }
}
