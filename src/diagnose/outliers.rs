//! Outliers: readings inconsistent with the rest (Hemingray et al. 1971, §5.3: the scatter
//! estimate is only as good as its readings).
//!
//! Each reading's externally studentised residual in the full time model (cell effects,
//! run effects, drift, thermal growth and a warm-up found, so that a drift does not make the first and last
//! runs look like outliers): t = r / (s₍₋ₖ₎ √(1 − h)), with s₍₋ₖ₎ the scatter without the
//! reading and h its leverage; t follows Student's t with df − 1 degrees of freedom.
//! The largest |t| is tested with a Bonferroni correction over all readings; a reading
//! found is set aside and the search repeats. A cell needs n ≥ 3 readings: with two, either
//! could be the odd one.

use super::maths::stats::t_two_sided;
use super::prep::Prep;
use super::time_fit::{Terms, fit};

/// One outlier.
#[derive(Debug, Clone)]
pub(crate) struct Hit {
    /// Row index in `Prep::rows`.
    pub row: usize,
    pub t: f64,
    /// Bonferroni-adjusted p-value.
    pub p_adj: f64,
    /// Deleted residual: the reading minus what the rest predicts, µm or arcsec.
    pub size: f64,
}

/// Finds outliers among `values` at family-wise level `alpha`; `scale` is the relative
/// scatter per cell; `warm` the time constant of a warm-up found, whose curve within the
/// first run would otherwise leave its first readings as outliers.
pub(crate) fn detect(
    prep: &Prep,
    values: &[f64],
    scale: &[f64],
    warm: Option<f64>,
    alpha: f64,
) -> Vec<Hit> {
    let mut hits = Vec::new();
    if prep.n < 3 {
        return hits;
    }
    let total = prep.rows.len();
    let mut active = vec![true; total];
    // At most one reading in twenty, and 50 in all: beyond that the scatter itself is
    // the problem, not single readings.
    let cap = (total / 20).clamp(1, 50);
    let terms = Terms {
        thermal: true,
        runs: true,
        drift: true,
        warm,
    };
    while hits.len() < cap {
        let f = fit(prep, values, &active, scale, terms);
        let df = f.df;
        if df < 3.0 || f.rss <= 0.0 {
            break;
        }
        let mut count = vec![0usize; prep.cells()];
        for &k in &f.rows {
            count[prep.cell(&prep.rows[k])] += 1;
        }
        let mut best: Option<(usize, f64, f64)> = None;
        for (idx, &k) in f.rows.iter().enumerate() {
            let c = prep.cell(&prep.rows[k]);
            if count[c] < 3 {
                continue;
            }
            let h = 1.0 / count[c] as f64 + f.ls.leverage(idx);
            if 1.0 - h <= 1e-9 {
                continue;
            }
            let r = f.ls.residuals[idx];
            let s2 = (f.rss - r * r / (1.0 - h)) / (df - 1.0);
            if s2 <= 0.0 {
                continue;
            }
            let t = r / (s2 * (1.0 - h)).sqrt();
            if best.is_none_or(|(_, bt, _)| t.abs() > bt.abs()) {
                best = Some((k, t, r / (1.0 - h) * scale[c]));
            }
        }
        let Some((k, t, size)) = best else { break };
        let p_adj = (t_two_sided(t, df - 1.0) * total as f64).min(1.0);
        if p_adj.is_nan() || p_adj >= alpha {
            break;
        }
        hits.push(Hit {
            row: k,
            t,
            p_adj,
            size,
        });
        active[k] = false;
    }
    hits
}
