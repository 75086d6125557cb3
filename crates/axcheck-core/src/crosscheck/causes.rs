//! Formulas other tools are known to use in place of ISO 230-2's, each with the quantity
//! it replaces: when a tool's printed value is what one of them gives from the same
//! readings (within the roundings), that formula is the cause of the difference.
//!
//! Known from the tools' published source and their reports' own words:
//! - the ecmc ISO 230 app (anderssandstrom/ecmc_cfg_tool, `ecmc_iso230_qt.py`): from
//!   2026-03-09 to 2026-03-27 R_i = max(√(2s↑² + 2s↓² + B_i²), R↑_i, R↓_i); before
//!   2026-03-09 ranges for the repeatability, |B_i| for the reversal and E = M + B̄;
//! - the ecmc ISO 230-2 scripts of 2021 (anderssandstrom/ecmccomgui, `ecmcISO230_2.py`):
//!   R = max(R↑, R↓) (their report says "max(R_fwd,R_bwd)"), and the two directions
//!   swapped in the reports they wrote (the input's forward readings stored as backward);
//!   E taken as the larger maximum minus the larger minimum of the two directions' means
//!   (a `>` for a `<` in `ecmcISO230_2.py`); the 2021-10 bash version (`mainISO230.bash`)
//!   computing every s from the last target's readings (a variable-name slip) with its
//!   variance cut to 0.00001 mm² before the root (`bc`'s `scale=5`);
//! - a standard deviation divided by n instead of n − 1 (ISO 230-2 2.16 divides by n − 1).

use crate::evaluate::{Evaluation, ParamKey};
use crate::measurement::reported::{Family, ReportedQuantity};

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

/// What a formula is computed from: the targets' statistics, the factor √((n − 1)/n)
/// that turns s into the standard deviation divided by n, and the standard's parameters.
struct Context<'a> {
    targets: &'a [Target],
    population: f64,
    e: &'a Evaluation,
}

/// A formula in place of the standard's.
struct Alternative {
    /// The tool known to use it (`None`: a slip any tool may make).
    by: Option<Family>,
    /// The quantity it replaces: a parameter, or max(R↑, R↓) ([`R_UNI`]).
    replaces: ReportedQuantity,
    cause: &'static str,
    value: fn(&Context) -> Option<f64>,
}

const SQRT_R: &str = "the tool computes R_i = max(√(2s↑² + 2s↓² + B_i²), R↑_i, R↓_i) (the ecmc ISO 230 app from 2026-03-09 to 2026-03-27, as its notes say); ISO 230-2 2.17 gives R_i = max(2s↑ + 2s↓ + |B_i|, R↑_i, R↓_i), which is never smaller";
const BAND: &str = "the tool takes R_i as the width of the band of both directions' readings, x̄ ± range/2 (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.17 gives R_i = max(2s↑ + 2s↓ + |B_i|, R↑_i, R↓_i)";
const LARGER_R: &str = "the tool takes R as the larger of R↑ and R↓ (the ecmc ISO 230-2 scripts of 2021: \"max(R_fwd,R_bwd)\"), leaving out the reversal; ISO 230-2 2.18 takes the largest R_i = max(2s↑ + 2s↓ + |B_i|, R↑_i, R↓_i)";
const BY_N: &str =
    "the tool's standard deviation divides by n instead of n − 1 (ISO 230-2 2.16 divides by n − 1)";
const RANGE_R: &str = "the tool takes the unidirectional repeatability as the range of the readings, max − min (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.16 gives R↑_i = 4s↑_i";
const ABS_B: &str = "the tool averages |B_i|, the reversal's size (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.14 averages B_i with its sign";
const M_PLUS_B: &str = "the tool computes E = M + the mean of |B_i| (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.20 takes the range of all the unidirectional mean deviations";
const BAND_A: &str = "the tool bounds each direction by x̄ ± range/2 of its readings (the ecmc ISO 230 app before 2026-03-09); ISO 230-2 2.23 takes x̄ ± 2s";
const LARGER_MIN_E: &str = "the tool takes E as the larger of the directions' highest mean deviations minus the larger of their lowest (the ecmc ISO 230-2 scripts of 2021, a `>` for a `<`); ISO 230-2 2.20 takes the highest minus the lowest of all of them";
const LAST_TARGET_S: &str = "the tool computes every target's s from the last target's readings, its variance cut to 0.00001 mm² before the root (the ecmc ISO 230-2 bash script of 2021-10, a variable-name slip); ISO 230-2 2.15 takes each target's own readings, so every value made of s (R, A) is wrong there";
const SWAPPED: &str = "the report has the two directions the other way round (the ecmc ISO 230-2 scripts of 2021 store the input's forward readings as backward): its value is axcheck's for the other direction";
const SWAPPED_B: &str = "the report has the two directions the other way round (the ecmc ISO 230-2 scripts of 2021 store the input's forward readings as backward), which turns the sign of the reversal";

