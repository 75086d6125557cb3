//! The project's model of an axis: its error model ([`ErrorModel`]: progressive, periodic
//! and reversal errors, scatter, drift, warm-up and thermal growth as Hemingray et al.
//! 1971 describe them), the test plan that measures it ([`TestPlan`], ISO 230-2 4.2–4.3),
//! and a test simulated from both ([`Simulation::run`]). `axcheck simulate` writes it to a
//! file (`crate::simulate`); `axcheck diagnose` fits it to measured data.
//!
//! Output is deterministic for a seed: each random term draws from its own stream
//! ([`rng`]).

pub mod geometry;
pub mod model;
pub mod plan;
pub mod rng;

pub use model::{ErrorModel, PeriodicTerm, PlantedOutlier};
pub use plan::{Cycle, Step, TargetSpacing, TestPlan, Visit};

use crate::measurement::{AxisData, RawReading};
use crate::units::AxisKind;
use rng::Rng;
use serde::{Deserialize, Serialize};

/// A simulation file: axis kind, seed, error model and test plan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Simulation {
    /// Read as text by the simulation file's loader first (`simulate::yaml`), whose error
    /// for anything else names the kinds.
    pub kind: AxisKind,
    #[serde(default)]
    pub seed: u64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    #[serde(default)]
    pub model: ErrorModel,
    pub plan: TestPlan,
}

/// A value of a simulation that cannot be simulated: the key as the file writes it
/// (`model.scatter`, `plan.targets.jitter`) and what is wrong with it, in one message
/// that the simulation files' reader places at the key's line.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{0}")]
pub struct InvalidSimulation(pub String);

/// Decimals kept in simulated deviations (as the CSV writer writes them).
const DECIMALS: i32 = 4;

impl Simulation {
    /// Checks values a simulation cannot use: the plan's first, then the model's.
    pub fn validate(&self) -> Result<(), InvalidSimulation> {
        self.plan.validate().map_err(InvalidSimulation)?;
        if self.kind == AxisKind::Rotary && !self.model.geometry.is_empty() {
            let why = "model.geometry: straightness, rotations and the beam's offset are of a linear axis; this model is rotary";
            return Err(InvalidSimulation(why.into()));
        }
        let m = match (&self.plan.target_list, &self.plan.targets) {
            (Some(l), _) => l.len(),
            (None, Some(t)) => t.count,
            _ => 0,
        };
        self.model
            .validate(self.plan.runs, m)
            .map_err(InvalidSimulation)
    }

    /// Runs the simulation with `seed` (the file's seed unless overridden).
    pub fn run(&self, seed: u64) -> AxisData {
        let kind = self.kind;
        let plan = &self.plan;
        let model = &self.model;
        let targets = plan.target_positions(seed);
        let travel = (targets[0], targets[targets.len() - 1]);
        let visits = plan.schedule(&targets);

        let mut offsets_rng = Rng::new(seed, 2);
        let run_offsets: Vec<f64> = (0..plan.runs)
            .map(|j| {
                let fixed = model.run_offsets.get(j).copied().unwrap_or(0.0);
                let random = if model.run_offset_sd > 0.0 {
                    model.run_offset_sd * offsets_rng.normal()
                } else {
                    0.0
                };
                fixed + random
            })
            .collect();
        let mut scatter_rng = Rng::new(seed, 3);
        let mut outlier_rng = Rng::new(seed, 4);
        let raw = visits
            .iter()
            .map(|v| {
                let position = targets[v.target];
                let mut x = model.expected(kind, position, v.direction, v.time_s, travel)
                    + run_offsets[v.run]
                    + model.geometry.abbe_at_beam(position, v.direction, travel);
                // Draw for every reading, whatever σ, so streams stay aligned across models.
                x += model.scatter_at(position, travel) * scatter_rng.normal();
                let (hit, sign) = (outlier_rng.uniform(), outlier_rng.uniform());
                if hit < model.outlier_rate {
                    x += if sign < 0.5 {
                        -model.outlier_size
                    } else {
                        model.outlier_size
                    };
                }
                for o in &model.outliers {
                    if o.run as usize == v.run + 1
                        && o.target == v.target + 1
                        && o.direction == v.direction
                    {
                        x += o.size;
                    }
                }
                if model.resolution > 0.0 {
                    x = (x / model.resolution).round() * model.resolution;
                }
                reading(position, v, x)
            })
            .collect();
        AxisData::from_raw(kind, raw, Vec::new(), "simulation")
            .expect("a simulated plan visits every target in both directions in every run")
    }

    /// A straightness (along `letter`, µm) or angular (about `letter`, arcsec) test of the
    /// model's geometry, on the plan's targets, runs and order; `None` when the model has
    /// no such term. Its scatter draws from its own stream, so that the positioning test
    /// of the same seed stays as it was.
    pub fn run_geometry(&self, seed: u64, letter: char) -> Option<AxisData> {
        let g = &self.model.geometry;
        let (profile, stream) = match g.straightness.get(&letter) {
            Some(p) => (p, 20 + letter as u64),
            None => (g.angular.get(&letter)?, 40 + letter as u64),
        };
        let targets = self.plan.target_positions(seed);
        let travel = (targets[0], targets[targets.len() - 1]);
        let mut scatter = Rng::new(seed, stream);
        let raw = (self.plan.schedule(&targets).iter())
            .map(|v| {
                let position = targets[v.target];
                let x =
                    profile.at(position, v.direction, travel) + profile.scatter * scatter.normal();
                reading(position, v, x)
            })
            .collect();
        let data = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "simulation");
        Some(data.expect("a simulated plan visits every target in both directions in every run"))
    }
}

/// The reading of `visit` at `position` with deviation `x`, rounded as the CSV writer
/// writes it (deviations to [`DECIMALS`], times to ms; −0 written as 0).
fn reading(position: f64, visit: &Visit, x: f64) -> RawReading {
    let scale = 10f64.powi(DECIMALS);
    RawReading {
        target: position,
        direction: visit.direction,
        run: visit.run as u32 + 1,
        deviation: (x * scale).round() / scale + 0.0,
        time_s: Some((visit.time_s * 1000.0).round() / 1000.0),
        temps_c: Vec::new(),
        line: 0,
    }
}
