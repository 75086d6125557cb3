//! Warm-up: the deviations approach a new level exponentially, as a machine tested before
//! it is warm (ISO 230-2 clause 3.3: a warm-up before the test, and an ordered sequence
//! of deviations at a target as the sign that the thermal state is not stable; Hemingray
//! et al. 1971, §5.4: drift over the first half hour). Tested (below)
//! as an exponential approach beyond a linear drift, against the scatter or, when free run
//! offsets are real beyond it, against the run-to-run variation.
//!
//! The test. The approach is fast at first and slower later — the first-order thermal
//! response of a machine tested before it is warm. ISO 230-2 clause 3.3 asks for a warm-up before the test and names the symptom: when
//! successive approaches to a target give deviations in an ordered sequence, the thermal
//! state is not yet stable. Hemingray et al. 1971, §5.4 saw whole sets of readings drift
//! within about half an hour, usually only for a short time, and ask that a test last at
//! least half an hour to show it.
//!
//! Model: `(a + g·(P − P̄))·(1 − exp(−(t − t₀)/τ))` beside the cell effects and the linear
//! trend (drift and thermal growth), t₀ the first reading. For a given τ the model is
//! linear, so τ is profiled: the test takes the best of a log-spaced grid from a quarter
//! of a run to three times the test; the estimate refines it by golden-section search on
//! the gain of both columns. A shorter warm-up is over within the first run and cannot be
//! told from a shift of its first readings; a longer one is a straight line over the test:
//! a drift.
//!
//! The test: each column's gain beyond the linear trend, largest over τ, as a squared t
//! statistic. That maximum is not F-distributed (τ exists only under the alternative);
//! Davies (1987, "Hypothesis testing when a nuisance parameter is present only under the
//! alternative") bounds its tail by the F tail plus the expected number of up-crossings,
//! which grows with the length L of the path the standardised column traces as τ moves:
//! P(sup T² ≥ u) ≤ P(F(1, ν) ≥ u) + L/π·(1 + u/ν)^(−(ν−1)/2). The uniform and the
//! position-proportional column are tested at α/2 each.
//!
//! Against what: the pure scatter or, when free run offsets are real beyond the smooth
//! model (linear trend and warm-up), the run-to-run variation — as for the drift, only a
//! curve larger than the zero shifts is a warm-up. Beside the decision the finding gives
//! the comparison with free run offsets both ways — the run offsets beyond the warm-up
//! (between the runs) and the warm-up beyond free run offsets (within the runs, where a
//! zero shift cannot reach) — and the change of the Bayesian information criterion
//! against a linear drift and against free run offsets.

mod beside;
pub(crate) mod fading;
mod power;

pub(crate) use beside::linear_tests;
pub(crate) use power::detectable;

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::linalg::dot;
use crate::diagnose::maths::stats::{f_upper, t_two_sided};
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::prep::TimeUnit;
use crate::diagnose::time_fit::warm_shape;
use crate::diagnose::time_fit::{CellDemean, Terms, TimeFit, fit, warm_columns};
use crate::units::AxisKind;
use std::f64::consts::PI;

/// A warm-up: the level the deviations approach, its time constant and how long it takes.
/// Times are minutes with time stamps, runs of the standard test cycle without them.
#[derive(Debug, Clone, PartialEq)]
pub struct WarmUp {
    /// From the first reading to the final level, at the mean target position; deviation
    /// unit.
    pub amplitude: f64,
    pub(crate) amplitude_se: f64,
    /// Time constant τ.
    pub tau: f64,
    /// From the start of the test until every target is within 1 µm (1 arcsec) of its
    /// final level.
    pub(crate) time_to_within_1: f64,
    /// The largest distance from the final level along the travel at the last reading,
    /// deviation unit.
    pub(crate) remaining_at_end: f64,
    /// The position-proportional part at the end state, ppm (µm per m), with its standard
    /// error, when found.
    pub(crate) growth_ppm: Option<(f64, f64)>,
    /// F and p of free run offsets beyond the warm-up (on the run means).
    pub(crate) run_offsets_beyond: Option<(f64, f64)>,
    /// F and p of the warm-up beyond free run offsets (within the runs).
    pub(crate) within_runs: Option<(f64, f64)>,
    /// BIC with the warm-up minus BIC with a linear drift instead, and with free run
    /// offsets instead (negative: the warm-up explains the data better).
    pub(crate) delta_bic_vs_drift: f64,
    pub(crate) delta_bic_vs_run_offsets: f64,
    /// What it was tested against: `scatter` or `run-to-run variation`.
    pub(crate) tested_against: &'static str,
    /// Whether the time constant is at an end of the range searched.
    pub(crate) at_bound: Option<Bound>,
}