/// The unidirectional repeatability a tool reports: the larger of R↑ and R↓.
const R_UNI: ReportedQuantity = ReportedQuantity::LargerOf(ParamKey::RUp, ParamKey::RDown);

const ALTERNATIVES: &[Alternative] = &[
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: ReportedQuantity::Parameter(ParamKey::R),
        cause: SQRT_R,
        value: |c| max_of(c.targets, sqrt_r),
    },
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: ReportedQuantity::Parameter(ParamKey::R),
        cause: BAND,
        value: |c| max_of(c.targets, |t| band(t).0 - band(t).1),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::R),
        cause: LARGER_R,
        value: |c| Some(c.e.value(ParamKey::RUp)?.max(c.e.value(ParamKey::RDown)?)),
    },
    Alternative {
        by: None,
        replaces: ReportedQuantity::Parameter(ParamKey::R),
        cause: BY_N,
        value: |c| max_of(c.targets, |t| iso_r(t, c.population)),
    },
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: R_UNI,
        cause: RANGE_R,
        value: |c| max_of(c.targets, |t| t.up_range.max(t.down_range)),
    },
    Alternative {
        by: None,
        replaces: R_UNI,
        cause: BY_N,
        value: |c| max_of(c.targets, |t| 4.0 * c.population * t.up_s.max(t.down_s)),
    },
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: ReportedQuantity::Parameter(ParamKey::BMean),
        cause: ABS_B,
        value: |c| mean_of(c.targets, |t| t.reversal.abs()),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::BMean),
        cause: SWAPPED_B,
        value: |c| Some(-c.e.value(ParamKey::BMean)?),
    },
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: ReportedQuantity::Parameter(ParamKey::E),
        cause: M_PLUS_B,
        value: |c| Some(c.e.value(ParamKey::M)? + mean_of(c.targets, |t| t.reversal.abs())?),
    },
    Alternative {
        by: Some(Family::EcmcApp),
        replaces: ReportedQuantity::Parameter(ParamKey::A),
        cause: BAND_A,
        value: |c| Some(max_of(c.targets, |t| band(t).0)? - min_of(c.targets, |t| band(t).1)?),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::E),
        cause: LARGER_MIN_E,
        value: |c| {
            let (up, down) = (|t: &Target| t.up_mean, |t: &Target| t.down_mean);
            let top = max_of(c.targets, up)?.max(max_of(c.targets, down)?);
            Some(top - min_of(c.targets, up)?.max(min_of(c.targets, down)?))
        },
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::R),
        cause: LAST_TARGET_S,
        value: |c| {
            Some(
                max_of(c.targets, |t| 4.0 * last_s(c, t.up_mean, true))?
                    .max(max_of(c.targets, |t| 4.0 * last_s(c, t.down_mean, false))?),
            )
        },
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::RUp),
        cause: LAST_TARGET_S,
        value: |c| max_of(c.targets, |t| 4.0 * last_s(c, t.up_mean, true)),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::RDown),
        cause: LAST_TARGET_S,
        value: |c| max_of(c.targets, |t| 4.0 * last_s(c, t.down_mean, false)),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::AUp),
        cause: LAST_TARGET_S,
        value: |c| last_s_a(c, Some(true)),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::ADown),
        cause: LAST_TARGET_S,
        value: |c| last_s_a(c, Some(false)),
    },
    Alternative {
        by: Some(Family::EcmcScripts),
        replaces: ReportedQuantity::Parameter(ParamKey::A),
        cause: LAST_TARGET_S,
        value: |c| last_s_a(c, None),
    },
    Alternative {
        by: None,
        replaces: ReportedQuantity::Parameter(ParamKey::A),
        cause: BY_N,
        value: |c| by_n_a(c),
    },
];

/// The keys whose value for the other direction explains a swapped report.
const DIRECTED: &[(ParamKey, ParamKey)] = &[
    (ParamKey::RUp, ParamKey::RDown),
    (ParamKey::EUp, ParamKey::EDown),
    (ParamKey::AUp, ParamKey::ADown),
];

/// R_i by ISO 230-2 2.17 with both s scaled by `k`.
fn iso_r(t: &Target, k: f64) -> f64 {
    let (u, d) = (t.up_s * k, t.down_s * k);
    (2.0 * u + 2.0 * d + t.reversal.abs())
        .max(4.0 * u)
        .max(4.0 * d)
}

fn sqrt_r(t: &Target) -> f64 {
    let root = (2.0 * t.up_s.powi(2) + 2.0 * t.down_s.powi(2) + t.reversal.powi(2)).sqrt();
    root.max(4.0 * t.up_s).max(4.0 * t.down_s)
}

