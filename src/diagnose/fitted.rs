//! The extended model fitted on all (non-outlier) readings with the kept terms, as the
//! effects read it, and the two models as simulation files: the base model (the
//! standard's assumptions, simulated for the model checks) and the extended model.

use super::analysis::{Analysis, smooth_trend};
use super::effects::Effect;
use super::model::{self, PlanGuess, r4};
use super::periodic::Peak;
use super::prep::TimeUnit;
use super::select::Selection;
use super::validate::Predictor;
use crate::simulate::{ErrorModel, Simulation, TestPlan};
use crate::units::Direction;

/// The extended model's terms as the simulator has them.
pub(crate) struct Fitted {
    pub pred: Predictor,
    pub guess: PlanGuess,
    /// Hours per time unit (1, or the guessed plan's duration of a run).
    pub hours_per_unit: f64,
    /// Drift δ per time unit at the thermal origin.
    pub drift_rate: f64,
    /// Thermal growth γ, deviation per position unit per time unit.
    pub growth: f64,
    /// Where the thermal growth is zero.
    pub origin: f64,
    /// Run offsets, centred (empty without the term).
    pub run_offsets: Vec<f64>,
    /// Reversal value per target, and its mean.
    pub reversal: Vec<f64>,
    pub reversal_mean: f64,
    /// The periodic term, when kept.
    pub periodic: Option<Peak>,
    /// Rows the fit used.
    pub train: Vec<bool>,
}

impl Fitted {
    pub fn new(a: &Analysis, sel: &Selection) -> Fitted {
        let (p, kept) = (&a.prep, sel.terms);
        let train: Vec<bool> = a.active.iter().map(|&act| act || !kept.outliers).collect();
        let pred = Predictor::fit(p, &a.x, &train, kept);
        let guess = model::guess_plan(a.data);
        let hours_per_unit = match p.time_unit {
            TimeUnit::Hours => 1.0,
            TimeUnit::Runs => {
                let visits = guess.plan.schedule(&a.data.targets);
                let total = visits.last().map_or(0.0, |v| v.time_s);
                total / p.n as f64 / 3600.0
            }
        };
        // Time terms as the simulator has them: drift δ and growth γ about an origin.
        let (beta, gamma) = (pred.time.beta, pred.time.gamma);
        let (drift_rate, growth, origin) = if kept.thermal && gamma != 0.0 {
            let p0 = p.pbar - beta / gamma;
            let o = if kept.drift {
                let margin = 0.25 * p.length();
                p0.clamp(p.lo - margin, p.hi + margin)
            } else {
                p0
            };
            (beta + gamma * (o - p.pbar), gamma, o)
        } else if kept.drift {
            (beta, 0.0, p.pbar)
        } else {
            (0.0, 0.0, p.pbar)
        };
        let run_offsets: Vec<f64> = if kept.runs && !pred.time.alpha.is_empty() {
            let mean = pred.time.alpha.iter().sum::<f64>() / p.n as f64;
            pred.time.alpha.iter().map(|a| a - mean).collect()
        } else {
            Vec::new()
        };
        let reversal = pred.lines.reversal.clone();
        let reversal_mean = reversal.iter().sum::<f64>() / p.m as f64;
        Fitted {
            pred,
            guess,
            hours_per_unit,
            drift_rate,
            growth,
            origin,
            run_offsets,
            reversal,
            reversal_mean,
            periodic: sel.periodic.clone(),
            train,
        }
    }

