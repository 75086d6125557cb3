//! What the report templates show, as JSON: every number already formatted, every label
//! in words. The templates only lay out; they compute nothing and evaluate no user text.

use super::charts::{AxisChart, DirectionSeries, Span};
use crate::batch::{AxisTest, CampaignResult};
use crate::campaign::{Conditions, SensorKind};
use crate::evaluate::{DirectionResult, Evaluation, Role, StandardId};
use crate::judge::Verdict;
use crate::rules::Severity;
use crate::units::Travel;
use crate::units::{AxisKind, fmt_fixed, fmt_position};
use serde_json::{Value, json};

/// Deviation values in reports: 2 decimals (0.01 µm / 0.01″).
pub(super) fn num(x: f64) -> String {
    fmt_fixed(x, 2).replace('-', "−")
}

fn opt(x: Option<f64>) -> String {
    x.map_or("–".into(), num)
}

fn pos(kind: AxisKind, x: f64) -> String {
    match kind {
        AxisKind::Linear => format!("{} mm", fmt_position(x).replace('-', "−")),
        AxisKind::Rotary => format!("{}°", fmt_position(x).replace('-', "−")),
    }
}

/// Words for a verdict.
fn verdict_json(t: &AxisTest) -> Value {
    let detail = match t.verdict {
        Verdict::Pass if t.no_tolerance() => {
            "No tolerance applied: evaluated and checked against the test-plan rules only."
                .to_string()
        }
        Verdict::Pass => {
            let n = t.judgement.as_ref().map_or(0, |j| j.checks.len());
            format!("All {n} limited parameters are within tolerance.")
        }
        Verdict::Fail => {
            let failed: Vec<String> = t
                .judgement
                .iter()
                .flat_map(|j| j.failed())
                .map(|c| label_of(t, &c.key))
                .collect();
            format!("Over the limit: {}.", failed.join(", "))
        }
        Verdict::Noncompliant => {
            let ids: Vec<&str> = t
                .findings
                .iter()
                .filter(|f| f.severity == Severity::Error)
                .map(|f| f.id)
                .collect();
            format!(
                "The test does not follow the standard's plan ({}): its results cannot be used for acceptance.",
                ids.join(", ")
            )
        }
        Verdict::Error => t.error.clone().unwrap_or_default(),
    };
    json!({"key": t.verdict.name(), "word": t.verdict.name().to_uppercase(), "detail": detail})
}

fn label_of(t: &AxisTest, key: &str) -> String {
    t.evaluation
        .as_ref()
        .and_then(|e| e.parameter(key))
        .map_or(key.to_string(), |p| p.symbol().to_string())
}

/// Clause 7.1 items the campaign gives, in the standard's order, as (label, text).
fn conditions_json(c: &Conditions, kind: AxisKind, t: &AxisTest) -> Vec<Value> {
    let mut rows: Vec<(String, String)> = Vec::new();
    let mut add = |label: &str, value: Option<String>| {
        if let Some(v) = value.filter(|v| !v.trim().is_empty()) {
            rows.push((label.to_string(), v));
        }
    };
    if let Some(i) = &c.instrument {
        let mut name = i.name.clone().unwrap_or_default();
        if let Some(s) = &i.serial {
            name = format!("{name}, s/n {s}");
        }
        add("Measuring instrument", Some(name));
        add("Position of the instrument", i.position.clone());
    }
    add(
        "Test equipment",
        (!c.equipment.is_empty()).then(|| c.equipment.join("; ")),
    );
    add("Positioning element", c.positioning_element.clone());
    let nde = match (&t.nde, &c.nde) {
        (Some(n), _) => Some(format!(
            "applied by axcheck to 20 °C: α = {} µm/(m·°C), mean temperature {} °C from {}; largest correction {} µm",
            fmt_position(n.coefficient_um_per_m_c),
            fmt_fixed(n.mean_temperature_c, 2),
            n.source,
            fmt_fixed(n.max_correction_um, 2)
        )),
        (None, Some(n)) if n.corrected => Some(format!(
            "yes, in the data (by the instrument){}",
            n.coefficient_um_per_m_c.map_or(String::new(), |a| format!(
                "; α = {} µm/(m·°C)",
                fmt_position(a)
            ))
        )),
        (None, Some(n)) => Some(format!(
            "not applied (no temperature given){}",
            n.coefficient_um_per_m_c.map_or(String::new(), |a| format!(
                "; α = {} µm/(m·°C)",
                fmt_position(a)
            ))
        )),
        (None, None) => None,
    };
    add("NDE correction (3.1)", nde);
    let per_min = match kind {
        AxisKind::Linear => "mm/min",
        AxisKind::Rotary => "°/min",
    };
    add(
        "Feed rate",
        c.feed_mm_per_min
            .map(|f| format!("{} {per_min}", fmt_position(f))),
    );
    add(
        "Dwell at each target",
        c.dwell_s.map(|d| format!("{} s", fmt_position(d))),
    );
    add("Compensation active (3.2)", c.compensation.clone());
    add("Positions of the other axes (3.2)", c.other_axes.clone());
    add("Tool offset", c.tool_offset.clone());
    add("Workpiece offset", c.workpiece_offset.clone());
    add("Warm-up (3.3)", c.warm_up.clone());
    add(
        "Test cycle",
        c.cycle.map(|cy| {
            match cy {
                crate::simulate::Cycle::Standard => "standard test cycle (ISO 230-2 Fig. 1)",
                crate::simulate::Cycle::Step => "step cycle (ISO 230-2 Annex A)",
                crate::simulate::Cycle::Pilgrim => "pilgrim-step cycle (GOST 27843 Черт. 2)",
            }
            .to_string()
        }),
    );
    if let Some(a) = &c.air {
        let mut parts = Vec::new();
        if a.temperature_start_c.is_some() || a.temperature_end_c.is_some() {
            parts.push(format!(
                "{} → {} °C",
                a.temperature_start_c
                    .map_or("–".into(), |t| fmt_fixed(t, 1)),
                a.temperature_end_c.map_or("–".into(), |t| fmt_fixed(t, 1))
            ));
        }
        if let Some(p) = a.pressure_kpa {
            parts.push(format!("{} kPa", fmt_position(p)));
        }
        if let Some(h) = a.humidity_pct {
            parts.push(format!("{} % RH", fmt_position(h)));
        }
        add("Air (start → end)", Some(parts.join(", ")));
    }
    add("Pressure of air or oil", c.fluid_pressure.clone());
    if let Some(e) = &t.evaluation {
        add(
            "Approaches per direction",
            Some(format!(
                "n = {} at each of {} targets",
                e.n,
                e.targets.len()
            )),
        );
    }
    add("Notes", c.notes.clone());
    rows.into_iter()
        .map(|(l, v)| json!({"label": l, "value": v}))
        .collect()
}

