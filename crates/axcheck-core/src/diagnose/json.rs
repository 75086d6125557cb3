//! The stable JSON of a diagnosis (`diagnose --json`, the `diagnosis` of `results.json`),
//! derived by serde from the typed diagnosis.
//!
//! Top level: `unit` (deviations: `um` or `arcsec`), `position_unit`, `time_unit` (`h`,
//! or `run` without time stamps), `standard`, `findings` (each `effect`, `params` keyed
//! with units, `labels`, `evidence` {`statistic`, `value`, `p_value`, `effect_size`},
//! `message`), `unconfirmed` (the findings of the tests whose term the held-out prediction
//! does not confirm: `effect`, `params`, `labels`, `evidence`, `message`, `scheme`,
//! `gain_pct`, `threshold_pct`, `null`), `base` and `extended` (each `terms`, `heldout_rms`, `heldout_nlpd`,
//! `between_targets_rms`), `gain_pct` (held-out RMS of the readings),
//! `gain_between_targets_pct` (leave-targets-out, when a periodic term was judged),
//! `term_gains` (each judged term: `effect`, `scheme`, `without`, `with`, `gain_pct`,
//! `threshold_pct`, `kept`, `null`: what the gain was compared with — `time_orders`,
//! `ordinary_readings` or `simulated_tests` (`run_orders` and `target_orders` before issue 43); `shape` and
//! `shapes` for a term along the axis: `line`, `curve` or `per_target`, each with its
//! `parameters` and `heldout_rms`), `validation`, `checks`, `model_check` (`verdict`:
//! `explained`, `effects_found`, `not_explained` or `not_checked`; `checks`; `outside`, each
//! `statistic`, `side`, `points_to`, `accounted_for_by`, `seen_unconfirmed`, and `read_as_warm_up` where some are; `sentence`), `detectable` (every effect: `effect`,
//! `size` found in 80 % of tests with this plan, null when the plan cannot test it,
//! `measure` with its unit, `assumed` (the period or time constant the size assumes,
//! keyed with units), `more_targets` and `size_with_more_targets`, `advice`), `corrected`, `residuals`,
//! `base_model` and `extended_model` (simulation files as YAML text, which the caller
//! writes: the core writes no YAML), `notes`.
//! Numbers that do not apply are `null`.

use super::checks::{ModelCheck, describe};
use super::finding::keyed;
use super::{Corrected, Diagnosis, Finding, ModelFit, Residuals, TermGain, Unconfirmed};
use crate::axis_model::Simulation;
use serde::{Serialize, Serializer};

/// Writes a simulation file's text: the caller's (the simulation files' own writer), since
/// the core writes no YAML.
pub type ModelText = fn(&Simulation) -> String;

/// The JSON of a diagnosis ([`Diagnosis::json`]).
#[derive(Serialize)]
pub struct DiagnosisJson<'a> {
    unit: &'static str,
    position_unit: &'static str,
    time_unit: &'static str,
    standard: &'static str,
    findings: &'a [Finding],
    unconfirmed: &'a [Unconfirmed],
    base: &'a ModelFit,
    extended: &'a ModelFit,
    gain_pct: f64,
    gain_between_targets_pct: Option<f64>,
    term_gains: &'a [TermGain],
    validation: &'static str,
    checks: Vec<CheckJson<'a>>,
    model_check: &'a super::ModelVerdict,
    detectable: &'a [super::Detectable],
    corrected: &'a [Corrected],
    residuals: &'a Residuals,
    base_model: String,
    extended_model: String,
    notes: &'a [String],
}

#[derive(Serialize)]
struct CheckJson<'a> {
    statistic: &'a str,
    description: &'static str,
    measured: f64,
    simulated_low: f64,
    simulated_high: f64,
    outside: bool,
    side: Option<&'static str>,
}

impl<'a> From<&'a ModelCheck> for CheckJson<'a> {
    fn from(c: &'a ModelCheck) -> CheckJson<'a> {
        CheckJson {
            statistic: &c.statistic,
            description: describe(&c.statistic),
            measured: c.measured,
            simulated_low: c.simulated_low,
            simulated_high: c.simulated_high,
            outside: c.outside,
            side: c.side,
        }
    }
}

#[derive(Serialize)]
struct MeasuredAndCorrected {
    measured: f64,
    corrected: f64,
}

impl Serialize for Corrected {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct CorrectedJson<'a, P> {
            effect: &'a str,
            parameters: P,
        }
        let parameters = self
            .parameters
            .iter()
            .map(|p| {
                let values = MeasuredAndCorrected {
                    measured: p.measured,
                    corrected: p.corrected,
                };
                (p.key.as_str(), values)
            })
            .collect();
        CorrectedJson {
            effect: &self.effect,
            parameters: keyed(parameters),
        }
        .serialize(s)
    }
}

impl Diagnosis {
    /// The stable JSON of this diagnosis, its base and extended models as simulation files
    /// written by `model_text`.
    pub fn json(&self, model_text: ModelText) -> DiagnosisJson<'_> {
        DiagnosisJson {
            unit: self.kind.deviation_unit(),
            position_unit: self.kind.position_unit(),
            time_unit: self.time_unit.key(),
            standard: self.standard.key(),
            findings: &self.findings,
            unconfirmed: &self.unconfirmed,
            base: &self.base,
            extended: &self.extended,
            gain_pct: self.gain_pct,
            gain_between_targets_pct: self.gain_between_targets_pct,
            term_gains: &self.term_gains,
            validation: self.validation,
            checks: self.checks.iter().map(CheckJson::from).collect(),
            model_check: &self.model_check,
            detectable: &self.detectable,
            corrected: &self.corrected,
            residuals: &self.residuals,
            base_model: model_text(&self.base_model),
            extended_model: model_text(&self.extended_model),
            notes: &self.notes,
        }
    }
}
