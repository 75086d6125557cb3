//! The JSON form of an [`Evaluation`]: a stable interface for scripts.
//!
//! ```json
//! {"standard": "iso230-2:1997", "kind": "linear", "unit": "um", "position_unit": "mm",
//!  "n": 5, "m": 11, "coverage_factor": 2.0,
//!  "parameters": {"A": 9.586, "A_up": 6.138, …},
//!  "at_target": {"R": 9, "R_up": 10, "R_down": 10, "B": 2},
//!  "details": [{"key": "A", "label": "A", "name": …, "clause": …, "value": …, "span": [hi, lo]}],
//!  "targets": [{"i": 1, "position": 6.711, "mean": …, "reversal": …, "repeatability": …,
//!               "up": {"deviations": […], "mean": …, "s": …, "range": …, "upper": …,
//!                      "lower": …, "repeatability": …}, "down": {…}}],
//!  "notes": []}
//! ```
//! A parameter or value that does not apply is absent. Target indices `i` are 1-based
//! as in the standards.

use super::{DirectionResult, Evaluation, TargetResult};
use serde_json::{Map, Value, json};

impl Evaluation {
    /// Parameter values keyed by their stable key (absent when not applicable).
    pub fn parameters_json(&self) -> Value {
        let mut map = Map::new();
        for p in &self.parameters {
            map.insert(p.key.to_string(), json!(p.value));
        }
        Value::Object(map)
    }

    /// The whole evaluation as JSON.
    pub fn to_json(&self) -> Value {
        let mut at = Map::new();
        for p in &self.parameters {
            if let Some(i) = p.at_target {
                at.insert(p.key.to_string(), json!(i + 1));
            }
        }
        let details: Vec<Value> = self
            .parameters
            .iter()
            .map(|p| {
                let mut d = Map::new();
                d.insert("key".into(), json!(p.key));
                d.insert("label".into(), json!(p.label));
                d.insert("name".into(), json!(p.name));
                d.insert("clause".into(), json!(p.clause));
                d.insert("value".into(), json!(p.value));
                if let Some(i) = p.at_target {
                    d.insert("target_index".into(), json!(i + 1));
                    d.insert("target_position".into(), json!(self.targets[i].position));
                }
                if let Some((hi, lo)) = p.span {
                    d.insert("span".into(), json!([hi, lo]));
                }
                Value::Object(d)
            })
            .collect();
        json!({
            "standard": self.standard.key(),
            "title": self.standard.title(),
            "kind": self.kind.to_string(),
            "unit": self.unit(),
            "position_unit": self.kind.position_unit(),
            "n": self.n,
            "m": self.targets.len(),
            "coverage_factor": self.coverage_factor,
            "parameters": self.parameters_json(),
            "at_target": Value::Object(at),
            "details": details,
            "targets": self.targets.iter().enumerate().map(|(i, t)| target_json(i, t)).collect::<Vec<_>>(),
            "notes": self.notes,
        })
    }
}

fn direction_json(d: &DirectionResult) -> Value {
    let mut map = Map::new();
    map.insert("deviations".into(), json!(d.deviations));
    map.insert("mean".into(), json!(d.mean));
    for (key, value) in [
        ("s", d.s),
        ("range", d.range),
        ("upper", d.upper),
        ("lower", d.lower),
        ("repeatability", d.repeatability),
    ] {
        if let Some(v) = value {
            map.insert(key.into(), json!(v));
        }
    }
    Value::Object(map)
}

fn target_json(i: usize, t: &TargetResult) -> Value {
    let mut map = Map::new();
    map.insert("i".into(), json!(i + 1));
    map.insert("position".into(), json!(t.position));
    map.insert("mean".into(), json!(t.mean));
    map.insert("reversal".into(), json!(t.reversal));
    if let Some(r) = t.repeatability {
        map.insert("repeatability".into(), json!(r));
    }
    for (key, value) in &t.extra {
        map.insert((*key).to_string(), json!(value));
    }
    map.insert("up".into(), direction_json(&t.up));
    map.insert("down".into(), direction_json(&t.down));
    Value::Object(map)
}
