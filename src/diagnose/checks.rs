//! Model checks: statistics of the measurement beside their distribution over tests
//! simulated from the fitted base model with the file's own plan (a parametric
//! bootstrap). A measured value outside the simulated 2.5–97.5 % band is something the
//! standard's model does not explain.

use super::periodic::{self, Scanner};
use super::prep::Prep;
use super::stats::quantile;
use crate::measurement::AxisData;
use crate::simulate::Simulation;
use crate::simulate::rng::Rng;
use rayon::prelude::*;

/// Names of the statistics, in the order of [`statistics`].
pub(crate) const NAMES: [&str; 8] = [
    "R",
    "run_mean_spread",
    "lag1_autocorrelation",
    "max_studentized_residual",
    "reversal_range",
    "scatter_ratio_end_to_start",
    "periodogram_max_f",
    "trend_lack_of_fit_rms",
];

/// Human description of each statistic.
pub(crate) fn describe(name: &str) -> &'static str {
    match name {
        "R" => "bidirectional repeatability of positioning R = max Ri (ISO 230-2 2.18)",
        "run_mean_spread" => "range of the run means of the within-cell residuals",
        "lag1_autocorrelation" => {
            "lag-1 autocorrelation of the within-cell residuals in time order"
        }
        "max_studentized_residual" => "largest |residual| / (s·√((n−1)/n)) over all readings",
        "reversal_range" => "max Bi − min Bi (reversal value along the axis)",
        "scatter_ratio_end_to_start" => {
            "scatter of the upper half of the travel over that of the lower half"
        }
        "periodogram_max_f" => "highest F of the Lomb–Scargle periodogram of the target means",
        "trend_lack_of_fit_rms" => "RMS of the bidirectional target means about a cubic trend",
        _ => "",
    }
}

/// The statistics of one test (NaN where one does not apply).
pub(crate) fn statistics(data: &AxisData) -> [f64; 8] {
    let prep = Prep::new(data);
    let (m, n) = (prep.m, prep.n);
    let all = vec![true; prep.rows.len()];
    let x: Vec<f64> = prep.rows.iter().map(|r| r.x).collect();
    let (means, _) = prep.cell_means(&x, &all);
    let resid: Vec<f64> = prep
        .rows
        .iter()
        .zip(&x)
        .map(|(r, v)| v - means[prep.cell(r)])
        .collect();
    let mut ss = vec![0.0; prep.cells()];
    for (r, e) in prep.rows.iter().zip(&resid) {
        ss[prep.cell(r)] += e * e;
    }
    let nan = f64::NAN;
    let mut out = [nan; 8];
    let b: Vec<f64> = (0..m).map(|i| means[2 * i] - means[2 * i + 1]).collect();
    if n >= 2 {
        let s: Vec<f64> = ss.iter().map(|v| (v / (n - 1) as f64).sqrt()).collect();
        out[0] = (0..m)
            .map(|i| {
                let (su, sd) = (s[2 * i], s[2 * i + 1]);
                (2.0 * su + 2.0 * sd + b[i].abs())
                    .max(4.0 * su)
                    .max(4.0 * sd)
            })
            .fold(f64::NEG_INFINITY, f64::max);
        let mut run_sum = vec![0.0; n];
        for (r, e) in prep.rows.iter().zip(&resid) {
            run_sum[r.run] += e;
        }
        let per = (2 * m) as f64;
        let (lo, hi) = run_sum
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), v| {
                (a.min(v / per), c.max(v / per))
            });
        out[1] = hi - lo;
        let mut ordered: Vec<(usize, f64)> = prep
            .rows
            .iter()
            .map(|r| r.order)
            .zip(resid.iter().copied())
            .collect();
        ordered.sort_by_key(|&(o, _)| o);
        let den: f64 = ordered.iter().map(|(_, e)| e * e).sum();
        if den > 0.0 {
            out[2] = ordered.windows(2).map(|w| w[0].1 * w[1].1).sum::<f64>() / den;
        }
        let pooled = ss.iter().sum::<f64>() / (prep.rows.len() - prep.cells()) as f64;
        if n >= 3 && pooled > 0.0 {
            let k = (pooled * (n - 1) as f64 / n as f64).sqrt();
            out[3] = resid.iter().fold(0.0f64, |a, e| a.max(e.abs() / k));
        }
        if m >= 2 {
            let mid = (prep.lo + prep.hi) / 2.0;
            let (mut lo_ss, mut lo_c, mut hi_ss, mut hi_c) = (0.0, 0usize, 0.0, 0usize);
            for (c, v) in ss.iter().enumerate() {
                if prep.positions[c / 2] < mid {
                    lo_ss += v;
                    lo_c += n - 1;
                } else {
                    hi_ss += v;
                    hi_c += n - 1;
                }
            }
            if lo_c > 0 && hi_c > 0 && lo_ss > 0.0 {
                out[5] = ((hi_ss / hi_c as f64) / (lo_ss / lo_c as f64)).sqrt();
            }
        }
    }
    if m >= 2 {
        let (lo, hi) = b
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, c), v| {
                (a.min(*v), c.max(*v))
            });
        out[4] = hi - lo;
    }
    let bidir: Vec<f64> = (0..m)
        .map(|i| (means[2 * i] + means[2 * i + 1]) / 2.0)
        .collect();
    let res = periodic::resolution(&prep.positions);
    if m >= 5 {
        let scanner = Scanner::new(&prep.positions, &bidir, None);
        let r = scanner.trend_residuals();
        let dof = scanner.trend_dof();
        if dof > 0.0 {
            out[7] = (r.iter().map(|v| v * v).sum::<f64>() / dof).sqrt();
        }
        if res.applicable {
            let (f, _) = scanner.best(1.0 / res.p_max, 1.0 / res.p_min, res.length);
            out[6] = scanner.f_stat(f);
        }
    }
    out
}