/// A with s divided by n: the ends x̄ ± 2s over both directions.
fn by_n_a(c: &Context) -> Option<f64> {
    let k = 2.0 * c.population;
    let hi = |t: &Target| (t.up_mean + k * t.up_s).max(t.down_mean + k * t.down_s);
    let lo = |t: &Target| (t.up_mean - k * t.up_s).min(t.down_mean - k * t.down_s);
    Some(max_of(c.targets, hi)? - min_of(c.targets, lo)?)
}

/// The 2021-10 script's s at a target whose mean is `mean`: from the last target's readings
/// of the direction, the variance in mm² cut to five decimals, as `bc` with `scale=5` does.
fn last_s(c: &Context, mean: f64, up: bool) -> f64 {
    let Some(last) = c.e.targets.last() else {
        return 0.0;
    };
    let x = if up {
        &last.up.deviations
    } else {
        &last.down.deviations
    };
    let n = x.len() as f64;
    let variance_mm2 = x.iter().map(|v| ((v - mean) / 1000.0).powi(2)).sum::<f64>() / (n - 1.0);
    ((variance_mm2 * 1e5).floor() / 1e5).sqrt() * 1000.0
}

/// A by ISO 230-2 2.22/2.23 with the 2021-10 script's s: one direction (`Some(up)`) or both.
fn last_s_a(c: &Context, up: Option<bool>) -> Option<f64> {
    let ends = |t: &Target, dir: bool| {
        let (mean, s) = match dir {
            true => (t.up_mean, last_s(c, t.up_mean, true)),
            false => (t.down_mean, last_s(c, t.down_mean, false)),
        };
        (mean + 2.0 * s, mean - 2.0 * s)
    };
    let dirs: &[bool] = match up {
        Some(true) => &[true],
        Some(false) => &[false],
        None => &[true, false],
    };
    let hi = |t: &Target| dirs.iter().map(|&d| ends(t, d).0).fold(f64::MIN, f64::max);
    let lo = |t: &Target| dirs.iter().map(|&d| ends(t, d).1).fold(f64::MAX, f64::min);
    Some(max_of(c.targets, hi)? - min_of(c.targets, lo)?)
}

/// The upper and lower ends of x̄ ± range/2 over both directions at a target.
fn band(t: &Target) -> (f64, f64) {
    let (u, d) = (t.up_range / 2.0, t.down_range / 2.0);
    (
        (t.up_mean + u).max(t.down_mean + d),
        (t.up_mean - u).min(t.down_mean - d),
    )
}

fn max_of<T>(items: &[T], f: impl Fn(&T) -> f64) -> Option<f64> {
    items.iter().map(f).reduce(f64::max)
}

fn min_of<T>(items: &[T], f: impl Fn(&T) -> f64) -> Option<f64> {
    items.iter().map(f).reduce(f64::min)
}

fn mean_of<T>(items: &[T], f: impl Fn(&T) -> f64) -> Option<f64> {
    (!items.is_empty()).then(|| items.iter().map(f).sum::<f64>() / items.len() as f64)
}

/// What is compared: the tool, its value `theirs` for `quantity`, the roundings.
pub struct Printed {
    pub family: Family,
    pub quantity: ReportedQuantity,
    pub theirs: f64,
    pub rounding: f64,
}

/// The known cause of a tool's printed value: the first formula known of the tool (or of
/// any tool) that gives it within the roundings.
pub fn explain(printed: &Printed, e: &Evaluation) -> Option<String> {
    let Printed {
        family,
        quantity,
        theirs,
        rounding,
    } = *printed;
    if let ReportedQuantity::NotIso(_) = quantity {
        return None;
    }
    let close = |x: f64| (x - theirs).abs() <= rounding * (1.0 + 1e-6);
    let swapped = (DIRECTED.iter()).find_map(|&(a, b)| {
        let is = |k| quantity == ReportedQuantity::Parameter(k);
        is(a).then_some(b).or(is(b).then_some(a))
    });
    if let Some(other) = swapped
        && family == Family::EcmcScripts
        && e.value(other).is_some_and(close)
    {
        return Some(SWAPPED.to_string());
    }
    let targets = targets(e)?;
    let n = e.n as f64;
    let context = Context {
        targets: &targets,
        population: ((n - 1.0) / n).sqrt(),
        e,
    };
    (ALTERNATIVES.iter())
        .filter(|a| a.replaces == quantity && a.by.is_none_or(|by| by == family))
        .find(|a| (a.value)(&context).is_some_and(close))
        .map(|a| a.cause.to_string())
}

/// The targets' statistics; `None` without repeated runs (no s).
fn targets(e: &Evaluation) -> Option<Vec<Target>> {
    (e.targets.iter())
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
