//! A warm-up's course within the runs, as each run's own reversal values show it.
//!
//! Beside free run offsets a warm-up is tested on what the offsets leave of it between the
//! runs, which a few runs may not let reach the level. Within one run of the standard
//! cycle a target's ↑ and ↓ approaches lie apart in time by `gap = t↓ − t↑`, so a time
//! effect `w` adds `w(t↓) − w(t↑) ≈ w′(t)·gap` to that run's Bi (ISO 230-2 Annex A shows
//! it for a drift). A difference within one run carries neither the run's offset nor the
//! target's systematic deviation. A reversal of the mechanism is the same in every run,
//! in any shape along the axis; a drift adds the same `w′·gap` to every run; a warm-up's
//! rate fades (ISO 230-2 3.3: an ordered sequence of deviations while the thermal state
//! settles), so its part of Bi shrinks from run to run.
//!
//! The test: `Bi(j, i) = βᵢ + b·gap(j, i)·(t(j, i) − t̄)` by weighted least squares with
//! free βᵢ (every shape of reversal), the t of `b` against the scatter σ (its df). One
//! sided: a warm-up's rate shrinks in size, so `b` lies against the sign of the part of Bi
//! that follows the gap (`a` of `Bi = c + a·gap`). Linear in time: over a few runs the
//! exponential's change of rate is close to its straight line.

use crate::diagnose::effects::{Effect, Finding};
use crate::diagnose::finding::{fmt, fmt_p};
use crate::diagnose::maths::linalg::least_squares;
use crate::diagnose::maths::stats::t_two_sided;
use crate::diagnose::prep::Prep;

/// The level below which a fading puts a reversal or scatter variation found beside run
/// offsets down to a warm-up the plan could not test otherwise. A finding needs
/// [`crate::diagnose::ALPHA`]; doubting one needs less evidence, and the cost is set
/// against what it buys: on the project's sweep (200 axes each) at 1 % it took 4 of the 5
/// reversal and scatter variations that a warm-up beside run offsets made (t of 2.4–3.95;
/// the fifth 2.0), and withheld 3 of 198 real reversal variations beside run offsets and
/// 1 of 170 scatter variations (a one-sided test at 1 % withholds 1 % of them).
pub(crate) const LEVEL: f64 = 0.01;

/// The fading of Bi's time-following part from run to run.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Fading {
    /// t of the fading coefficient, signed so that a fading rate is positive.
    pub t: f64,
    /// One-sided p of `t` (Student, σ's df).
    pub p: f64,
}

/// One run's Bi at one target: value, variance, time gap ↓ − ↑ and mean time.
struct RunB {
    j: usize,
    i: usize,
    b: f64,
    var: f64,
    gap: f64,
    t: f64,
}

/// Tests the fading on `values` (the readings as the reversal test takes them) over the
/// `active` rows; `scale` is the relative scatter per cell, `sigma2` the scatter and `df`
/// its degrees of freedom. None where fewer than three runs give a Bi.
pub(crate) fn test(
    p: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    sigma2: f64,
    df: f64,
) -> Option<Fading> {
    if !(sigma2 > 0.0 && df >= 1.0) {
        return None;
    }
    let bs = run_reversals(p, values, active, scale, sigma2);
    let mut runs: Vec<usize> = bs.iter().map(|b| b.j).collect();
    runs.dedup();
    if runs.len() < 3 {
        return None;
    }
    let w: Vec<f64> = bs.iter().map(|b| 1.0 / b.var).collect();
    let sw: f64 = w.iter().sum();
    let tbar = bs.iter().zip(&w).map(|(b, w)| w * b.t).sum::<f64>() / sw;
    let y: Vec<f64> = bs.iter().zip(&w).map(|(b, w)| w.sqrt() * b.b).collect();
    // The sign of the part that follows the gap: Bi = c + a·gap.
    let one: Vec<f64> = w.iter().map(|w| w.sqrt()).collect();
    let gap: Vec<f64> = bs.iter().zip(&w).map(|(b, w)| w.sqrt() * b.gap).collect();
    let along = least_squares(&[one, gap], &y);
    let a = along.coef[1];
    // Free βᵢ and the fading column.
    let mut cols: Vec<Vec<f64>> = (0..p.m)
        .map(|k| {
            bs.iter()
                .zip(&w)
                .map(|(b, w)| if b.i == k { w.sqrt() } else { 0.0 })
                .collect()
        })
        .collect();
    cols.push(
        bs.iter()
            .zip(&w)
            .map(|(b, w)| w.sqrt() * b.gap * (b.t - tbar))
            .collect(),
    );
    let fit = least_squares(&cols, &y);
    let last = cols.len() - 1;
    if !fit.kept[last] || !along.kept[1] {
        return None;
    }
    let t = -a.signum() * fit.coef[last] / fit.cov[last][last].sqrt();
    let two = t_two_sided(t, df);
    let p = if t > 0.0 { two / 2.0 } else { 1.0 - two / 2.0 };
    Some(Fading { t, p })
}