/// An end of the range of time constants searched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// A quarter of a run: the warm-up was over within the first run.
    Shortest,
    /// Three times the test: the curve is barely bent.
    Longest,
}

impl Bound {
    /// The end of the range searched that `tau` lies at (within 1 %), if any.
    fn of(prep: &Prep, tau: f64) -> Option<Bound> {
        let (lo, hi) = tau_range(prep)?;
        if tau <= lo * 1.01 {
            Some(Bound::Shortest)
        } else if tau >= hi / 1.01 {
            Some(Bound::Longest)
        } else {
            None
        }
    }
}

/// The time unit of a warm-up's times in keys: `min`, or `run` without time stamps.
fn time_key(u: Units) -> &'static str {
    match u.time {
        TimeUnit::Hours => "min",
        TimeUnit::Runs => "run",
    }
}

/// Time units of the diagnosis (hours or runs) in the warm-up's (minutes or runs).
fn to_reported(u: Units, t: f64) -> f64 {
    match u.time {
        TimeUnit::Hours => t * 60.0,
        TimeUnit::Runs => t,
    }
}

impl Fields for WarmUp {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let (du, tk) = (u.dev(), time_key(u));
        let mut params = vec![
            (format!("amplitude_{du}"), self.amplitude),
            (format!("amplitude_se_{du}"), self.amplitude_se),
            (format!("tau_{tk}"), self.tau),
            (format!("time_to_1{du}_{tk}"), self.time_to_within_1),
            (format!("remaining_at_end_{du}"), self.remaining_at_end),
        ];
        if let Some((g, se)) = self.growth_ppm {
            let key = match u.kind {
                AxisKind::Linear => "um_per_m",
                AxisKind::Rotary => "ppm",
            };
            params.push((format!("growth_{key}"), g));
            params.push((format!("growth_se_{key}"), se));
        }
        if let Some((f, p)) = self.run_offsets_beyond {
            params.push(("run_offsets_beyond_f".into(), f));
            params.push(("run_offsets_beyond_p".into(), p));
        }
        if let Some((f, p)) = self.within_runs {
            params.push(("within_runs_f".into(), f));
            params.push(("within_runs_p".into(), p));
        }
        params.push(("delta_bic_vs_drift".into(), self.delta_bic_vs_drift));
        params.push((
            "delta_bic_vs_run_offsets".into(),
            self.delta_bic_vs_run_offsets,
        ));
        params
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        let mut labels = vec![("tested_against", self.tested_against)];
        match self.at_bound {
            Some(Bound::Shortest) => labels.push(("time_constant", "shortest searched")),
            Some(Bound::Longest) => labels.push(("time_constant", "longest searched")),
            None => {}
        }
        labels
    }

    /// ISO 230-2 3.3: a warm-up before the test, as long as the machine takes to settle.
    fn advice(&self, u: Units) -> String {
        let (unit, long) = match u.time {
            TimeUnit::Hours => ("min", "min"),
            TimeUnit::Runs => ("runs", "runs of the test cycle"),
        };
        format!(
            "warm the machine up before re-testing (ISO 230-2 3.3): here it took {} {long} to come within 1 {ds} of its final level (τ = {} {unit}), and {} {ds} remained at the last reading; a compensation table cannot remove a warm-up",
            fmt(self.time_to_within_1),
            fmt(self.tau),
            fmt(self.remaining_at_end.abs()),
            ds = u.symbol()
        )
    }
}

