//! Held-out validation of the base and extended models.
//!
//! Readings: 10-fold cross-validation over readings, folds stratified by cell (each fold
//! holds out at most ⌈n/10⌉ readings of a target and direction, so every cell keeps a
//! training reading). Leave-one-run-out cannot judge run offsets (an unseen run's zero
//! shift is unknowable), k-fold over readings can: the run's other readings tell it.
//! Each fold refits the model on the rest and predicts the held-out readings:
//!
//! * base (the standard's model, the simulator with its assumptions): the bidirectional
//!   mean at each target, one reversal value B̄ for the axis, nothing in time;
//! * extended: plus the kept terms — drift, warm-up (its τ profiled on each fold's
//!   training readings) and thermal growth (time regressors with cell effects), run offsets, a reversal varying linearly along the axis, outliers left out
//!   of the fit, a scatter varying along the axis (changes only the predictive variance,
//!   so it is judged by the mean negative log predictive density, not the RMS).
//!
//! Readings diagnosed as outliers are left out of both models' scores so that the score
//! compares models, not the outliers themselves.
//!
//! Between targets: per-target means already hold a periodic error *at* the targets; its
//! cost is between them. Leave-one-target-out predicts each inner target's mean from the
//! others by the simulator's C¹ cubic through them (base) or by that interpolation of
//! what the periodic term leaves plus the term (extended).

use super::periodic::Trend;
use super::prep::Prep;
use super::scatter;
use super::time::{Terms, TimeFit, fit};
use super::warm;
use crate::simulate::model::interpolate;
use crate::simulate::rng::Rng;
use std::f64::consts::TAU;

/// Number of folds.
pub(crate) const K: usize = 10;

/// The terms of a model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct ModelTerms {
    pub drift: bool,
    pub warm: bool,
    pub thermal: bool,
    pub runs: bool,
    pub reversal: bool,
    pub outliers: bool,
    pub scatter: bool,
}

/// A model fitted to training rows.
pub(crate) struct Predictor {
    pub time: TimeFit,
    /// Bidirectional mean per target.
    pub mean: Vec<f64>,
    /// Reversal value per target as the model has it.
    pub reversal: Vec<f64>,
    /// Scatter σ per cell.
    pub sigma: Vec<f64>,
    /// Training readings per cell.
    pub count: Vec<usize>,
}

impl Predictor {
    /// Fits `terms` on the `train` rows of `x`.
    pub fn fit(prep: &Prep, x: &[f64], train: &[bool], terms: ModelTerms) -> Predictor {
        let ones = vec![1.0; prep.cells()];
        let mut time_terms = Terms {
            thermal: terms.thermal,
            runs: terms.runs,
            drift: terms.drift || terms.thermal,
            warm: None,
        };
        if terms.warm {
            // τ profiled on the training rows alone, as the rest of the model.
            let base = fit(prep, x, train, &ones, time_terms);
            time_terms.warm = warm::profile(prep, &base, &ones, true).map(|p| p.tau);
        }
        let time = fit(prep, x, train, &ones, time_terms);
        let mut count = vec![0usize; prep.cells()];
        for &k in &time.rows {
            count[prep.cell(&prep.rows[k])] += 1;
        }
        let mu = &time.intercepts;
        let mut mean = Vec::with_capacity(prep.m);
        let mut b = Vec::with_capacity(prep.m);
        for i in 0..prep.m {
            let (u, d) = (mu[2 * i], mu[2 * i + 1]);
            mean.push((u + d) / 2.0);
            b.push(u - d);
        }
        let finite: Vec<usize> = (0..prep.m).filter(|&i| b[i].is_finite()).collect();
        let reversal = if terms.reversal && finite.len() >= 2 {
            let n = finite.len() as f64;
            let px = finite.iter().map(|&i| prep.positions[i]).sum::<f64>() / n;
            let by = finite.iter().map(|&i| b[i]).sum::<f64>() / n;
            let sxx: f64 = finite
                .iter()
                .map(|&i| (prep.positions[i] - px).powi(2))
                .sum();
            let sxy: f64 = finite
                .iter()
                .map(|&i| (prep.positions[i] - px) * (b[i] - by))
                .sum();
            let slope = if sxx > 0.0 { sxy / sxx } else { 0.0 };
            (0..prep.m)
                .map(|i| by + slope * (prep.positions[i] - px))
                .collect()
        } else {
            let bbar = finite.iter().map(|&i| b[i]).sum::<f64>() / finite.len().max(1) as f64;
            vec![bbar; prep.m]
        };
        let s2 = time.sigma2();
        let sigma = match (terms.scatter, s2 > 0.0) {
            (true, true) => match scatter::test(prep, &time.residuals, s2) {
                Some(t) => t.rel_scale.iter().map(|r| r * s2.sqrt()).collect(),
                None => vec![s2.sqrt(); prep.cells()],
            },
            _ => vec![s2.sqrt(); prep.cells()],
        };
        Predictor {
            time,
            mean,
            reversal,
            sigma,
            count,
        }
    }

