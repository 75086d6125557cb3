//! The tests of one measurement, run once and read by every effect.
//!
//! Order, chosen so that one effect does not pass for another: outliers (in the full time
//! model), time effects (drift, warm-up, thermal growth, run offsets; [`super::time`]), scatter
//! along the axis ([`super::effects::scatter_variation`]; when found, outliers and time effects are redone
//! with the scatter model as weights), then on readings corrected for the time effects the
//! reversal along the axis ([`super::effects::reversal_variation`]) and the periodic error
//! ([`super::effects::periodic`]).

use super::basis::Basis;
use super::detectable::Detectable;
use super::effects::outlier::{self, Hit};
use super::effects::periodic::{self, Search};
use super::effects::reversal_variation::{self, ReversalTest};
use super::effects::scatter_variation::{self, ScatterTest};
use super::effects::warm_up::fading::{self, Fading, Withheld};
use super::effects::{Effect, Finding, drift, run_offset, thermal_growth, warm_up};
use super::finding::Units;
use super::options::{ALPHA, Options};
use super::prep::{Prep, TimeUnit};
use super::time::{self, TimeTests};
use crate::measurement::AxisData;

/// What the tests found out about one measurement: the shared part every effect reads
/// and each effect's own test.
pub(crate) struct Analysis<'a> {
    pub(crate) basis: Basis<'a>,
    pub hits: Vec<Hit>,
    pub time: TimeTests,
    pub scatter: Option<ScatterTest>,
    pub reversal: Option<ReversalTest>,
    pub periodic: Search,
    /// Whether each run's Bi fade from run to run, as a warm-up's course within the runs
    /// makes them: tested only beside real run offsets where the warm-up could not be.
    pub fading: Option<Fading>,
}