/// The level approached at the first and the last target (the growth only when found).
fn end_levels(a: &Basis, e: &WarmEstimate, growth: bool) -> [f64; 2] {
    let g = if growth { e.g } else { 0.0 };
    [a.prep.lo, a.prep.hi].map(|p| e.a + g * (p - a.prep.pbar))
}

impl WarmUp {
    fn new(a: &Basis, w: &WarmTest, e: &WarmEstimate) -> WarmUp {
        let u = a.units;
        let growth = e.growth_found();
        let levels = end_levels(a, e, growth);
        let largest = levels[0].abs().max(levels[1].abs());
        // Within 1 µm (1 arcsec): |level|·exp(−t/τ) ≤ 1.
        let within = if largest > 1.0 {
            e.tau * largest.ln()
        } else {
            0.0
        };
        let end = a.prep.t_span;
        let ppm = a.prep.ppm_factor();
        WarmUp {
            amplitude: e.a,
            amplitude_se: e.a_se,
            tau: to_reported(u, e.tau),
            time_to_within_1: to_reported(u, within),
            remaining_at_end: largest * (1.0 - warm_shape(end, e.tau)),
            growth_ppm: growth.then(|| (e.g / ppm, e.g_se / ppm)),
            run_offsets_beyond: w.runs_beyond.as_ref().map(|t| (t.f, t.p)),
            within_runs: w.within_runs.as_ref().map(|t| (t.f, t.p)),
            delta_bic_vs_drift: w.delta_bic_drift,
            delta_bic_vs_run_offsets: w.delta_bic_runs,
            tested_against: w.against,
            at_bound: Bound::of(&a.prep, e.tau),
        }
    }

    fn message(&self, u: Units, w: &WarmTest) -> String {
        let (ds, tk) = (u.symbol(), time_key(u));
        let tw = if tk == "min" { "min" } else { "runs" };
        let growth = match (self.growth_ppm, u.kind) {
            (Some((g, _)), AxisKind::Linear) => format!(" and {} µm per m along the axis", fmt(g)),
            (Some((g, _)), AxisKind::Rotary) => format!(" and {} ppm of the angle", fmt(g)),
            (None, _) => String::new(),
        };
        let beyond = match self.run_offsets_beyond {
            Some((f, p)) => format!("; free run offsets add F = {}, p = {}", fmt(f), fmt_p(p)),
            None => String::new(),
        };
        let bound = match self.at_bound {
            Some(Bound::Shortest) => {
                "; the time constant is the shortest searched (a quarter of a run): the change came within the first run, where a warm-up cannot be told from a shift of the first readings"
            }
            Some(Bound::Longest) => {
                "; the time constant is the longest searched (three times the test): the curve is barely bent, and its time constant and level are uncertain"
            }
            None => "",
        };
        format!(
            "the deviations approach a new level exponentially, as a machine still warming up (ISO 230-2 3.3): {} {ds} from the first reading to the final level{growth}, time constant {} {tw}; within 1 {ds} of it {} {tw} after the start, {} {ds} away at the end of the test (F = {} beyond a linear drift, p = {}, against the {}{beyond}){bound}",
            fmt(self.amplitude),
            fmt(self.tau),
            fmt(self.time_to_within_1),
            fmt(self.remaining_at_end),
            fmt(w.f[0].max(w.f[1])),
            fmt_p(w.p),
            w.against,
        )
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    pub(crate) fn find(&self, a: &Basis, warm: Option<&WarmTest>) -> Vec<Finding> {
        let Some(w) = warm.filter(|w| w.p < ALPHA) else {
            return Vec::new();
        };
        let Some(e) = w.estimate.as_ref() else {
            return Vec::new();
        };
        let u = a.units;
        let warm = WarmUp::new(a, w, e);
        let message = warm.message(u, w);
        let column = if w.p_column[0] <= w.p_column[1] {
            "uniform"
        } else {
            "position-proportional"
        };
        vec![Finding {
            evidence: Evidence {
                statistic: format!(
                    "largest F over the time constant of the {column} exponential approach beyond a linear drift (1, {} df, against the {}; p by Davies' bound, doubled for the two columns)",
                    w.df, w.against
                ),
                value: w.f[0].max(w.f[1]),
                p_value: Some(w.p),
                effect_size: relative(warm.amplitude.abs(), a.sigma),
            },
            estimate: warm.into(),
            units: u,
            message,
        }]
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Readings(|t| t.warm = true)
    }

    /// A curve in time: compared with the same curve read at the readings' times in
    /// random orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TimeOrders
    }

    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        let time = &fit.pred.time;
        let Some(tau) = time.tau else { return };
        let g = if fit.warm_growth { time.warm_g } else { 0.0 };
        // The simulator's warm-up starts at its time 0, the diagnosis's at the first
        // reading: the level at that reading is what is left of the simulator's.
        let tau_h = tau * fit.hours_per_unit;
        let first_h = fit
            .guess
            .plan
            .schedule(&a.data.targets)
            .first()
            .map_or(0.0, |v| v.time_s / 3600.0);
        let scale = (first_h / tau_h).exp();
        model.warm_up_tau_min = r4(tau_h * 60.0);
        model.warm_up = r4(scale * (time.warm_a + g * (fit.origin - a.prep.pbar)));
        if fit.warm_growth {
            model.warm_up_ppm = r4(scale * g / a.prep.ppm_factor());
            model.thermal_origin = r4(fit.origin);
        }
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        // To the final level: as the readings of the warm machine.
        let time = &fit.pred.time;
        let tau = time.tau?;
        let p = &a.prep;
        Some(
            p.rows
                .iter()
                .map(|r| {
                    let level = time.warm_a + time.warm_g * (p.positions[r.i] - p.pbar);
                    level * (warm_shape(r.t - p.t0, tau) - 1.0)
                })
                .collect(),
        )
    }
}