    /// The predicted reading of row `k`.
    pub fn predict(&self, prep: &Prep, k: usize) -> f64 {
        let r = &prep.rows[k];
        self.mean[r.i] + r.sign * self.reversal[r.i] / 2.0 + self.time.effect(prep, k)
    }

    /// Predictive variance of a new reading in the cell of row `k`.
    pub fn variance(&self, prep: &Prep, k: usize) -> f64 {
        let c = prep.cell(&prep.rows[k]);
        let s = self.sigma[c];
        s * s * (1.0 + 1.0 / self.count[c].max(1) as f64)
    }
}

/// The fold of each row (stratified by cell, deterministic for `seed`).
pub(crate) fn folds(prep: &Prep, seed: u64) -> Vec<usize> {
    let mut rng = Rng::new(seed, 0xD1A6);
    let mut by_cell: Vec<Vec<usize>> = vec![Vec::new(); prep.cells()];
    for (k, r) in prep.rows.iter().enumerate() {
        by_cell[prep.cell(r)].push(k);
    }
    let mut fold = vec![0usize; prep.rows.len()];
    for rows in &mut by_cell {
        // Fisher–Yates.
        for a in (1..rows.len()).rev() {
            let b = (rng.uniform() * (a + 1) as f64) as usize;
            rows.swap(a, b.min(a));
        }
        let start = (rng.uniform() * K as f64) as usize;
        for (idx, &k) in rows.iter().enumerate() {
            fold[k] = (start + idx) % K;
        }
    }
    fold
}

/// Held-out scores of a model.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Score {
    pub rms: f64,
    /// Mean negative log predictive density (Gaussian) per reading.
    pub nlpd: f64,
}

/// Cross-validates `terms`; `outlier` marks readings diagnosed as outliers (left out of
/// the score, and out of the training when the model has the outlier term).
pub(crate) fn score(
    prep: &Prep,
    x: &[f64],
    fold: &[usize],
    outlier: &[bool],
    terms: ModelTerms,
) -> Score {
    if prep.n < 2 {
        return Score {
            rms: f64::NAN,
            nlpd: f64::NAN,
        };
    }
    let (mut se, mut nl, mut count) = (0.0, 0.0, 0usize);
    for f in 0..K {
        if !fold.contains(&f) {
            continue;
        }
        let train: Vec<bool> = (0..prep.rows.len())
            .map(|k| fold[k] != f && !(terms.outliers && outlier[k]))
            .collect();
        let p = Predictor::fit(prep, x, &train, terms);
        for k in 0..prep.rows.len() {
            if fold[k] != f || outlier[k] {
                continue;
            }
            let e = x[k] - p.predict(prep, k);
            let v = p.variance(prep, k);
            if !e.is_finite() {
                continue;
            }
            se += e * e;
            if v > 0.0 && v.is_finite() {
                nl += 0.5 * (TAU * v).ln() + e * e / (2.0 * v);
            }
            count += 1;
        }
    }
    if count == 0 {
        return Score {
            rms: f64::NAN,
            nlpd: f64::NAN,
        };
    }
    Score {
        rms: (se / count as f64).sqrt(),
        nlpd: nl / count as f64,
    }
}

