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
use serde_json::{Map, Value, json};

fn num(v: f64) -> Value {
    if v.is_finite() { json!(v) } else { Value::Null }
}

fn opt(v: Option<f64>) -> Value {
    v.map_or(Value::Null, num)
}

fn fit(f: &ModelFit) -> Value {
    json!({
        "terms": f.terms,
        "heldout_rms": num(f.heldout_rms),
        "heldout_nlpd": num(f.heldout_nlpd),
        "between_targets_rms": opt(f.between_targets_rms),
    })
}

impl Diagnosis {
    /// The stable JSON interface (see the module documentation of `diagnose::json`).
    pub fn to_json(&self) -> Value {
        let findings: Vec<Value> = self
            .findings
            .iter()
            .map(|f| {
                let mut params = Map::new();
                for (k, v) in &f.params {
                    params.insert(k.clone(), num(*v));
                }
                let mut labels = Map::new();
                for (k, v) in &f.labels {
                    labels.insert(k.clone(), json!(v));
                }
                json!({
                    "effect": f.effect.name(),
                    "params": params,
                    "labels": labels,
                    "evidence": {
                        "statistic": f.evidence.statistic,
                        "value": num(f.evidence.value),
                        "p_value": opt(f.evidence.p_value),
                        "effect_size": opt(f.evidence.effect_size),
                    },
                    "message": f.message,
                })
            })
            .collect();
        let checks: Vec<Value> = self
            .checks
            .iter()
            .map(|c| {
                json!({
                    "statistic": c.statistic,
                    "description": super::checks::describe(&c.statistic),
                    "measured": num(c.measured),
                    "simulated_low": num(c.simulated_low),
                    "simulated_high": num(c.simulated_high),
                    "outside": c.outside,
                    "side": c.side,
                })
            })
            .collect();
        let corrected: Vec<Value> = self
            .corrected
            .iter()
            .map(|c| {
                let mut params = Map::new();
                for p in &c.parameters {
                    params.insert(
                        p.key.clone(),
                        json!({"measured": num(p.measured), "corrected": num(p.corrected)}),
                    );
                }
                json!({"effect": c.effect, "parameters": params})
            })
            .collect();
        let readings: Vec<Value> = self
            .residuals
            .readings
            .iter()
            .map(|r| {
                json!({
                    "order": r.order,
                    "time_s": opt(r.time_s),
                    "position": num(r.position),
                    "direction": r.direction.name(),
                    "run": r.run,
                    "residual": num(r.residual),
                    "extended_residual": num(r.extended_residual),
                })
            })
            .collect();
        let along: Vec<Value> = self
            .residuals
            .along_axis
            .iter()
            .map(|a| {
                json!({
                    "position": num(a.position),
                    "mean": num(a.mean),
                    "trend": num(a.trend),
                    "residual": num(a.residual),
                    "reversal": num(a.reversal),
                })
            })
            .collect();
        let periodogram: Vec<Value> = self
            .residuals
            .periodogram
            .iter()
            .map(|(p, w)| json!({"period": num(*p), "power": num(*w)}))
            .collect();
        json!({
            "unit": self.kind.deviation_unit(),
            "position_unit": self.kind.position_unit(),
            "time_unit": self.time_unit.key(),
            "standard": self.standard.key(),
            "findings": findings,
            "base": fit(&self.base),
            "extended": fit(&self.extended),
            "gain_pct": num(self.gain_pct),
            "gain_between_targets_pct": opt(self.gain_between_targets_pct),
            "validation": self.validation,
            "checks": checks,
            "corrected": corrected,
            "residuals": {
                "readings": readings,
                "along_axis": along,
                "periodogram": periodogram,
            },
            "base_model": self.base_model.to_yaml(),
            "extended_model": self.extended_model.to_yaml(),
            "notes": self.notes,
        })
    }
}