fn sensors_json(c: &Conditions) -> Vec<Value> {
    c.temperature_sensors
        .iter()
        .map(|s| {
            json!({
                "name": s.name,
                "kind": match s.kind { SensorKind::Material => "material", SensorKind::Air => "air" },
                "position": s.position.clone().unwrap_or_default(),
                "start": s.start_c.map_or("–".into(), |t| format!("{} °C", fmt_fixed(t, 1))),
                "end": s.end_c.map_or("–".into(), |t| format!("{} °C", fmt_fixed(t, 1))),
            })
        })
        .collect()
}

/// The parameters of the standard with value, limit, margin and status, plus the
/// not-applicable ones of clause 5.2.
fn parameters_json(t: &AxisTest, e: &Evaluation) -> Vec<Value> {
    let kind = e.kind;
    let mut rows: Vec<Value> = e
        .parameters
        .iter()
        .map(|p| {
            let check = t
                .judgement
                .as_ref()
                .and_then(|j| j.checks.iter().find(|c| c.key == p.key()));
            let at = if let Some(i) = p.at_target {
                format!("at i = {} ({})", i + 1, pos(kind, e.targets[i].position))
            } else if let Some((hi, lo)) = p.span {
                format!("{} − ({})", num(hi), num(lo))
            } else {
                String::new()
            };
            json!({
                "symbol": p.symbol(),
                "name": p.name(),
                "clause": p.clause().replace(" (GB/T 17421.2 amendment No. 1)", ", amd. 1"),
                "value": num(p.value),
                "limit": check.map_or("–".into(), |c| num(c.limit)),
                "margin": check.map_or("–".into(), |c| num(c.margin)),
                "status": check.map_or("", |c| if c.pass { "pass" } else { "fail" }),
                "at": at,
            })
        })
        .collect();
    for def in e.not_applicable() {
        let clause = match e.standard {
            StandardId::Iso230_2 | StandardId::Gbt17421_2 => "ISO 230-2 5.2",
            _ => def.clause,
        };
        rows.push(json!({
            "symbol": def.symbol, "name": def.name, "clause": clause,
            "value": "not applicable", "limit": "–", "margin": "–", "status": "n/a",
            "at": format!("n = {}", e.n),
        }));
    }
    rows
}

fn direction_json(d: &DirectionResult, k: f64) -> Value {
    json!({
        "x": d.deviations.iter().map(|&x| num(x)).collect::<Vec<_>>(),
        "mean": num(d.mean),
        "s": opt(d.s),
        "ks": opt(d.s.map(|s| k * s)),
        "upper": opt(d.upper),
        "lower": opt(d.lower),
        "r": opt(d.repeatability),
    })
}

