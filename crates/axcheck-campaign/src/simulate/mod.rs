//! The axis simulator's files: a simulation (the axis model of [`crate::axis_model`]: an
//! error model and a test plan) read from and written to YAML with the axis kind's units,
//! and synthetic fleets for benchmarks ([`fleet`]).

pub mod fleet;
mod yaml;

// The model's names, where the simulator's users found them before it had its own module.
pub use crate::axis_model::{
    Cycle, ErrorModel, InvalidSimulation, PeriodicTerm, PlantedOutlier, Simulation, Step,
    TargetSpacing, TestPlan, Visit, model, plan, rng,
};

/// A simulation file that cannot be used: `file:line:column: message`.
pub(crate) type SimulationError = crate::yaml::YamlError;

/// A simulation as a file: read from and written to YAML with the axis kind's units (the
/// core's [`Simulation`] knows no YAML).
pub trait SimulationFile: Sized {
    /// Parses and checks a simulation file; `file` names it in errors.
    fn from_yaml(text: &str, file: &str) -> Result<Self, SimulationError>;
    /// The simulation file text, keys spelled with the kind's units.
    fn to_yaml(&self) -> String;
    /// [`Simulation::validate`] with the keys spelled as the written file spells them
    /// (`plan.targets_mm`), for a model made in code before it is written.
    fn validate_as_written(&self) -> Result<(), InvalidSimulation>;
}

/// The text of a simulation file, for [`crate::diagnose::Diagnosis::json`].
pub fn model_text(sim: &Simulation) -> String {
    sim.to_yaml()
}

impl SimulationFile for Simulation {
    fn from_yaml(text: &str, file: &str) -> Result<Simulation, SimulationError> {
        let (value, index) = crate::yaml::parse(text, file)?;
        let fail = |located: crate::yaml::Located| located.in_file(file);
        let kind = yaml::kind(&value, &index).map_err(fail)?;
        yaml::check_keys(&value, kind, &index).map_err(fail)?;
        let spell = |path: &str, field: &str| yaml::spell(path, field, kind);
        let sim: Simulation =
            crate::yaml::deserialize_spelled(&value, "", &index, &spell).map_err(fail)?;
        sim.validate()
            .map_err(|invalid| fail(yaml::locate(&invalid.0, kind, &index)))?;
        Ok(sim)
    }

    fn to_yaml(&self) -> String {
        let value = serde_norway::to_value(self).expect("a simulation serialises");
        let value = yaml::externalize(value, self.kind);
        serde_norway::to_string(&value).expect("a YAML value serialises")
    }

    fn validate_as_written(&self) -> Result<(), InvalidSimulation> {
        self.validate()
            .map_err(|invalid| InvalidSimulation(yaml::respell(&invalid.0, self.kind).0))
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
