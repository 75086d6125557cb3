//! VDI 3441 as Hemingray, Cowley and Burdekin (1971, §3.2) describe it.
//!
//! σi = Ri / d from the range Ri of the N readings at a point, with d from the paper's
//! table; the mean σ over all points; the mean position deviation Ā = (X̄max + X̄min)/2;
//! the limits G = Ā ± ((X̄max − X̄min)/2 + 3σ); the position error T = X̄max − X̄min + 6σ;
//! the position scatter width Rp = 6σ. VDI 3441 as described states no approach
//! direction: axcheck takes each direction's readings at a target as one point (so
//! X̄max and X̄min range over X̄i↑ and X̄i↓, and σ averages over both directions).

use super::band;
use super::catalogue::vdi3441 as vdi;
use super::stats::{d2, mean, range};
use super::{Evaluation, Parameter, Standard, StandardId, TargetResult};
use crate::measurement::AxisData;
use crate::units::Direction;

/// The correction factor d for N readings as printed in the paper (N = 2…8, 10, 12);
/// other N use d2(N) of the same statistical table, computed.
pub(crate) fn d_factor(n: usize) -> Option<f64> {
    match n {
        0 | 1 => None,
        2 => Some(1.13),
        3 => Some(1.69),
        4 => Some(2.06),
        5 => Some(2.33),
        6 => Some(2.53),
        7 => Some(2.70),
        8 => Some(2.84),
        10 => Some(3.08),
        12 => Some(3.26),
        _ => Some(d2(n)),
    }
}

/// The axis figures of VDI 3441 from the extreme means and the mean σ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vdi3441Figures {
    /// Ā = (X̄max + X̄min)/2.
    pub(crate) mean_deviation: f64,
    /// Ā + ((X̄max − X̄min)/2 + 3σ).
    pub(crate) upper_limit: f64,
    /// Ā − ((X̄max − X̄min)/2 + 3σ).
    pub(crate) lower_limit: f64,
    /// T = X̄max − X̄min + 6σ.
    pub(crate) position_error: f64,
    /// Rp = 6σ.
    pub(crate) scatter_width: f64,
}

/// VDI 3441's formulas (Hemingray et al. 1971, Fig. 2).
pub fn summary(x_max: f64, x_min: f64, sigma_mean: f64) -> Vdi3441Figures {
    let a = (x_max + x_min) / 2.0;
    let half = (x_max - x_min) / 2.0 + 3.0 * sigma_mean;
    Vdi3441Figures {
        mean_deviation: a,
        upper_limit: a + half,
        lower_limit: a - half,
        position_error: x_max - x_min + 6.0 * sigma_mean,
        scatter_width: 6.0 * sigma_mean,
    }
}

pub struct Vdi3441;

impl Standard for Vdi3441 {
    fn id(&self) -> StandardId {
        StandardId::Vdi3441
    }

    fn evaluate(&self, data: &AxisData) -> Evaluation {
        let n = data.runs();
        let d = d_factor(n);
        // σi = Ri/d (the paper's §3.2), limits X̄ ± 3σ.
        let sigma = |x: &[f64]| range(x).zip(d).map(|(w, d)| w / d);
        let targets: Vec<TargetResult> = (0..data.target_count())
            .map(|i| {
                let up = band::direction(data.deviations(i, Direction::Up).to_vec(), 3.0, sigma);
                let down =
                    band::direction(data.deviations(i, Direction::Down).to_vec(), 3.0, sigma);
                TargetResult {
                    position: data.targets[i],
                    mean: (up.mean + down.mean) / 2.0,
                    reversal: up.mean - down.mean,
                    repeatability: None,
                    up,
                    down,
                    nmtba: None,
                }
            })
            .collect();
        let (parameters, notes) = parameters(&targets, n, d);
        Evaluation {
            standard: StandardId::Vdi3441,
            kind: data.kind,
            n,
            coverage_factor: 3.0,
            parameters,
            targets,
            notes,
        }
    }
}

/// The extreme means, and with σ the limits, T and Rp; notes on how d was found.
fn parameters(targets: &[TargetResult], n: usize, d: Option<f64>) -> (Vec<Parameter>, Vec<String>) {
    let (_, x_max, x_min) = band::systematic(targets, &[Direction::Up, Direction::Down]);
    let plain = Parameter::plain;
    let mut p = vec![
        plain(&vdi::X_MAX, x_max),
        plain(&vdi::X_MIN, x_min),
        plain(&vdi::A_MEAN, (x_max + x_min) / 2.0),
    ];
    let mut notes = Vec::new();
    let sigmas: Option<Vec<f64>> = targets.iter().flat_map(|t| [t.up.s, t.down.s]).collect();
    let Some(sigmas) = sigmas else {
        notes.push("n = 1: no ranges, so σ, the limits, T and Rp are not applicable".into());
        return (p, notes);
    };
    let sigma = mean(&sigmas);
    let s = summary(x_max, x_min, sigma);
    p.push(plain(&vdi::SIGMA_MEAN, sigma));
    p.push(plain(&vdi::G_UPPER, s.upper_limit));
    p.push(plain(&vdi::G_LOWER, s.lower_limit));
    p.push(plain(&vdi::T, s.position_error));
    p.push(plain(&vdi::R_P, s.scatter_width));
    if !matches!(n, 2..=8 | 10 | 12) {
        notes.push(format!(
            "d for N = {n} is not printed in the source; d2({n}) = {:.3} computed",
            d.unwrap_or(f64::NAN)
        ));
    }
    (p, notes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_papers_figure_2() {
        // X̄max = 5.3 µm, X̄min = −0.2 µm, 6σ = 5.8 µm → Ā = 2.55 µm, T = 11.3 µm.
        let s = summary(5.3, -0.2, 5.8 / 6.0);
        assert!((s.mean_deviation - 2.55).abs() < 1e-12);
        assert!((s.position_error - 11.3).abs() < 1e-12);
        assert!((s.scatter_width - 5.8).abs() < 1e-12);
        assert!((s.upper_limit - (2.55 + 5.65)).abs() < 1e-12);
        assert!((s.lower_limit - (2.55 - 5.65)).abs() < 1e-12);
    }

    #[test]
    fn d_table() {
        assert_eq!(d_factor(5), Some(2.33));
        assert!((d_factor(9).unwrap() - 2.970).abs() < 0.001);
        assert_eq!(d_factor(1), None);
    }
}