fn targets_json(e: &Evaluation) -> Vec<Value> {
    let k = e.coverage_factor;
    e.targets
        .iter()
        .enumerate()
        .map(|(i, t)| {
            json!({
                "i": (i + 1).to_string(),
                "position": fmt_position(t.position).replace('-', "−"),
                "up": direction_json(&t.up, k),
                "down": direction_json(&t.down, k),
                "b": num(t.reversal),
                "r": opt(t.repeatability),
                "mean": num(t.mean),
            })
        })
        .collect()
}

/// The chart data of an evaluation (ISO 230-2 Fig. 2a/2b).
pub fn axis_chart(e: &Evaluation) -> (AxisChart, Vec<Span>, Vec<Span>) {
    let series = |d: crate::units::Direction| {
        let r: Vec<&DirectionResult> = e.targets.iter().map(|t| t.direction(d)).collect();
        let all = |f: &dyn Fn(&DirectionResult) -> Option<f64>| {
            r.iter().map(|x| f(x)).collect::<Option<Vec<f64>>>()
        };
        DirectionSeries {
            mean: r.iter().map(|x| x.mean).collect(),
            upper: all(&|x| x.upper),
            lower: all(&|x| x.lower),
            deviations: r.iter().map(|x| x.deviations.clone()).collect(),
        }
    };
    let span = |key: &str| {
        e.parameter(key).and_then(|p| {
            p.span.map(|(upper, lower)| Span {
                label: p.symbol().to_string(),
                upper,
                lower,
            })
        })
    };
    let spans = |keys: &[&str]| keys.iter().filter_map(|k| span(k)).collect::<Vec<_>>();
    let (pos_unit, dev_unit) = match e.kind {
        AxisKind::Linear => ("mm", "µm"),
        AxisKind::Rotary => ("°", "arcsec"),
    };
    let s = match e.standard {
        StandardId::Vdi3441 | StandardId::Nmtba => "σ",
        _ => "S",
    };
    let chart = AxisChart {
        positions: e.targets.iter().map(|t| t.position).collect(),
        position_label: format!("Target position Pi / {pos_unit}"),
        deviation_label: format!("Positional deviation / {dev_unit}"),
        up: series(crate::units::Direction::Up),
        down: series(crate::units::Direction::Down),
        mean: e.targets.iter().map(|t| t.mean).collect(),
        band_label: format!("X̄ ± {}{s}", e.coverage_factor),
        spans: spans(&["A", "E", "M"]),
    };
    (
        chart,
        spans(&["A_up", "E_up"]),
        spans(&["A_down", "E_down"]),
    )
}

/// The campaign header both templates show (absent items as empty strings).
fn campaign_json(result: &CampaignResult) -> Value {
    let info = &result.info;
    json!({
        "name": info.name,
        "site": info.site.clone().unwrap_or_default(),
        "purpose": info.purpose.clone().unwrap_or_default(),
        "date": info.date.clone().unwrap_or_default(),
        "inspector": info.inspector.clone().unwrap_or_default(),
        "file": result.file_name,
        "standard": result.standard.title(),
    })
}

