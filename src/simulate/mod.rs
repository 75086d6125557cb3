//! The axis simulator: an error model and a test plan produce a measurement.
//!
//! It is the project's model of an axis; `axcheck diagnose` fits it to measured data.
//! Output is deterministic for a seed: each random term draws from its own stream.

pub mod fleet;
pub mod model;
pub mod plan;
pub mod rng;
mod yaml;

pub use model::{ErrorModel, Outlier, PeriodicTerm};
pub use plan::{Cycle, Step, TargetSpacing, TestPlan, Visit};

use crate::measurement::{AxisData, RawReading};
use crate::units::AxisKind;
use rng::Rng;
use serde::{Deserialize, Serialize};

/// A simulation file: axis kind, seed, error model and test plan.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Simulation {
    #[serde(deserialize_with = "crate::yaml::keyword")]
    pub kind: AxisKind,
    #[serde(default)]
    pub seed: u64,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    #[serde(default)]
    pub model: ErrorModel,
    pub plan: TestPlan,
}

/// A simulation file that cannot be used: `file:line:column: message`.
pub type SimulationError = crate::yaml::YamlError;

/// Decimals kept in simulated deviations (as the CSV writer writes them).
const DECIMALS: i32 = 4;

impl Simulation {
    /// Parses and checks a simulation file; `file` names it in errors.
    pub fn from_yaml(text: &str, file: &str) -> Result<Simulation, SimulationError> {
        let (value, index) = crate::yaml::parse(text, file)?;
        let fail = |located: crate::yaml::Located| located.in_file(file);
        let kind = yaml::kind(&value, &index).map_err(fail)?;
        yaml::check_keys(&value, kind, &index).map_err(fail)?;
        let spell = |path: &str, field: &str| yaml::spell(path, field, kind);
        let sim: Simulation =
            crate::yaml::deserialize_spelled(&value, "", &index, &spell).map_err(fail)?;
        sim.validate()
            .map_err(|message| fail(yaml::locate(&message, kind, &index)))?;
        Ok(sim)
    }

    /// The simulation file text, keys spelled with the kind's units.
    pub fn to_yaml(&self) -> String {
        let value = serde_norway::to_value(self).expect("a simulation serialises");
        let value = yaml::externalize(value, self.kind);
        serde_norway::to_string(&value).expect("a YAML value serialises")
    }

    pub fn validate(&self) -> Result<(), String> {
        self.plan.validate()?;
        let m = match (&self.plan.target_list, &self.plan.targets) {
            (Some(l), _) => l.len(),
            (None, Some(t)) => t.count,
            _ => 0,
        };
        self.model.validate(self.plan.runs, m)
    }