/// Points of the τ grid.
const GRID: usize = 32;
/// Golden-section steps of the refinement.
const REFINE: usize = 36;

/// The τ searched, in time units: a quarter of a run to three times the test.
pub(crate) fn tau_range(prep: &Prep) -> Option<(f64, f64)> {
    let span = prep.t_span;
    (prep.n >= 2 && span > 0.0 && span.is_finite())
        .then(|| (span / (4.0 * prep.n as f64), 3.0 * span))
}

/// The warm-up columns at one τ beyond a base fit.
struct AtTau {
    /// Gain (fall of the residual sum of squares, scaled units) of the uniform and the
    /// position-proportional column alone, and of both.
    single: [f64; 2],
    joint: f64,
    /// Each column beyond the base fit, of unit length (empty when nothing is left).
    directions: [Vec<f64>; 2],
}

fn at_tau(prep: &Prep, base: &TimeFit, dm: &CellDemean, tau: f64) -> AtTau {
    let r = &base.ls.residuals;
    let cols = warm_columns(prep, &base.rows, tau).map(|c| {
        let demeaned = dm.apply(&c);
        let before = dot(&demeaned, &demeaned);
        let left = base.ls.residualize(&demeaned);
        let norm2 = dot(&left, &left);
        // A column the base fit spans adds nothing.
        if norm2 > 1e-18 * before && norm2 > 0.0 {
            left
        } else {
            Vec::new()
        }
    });
    let norm2 = |c: &[f64]| dot(c, c);
    let (n0, n1) = (norm2(&cols[0]), norm2(&cols[1]));
    let b = [dot(&cols[0], r), dot(&cols[1], r)];
    let single = [
        if n0 > 0.0 { b[0] * b[0] / n0 } else { 0.0 },
        if n1 > 0.0 { b[1] * b[1] / n1 } else { 0.0 },
    ];
    let joint = if n0 > 0.0 && n1 > 0.0 {
        let n01 = dot(&cols[0], &cols[1]);
        let det = n0 * n1 - n01 * n01;
        if det > 1e-12 * n0 * n1 {
            (b[0] * b[0] * n1 - 2.0 * b[0] * b[1] * n01 + b[1] * b[1] * n0) / det
        } else {
            single[0].max(single[1])
        }
    } else {
        single[0].max(single[1])
    };
    let directions = [n0, n1].map(|n| n.sqrt());
    let mut unit = cols;
    for (c, n) in unit.iter_mut().zip(directions) {
        for v in c.iter_mut() {
            *v /= n;
        }
    }
    AtTau {
        single,
        joint,
        directions: unit,
    }
}

