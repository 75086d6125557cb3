//! The extended model: fitted on all (non-outlier) readings with the terms the selection
//! kept ([`Fitted::new`]), and written as a simulation file with each kept effect's terms
//! ([`Fitted::extended_model`]). It stands above the effects, whose rules add their terms;
//! the fitted terms they read ([`Fitted`]) stand below them.

use super::analysis::Analysis;
use super::effects::{Effect, scatter_variation};
use super::fitted::Fitted;
use super::model::{self, r4};
use super::model_terms::Predictor;
use super::prep::TimeUnit;
use super::select::Selection;
use super::shape::Shape;
use crate::axis_model::{ErrorModel, Simulation};
use crate::units::Direction;

impl Fitted {
    pub fn new(a: &Analysis, sel: &Selection) -> Fitted {
        let (p, kept) = (&a.basis.prep, sel.terms);
        let train: Vec<bool> = a
            .basis
            .active
            .iter()
            .map(|&act| act || !kept.outliers)
            .collect();
        let pred = Predictor::fit(p, &a.basis.x, &train, kept);
        let guess = model::guess_plan(a.basis.data);
        let hours_per_unit = match p.time_unit {
            TimeUnit::Hours => 1.0,
            TimeUnit::Runs => {
                let visits = guess.plan.schedule(&a.basis.data.targets);
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
                (p.thermal_origin).unwrap_or(p0.clamp(p.lo - margin, p.hi + margin))
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
            reversal_shape: sel.terms.reversal_shape,
            periodic: sel.periodic.clone(),
            train,
            outliers: a.hits.iter().map(|h| (h.row, h.size)).collect(),
            scatter_ends: a.scatter.as_ref().map(|s| (s.sigma_lo, s.sigma_hi)),
            scatter_knots: (sel.terms.scatter && sel.terms.scatter_shape != Shape::Line)
                .then(|| {
                    let (tt, shape) = (&a.time, sel.terms.scatter_shape);
                    scatter_variation::sigma_per_target(
                        p,
                        &tt.full.residuals,
                        tt.sigma2,
                        tt.df,
                        shape,
                    )
                })
                .flatten(),
            warm_growth: (a.time.warm.as_ref())
                .and_then(|w| w.estimate.as_ref())
                .is_some_and(|e| e.growth_found()),
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
            e.rule().extend(&a.basis, self, &mut model);
        }
        model.shape = self.shape_knots(a, &model);
        let describe = if kept.is_empty() {
            "no terms beyond the standard's model".to_string()
        } else {
            kept.iter().map(|e| e.name()).collect::<Vec<_>>().join(", ")
        };
        Simulation {
            kind: a.basis.data.kind,
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
        let (p, m, n) = (&a.basis.prep, a.basis.prep.m, a.basis.prep.n);
        let key = |i: usize, d: usize, j: usize| (i * 2 + d) * n + j;
        let mut time_of = vec![0.0; 2 * m * n];
        for v in &self.guess.plan.schedule(&a.basis.data.targets) {
            time_of[key(v.target, v.direction.index(), v.run)] = v.time_s;
        }
        let travel = (p.lo, p.hi);
        let rest: Vec<f64> = p
            .rows
            .iter()
            .zip(&a.basis.x)
            .map(|(r, x)| {
                let dir = if r.d == 0 {
                    Direction::Up
                } else {
                    Direction::Down
                };
                let t = time_of[key(r.i, r.d, r.run)];
                let mut e = model.expected(a.basis.data.kind, p.positions[r.i], dir, t, travel);
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