/// The data of one axis report.
pub fn axis_report(result: &CampaignResult, t: &AxisTest) -> Value {
    let info = &result.info;
    let m = &t.machine;
    let kind = t.kind();
    let travel = t
        .spec
        .as_ref()
        .and_then(|s| s.raw.travel)
        .zip(kind)
        .map(|(tr, k)| match tr {
            Travel::Length(l) => pos(k, l),
            Travel::Range([a, b]) => format!("{} … {}", pos(k, a), pos(k, b)),
        });
    let measured = t.data.as_ref().map(|d| {
        let (a, b) = d.measurement_travel();
        format!("{} … {}", pos(d.kind, a), pos(d.kind, b))
    });
    let mut facts: Vec<Value> = Vec::new();
    let mut fact = |label: &str, value: Option<String>| {
        if let Some(v) = value.filter(|v| !v.is_empty()) {
            facts.push(json!({"label": label, "value": v}));
        }
    };
    fact("Machine", Some(m.id.clone()));
    fact("Model", m.model.clone());
    fact("Serial number", m.serial.clone());
    fact("Type", m.machine_type.clone());
    fact("Location", m.location.clone());
    fact(
        "Axis",
        Some(format!(
            "{}{}",
            t.axis,
            kind.map_or(String::new(), |k| format!(" ({k})"))
        )),
    );
    fact("Axis travel", travel);
    fact("Measurement travel", measured);
    fact("Measurement file", t.file.clone());
    if t.tests > 1 {
        fact(
            "Test",
            Some(format!("{} of {} tests of this axis", t.test, t.tests)),
        );
    }
    fact("Standard", t.standard().map(|s| s.title().to_string()));
    fact(
        "Acceptance spec",
        t.judgement.as_ref().map(|j| j.limits.describe()),
    );
    fact("Test date", info.date.clone());
    fact("Inspector", info.inspector.clone());
    let conditions = t.spec.as_ref().map(|s| &s.raw.conditions);
    json!({
        "campaign": campaign_json(result),
        "title": format!("{} — axis {}", m.id, t.axis),
        "facts": facts,
        "verdict": verdict_json(t),
        "unit": kind.map_or("", |k| k.deviation_symbol()),
        "conditions": match (conditions, kind) {
            (Some(c), Some(k)) => conditions_json(c, k, t),
            _ => Vec::new(),
        },
        "sensors": conditions.map_or(Vec::new(), sensors_json),
        "parameters": t.evaluation.as_ref().map_or(Vec::new(), |e| parameters_json(t, e)),
        "coverage": t.evaluation.as_ref().map_or(String::new(), |e| fmt_position(e.coverage_factor)),
        "s_symbol": match t.standard() { Some(StandardId::Vdi3441 | StandardId::Nmtba) => "σ", _ => "S" },
        "n": t.evaluation.as_ref().map_or(0, |e| e.n),
        "targets": t.evaluation.as_ref().map_or(Vec::new(), targets_json),
        "notes": t.evaluation.as_ref().map_or(Vec::new(), |e| e.notes.clone()),
        "findings": t.findings.iter().map(|f| json!({
            "id": f.id,
            "clause": f.clause,
            "severity": match f.severity { Severity::Error => "error", Severity::Warning => "warning" },
            "message": f.message,
        })).collect::<Vec<_>>(),
        "has_charts": t.evaluation.is_some(),
        "diagnosis": t.diagnosis.as_ref().map(super::diagnosis_data::diagnosis_json),
        "generator": format!("axcheck {}", env!("CARGO_PKG_VERSION")),
    })
}

/// Summary rows sorted so that what needs attention comes first.
pub fn summary(result: &CampaignResult) -> Value {
    let mut tests: Vec<&AxisTest> = result.tests.iter().collect();
    tests.sort_by_key(|t| t.verdict.attention_rank());
    let rows: Vec<Value> = tests
        .iter()
        .map(|t| {
            let e = t.evaluation.as_ref();
            let v = |role: Role| e.and_then(|e| e.headline(role)).map_or("–".to_string(), |p| num(p.value));
            let travel = t.data.as_ref().map_or("–".into(), |d| {
                let (a, b) = d.measurement_travel();
                pos(d.kind, ((b - a) * 1e6).round() / 1e6)
            });
            let worst = t.judgement.as_ref().and_then(|j| j.worst()).map_or(
                if t.no_tolerance() && t.evaluation.is_some() { "no tolerance".to_string() } else { "–".to_string() },
                |c| format!("{} {}", label_of(t, &c.key), fmt_fixed(c.ratio(), 2)),
            );
            json!({
                "machine": t.machine.id,
                "axis": if t.tests > 1 { format!("{} ({}/{})", t.axis, t.test, t.tests) } else { t.axis.clone() },
                "travel": travel,
                "n": e.map_or("–".into(), |e| e.n.to_string()),
                "a": v(Role::Accuracy),
                "e": v(Role::Systematic),
                "r": v(Role::Repeatability),
                "b": v(Role::Reversal),
                "unit": t.kind().map_or("", |k| k.deviation_symbol()),
                "worst": worst,
                "diagnosis": t.diagnosis.as_ref().map_or("–".to_string(), |d| d.effects_label().replace('_', " ")),
                "verdict": t.verdict.name(),
            })
        })
        .collect();
    let counts = result.counts();
    json!({
        "campaign": campaign_json(result),
        "counts": {
            "total": result.tests.len(),
            "pass": counts[&Verdict::Pass],
            "fail": counts[&Verdict::Fail],
            "noncompliant": counts[&Verdict::Noncompliant],
            "error": counts[&Verdict::Error],
        },
        "rows": rows,
        "errors": result.tests.iter().filter(|t| t.verdict == Verdict::Error).map(|t| json!({
            "label": t.label(),
            "message": t.error.clone().unwrap_or_default(),
        })).collect::<Vec<_>>(),
        "noncompliant": result.tests.iter().filter(|t| t.verdict == Verdict::Noncompliant).map(|t| json!({
            "label": t.label(),
            "message": t.findings.iter().filter(|f| f.severity == Severity::Error).map(|f| format!("{} ({}): {}", f.id, f.clause, f.message)).collect::<Vec<_>>().join("; "),
        })).collect::<Vec<_>>(),
        "has_chart": result.tests.iter().any(|t| t.judgement.as_ref().and_then(|j| j.worst()).is_some()),
        "generator": format!("axcheck {}", env!("CARGO_PKG_VERSION")),
    })
}