impl<'a> Analysis<'a> {
    /// Runs the tests; notes on what could not be assessed go to `notes`.
    pub fn run(data: &'a AxisData, options: &Options, notes: &mut Vec<String>) -> Analysis<'a> {
        let pitch = options.pitch;
        let prep = Prep {
            thermal_origin: options.thermal_origin,
            ..Prep::new(data)
        };
        notes.extend(opening_notes(prep.time_unit, prep.n));
        let x: Vec<f64> = prep.rows.iter().map(|r| r.x).collect();
        let (hits, active, tt, sc, scale) = time_and_scatter(&prep, &x);
        let known = prep.n >= 2 && tt.df >= 1.0 && tt.sigma2 > 0.0;
        let sigma = if known { tt.sigma2.sqrt() } else { f64::NAN };
        let m = prep.m;
        // Readings corrected for the time effects (the smooth model's drift, growth and
        // warm-up) when one is found. Not otherwise: under the standard cycle a target's ↑
        // and ↓ readings of one run lie apart in time by an interval that changes linearly
        // along the axis, so a drift subtracted that is not there (the straight line
        // through run offsets, say) would tilt every Bi along the axis and pass for a
        // reversal that varies (as a real drift does under that cycle, ISO 230-2 Annex A).
        let v: Vec<f64> = if smooth_time_effect(&tt) {
            x.iter()
                .enumerate()
                .map(|(k, x)| x - tt.trend.effect(&prep, k))
                .collect()
        } else {
            x.clone()
        };
        let (cm, cc) = prep.cell_means(&v, &active);
        let var_cell = |c: usize| tt.sigma2 * scale[c] * scale[c] / cc[c].max(1) as f64;
        let b: Vec<f64> = (0..m).map(|i| cm[2 * i] - cm[2 * i + 1]).collect();
        let bvar: Option<Vec<f64>> = known.then(|| {
            (0..m)
                .map(|i| var_cell(2 * i) + var_cell(2 * i + 1))
                .collect()
        });
        let rev = reversal_variation::test(&prep.positions, &b, bvar.as_deref(), tt.df);
        let means: Vec<f64> = (0..m).map(|i| (cm[2 * i] + cm[2 * i + 1]) / 2.0).collect();
        let mvar: Option<Vec<f64>> = known.then(|| {
            (0..m)
                .map(|i| (var_cell(2 * i) + var_cell(2 * i + 1)) / 4.0)
                .collect()
        });
        // Beside run offsets where the warm-up could not be tested: each run's Bi.
        let fading = untested_warm_up(&tt)
            .then(|| fading::test(&prep, &v, &active, &scale, tt.sigma2, tt.df))
            .flatten();
        let ps = periodic::search(&prep.positions, &means, mvar.as_deref(), pitch, ALPHA);
        periodic::plan_notes(&ps.resolution, pitch, data.kind, notes);
        Analysis {
            basis: Basis {
                data,
                units: Units {
                    kind: data.kind,
                    time: prep.time_unit,
                },
                prep,
                x,
                active,
                sigma,
                b,
                means,
            },
            hits,
            time: tt,
            scatter: sc,
            reversal: rev,
            periodic: ps,
            fading,
        }
    }
}

impl Analysis<'_> {
    /// The smallest confirmable size of every effect, in the order of the vocabulary.
    pub fn detectable(&self) -> Vec<Detectable> {
        let (p, u, tt) = (&self.basis.prep, self.basis.units, &self.time);
        Effect::ALL
            .iter()
            .map(|&e| match e {
                Effect::Drift => drift::detectable(p, u, tt.drift.as_ref()),
                Effect::WarmUp => warm_up::detectable(p, u, tt.warm.as_ref()),
                Effect::ThermalGrowth => thermal_growth::detectable(p, u, tt.thermal.as_ref()),
                Effect::RunOffset => {
                    let rows = tt.full.rows.len();
                    let warm_curve = tt.warm.is_some();
                    run_offset::detectable(p, u, tt.runs.as_ref(), tt.sigma2, rows, warm_curve)
                }
                Effect::Periodic => periodic::detectable(p, u, &self.periodic),
                Effect::ReversalVariation => {
                    reversal_variation::detectable(p, u, self.reversal.as_ref())
                }
                Effect::Outlier => outlier::detectable(p, u, tt.sigma2, tt.df),
                Effect::ScatterVariation => scatter_variation::detectable(p, &tt.full),
            })
            .collect()
    }

    /// Each effect's findings from its own test, in the order of the vocabulary, and
    /// apart the reversal or scatter variations that the fading of each run's Bi puts
    /// down to a warm-up (not findings; their notes say what they were read as).
    pub fn findings(&self) -> (Vec<Finding>, Vec<Withheld>) {
        let (b, t) = (&self.basis, &self.time);
        let untested = untested_warm_up(t);
        let along_axis = [
            reversal_variation::Rule.find(b, self.reversal.as_ref(), untested),
            scatter_variation::Rule.find(b, self.scatter.as_ref(), untested),
        ];
        let mut withheld = Vec::new();
        let faded = self.fading.as_ref().filter(|f| f.p < fading::LEVEL);
        let [reversal, scatter] = match faded {
            Some(f) => along_axis.map(|found| {
                withheld.extend(found.iter().map(|x| Withheld {
                    effect: x.effect(),
                    note: fading::note(x, f),
                }));
                Vec::new()
            }),
            None => along_axis,
        };
        let findings = [
            drift::Rule.find(b, t.drift.as_ref(), unresolved_warm_up(t)),
            warm_up::Rule.find(b, t.warm.as_ref()),
            thermal_growth::Rule.find(
                b,
                t.thermal.as_ref(),
                t.drift.as_ref().and_then(|d| d.origin),
            ),
            run_offset::Rule.find(b, t.runs.as_ref()),
            periodic::Rule.find(b, &self.periodic),
            reversal,
            outlier::Rule.find(b, &self.hits),
            scatter,
        ]
        .concat();
        (findings, withheld)
    }
}

