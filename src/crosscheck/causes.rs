//! Formulas other tools are known to use in place of ISO 230-2's, each with the quantity
//! it replaces: when a tool's printed value is what one of them gives from the same
//! readings (within the tool's rounding), that formula is the cause of the difference.
//!
//! Known from the ecmc ISO 230 app's published source and its reports' notes
//! (anderssandstrom/ecmc_cfg_tool, `ecmc_iso230_qt.py`): from 2026-03-09 to 2026-03-27 it
//! computed R_i = max(√(2s↑² + 2s↓² + B_i²), R↑_i, R↓_i); before 2026-03-09 it took the
//! range of the readings for the repeatability, |B_i| for the reversal and E = M + B̄.
//! A tool dividing by n instead of n − 1 for the standard deviation is the other common
//! slip (ISO 230-2 2.16 divides by n − 1).

use crate::evaluate::Evaluation;
use crate::measurement::reported::Quantity;

/// One target's statistics, as the formulas use them (µm or arcsec).
struct Target {
    up_mean: f64,
    down_mean: f64,
    up_s: f64,
    down_s: f64,
    up_range: f64,
    down_range: f64,
    /// B_i = x̄↑ − x̄↓ (ISO 230-2 2.12).
    reversal: f64,
}

/// A formula in place of the standard's.
struct Alternative {
    /// The quantity it replaces: a parameter key, or `R_uni` for max(R↑, R↓).
    replaces: &'static str,
    cause: &'static str,
    value: fn(&[Target], f64) -> f64,
}

const ALTERNATIVES: &[Alternative] = &[
    Alternative {
        replaces: "R",
        cause: "the tool computes R_i = max(√(2s↑² + 2s↓² + B_i²), R↑_i, R↓_i) (the ecmc ISO 230 app from 2026-03-09 to 2026-03-27, as its notes say); ISO 230-2 2.17 gives R_i = max(2s↑ + 2s↓ + |B_i|, R↑_i, R↓_i), which is never smaller",
        value: |t, _| {
            max_of(t, |t| {
                (2.0 * t.up_s.powi(2) + 2.0 * t.down_s.powi(2) + t.reversal.powi(2))
                    .sqrt()
                    .max(4.0 * t.up_s)
                    .max(4.0 * t.down_s)
            })
        },
    },
    Alternative {
        replaces: "R",
        cause: "the tool takes R_i as the width of the band of both directions' readings, x̄ ± range/2 (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.17 gives R_i = max(2s↑ + 2s↓ + |B_i|, R↑_i, R↓_i)",
        value: |t, _| max_of(t, |t| band(t).0 - band(t).1),
    },
    Alternative {
        replaces: "R",
        cause: "the tool's standard deviation divides by n instead of n − 1 (ISO 230-2 2.16 divides by n − 1)",
        value: |t, n| {
            max_of(t, |t| {
                let (u, d) = (t.up_s * n, t.down_s * n);
                (2.0 * u + 2.0 * d + t.reversal.abs())
                    .max(4.0 * u)
                    .max(4.0 * d)
            })
        },
    },
    Alternative {
        replaces: "R_uni",
        cause: "the tool takes the unidirectional repeatability as the range of the readings, max − min (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.16 gives R↑_i = 4s↑_i",
        value: |t, _| max_of(t, |t| t.up_range.max(t.down_range)),
    },
    Alternative {
        replaces: "R_uni",
        cause: "the tool's standard deviation divides by n instead of n − 1 (ISO 230-2 2.16 divides by n − 1)",
        value: |t, n| max_of(t, |t| 4.0 * n * t.up_s.max(t.down_s)),
    },
    Alternative {
        replaces: "B_mean",
        cause: "the tool averages |B_i|, the reversal's size (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.14 averages B_i with its sign",
        value: |t, _| t.iter().map(|t| t.reversal.abs()).sum::<f64>() / t.len() as f64,
    },
    Alternative {
        replaces: "E",
        cause: "the tool computes E = M + the mean of |B_i| (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.20 takes the range of all the unidirectional mean deviations",
        value: |t, _| {
            let means: Vec<f64> = t.iter().map(|t| (t.up_mean + t.down_mean) / 2.0).collect();
            let m = max_of(&means, |x| *x) - min_of(&means, |x| *x);
            m + t.iter().map(|t| t.reversal.abs()).sum::<f64>() / t.len() as f64
        },
    },
    Alternative {
        replaces: "A",
        cause: "the tool bounds each direction by x̄ ± range/2 of its readings (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.23 takes x̄ ± 2s",
        value: |t, _| max_of(t, |t| band(t).0) - min_of(t, |t| band(t).1),
    },
    Alternative {
        replaces: "A",
        cause: "the tool's standard deviation divides by n instead of n − 1 (ISO 230-2 2.16 divides by n − 1)",
        value: |t, n| {
            let hi =
                |t: &Target| (t.up_mean + 2.0 * n * t.up_s).max(t.down_mean + 2.0 * n * t.down_s);
            let lo =
                |t: &Target| (t.up_mean - 2.0 * n * t.up_s).min(t.down_mean - 2.0 * n * t.down_s);
            max_of(t, hi) - min_of(t, lo)
        },
    },
];

/// The upper and lower ends of x̄ ± range/2 over both directions at a target.
fn band(t: &Target) -> (f64, f64) {
    let (u, d) = (t.up_range / 2.0, t.down_range / 2.0);
    (
        (t.up_mean + u).max(t.down_mean + d),
        (t.up_mean - u).min(t.down_mean - d),
    )
}

fn max_of<T>(items: &[T], f: impl Fn(&T) -> f64) -> f64 {
    items.iter().map(f).fold(f64::NEG_INFINITY, f64::max)
}

fn min_of<T>(items: &[T], f: impl Fn(&T) -> f64) -> f64 {
    items.iter().map(f).fold(f64::INFINITY, f64::min)
}

/// The known cause of a tool's value `theirs` for `quantity`: the first alternative
/// formula that gives it within `rounding`.
pub fn explain(quantity: Quantity, theirs: f64, rounding: f64, e: &Evaluation) -> Option<String> {
    let key = match quantity {
        Quantity::Parameter(key) => key,
        Quantity::LargerOf(..) => "R_uni",
        Quantity::NotIso(_) => return None,
    };
    let targets = targets(e)?;
    // s with n in the denominator: s · √((n − 1)/n).
    let n = e.n as f64;
    let population = ((n - 1.0) / n).sqrt();
    ALTERNATIVES
        .iter()
        .filter(|a| a.replaces == key)
        .find(|a| ((a.value)(&targets, population) - theirs).abs() <= rounding * (1.0 + 1e-6))
        .map(|a| a.cause.to_string())
}

/// The targets' statistics; `None` without repeated runs (no s).
fn targets(e: &Evaluation) -> Option<Vec<Target>> {
    e.targets
        .iter()
        .map(|t| {
            Some(Target {
                up_mean: t.up.mean,
                down_mean: t.down.mean,
                up_s: t.up.s?,
                down_s: t.down.s?,
                up_range: t.up.range?,
                down_range: t.down.range?,
                reversal: t.reversal,
            })
        })
        .collect()
}
