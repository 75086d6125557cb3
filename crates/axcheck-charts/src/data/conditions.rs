//! The test conditions of ISO 230-2 clause 7.1 that the campaign gives, in the standard's
//! order, and the temperature sensors.

use crate::axis_model::Cycle;
use crate::campaign::{Air, Conditions, InstrumentEntry, Nde, SensorKind, TemperatureSensor};
use crate::nde::NdeCorrection;
use crate::results::AxisTest;
use crate::units::{AxisKind, fmt_fixed, fmt_position};
use crate::words::Words;
use serde::Serialize;

/// A labelled line: a header fact or a test condition.
#[derive(Debug, Serialize)]
pub(super) struct Row {
    label: String,
    value: String,
}

impl Row {
    /// The rows whose value is given and not blank, in order.
    pub(super) fn present<const N: usize>(rows: [(&'static str, Option<String>); N]) -> Vec<Row> {
        rows.into_iter()
            .filter_map(|(label, value)| {
                let value = value.filter(|v| !v.trim().is_empty())?;
                Some(Row {
                    label: label.to_string(),
                    value,
                })
            })
            .collect()
    }

    /// [`Row::present`] with each label a key of the catalogue, in `words`' language.
    pub(super) fn labelled<const N: usize>(
        words: &Words,
        rows: [(&'static str, Option<String>); N],
    ) -> Vec<Row> {
        let mut rows = Row::present(rows);
        for r in &mut rows {
            r.label = words.get(&r.label);
        }
        rows
    }
}

/// Clause 7.1 items the campaign gives, in the standard's order.
pub(super) fn condition_rows(
    c: &Conditions,
    kind: AxisKind,
    t: &AxisTest,
    words: &Words,
) -> Vec<Row> {
    let (instrument, position) =
        (c.instrument.as_ref()).map_or((None, None), |i| instrument(i, words));
    let per_min = words.get(match kind {
        AxisKind::Linear => "unit-mm-per-min",
        AxisKind::Rotary => "unit-deg-per-min",
    });
    let approaches = t.evaluated().map(|e| &e.evaluation).map(|e| {
        let (n, targets) = (e.n.to_string(), e.targets.len().to_string());
        words.args("cond-approaches-value", &[("n", &n), ("targets", &targets)])
    });
    Row::labelled(
        words,
        [
            ("cond-instrument", instrument),
            ("cond-instrument-position", position),
            (
                "cond-equipment",
                (!c.equipment.is_empty()).then(|| c.equipment.join("; ")),
            ),
            ("cond-positioning-element", c.positioning_element.clone()),
            (
                "cond-nde",
                nde(
                    t.evaluated().and_then(|e| e.nde.as_ref()),
                    c.nde.as_ref(),
                    words,
                ),
            ),
            (
                "cond-feed",
                c.feed_mm_per_min
                    .map(|f| format!("{} {per_min}", super::local(&fmt_position(f)))),
            ),
            (
                "cond-dwell",
                c.dwell_s
                    .map(|d| format!("{} {}", super::local(&fmt_position(d)), words.unit("s"))),
            ),
            ("cond-compensation", c.compensation.clone()),
            ("cond-other-axes", c.other_axes.clone()),
            ("cond-tool-offset", c.tool_offset.clone()),
            ("cond-workpiece-offset", c.workpiece_offset.clone()),
            ("cond-warm-up", c.warm_up.clone()),
            ("cond-cycle", c.cycle.map(|cy| words.get(cycle(cy)))),
            ("cond-air", c.air.as_ref().map(|a| air(a, words))),
            ("cond-pressure", c.fluid_pressure.clone()),
            ("cond-approaches", approaches),
            ("cond-read-as", t.recognised().map(read_as)),
            (
                "cond-from-file",
                (t.evaluated().map(|e| e.conditions_from_file.join(", ")))
                    .filter(|s| !s.is_empty()),
            ),
            ("cond-notes", c.notes.clone()),
        ],
    )
    .into_iter()
    .chain(not_stated(t, words))
    .collect()
}

/// A row "not stated" for each clause 7.1 item neither the campaign nor the file states,
/// in the clause's order.
fn not_stated(t: &AxisTest, words: &Words) -> Vec<Row> {
    let unstated = t.evaluated().map_or(&[][..], |e| &e.unstated);
    (unstated.iter())
        .map(|label| Row {
            label: unstated_key(label).map_or(label.to_string(), |k| words.get(k)),
            value: words.get("cond-not-stated"),
        })
        .collect()
}

/// The catalogue key of a clause 7.1 item as `campaign::clause7_1::unstated` words it.
fn unstated_key(label: &str) -> Option<&'static str> {
    Some(match label {
        "Position of the measuring instrument" => "unstated-instrument-position",
        "Positions of the temperature sensors" => "unstated-sensor-positions",
        "NDE correction (3.1)" => "cond-nde",
        "Test date" => "fact-date",
        "Machine model" => "unstated-model",
        "Machine type" => "unstated-type",
        "Axis travel" => "fact-axis-travel",
        "Test equipment (maker, type, serial numbers)" => "unstated-equipment",
        "Positioning element" => "cond-positioning-element",
        "Expansion coefficient of the positioning element" => "unstated-expansion",
        "Positions of the other axes (3.2)" => "cond-other-axes",
        "Tool and workpiece offsets" => "unstated-offsets",
        "Feed rate" => "cond-feed",
        "Dwell at each target" => "cond-dwell",
        "Warm-up (3.3)" => "cond-warm-up",
        "Material temperatures at start and end" => "unstated-material",
        "Air temperature at start and end" => "unstated-air",
        "Air pressure and humidity at start and end" => "unstated-pressure",
        "Compensation active during the test (3.2)" => "unstated-compensation",
        _ => return None,
    })
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
fn instrument(i: &InstrumentEntry, words: &Words) -> (Option<String>, Option<String>) {
    let mut name = i.name.clone().unwrap_or_default();
    if let Some(s) = &i.serial {
        name = words.args("instrument-serial", &[("name", &name), ("serial", s)]);
    }
    (Some(name), i.position.clone())
}

/// Whether and how the deviations were corrected to 20 °C (clause 3.1).
fn nde(applied: Option<&NdeCorrection>, declared: Option<&Nde>, words: &Words) -> Option<String> {
    let number = |x: f64| super::local(&fmt_position(x));
    let alpha = |n: &Nde| {
        (n.coefficient_um_per_m_c).map_or(String::new(), |a| {
            words.args("nde-alpha", &[("alpha", &number(a))])
        })
    };
    match (applied, declared) {
        (Some(n), _) => Some(words.args(
            "nde-applied",
            &[
                ("alpha", &number(n.coefficient_um_per_m_c)),
                ("mean", &super::local(&fmt_fixed(n.mean_temperature_c, 2))),
                ("source", &n.source),
                ("max", &super::local(&fmt_fixed(n.max_correction_um, 2))),
            ],
        )),
        (None, Some(n)) if n.corrected => Some(words.args("nde-in-data", &[("alpha", &alpha(n))])),
        (None, Some(n)) => Some(words.args("nde-not-applied", &[("alpha", &alpha(n))])),
        (None, None) => None,
    }
}

fn cycle(cycle: Cycle) -> &'static str {
    match cycle {
        Cycle::Standard => "cycle-standard",
        Cycle::Step => "cycle-step",
        Cycle::Pilgrim => "cycle-pilgrim",
    }
}

/// Air temperature from start to end, pressure and humidity.
fn air(a: &Air, words: &Words) -> String {
    let mut parts = Vec::new();
    if a.temperature_start_c.is_some() || a.temperature_end_c.is_some() {
        parts.push(format!(
            "{} → {} °C",
            celsius(a.temperature_start_c),
            celsius(a.temperature_end_c)
        ));
    }
    if let Some(p) = a.pressure_kpa {
        let p = super::local(&fmt_position(p));
        parts.push(format!("{p} {}", words.get("unit-kpa")));
    }
    if let Some(h) = a.humidity_pct {
        let h = super::local(&fmt_position(h));
        parts.push(words.args("unit-rh", &[("value", &h)]));
    }
    parts.join(", ")
}

/// A temperature to 0.1 °C, or a dash.
fn celsius(t: Option<f64>) -> String {
    t.map_or("–".into(), |t| super::local(&fmt_fixed(t, 1)))
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
    let degrees = |t: Option<f64>| {
        t.map_or("–".into(), |t| {
            format!("{} °C", super::local(&fmt_fixed(t, 1)))
        })
    };
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
