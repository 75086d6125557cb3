//! The stable JSON of a diagnosis.
//!
//! Top level: `unit` (deviations: `um` or `arcsec`), `position_unit`, `time_unit` (`h`,
//! or `run` without time stamps), `standard`, `findings` (each `effect`, `params` keyed
//! with units, `labels`, `evidence` {`statistic`, `value`, `p_value`, `effect_size`},
//! `message`), `base` and `extended` (each `terms`, `heldout_rms`, `heldout_nlpd`,
//! `between_targets_rms`), `gain_pct` (held-out RMS of the readings),
//! `gain_between_targets_pct` (leave-one-target-out, when a periodic term was judged),
//! `validation`, `checks`, `corrected`, `residuals`,
//! `base_model` and `extended_model` (simulation files as YAML text), `notes`.
//! Numbers that do not apply are `null`.

use super::{Diagnosis, ModelFit};
use serde_json::{Map, Value};

fn num(v: f64) -> Value {
    if v.is_finite() {
        Value::from(v)
    } else {
        Value::Null
    }
}

fn opt(v: Option<f64>) -> Value {
    v.map_or(Value::Null, num)
}

/// An object with `entries` in order: what `json!({...})` builds, with its map sized
/// once (the per-reading and per-frequency objects are most of the diagnosis JSON).
fn object<const N: usize>(entries: [(&str, Value); N]) -> Value {
    let mut m = Map::with_capacity(N);
    for (k, v) in entries {
        m.insert(k.to_string(), v);
    }
    Value::Object(m)
}

fn fit(f: &ModelFit) -> Value {
    object([
        ("terms", strings(&f.terms)),
        ("heldout_rms", num(f.heldout_rms)),
        ("heldout_nlpd", num(f.heldout_nlpd)),
        ("between_targets_rms", opt(f.between_targets_rms)),
    ])
}

fn strings(v: &[String]) -> Value {
    Value::Array(v.iter().map(|s| Value::from(s.as_str())).collect())
}

impl Diagnosis {
    /// The stable JSON interface (see the module documentation of `diagnose::json`).
    ///
    /// Built by moving each part into its place: `json!` would copy every value given to
    /// it (by serialising it again), the per-reading objects included.
    pub fn to_json(&self) -> Value {
        let findings: Vec<Value> = self
            .findings
            .iter()
            .map(|f| {
                let mut params = Map::with_capacity(f.params.len());
                for (k, v) in &f.params {
                    params.insert(k.clone(), num(*v));
                }
                let mut labels = Map::with_capacity(f.labels.len());
                for (k, v) in &f.labels {
                    labels.insert(k.clone(), Value::from(v.as_str()));
                }
                object([
                    ("effect", Value::from(f.effect.name())),
                    ("params", Value::Object(params)),
                    ("labels", Value::Object(labels)),
                    (
                        "evidence",
                        object([
                            ("statistic", Value::from(f.evidence.statistic.as_str())),
                            ("value", num(f.evidence.value)),
                            ("p_value", opt(f.evidence.p_value)),
                            ("effect_size", opt(f.evidence.effect_size)),
                        ]),
                    ),
                    ("message", Value::from(f.message.as_str())),
                ])
            })
            .collect();
        let checks: Vec<Value> = self
            .checks
            .iter()
            .map(|c| {
                object([
                    ("statistic", Value::from(c.statistic.as_str())),
                    (
                        "description",
                        Value::from(super::checks::describe(&c.statistic)),
                    ),
                    ("measured", num(c.measured)),
                    ("simulated_low", num(c.simulated_low)),
                    ("simulated_high", num(c.simulated_high)),
                    ("outside", Value::Bool(c.outside)),
                    ("side", c.side.map_or(Value::Null, Value::from)),
                ])
            })
            .collect();
        let corrected: Vec<Value> = self
            .corrected
            .iter()
            .map(|c| {
                let mut params = Map::with_capacity(c.parameters.len());
                for p in &c.parameters {
                    params.insert(
                        p.key.clone(),
                        object([
                            ("measured", num(p.measured)),
                            ("corrected", num(p.corrected)),
                        ]),
                    );
                }
                object([
                    ("effect", Value::from(c.effect.as_str())),
                    ("parameters", Value::Object(params)),
                ])
            })
            .collect();
        let readings: Vec<Value> = self
            .residuals
            .readings
            .iter()
            .map(|r| {
                object([
                    ("order", Value::from(r.order)),
                    ("time_s", opt(r.time_s)),
                    ("position", num(r.position)),
                    ("direction", Value::from(r.direction.name())),
                    ("run", Value::from(r.run)),
                    ("residual", num(r.residual)),
                    ("extended_residual", num(r.extended_residual)),
                ])
            })
            .collect();
        let along: Vec<Value> = self
            .residuals
            .along_axis
            .iter()
            .map(|a| {
                object([
                    ("position", num(a.position)),
                    ("mean", num(a.mean)),
                    ("trend", num(a.trend)),
                    ("residual", num(a.residual)),
                    ("reversal", num(a.reversal)),
                ])
            })
            .collect();
        let periodogram: Vec<Value> = self
            .residuals
            .periodogram
            .iter()
            .map(|(p, w)| object([("period", num(*p)), ("power", num(*w))]))
            .collect();
        object([
            ("unit", Value::from(self.kind.deviation_unit())),
            ("position_unit", Value::from(self.kind.position_unit())),
            ("time_unit", Value::from(self.time_unit.key())),
            ("standard", Value::from(self.standard.key())),
            ("findings", Value::Array(findings)),
            ("base", fit(&self.base)),
            ("extended", fit(&self.extended)),
            ("gain_pct", num(self.gain_pct)),
            (
                "gain_between_targets_pct",
                opt(self.gain_between_targets_pct),
            ),
            ("validation", Value::from(self.validation)),
            ("checks", Value::Array(checks)),
            ("corrected", Value::Array(corrected)),
            (
                "residuals",
                object([
                    ("readings", Value::Array(readings)),
                    ("along_axis", Value::Array(along)),
                    ("periodogram", Value::Array(periodogram)),
                ]),
            ),
            ("base_model", Value::from(self.base_model.to_yaml())),
            ("extended_model", Value::from(self.extended_model.to_yaml())),
            ("notes", strings(&self.notes)),
        ])
    }
}