    /// [`Simulation::validate`] with the keys spelled as the written file spells them
    /// (`plan.targets_mm`), for a model made in code before it is written.
    pub fn validate_as_written(&self) -> Result<(), String> {
        self.validate().map_err(|m| yaml::respell(&m, self.kind).0)
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
        let scale = 10f64.powi(DECIMALS);
        let raw = visits
            .iter()
            .map(|v| {
                let position = targets[v.target];
                let mut x = model.expected(kind, position, v.direction, v.time_s, travel)
                    + run_offsets[v.run];
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
                RawReading {
                    target: position,
                    direction: v.direction,
                    run: v.run as u32 + 1,
                    deviation: (x * scale).round() / scale + 0.0,
                    time_s: Some((v.time_s * 1000.0).round() / 1000.0),
                    temps_c: Vec::new(),
                    line: 0,
                }
            })
            .collect();
        AxisData::from_raw(kind, raw, Vec::new(), "simulation")
            .expect("a simulated plan visits every target in both directions in every run")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::units::Direction;

    const LINEAR: &str = "
kind: linear
seed: 11
model:
  scale_um_per_m: 10
  reversal_um: 4
  scatter_um: 0.5
  periodic:
    - {pitch_mm: 10, amplitude_um: 1.0, phase_deg: 30}
  warm_up_um: 3
  warm_up_um_per_m: 4
  warm_up_tau_min: 15
plan:
  targets: {start_mm: 0, end_mm: 1000, count: 11, jitter_mm: 5}
  runs: 5
  cycle: standard
  feed_mm_per_min: 2000
  dwell_s: 3
";

    #[test]
    fn parses_runs_and_round_trips() {
        let sim = Simulation::from_yaml(LINEAR, "m.yaml").unwrap();
        let data = sim.run(sim.seed);
        assert_eq!(data.target_count(), 11);
        assert_eq!(data.runs(), 5);
        assert_eq!(data.readings.len(), 110);
        assert!(data.has_times());
        assert_eq!(data, sim.run(sim.seed), "deterministic");
        let text = sim.to_yaml();
        assert!(text.contains("reversal_um: 4"), "{text}");
        assert!(text.contains("pitch_mm: 10"), "{text}");
        assert!(text.contains("warm_up_um: 3"), "{text}");
        assert!(text.contains("warm_up_tau_min: 15"), "{text}");
        let again = Simulation::from_yaml(&text, "again.yaml").unwrap();
        assert_eq!(again, sim);
    }

    #[test]
    fn reversal_sign_follows_clause_2_12() {
        let sim = Simulation::from_yaml(
            "kind: linear\nmodel: {reversal_um: 4}\nplan: {targets_mm: [0, 100], runs: 2}\n",
            "m.yaml",
        )
        .unwrap();
        let d = sim.run(0);
        assert_eq!(d.deviation(0, Direction::Up, 0), 2.0);
        assert_eq!(d.deviation(0, Direction::Down, 0), -2.0);
    }

    #[test]
    fn unit_keys_must_match_the_kind() {
        let e = |text: &str| {
            Simulation::from_yaml(text, "m.yaml")
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e("kind: rotary\nmodel: {reversal_um: 4}\nplan: {targets_deg: [0, 90]}\n"),
            "m.yaml:2:9: `model.reversal_um` has a linear unit, but this is a rotary model; write `reversal_arcsec`"
        );
        assert_eq!(
            e("kind: linear\nmodel: {reversal: 4}\nplan: {targets_mm: [0, 90]}\n"),
            "m.yaml:2:9: `model.reversal` has no unit; write `reversal_um`"
        );
        assert!(
            e("kind: linear\nmodel: {revrsal_um: 4}\nplan: {targets_mm: [0, 90]}\n").starts_with(
                "m.yaml:2:9: unknown key `model.revrsal_um` (did you mean `reversal_um`?)"
            )
        );
        assert_eq!(
            e("kind: linear\nmodel: {scatter_um: abc}\nplan: {targets_mm: [0, 90]}\n"),
            "m.yaml:2:21: model.scatter_um: expected a number, got the text `abc`"
        );
    }

    /// Every error names the place and says what was expected, in the file's spelling.
    #[test]
    fn errors_in_the_users_words() {
        let e = |text: &str| {
            Simulation::from_yaml(text, "m.yaml")
                .unwrap_err()
                .to_string()
        };
        assert_eq!(
            e("kind: linar\nplan: {targets_mm: [0, 100]}\n"),
            "m.yaml:1:7: kind: unknown kind `linar` (did you mean `linear`?); expected linear or rotary"
        );
        assert_eq!(
            e("kind: [linear]\nplan: {targets_mm: [0, 100]}\n"),
            "m.yaml:1:7: kind: expected linear or rotary, got a list of 1 item"
        );
        assert_eq!(
            e("plan: {targets_mm: [0, 100]}\n"),
            "m.yaml:1:1: missing `kind: linear` or `kind: rotary`"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets_mm: [0, 100], cycle: [step]}\n"),
            "m.yaml:2:37: plan.cycle: expected standard, step or pilgrim, got a list of 1 item"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets: {end_mm: 10, count: 3}}\n"),
            "m.yaml:2:17: plan.targets: missing key `start_mm`"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets_mm: [0, 100], feed_mm_per_min: 0}\n"),
            "m.yaml:2:47: plan.feed_mm_per_min must be > 0"
        );
        assert_eq!(
            e("kind: linear\nmodel: {scatter_um: -1}\nplan: {targets_mm: [0, 100]}\n"),
            "m.yaml:2:21: model.scatter_um must be a finite number ≥ 0, found -1"
        );
        assert_eq!(
            e("kind: linear\nmodel: {warm_up_um: 3}\nplan: {targets_mm: [0, 100]}\n"),
            "m.yaml:2:21: model.warm_up_um needs a time constant: add model.warm_up_tau_min (> 0)"
        );
        assert_eq!(
            e(
                "kind: rotary\nmodel: {warm_up_arcsec: 3, warm_up_tau_min: -2}\nplan: {targets_deg: [0, 90]}\n"
            ),
            "m.yaml:2:45: model.warm_up_tau_min must be a finite number ≥ 0, found -2"
        );
        assert_eq!(
            e("kind: rotary\nmodel: {warm_up_um: 3}\nplan: {targets_deg: [0, 90]}\n"),
            "m.yaml:2:9: `model.warm_up_um` has a linear unit, but this is a rotary model; write `warm_up_arcsec`"
        );
        assert_eq!(
            e(""),
            "m.yaml:1:1: expected a mapping with kind, model and plan, got an empty file"
        );
        // Found by fuzzing: an infinite end made every target `inf`, then a panic.
        assert_eq!(
            e("kind: linear\nplan:\n  targets: {start_mm: 10, end_mm: .inf, count: 13}\n"),
            "m.yaml:3:35: plan.targets.end_mm must be a number within ±1000000, found inf"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets_mm: [0, 0.0004], dwell_s: 1}\n"),
            "m.yaml:2:20: plan.targets_mm: targets 0 and 0.0004 are the same position as recorded (to 0.001)"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets_mm: [0, 1e300]}\n"),
            "m.yaml:2:20: plan.targets_mm: targets must be numbers within ±1000000, found 1e300"
        );
        assert_eq!(
            e(
                "kind: rotary\nplan:\n  targets: {start_deg: 0, end_deg: 0.01, count: 11, jitter_deg: 0}\n"
            ),
            "m.yaml:3:12: plan.targets: targets 0.0010 apart, each moved by up to 0 (jitter), can come closer than 0.002, and positions are recorded to 0.001; widen the spacing or lower the jitter"
        );
        assert_eq!(
            e("kind: linear\nplan: {targets_mm: [0, 100], dwell_s: .inf}\n"),
            "m.yaml:2:39: plan.dwell_s must be a finite number ≥ 0"
        );
    }
}