/// The level of the smallest warm-up this plan confirms, when the warm-up is tested and
/// not found: a smaller one shows only as its trend.
fn unresolved_warm_up(tt: &TimeTests) -> Option<f64> {
    let w = tt.warm.as_ref().filter(|w| w.p >= ALPHA)?;
    w.smallest.map(|s| s.level)
}

/// Whether the run offsets are found and the warm-up, not found, could not be tested
/// beside them (no level reaches the power: [`warm_up::detectable`] is none).
fn untested_warm_up(tt: &TimeTests) -> bool {
    let runs_real = tt.runs.as_ref().is_some_and(|r| r.p < ALPHA);
    let untested = (tt.warm.as_ref()).is_some_and(|w| w.p >= ALPHA && w.smallest.is_none());
    runs_real && untested
}

/// Whether the tests find a drift, a thermal growth or a warm-up.
fn smooth_time_effect(tt: &TimeTests) -> bool {
    let found = |p: Option<f64>| p.is_some_and(|p| p < ALPHA);
    found(tt.drift.as_ref().map(|d| d.test.p))
        || found(tt.thermal.as_ref().map(|t| t.p))
        || tt.warm_tau(ALPHA).is_some()
}

/// What the number of runs and the time stamps leave out.
fn opening_notes(time_unit: TimeUnit, n: usize) -> Vec<String> {
    let mut notes = Vec::new();
    if time_unit == TimeUnit::Runs {
        notes.push(
            "no time stamps: time taken as the order of the standard test cycle (ISO 230-2 Fig. 1); rates are per run"
                .to_string(),
        );
    }
    if n == 1 {
        notes.push(
            "n = 1: no repeated approaches, so scatter, drift, thermal growth, run offsets, outliers and scatter variation cannot be assessed and there is no held-out validation; reversal variation and periodic error are tested against their own residuals"
                .to_string(),
        );
    } else if n == 2 {
        notes.push(
            "n = 2: an outlier cannot be located (either reading of a pair could be the odd one), a drift cannot be told from a zero shift between the two runs, and scatter variation is not tested"
                .to_string(),
        );
    }
    notes
}

/// Outliers, time effects and scatter variation; redone with the scatter model as
/// weights when the scatter changes along the axis. Returns the outliers, the active
/// rows, the time tests, the scatter test and the relative scatter per cell.
fn time_and_scatter(
    prep: &Prep,
    x: &[f64],
) -> (
    Vec<Hit>,
    Vec<bool>,
    TimeTests,
    Option<ScatterTest>,
    Vec<f64>,
) {
    let mask = |hits: &[Hit]| {
        let mut a = vec![true; prep.rows.len()];
        for h in hits {
            a[h.row] = false;
        }
        a
    };
    let mut scale = vec![1.0; prep.cells()];
    let mut hits = outlier::detect(prep, x, &scale, None, ALPHA);
    let mut active = mask(&hits);
    let mut tt = time::tests(prep, x, &active, &scale, ALPHA);
    if let Some(tau) = tt.warm_tau(ALPHA).filter(|_| !hits.is_empty()) {
        // Readings early in a warm-up are no outliers of a model that has it.
        hits = outlier::detect(prep, x, &scale, Some(tau), ALPHA);
        active = mask(&hits);
        tt = time::tests(prep, x, &active, &scale, ALPHA);
    }
    let mut sc = scatter_variation::test(prep, &tt.full.residuals, tt.sigma2, tt.df);
    if let Some(s) = sc.as_ref().filter(|s| s.p < ALPHA) {
        scale = s.rel_scale.clone();
        let at = scatter_variation::outlier_scale(prep, s, &tt.full, x);
        hits = outlier::detect(prep, x, &at, tt.warm_tau(ALPHA), ALPHA);
        active = mask(&hits);
        tt = time::tests(prep, x, &active, &scale, ALPHA);
        if let Some(s2) = scatter_variation::test(prep, &tt.full.residuals, tt.sigma2, tt.df) {
            sc = Some(s2);
        }
    }
    (hits, active, tt, sc, scale)
}
