//! `results.json`: everything, and a stable interface for scripts.
//!
//! Top level: `axcheck` (version), `campaign`, `counts`, `axes`. One entry in `axes` per
//! test of an axis (most axes have one): `machine`, `axis`, `test`, `tests`, `file`,
//! `kind`, `standard`, `unit`, `n`, `verdict` (`pass`/`fail`/`noncompliant`/`error`),
//! `parameters` (keyed as in `axcheck eval --json`), `limits`, `checks`, `rules`
//! (`{id, clause, severity, message}`), `conditions`, `nde`, and `error` with the message
//! when the verdict is `error`. No time stamps or absolute paths: the same campaign gives
//! the same bytes.

use super::{ExportError, Exporter, OutputFile};
use crate::batch::{AxisTest, CampaignResult};
use serde_json::{Map, Value, json};

pub struct Json;

/// The JSON of one test.
pub fn test_json(t: &AxisTest) -> Value {
    let mut m = Map::new();
    m.insert("machine".into(), json!(t.machine.id));
    m.insert(
        "machine_info".into(),
        serde_json::to_value(&*t.machine).unwrap_or(Value::Null),
    );
    m.insert("axis".into(), json!(t.axis));
    m.insert("test".into(), json!(t.test));
    m.insert("tests".into(), json!(t.tests));
    m.insert("file".into(), json!(t.file));
    m.insert("kind".into(), json!(t.kind().map(|k| k.to_string())));
    m.insert("standard".into(), json!(t.standard().map(|s| s.key())));
    m.insert("unit".into(), json!(t.kind().map(|k| k.deviation_unit())));
    m.insert(
        "position_unit".into(),
        json!(t.kind().map(|k| k.position_unit())),
    );
    if let Some(spec) = &t.spec {
        m.insert(
            "travel".into(),
            serde_json::to_value(spec.raw.travel).unwrap_or(Value::Null),
        );
        m.insert(
            "declared_measurement_travel".into(),
            json!(spec.raw.measurement_travel),
        );
        m.insert(
            "conditions".into(),
            serde_json::to_value(&spec.raw.conditions).unwrap_or(Value::Null),
        );
    }
    if let Some(d) = &t.data {
        let (a, b) = d.measurement_travel();
        m.insert("measurement_travel".into(), json!([a, b]));
        m.insert("readings".into(), json!(d.readings.len()));
    }
    m.insert("verdict".into(), json!(t.verdict.name()));
    if let Some(e) = &t.evaluation {
        m.insert("n".into(), json!(e.n));
        m.insert("m".into(), json!(e.targets.len()));
        use crate::evaluate::json::{ParameterValues, TargetIndices};
        m.insert("parameters".into(), json!(ParameterValues(&e.parameters)));
        m.insert("at_target".into(), json!(TargetIndices(&e.parameters)));
        m.insert("notes".into(), json!(e.notes));
    }
    if let Some(j) = &t.judgement {
        m.insert("spec".into(), json!(j.limits.spec));
        let limits: Map<String, Value> = j
            .limits
            .values
            .iter()
            .map(|(k, (v, _))| (k.clone(), json!(v)))
            .collect();
        m.insert("limits".into(), Value::Object(limits));
        m.insert(
            "checks".into(),
            serde_json::to_value(&j.checks).unwrap_or(Value::Null),
        );
        m.insert(
            "failed".into(),
            json!(j.failed().map(|c| c.key.clone()).collect::<Vec<_>>()),
        );
        m.insert("not_applicable_limits".into(), json!(j.not_applicable));
        m.insert("no_tolerance".into(), json!(j.limits.is_empty()));
    }
    m.insert(
        "rules".into(),
        serde_json::to_value(&t.findings).unwrap_or(Value::Null),
    );
    m.insert(
        "nde".into(),
        serde_json::to_value(&t.nde).unwrap_or(Value::Null),
    );
    if let Some(d) = &t.diagnosis {
        m.insert("diagnosis".into(), json!(d));
    }
    if let Some(e) = &t.error {
        m.insert("error".into(), json!(e));
    }
    Value::Object(m)
}

/// The whole `results.json` value.
/// Everything of `results.json` but the axes (`"axes": []`, last).
fn results_head(result: &CampaignResult) -> Value {
    let mut campaign = serde_json::to_value(&result.info).unwrap_or(Value::Null);
    if let Some(c) = campaign.as_object_mut() {
        c.insert("file".into(), json!(result.file_name));
        c.insert("standard".into(), json!(result.standard.key()));
    }
    let counts: Map<String, Value> = result
        .counts()
        .into_iter()
        .map(|(v, n)| (v.name().to_string(), json!(n)))
        .collect();
    json!({
        "axcheck": env!("CARGO_PKG_VERSION"),
        "campaign": campaign,
        "counts": counts,
        "axes": [],
    })
}

/// `results.json`, pretty-printed: the axes are serialised in parallel (1 000 axes are
/// 48 MB, 0.8 s of one core) and set into the head as `to_vec_pretty` would place them.
pub fn results_json(result: &CampaignResult) -> Result<Vec<u8>, serde_json::Error> {
    use rayon::prelude::*;
    let axes: Vec<Vec<u8>> = result
        .tests
        .par_iter()
        .map(|t| serde_json::to_vec_pretty(&test_json(t)))
        .collect::<Result<_, _>>()?;
    let mut out = serde_json::to_vec_pretty(&results_head(result))?;
    let empty = b"\"axes\": []\n}";
    if axes.is_empty() || !out.ends_with(empty) {
        return Ok(out);
    }
    out.truncate(out.len() - b"[]\n}".len());
    out.reserve(axes.iter().map(|a| a.len() + a.len() / 8).sum());
    out.extend_from_slice(b"[\n");
    for (i, axis) in axes.iter().enumerate() {
        // An element of the top-level object's array: four spaces deeper than standalone.
        out.extend_from_slice(b"    ");
        for &byte in axis {
            out.push(byte);
            if byte == b'\n' {
                out.extend_from_slice(b"    ");
            }
        }
        out.extend_from_slice(if i + 1 < axes.len() { b",\n" } else { b"\n" });
    }
    out.extend_from_slice(b"  ]\n}");
    Ok(out)
}

impl Exporter for Json {
    fn name(&self) -> &'static str {
        "json"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        let mut bytes = results_json(result).map_err(|e| ExportError::Format {
            format: "json",
            message: e.to_string(),
        })?;
        bytes.push(b'\n');
        Ok(vec![OutputFile {
            path: "results.json".into(),
            bytes,
        }])
    }
}