/// One model check.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelCheck {
    pub statistic: String,
    pub measured: f64,
    /// 2.5 % quantile of the simulated distribution.
    pub simulated_low: f64,
    /// 97.5 % quantile.
    pub simulated_high: f64,
    pub outside: bool,
    /// `above` or `below` the band when outside. Below can be telling too: a drift
    /// inflates the base model's scatter, so its simulated target means scatter more
    /// than the measured ones.
    pub side: Option<&'static str>,
}

/// Simulates `count` tests of `sim` (seeds from `seed`) and compares them with the
/// measured statistics; `strip_times` removes the simulated time stamps when the
/// measurement had none, so both are analysed alike.
pub(crate) fn run(
    measured: &[f64; 8],
    sim: &Simulation,
    count: usize,
    seed: u64,
    strip_times: bool,
) -> Vec<ModelCheck> {
    if count == 0 {
        return Vec::new();
    }
    let sims: Vec<[f64; 8]> = (0..count)
        .into_par_iter()
        .map(|s| {
            let mut rng = Rng::new(seed, 0xC4EC + s as u64);
            let mut data = sim.run(rng.next_u64());
            if strip_times {
                for r in &mut data.readings {
                    r.time_s = None;
                }
            }
            statistics(&data)
        })
        .collect();
    let mut out = Vec::new();
    for (k, name) in NAMES.iter().enumerate() {
        if !measured[k].is_finite() {
            continue;
        }
        let values: Vec<f64> = sims.iter().map(|s| s[k]).collect();
        let low = quantile(&values, 0.025);
        let high = quantile(&values, 0.975);
        if !(low.is_finite() && high.is_finite()) {
            continue;
        }
        out.push(ModelCheck {
            statistic: (*name).to_string(),
            measured: measured[k],
            simulated_low: low,
            simulated_high: high,
            outside: measured[k] < low || measured[k] > high,
            side: if measured[k] > high {
                Some("above")
            } else if measured[k] < low {
                Some("below")
            } else {
                None
            },
        });
    }
    out
}