/// The warm-up profiled over τ beyond a base fit.
#[derive(Debug, Clone)]
pub(crate) struct Profile {
    /// The τ of the largest joint gain.
    pub tau: f64,
    /// Largest gain over τ of each column alone (uniform, position-proportional).
    pub sup: [f64; 2],
    /// Length of the path each standardised column traces over the τ range (radians).
    pub path: [f64; 2],
}

/// Profiles the warm-up over τ beyond `base` (its rows and weights `scale`); `refine`
/// refines the best τ of the grid (the tests need only the grid: the gain is flat about
/// its maximum; the estimates need τ itself).
pub(crate) fn profile(prep: &Prep, base: &TimeFit, scale: &[f64], refine: bool) -> Option<Profile> {
    let (lo, hi) = tau_range(prep)?;
    if base.rows.len() < 3 {
        return None;
    }
    let dm = CellDemean::new(prep, &base.rows, scale);
    let step = (hi / lo).ln() / (GRID - 1) as f64;
    let grid: Vec<f64> = (0..GRID).map(|k| lo * (step * k as f64).exp()).collect();
    let (mut sup, mut path) = ([0.0f64; 2], [0.0f64; 2]);
    let mut previous: Option<[Vec<f64>; 2]> = None;
    let mut best = (0usize, f64::NEG_INFINITY);
    for (k, &tau) in grid.iter().enumerate() {
        let g = at_tau(prep, base, &dm, tau);
        for c in 0..2 {
            sup[c] = sup[c].max(g.single[c]);
            if let Some(p) = previous.as_ref().filter(|p| !p[c].is_empty())
                && !g.directions[c].is_empty()
            {
                path[c] += dot(&p[c], &g.directions[c]).abs().min(1.0).acos();
            }
        }
        if g.joint > best.1 {
            best = (k, g.joint);
        }
        previous = Some(g.directions);
    }
    if !refine {
        return Some(Profile {
            tau: grid[best.0],
            sup,
            path,
        });
    }
    let (a, b) = (
        grid[best.0.saturating_sub(1)].ln(),
        grid[(best.0 + 1).min(GRID - 1)].ln(),
    );
    let joint = |ln_tau: f64| at_tau(prep, base, &dm, ln_tau.exp());
    let ln_tau = golden_max(a, b, |x| joint(x).joint);
    let refined = joint(ln_tau);
    for (s, r) in sup.iter_mut().zip(refined.single) {
        *s = s.max(r);
    }
    let tau = if refined.joint >= best.1 {
        ln_tau.exp()
    } else {
        grid[best.0]
    };
    Some(Profile { tau, sup, path })
}

