//! Warm-up: the deviations approach a new level exponentially, as a machine tested before
//! it is warm (ISO 230-2 clause 3.3: a warm-up before the test, and an ordered sequence
//! of deviations at a target as the sign that the thermal state is not stable; Hemingray
//! et al. 1971, §5.4: drift over the first half hour). Tested in [`crate::diagnose::warm`]
//! as an exponential approach beyond a linear drift, against the scatter or, when free run
//! offsets are real beyond it, against the run-to-run variation.

use super::{Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::TimeUnit;
use crate::diagnose::time_fit::warm_shape;
use crate::diagnose::warm::{WarmEstimate, WarmTest, tau_range};
use crate::units::AxisKind;

/// A warm-up: the level the deviations approach, its time constant and how long it takes.
/// Times are minutes with time stamps, runs of the standard test cycle without them.
#[derive(Debug, Clone, PartialEq)]
pub struct WarmUp {
    /// From the first reading to the final level, at the mean target position; deviation
    /// unit.
    pub amplitude: f64,
    pub amplitude_se: f64,
    /// Time constant τ.
    pub tau: f64,
    /// From the start of the test until every target is within 1 µm (1 arcsec) of its
    /// final level.
    pub time_to_within_1: f64,
    /// The largest distance from the final level along the travel at the last reading,
    /// deviation unit.
    pub remaining_at_end: f64,
    /// The position-proportional part at the end state, ppm (µm per m), with its standard
    /// error, when found.
    pub growth_ppm: Option<(f64, f64)>,
    /// F and p of free run offsets beyond the warm-up (on the run means).
    pub run_offsets_beyond: Option<(f64, f64)>,
    /// F and p of the warm-up beyond free run offsets (within the runs).
    pub within_runs: Option<(f64, f64)>,
    /// BIC with the warm-up minus BIC with a linear drift instead, and with free run
    /// offsets instead (negative: the warm-up explains the data better).
    pub delta_bic_vs_drift: f64,
    pub delta_bic_vs_run_offsets: f64,
    /// What it was tested against: `scatter` or `run-to-run variation`.
    pub tested_against: &'static str,
    /// Whether the time constant is at an end of the range searched.
    pub at_bound: Option<Bound>,
}

/// An end of the range of time constants searched.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bound {
    /// A quarter of a run: the warm-up was over within the first run.
    Shortest,
    /// Three times the test: the curve is barely bent.
    Longest,
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
        let growth = e.g_p < ALPHA;
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
            at_bound: tau_range(&a.prep).and_then(|(lo, hi)| {
                if e.tau <= lo * 1.01 {
                    Some(Bound::Shortest)
                } else if e.tau >= hi / 1.01 {
                    Some(Bound::Longest)
                } else {
                    None
                }
            }),
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
