//! The test conditions of ISO 230-2 clause 7.1 that the campaign gives, in the standard's
//! order, and the temperature sensors.

use crate::axis_model::Cycle;
use crate::campaign::{Air, Conditions, InstrumentEntry, Nde, SensorKind, TemperatureSensor};
use crate::nde::NdeCorrection;
use crate::results::AxisTest;
use crate::units::{AxisKind, fmt_fixed, fmt_position};
use serde::Serialize;

/// A labelled line: a header fact or a test condition.
#[derive(Debug, Serialize)]
pub(super) struct Row {
    label: &'static str,
    value: String,
}

impl Row {
    /// The rows whose value is given and not blank, in order.
    pub(super) fn present<const N: usize>(rows: [(&'static str, Option<String>); N]) -> Vec<Row> {
        rows.into_iter()
            .filter_map(|(label, value)| {
                let value = value.filter(|v| !v.trim().is_empty())?;
                Some(Row { label, value })
            })
            .collect()
    }
}

/// Clause 7.1 items the campaign gives, in the standard's order.
pub(super) fn condition_rows(c: &Conditions, kind: AxisKind, t: &AxisTest) -> Vec<Row> {
    let (instrument, position) = c.instrument.as_ref().map_or((None, None), instrument);
    let per_min = match kind {
        AxisKind::Linear => "mm/min",
        AxisKind::Rotary => "°/min",
    };
    let approaches = t
        .evaluated()
        .map(|e| &e.evaluation)
        .map(|e| format!("n = {} at each of {} targets", e.n, e.targets.len()));
    Row::present([
        ("Measuring instrument", instrument),
        ("Position of the instrument", position),
        (
            "Test equipment",
            (!c.equipment.is_empty()).then(|| c.equipment.join("; ")),
        ),
        ("Positioning element", c.positioning_element.clone()),
        (
            "NDE correction (3.1)",
            nde(t.evaluated().and_then(|e| e.nde.as_ref()), c.nde.as_ref()),
        ),
        (
            "Feed rate",
            c.feed_mm_per_min
                .map(|f| format!("{} {per_min}", fmt_position(f))),
        ),
        (
            "Dwell at each target",
            c.dwell_s.map(|d| format!("{} s", fmt_position(d))),
        ),
        ("Compensation active (3.2)", c.compensation.clone()),
        ("Positions of the other axes (3.2)", c.other_axes.clone()),
        ("Tool offset", c.tool_offset.clone()),
        ("Workpiece offset", c.workpiece_offset.clone()),
        ("Warm-up (3.3)", c.warm_up.clone()),
        ("Test cycle", c.cycle.map(|cy| cycle(cy).to_string())),
        ("Air (start → end)", c.air.as_ref().map(air)),
        ("Pressure of air or oil", c.fluid_pressure.clone()),
        ("Approaches per direction", approaches),
        ("Measurement file read as", t.recognised().map(read_as)),
        (
            "Taken from the measurement file",
            (t.evaluated().map(|e| e.conditions_from_file.join(", "))).filter(|s| !s.is_empty()),
        ),
        ("Notes", c.notes.clone()),
    ])
    .into_iter()
    .chain(not_stated(t))
    .collect()
}

/// A row "not stated" for each clause 7.1 item neither the campaign nor the file states,
/// in the clause's order.
fn not_stated(t: &AxisTest) -> Vec<Row> {
    let unstated = t.evaluated().map_or(&[][..], |e| &e.unstated);
    (unstated.iter())
        .map(|label| Row {
            label,
            value: "not stated".to_string(),
        })
        .collect()
}

/// The layout the file was read as, then what was assumed or skipped: `wide CSV; 11
/// targets × 5 runs per direction; order of measurement assumed: …`.
fn read_as(r: &crate::measurement::Recognised) -> String {
    std::iter::once(r.layout.name())
        .chain(r.notes.iter().cloned())
        .collect::<Vec<_>>()
        .join("; ")
}

/// The instrument's name with its serial number, and where it stood. An instrument block
/// always gives a name line, even when empty (then it is left out as blank).
fn instrument(i: &InstrumentEntry) -> (Option<String>, Option<String>) {
    let mut name = i.name.clone().unwrap_or_default();
    if let Some(s) = &i.serial {
        name = format!("{name}, s/n {s}");
    }
    (Some(name), i.position.clone())
}

/// Whether and how the deviations were corrected to 20 °C (clause 3.1).
fn nde(applied: Option<&NdeCorrection>, declared: Option<&Nde>) -> Option<String> {
    let alpha = |n: &Nde| {
        n.coefficient_um_per_m_c.map_or(String::new(), |a| {
            format!("; α = {} µm/(m·°C)", fmt_position(a))
        })
    };
    match (applied, declared) {
        (Some(n), _) => Some(format!(
            "applied by axcheck to 20 °C: α = {} µm/(m·°C), mean temperature {} °C from {}; largest correction {} µm",
            fmt_position(n.coefficient_um_per_m_c),
            fmt_fixed(n.mean_temperature_c, 2),
            n.source,
            fmt_fixed(n.max_correction_um, 2)
        )),
        (None, Some(n)) if n.corrected => {
            Some(format!("yes, in the data (by the instrument){}", alpha(n)))
        }
        (None, Some(n)) => Some(format!("not applied (no temperature given){}", alpha(n))),
        (None, None) => None,
    }
}

fn cycle(cycle: Cycle) -> &'static str {
    match cycle {
        Cycle::Standard => "standard test cycle (ISO 230-2 Fig. 1)",
        Cycle::Step => "step cycle (ISO 230-2 Annex A)",
        Cycle::Pilgrim => "pilgrim-step cycle (GOST 27843 Черт. 2)",
    }
}

/// Air temperature from start to end, pressure and humidity.
fn air(a: &Air) -> String {
    let mut parts = Vec::new();
    if a.temperature_start_c.is_some() || a.temperature_end_c.is_some() {
        parts.push(format!(
            "{} → {} °C",
            celsius(a.temperature_start_c),
            celsius(a.temperature_end_c)
        ));
    }
    if let Some(p) = a.pressure_kpa {
        parts.push(format!("{} kPa", fmt_position(p)));
    }
    if let Some(h) = a.humidity_pct {
        parts.push(format!("{} % RH", fmt_position(h)));
    }
    parts.join(", ")
}

/// A temperature to 0.1 °C, or a dash.
fn celsius(t: Option<f64>) -> String {
    t.map_or("–".into(), |t| fmt_fixed(t, 1))
}

/// A temperature sensor's line of the conditions table.
#[derive(Serialize)]
pub(super) struct SensorRow<'a> {
    name: &'a str,
    kind: SensorKind,
    position: &'a str,
    start: String,
    end: String,
}

pub(super) fn sensor_rows(c: &Conditions) -> Vec<SensorRow<'_>> {
    let degrees = |t: Option<f64>| t.map_or("–".into(), |t| format!("{} °C", fmt_fixed(t, 1)));
    c.temperature_sensors
        .iter()
        .map(|s: &TemperatureSensor| SensorRow {
            name: &s.name,
            kind: s.kind,
            position: s.position.as_deref().unwrap_or_default(),
            start: degrees(s.start_c),
            end: degrees(s.end_c),
        })
        .collect()
}