/// Leave-targets-out RMS of the target means `y` at `positions`: (base, extended with a
/// sinusoid of `period`). Each inner target is predicted from the targets outside a block
/// of about a quarter period around it (h-block cross-validation, Burman, Chow and Nolan
/// 1994): with one target left out a dense plan interpolates a long period almost as well
/// without the term, and the gain the term brings between the targets stays hidden. The
/// block is one target (leave-one-target-out) when the period is shorter than eight
/// target spacings; only targets with the block inside the travel are predicted (the ends
/// would be extrapolated).
pub(crate) fn between_targets(positions: &[f64], y: &[f64], period: f64) -> (f64, f64) {
    let m = positions.len();
    if !(8..=3000).contains(&m) {
        return (f64::NAN, f64::NAN);
    }
    let spacing = (positions[m - 1] - positions[0]) / (m - 1) as f64;
    let h = half_block(period, spacing, m);
    let f = 1.0 / period;
    let (mut sb, mut se) = (0.0, 0.0);
    for i in 1 + h..m - 1 - h {
        let others: Vec<usize> = (0..m).filter(|&k| k.abs_diff(i) > h).collect();
        let p: Vec<f64> = others.iter().map(|&k| positions[k]).collect();
        let v: Vec<f64> = others.iter().map(|&k| y[k]).collect();
        let knots: Vec<[f64; 2]> = p.iter().zip(&v).map(|(a, b)| [*a, *b]).collect();
        let base = interpolate(&knots, positions[i]);
        let peak = Trend::new(&p, None).scanner(&v).peak(f);
        let phase = peak.phase_deg.to_radians();
        let wave = |x: f64| peak.amplitude * (TAU * f * x + phase).sin();
        let rest: Vec<[f64; 2]> = p.iter().zip(&v).map(|(a, b)| [*a, b - wave(*a)]).collect();
        let ext = interpolate(&rest, positions[i]) + wave(positions[i]);
        sb += (y[i] - base).powi(2);
        se += (y[i] - ext).powi(2);
    }
    let k = (m - 2 - 2 * h) as f64;
    ((sb / k).sqrt(), (se / k).sqrt())
}

/// Targets left out on each side of the predicted one: a block of about a quarter period,
/// keeping at least eight targets predicted and six to fit.
fn half_block(period: f64, spacing: f64, m: usize) -> usize {
    if !(spacing > 0.0 && period.is_finite()) {
        return 0;
    }
    let wanted = (period / (8.0 * spacing)).floor() as usize;
    wanted.min(m.saturating_sub(10) / 2)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A block of about a quarter period: ⌊period / (8 · spacing)⌋ targets on each side,
    /// none below eight spacings, at most what leaves ten targets.
    #[test]
    fn half_block_by_hand() {
        assert_eq!(half_block(5.0, 1.0, 50), 0);
        assert_eq!(half_block(7.9, 1.0, 50), 0);
        assert_eq!(half_block(11.0 * 0.4, 0.4, 85), 1);
        assert_eq!(half_block(40.0, 1.0, 50), 5);
        assert_eq!(half_block(400.0, 1.0, 14), 2);
        assert_eq!(half_block(f64::INFINITY, 1.0, 50), 0);
    }

    /// A sine of period 12 spacings at 40 targets, no noise: the term predicts every
    /// left-out target exactly, the smooth interpolation over the block (one target each
    /// side) misses by 0.183 of the amplitude RMS.
    #[test]
    fn the_block_shows_a_long_period_between_the_targets() {
        let positions: Vec<f64> = (0..40).map(f64::from).collect();
        let y: Vec<f64> = positions.iter().map(|x| (TAU * x / 12.0).sin()).collect();
        let (base, extended) = between_targets(&positions, &y, 12.0);
        assert!(extended < 1e-6 * base, "{base} {extended}");
        assert!((base - 0.183).abs() < 0.001, "{base}");
    }
}