    /// The extended model with the `kept` effects' terms; its plan is the file's plan.
    pub fn extended_model(&self, a: &Analysis, kept: &[Effect], seed: u64) -> Simulation {
        let s2 = self.pred.time.sigma2();
        let mut model = ErrorModel {
            reversal: r4(self.reversal_mean),
            scatter: r4(if s2 > 0.0 { s2.sqrt() } else { 0.0 }),
            ..ErrorModel::default()
        };
        for e in kept {
            e.rule().extend(a, self, &mut model);
        }
        model.shape = self.shape_knots(a, &model);
        let describe = if kept.is_empty() {
            "no terms beyond the standard's model".to_string()
        } else {
            kept.iter().map(|e| e.name()).collect::<Vec<_>>().join(", ")
        };
        Simulation {
            kind: a.data.kind,
            seed,
            description: Some(format!(
                "extended model fitted by axcheck diagnose ({describe}); plan: the measured targets, runs and cycle"
            )),
            model,
            plan: self.guess.plan.clone(),
        }
    }

    /// Shape knots: what the other terms of `model` leave at each target, with the
    /// simulator's times.
    fn shape_knots(&self, a: &Analysis, model: &ErrorModel) -> Vec<[f64; 2]> {
        let (p, m, n) = (&a.prep, a.prep.m, a.prep.n);
        let key = |i: usize, d: usize, j: usize| (i * 2 + d) * n + j;
        let mut time_of = vec![0.0; 2 * m * n];
        for v in &self.guess.plan.schedule(&a.data.targets) {
            time_of[key(v.target, v.direction.index(), v.run)] = v.time_s;
        }
        let travel = (p.lo, p.hi);
        let rest: Vec<f64> = p
            .rows
            .iter()
            .zip(&a.x)
            .map(|(r, x)| {
                let dir = if r.d == 0 {
                    Direction::Up
                } else {
                    Direction::Down
                };
                let t = time_of[key(r.i, r.d, r.run)];
                let mut e = model.expected(a.data.kind, p.positions[r.i], dir, t, travel);
                if let Some(o) = model.run_offsets.get(r.run) {
                    e += o;
                }
                x - e
            })
            .collect();
        let (rm, _) = p.cell_means(&rest, &self.train);
        (0..m)
            .map(|i| {
                let (u, d) = (rm[2 * i], rm[2 * i + 1]);
                let v = match (u.is_finite(), d.is_finite()) {
                    (true, true) => (u + d) / 2.0,
                    (true, false) => u,
                    (false, true) => d,
                    _ => 0.0,
                };
                [p.positions[i], r4(v)]
            })
            .collect()
    }
}

/// The base model (the standard's assumptions) fitted to the raw readings: smooth
/// systematic deviation, one reversal value, white scatter, nothing in time.
pub(crate) fn base_model(a: &Analysis, plan: &TestPlan, seed: u64) -> Simulation {
    let (p, m) = (&a.prep, a.prep.m);
    let all = vec![true; a.x.len()];
    let (raw_means, _) = p.cell_means(&a.x, &all);
    let raw_bidir: Vec<f64> = (0..m)
        .map(|i| (raw_means[2 * i] + raw_means[2 * i + 1]) / 2.0)
        .collect();
    let raw_b: Vec<f64> = (0..m)
        .map(|i| raw_means[2 * i] - raw_means[2 * i + 1])
        .collect();
    let trend = smooth_trend(&p.positions, &raw_bidir);
    let raw_sigma = if p.n >= 2 {
        let ss: f64 = p
            .rows
            .iter()
            .zip(&a.x)
            .map(|(r, v)| (v - raw_means[p.cell(r)]).powi(2))
            .sum();
        (ss / (a.x.len() - p.cells()) as f64).sqrt()
    } else {
        0.0
    };
    Simulation {
        kind: a.data.kind,
        seed,
        description: Some(
            "base model fitted by axcheck diagnose: smooth systematic deviation, one reversal value, white scatter, nothing in time"
                .to_string(),
        ),
        model: ErrorModel {
            shape: p
                .positions
                .iter()
                .zip(&trend)
                .map(|(p, t)| [*p, r4(*t)])
                .collect(),
            reversal: r4(raw_b.iter().sum::<f64>() / m as f64),
            scatter: r4(raw_sigma),
            ..ErrorModel::default()
        },
        plan: plan.clone(),
    }
}