/// The maximiser of `f` on [a, b] by golden-section search.
fn golden_max(mut a: f64, mut b: f64, f: impl Fn(f64) -> f64) -> f64 {
    let r = (5f64.sqrt() - 1.0) / 2.0;
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..REFINE {
        if fc >= fd {
            b = d;
            (d, fd) = (c, fc);
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            (c, fc) = (d, fd);
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    (a + b) / 2.0
}

/// Davies' bound on P(sup over τ of T² ≥ u) for a t-process with ν degrees of freedom
/// whose standardised regressor traces a path of length `path` (see the module doc).
pub(crate) fn davies(u: f64, nu: f64, path: f64) -> f64 {
    if !(u.is_finite() && nu > 0.0) {
        return if u.is_infinite() { 0.0 } else { f64::NAN };
    }
    let crossings = path / PI * (1.0 + u / nu).powf(-(nu - 1.0) / 2.0);
    (f_upper(u, 1.0, nu) + crossings).min(1.0)
}

/// An F test of a larger model against a smaller one nested in it.
#[derive(Debug, Clone)]
pub(crate) struct FTest {
    pub f: f64,
    pub(crate) df1: f64,
    pub p: f64,
}

fn f_test(small: &TimeFit, big: &TimeFit) -> Option<FTest> {
    let df1 = big.ls.rank as f64 - small.ls.rank as f64;
    let s2 = big.sigma2();
    if df1 < 1.0 || s2.is_nan() || s2 <= 0.0 {
        return None;
    }
    let f = (small.rss - big.rss).max(0.0) / df1 / s2;
    Some(FTest {
        f,
        df1,
        p: f_upper(f, df1, big.df),
    })
}

/// Bayesian information criterion of a fit (up to a constant shared by the fits of one
/// test); `extra` counts parameters outside the least squares (τ).
fn bic(fit: &TimeFit, extra: usize) -> f64 {
    let n = fit.rows.len() as f64;
    n * (fit.rss / n).ln() + (fit.ls.rank + extra) as f64 * n.ln()
}

/// The warm-up search on the linear-trend fits of [`crate::diagnose::time::tests`].
#[derive(Debug, Clone)]
pub(crate) struct WarmTest {
    pub tau: f64,
    /// Largest F over τ of the uniform and of the position-proportional column beyond
    /// the linear trend, and Davies' p of each.
    pub f: [f64; 2],
    pub(crate) p_column: [f64; 2],
    /// The decision's p-value: twice the smaller (each column at α/2); 1 for a barely
    /// bent curve that free run offsets explain better ([`search`]).
    pub p: f64,
    /// The reference mean square (scaled units) and its degrees of freedom.
    pub ms: f64,
    pub df: f64,
    /// `scatter` or `run-to-run variation`.
    pub against: &'static str,
    /// Free run offsets beyond the smooth model with the warm-up.
    pub(crate) runs_beyond: Option<FTest>,
    /// The warm-up beyond free run offsets and the linear trend: within the runs.
    pub(crate) within_runs: Option<FTest>,
    /// BIC of the smooth model with the warm-up minus that of a linear drift, and minus
    /// that of free run offsets (negative: the warm-up is preferred).
    pub(crate) delta_bic_drift: f64,
    pub(crate) delta_bic_runs: f64,
    /// Linear trend with the warm-up, without and with run effects.
    pub smooth: TimeFit,
    pub full: TimeFit,
    /// The estimate, with only the linear terms found beside it (when found).
    pub estimate: Option<WarmEstimate>,
    /// The warm-up this plan confirms in [`crate::diagnose::options::POWER`] of tests.
    pub smallest: Option<power::Smallest>,
}

/// Searches for a warm-up beyond the linear trend; `fits` are the full model (thermal,
/// runs, drift) and the trend (thermal, drift) on the active rows.
pub(crate) fn search(
    prep: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    fits: (&TimeFit, &TimeFit),
    alpha: f64,
) -> Option<WarmTest> {
    let (full0, trend0) = fits;
    let prof = profile(prep, trend0, scale, false)?;
    let terms = |runs| Terms {
        thermal: true,
        runs,
        drift: true,
        warm: Some(prof.tau),
        thermal_about: None,
    };
    let smooth = fit(prep, values, active, scale, terms(false));
    let full = fit(prep, values, active, scale, terms(true));
    if !(full.df >= 1.0 && full.sigma2() > 0.0) {
        return None;
    }
    let runs_beyond = f_test(&smooth, &full);
    let (ms, df, against) = match runs_beyond.as_ref().filter(|t| t.p < alpha) {
        Some(t) => (t.f * full.sigma2(), t.df1, "run-to-run variation"),
        None => (full0.sigma2(), full0.df, "scatter"),
    };
    let f = prof.sup.map(|g| g / ms);
    let smallest = power::smallest(prep, active, scale, (ms, df), prof.path[0], alpha);
    let p_column = [0, 1].map(|c| davies(f[c], df, prof.path[c]));
    // A curve at the longest time constant searched is barely bent: one more trend of the
    // run means, which free run offsets make as well. When their model explains the
    // readings better by the Schwarz criterion (BIC, its parameters counted) and they
    // are not found beyond the curve, the curve is taken for no warm-up.
    let delta_bic_runs = bic(&smooth, 1) - bic(full0, 0);
    let barely_bent = Bound::of(prep, prof.tau) == Some(Bound::Longest);
    let offsets_rival =
        barely_bent && runs_beyond.as_ref().is_none_or(|t| t.p >= alpha) && delta_bic_runs > 0.0;
    let p = if offsets_rival {
        1.0
    } else {
        (2.0 * p_column[0].min(p_column[1])).min(1.0)
    };
    Some(WarmTest {
        tau: prof.tau,
        f,
        p_column,
        p,
        ms,
        df,
        against,
        runs_beyond,
        within_runs: f_test(full0, &full),
        delta_bic_drift: bic(&smooth, 1) - bic(trend0, 0),
        delta_bic_runs,
        smooth,
        full,
        estimate: None,
        smallest,
    })
}

/// The warm-up's estimate.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct WarmEstimate {
    /// Time constant, time units.
    pub tau: f64,
    /// Level approached from the first reading at P̄, and its standard error.
    pub a: f64,
    pub(crate) a_se: f64,
    /// Level per position unit, its standard error and the p of its t test.
    pub g: f64,
    pub(crate) g_se: f64,
    pub(crate) g_p: f64,
}

impl WarmEstimate {
    /// Whether the level changes along the axis: the growth g is found at [`ALPHA`] (else
    /// the warm-up is taken as uniform, in the finding and in the extended model).
    pub(crate) fn growth_found(&self) -> bool {
        self.g_p < ALPHA
    }

    /// The estimate of a fit with the warm-up; `reference` is the mean square (scaled
    /// units) and degrees of freedom the warm-up was tested against.
    pub fn of(f: &TimeFit, reference: (f64, f64)) -> Option<WarmEstimate> {
        let (ms, df) = reference;
        let tau = f.tau?;
        let c = f.warm_col.filter(|&c| f.ls.kept[c])?;
        let se = |j: usize| (ms * f.ls.cov[j][j]).sqrt();
        let (g_se, g_p) = if f.ls.kept[c + 1] {
            let s = se(c + 1);
            (s, t_two_sided(f.warm_g / s, df))
        } else {
            (f64::NAN, 1.0)
        };
        Some(WarmEstimate {
            tau,
            a: f.warm_a,
            a_se: se(c),
            g: f.warm_g,
            g_se,
            g_p,
        })
    }
}

/// The fit of `terms` with a warm-up whose τ is profiled beyond them.
fn profiled(
    prep: &Prep,
    values: &[f64],
    active: &[bool],
    scale: &[f64],
    terms: Terms,
) -> Option<TimeFit> {
    let base = fit(prep, values, active, scale, terms);
    let tau = profile(prep, &base, scale, true)?.tau;
    let warm = Some(tau);
    Some(fit(prep, values, active, scale, Terms { warm, ..terms }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::effects::testing::standard_cycle;
    use crate::measurement::AxisData;

    /// A noiseless test in the standard cycle, one reading every 40 s: cell effects (a
    /// shape and a reversal) plus `warm(position, time_s)`.
    fn noiseless(targets: &[f64], runs: u32, warm: impl Fn(f64, f64) -> f64) -> AxisData {
        standard_cycle(targets, runs, (12.0, 40.0), |p, direction, time_s| {
            let cell = 0.003 * p * p - 0.5 * p + direction.sign() * 1.5;
            cell + warm(p, time_s)
        })
    }

    /// By hand: A(1 − e^(−t/τ)) with τ = 9 min from t = 0, the first reading at 12 s,
    /// so the level still to come at the first reading is A·e^(−12/540); and with
    /// 20 µm/m about P = 0, at the mean target P̄ = 250 mm another 5 µm·e^(−12/540).
    #[test]
    fn recovers_amplitude_time_constant_and_growth_from_noiseless_data() {
        let targets: Vec<f64> = (0..11).map(|i| 50.0 * i as f64).collect();
        let (a, ppm, tau_s) = (-6.0, 20.0, 540.0);
        let data = noiseless(&targets, 5, |p, t| {
            (a + ppm * 1e-3 * p) * (1.0 - (-t / tau_s).exp())
        });
        let prep = Prep::new(&data);
        let x: Vec<f64> = prep.rows.iter().map(|r| r.x).collect();
        let all = vec![true; x.len()];
        let ones = vec![1.0; prep.cells()];
        let f = profiled(&prep, &x, &all, &ones, Terms::default()).unwrap();
        let tau_h = tau_s / 3600.0;
        let tau = f.tau.unwrap();
        assert!((tau - tau_h).abs() < 1e-6 * tau_h, "τ {tau} h vs {tau_h} h");
        let left = (-12.0 / tau_s).exp();
        let want_a = (a + ppm * 1e-3 * 250.0) * left;
        assert!((f.warm_a - want_a).abs() < 1e-6, "{} vs {want_a}", f.warm_a);
        let want_g = ppm * 1e-3 * left;
        assert!((f.warm_g - want_g).abs() < 1e-9, "{} vs {want_g}", f.warm_g);
        assert!(f.rss < 1e-12, "{}", f.rss);
    }

    /// A linear drift beside the warm-up does not disturb it, and is told apart from it:
    /// the profile with a drift column finds both exactly.
    #[test]
    fn separates_a_warm_up_from_a_linear_drift_in_noiseless_data() {
        let targets: Vec<f64> = (0..8).map(|i| 100.0 * i as f64).collect();
        let (a, tau_s, rate_per_s) = (4.0, 900.0, -2.0 / 3600.0);
        let data = noiseless(&targets, 6, |_, t| {
            a * (1.0 - (-t / tau_s).exp()) + rate_per_s * t
        });
        let prep = Prep::new(&data);
        let x: Vec<f64> = prep.rows.iter().map(|r| r.x).collect();
        let all = vec![true; x.len()];
        let ones = vec![1.0; prep.cells()];
        let drift = Terms {
            drift: true,
            ..Terms::default()
        };
        let f = profiled(&prep, &x, &all, &ones, drift).unwrap();
        let tau = f.tau.unwrap() * 3600.0;
        assert!((tau - tau_s).abs() < 1e-6 * tau_s, "τ {tau} s");
        assert!((f.beta - (-2.0)).abs() < 1e-6, "drift {} µm/h", f.beta);
        let want_a = a * (-12.0 / tau_s).exp();
        assert!((f.warm_a - want_a).abs() < 1e-6, "{} vs {want_a}", f.warm_a);
    }

    /// Davies' bound is the F tail with no path, and grows with the path.
    #[test]
    fn davies_bound() {
        assert!((davies(9.0, 50.0, 0.0) - f_upper(9.0, 1.0, 50.0)).abs() < 1e-15);
        let (a, b) = (davies(9.0, 50.0, 1.0), davies(9.0, 50.0, 3.0));
        assert!(a > f_upper(9.0, 1.0, 50.0) && b > a);
        // ν → ∞: P(χ²₁ ≥ u) + L/π·e^(−u/2).
        let want = crate::diagnose::stats::chi2_upper(16.0, 1.0) + 2.0 / PI * (-8.0f64).exp();
        assert!((davies(16.0, 1e7, 2.0) - want).abs() < 1e-8);
    }

    #[test]
    fn golden_section_finds_a_maximum() {
        let x = golden_max(0.0, 3.0, |x| -(x - 1.234_567).powi(2));
        assert!((x - 1.234_567).abs() < 1e-4, "{x}");
    }
}