/// Each run's Bi per target from the cell means of that run.
fn run_reversals(
    p: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    sigma2: f64,
) -> Vec<RunB> {
    let cells = p.cells();
    // Per run and cell: sum of values, sum of times, count.
    let mut acc = vec![(0.0, 0.0, 0usize); p.n * cells];
    for (k, r) in p.rows.iter().enumerate() {
        if active[k] && r.run < p.n {
            let e = &mut acc[r.run * cells + p.cell(r)];
            e.0 += values[k];
            e.1 += r.t;
            e.2 += 1;
        }
    }
    let mut out = Vec::new();
    for j in 0..p.n {
        for i in 0..p.m {
            let (up, down) = (acc[j * cells + 2 * i], acc[j * cells + 2 * i + 1]);
            if up.2 == 0 || down.2 == 0 {
                continue;
            }
            let (nu, nd) = (up.2 as f64, down.2 as f64);
            let (tu, td) = (up.1 / nu, down.1 / nd);
            let var = sigma2 * (scale[2 * i].powi(2) / nu + scale[2 * i + 1].powi(2) / nd);
            if !(var > 0.0 && var.is_finite()) {
                continue;
            }
            out.push(RunB {
                j,
                i,
                b: up.0 / nu - down.0 / nd,
                var,
                gap: td - tu,
                t: (tu + td) / 2.0,
            });
        }
    }
    out
}

/// A reversal or scatter variation seen by its test and put down to a warm-up.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Withheld {
    pub effect: Effect,
    /// What it was read as ([`note`]).
    pub note: String,
}

/// The note that replaces `found` (a reversal or scatter variation) when the fading `f`
/// puts it down to a warm-up.
pub(crate) fn note(found: &Finding, f: &Fading) -> String {
    let (what, shows, before) = match found.effect() {
        Effect::ScatterVariation => (
            "a scatter variation",
            "the scatter changes along the axis",
            "looking for a mechanical cause",
        ),
        _ => (
            "a reversal variation",
            "Bi change along the axis",
            "compensating a reversal that varies",
        ),
    };
    format!(
        "not reported as {what}: {shows} (p = {}), but each run's Bi change less than the run's before (t = {}, one-sided p = {}), as in a machine still warming up in the first runs and not in a mechanism, which is the same in every run; beside these run offsets this plan cannot test the warm-up itself; re-test the warm machine (ISO 230-2 3.3) before {before}",
        fmt_p(found.evidence.p_value.unwrap_or(f64::NAN)),
        fmt(f.t),
        fmt_p(f.p)
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::testing::standard_cycle;

    /// A noiseless test in the standard cycle on targets 0, 100 and 200 mm, four runs, one
    /// reading every 40 s: `reversal(target)` split between ↑ and ↓, plus `w(minutes)`.
    fn cycle(reversal: impl Fn(f64) -> f64, w: impl Fn(f64) -> f64) -> Prep {
        let data = standard_cycle(&[0.0, 100.0, 200.0], 4, (0.0, 40.0), |p, d, time_s| {
            d.sign() * reversal(p) / 2.0 + w(time_s / 60.0)
        });
        Prep::new(&data)
    }

    fn fading(p: &Prep) -> Fading {
        let x: Vec<f64> = p.rows.iter().map(|r| r.x).collect();
        let all = vec![true; x.len()];
        test(p, &x, &all, &[1.0; 6], 0.25, 20.0).unwrap()
    }

    /// By hand. w = c·t + d·t² adds w(t↑) − w(t↓) = −gap·(c + 2d·t_mid) to a run's Bi,
    /// so the fading coefficient is −2d, against the sign of −c. Its variance with free
    /// βᵢ: 2σ² / Σᵢ gapᵢ²·Σⱼ(tⱼ − t̄)². With Δ = 2/3 min between readings, gapᵢ = 5Δ, 3Δ,
    /// Δ (Σ = 35Δ²) and runs 6Δ apart (Σⱼ = 36Δ²·(4·15/12) = 180Δ²): 6 300·Δ⁴ = 1 244.44
    /// min⁴, and with σ² = 0.25 µm² the standard error is √(0.5 / 1 244.44) = 0.020045.
    /// For d = −0.05 µm/min² (a rate that falls, c = 2 µm/min): t = 0.1 / 0.020045.
    #[test]
    fn a_falling_rate_fades_by_hand() {
        let p = cycle(|_| 3.0, |t| 2.0 * t - 0.05 * t * t);
        let f = fading(&p);
        let want = 0.1 / (0.5f64 / (6300.0 * (2.0f64 / 3.0).powi(4))).sqrt();
        assert!((f.t - want).abs() < 1e-9 * want, "t {} vs {want}", f.t);
        assert!(
            (f.p - t_two_sided(want, 20.0) / 2.0).abs() < 1e-12,
            "{}",
            f.p
        );
        // A rate that grows is no warm-up: the same size against the fading.
        let g = fading(&cycle(|_| 3.0, |t| 2.0 * t + 0.05 * t * t));
        assert!((g.t + want).abs() < 1e-9 * want && g.p > 0.99, "{g:?}");
    }

    /// A reversal of any shape and a drift are the same in every run: no fading.
    #[test]
    fn a_mechanism_and_a_drift_do_not_fade() {
        let worn = |p: f64| if p > 150.0 { 9.0 } else { 1.0 + 0.01 * p };
        let f = fading(&cycle(worn, |t| 1.5 * t));
        assert!(f.t.abs() < 1e-6, "{f:?}");
    }
}
