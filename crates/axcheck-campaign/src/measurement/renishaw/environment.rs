//! `ENVIRONMENT::`: the laser's weather station at the start and end of the test.
//!
//! ```text
//! Air temp   : 20.337280 20.384956 0
//! Air press  : 99.039005 99.049346 1
//! Air humid  : 46.954897 46.893887
//! Mat temp 1 : 20.203292 20.321342 0
//! Mat temp 2 : -10.000000 -10.000000 0
//! Exp coeff  : 8.000000 8.000000 0
//! Date Time  : "10:46 Dec 12 2016" "11:01 Dec 12 2016"
//! ```
//! Each line gives the value at the start and at the end of the test, then a flag whose
//! meaning is not known. The file states no units: they are inferred from the values
//! (°C, kPa, %RH, ppm/°C) and −10.000000 on both ends reads as "no sensor fitted". Values
//! outside plausible ranges are left out with a note, never guessed.

use super::text::{Line, Section, shown};

/// A value at the start and at the end of the test.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StartEnd {
    pub start: Option<f64>,
    pub end: Option<f64>,
}

impl StartEnd {
    /// The mean of what is given.
    pub fn mean(&self) -> Option<f64> {
        match (self.start, self.end) {
            (Some(a), Some(b)) => Some((a + b) / 2.0),
            (a, b) => a.or(b),
        }
    }
}

/// One material (machine) temperature sensor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaterialSensor {
    /// The sensor's number (`Mat temp 1` → 1).
    pub sensor: u32,
    pub(crate) temp_c: StartEnd,
}

/// The ENVIRONMENT:: values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Environment {
    /// `Air temp`, °C.
    pub(crate) air_temp_c: StartEnd,
    /// `Air press`, converted from the kPa written to hPa (= mbar).
    pub(crate) air_pressure_hpa: StartEnd,
    /// `Air humid`, % relative humidity.
    pub(crate) air_humidity_percent: StartEnd,
    /// `Mat temp N`, the sensors fitted (those reading −10 at both ends are left out).
    pub(crate) material_temps_c: Vec<MaterialSensor>,
    /// `Exp coeff`: the expansion coefficient set for the part, ppm/°C (µm/m/°C).
    pub expansion_ppm_per_c: Option<f64>,
    /// `Date Time`: start and end of the test, as written.
    pub(crate) date_time_start: Option<String>,
    pub(crate) date_time_end: Option<String>,
    /// Lines not interpreted (`Env factor`, `Final Data`, others), key and value as written.
    pub other: Vec<(String, String)>,
}

impl Environment {
    /// Mean material temperature over the fitted sensors and the test, °C.
    pub fn material_temp_c(&self) -> Option<f64> {
        let means: Vec<f64> = self
            .material_temps_c
            .iter()
            .filter_map(|s| s.temp_c.mean())
            .collect();
        (!means.is_empty()).then(|| means.iter().sum::<f64>() / means.len() as f64)
    }
}

/// Value reported by a sensor that is not fitted.
const NOT_FITTED: f64 = -10.0;
/// Plausible ranges: beyond them a value is a unit or sensor problem, left out.
const TEMP_C: (f64, f64) = (-20.0, 60.0);
const PRESSURE_KPA: (f64, f64) = (50.0, 120.0);
const HUMIDITY_PERCENT: (f64, f64) = (0.0, 100.0);
const EXPANSION_PPM_PER_C: (f64, f64) = (0.0, 100.0);
/// hPa per kPa.
const HPA_PER_KPA: f64 = 10.0;

/// Reads ENVIRONMENT::; what cannot be read is noted, never an error (the units and flags
/// are known from one source only).
pub(super) fn read(section: &Section, notes: &mut Vec<String>) -> Environment {
    let mut out = Environment::default();
    let mut not_fitted = Vec::new();
    let mut problems = Vec::new();
    for line in &section.lines {
        let Some(kv) = line.key_value() else {
            out.other.push((String::new(), line.text().to_string()));
            continue;
        };
        let mut values =
            |range: (f64, f64)| start_end(line, kv.key, kv.value, range, &mut problems);
        match kv.normal.as_str() {
            "airtemp" => out.air_temp_c = values(TEMP_C),
            "airpress" | "airpressure" => {
                let kpa = values(PRESSURE_KPA);
                out.air_pressure_hpa = StartEnd {
                    start: kpa.start.map(|p| p * HPA_PER_KPA),
                    end: kpa.end.map(|p| p * HPA_PER_KPA),
                };
            }
            "airhumid" | "airhumidity" => out.air_humidity_percent = values(HUMIDITY_PERCENT),
            "expcoeff" => out.expansion_ppm_per_c = values(EXPANSION_PPM_PER_C).start,
            "datetime" => (out.date_time_start, out.date_time_end) = date_times(kv.value),
            key => match key
                .strip_prefix("mattemp")
                .and_then(|n| n.parse::<u32>().ok())
            {
                Some(sensor) => {
                    let raw = numbers(kv.value);
                    if raw[..] == [NOT_FITTED, NOT_FITTED] || raw[..] == [NOT_FITTED] {
                        not_fitted.push(sensor.to_string());
                    } else {
                        let temp_c = values(TEMP_C);
                        out.material_temps_c.push(MaterialSensor { sensor, temp_c });
                    }
                }
                None => out.other.push((kv.key.to_string(), kv.value.to_string())),
            },
        }
    }
    notes.push(
        "ENVIRONMENT:: states no units: read as °C, kPa (converted to hPa), % relative humidity and ppm/°C".into(),
    );
    if !not_fitted.is_empty() {
        notes.push(format!(
            "ENVIRONMENT:: Mat temp {} read −10 °C at start and end: taken as no sensor fitted",
            not_fitted.join(", ")
        ));
    }
    notes.extend(problems);
    out
}

/// The first numbers of a value (start, end; the flag after them is not read).
fn numbers(value: &str) -> Vec<f64> {
    value
        .split_whitespace()
        .take(2)
        .map_while(|t| crate::measurement::parse_number(t, false).ok())
        .collect()
}

/// Start and end of one line, each kept only when it is a number within `range`.
fn start_end(
    line: &Line,
    key: &str,
    value: &str,
    (low, high): (f64, f64),
    problems: &mut Vec<String>,
) -> StartEnd {
    let mut tokens = value.split_whitespace();
    let mut take = |which: &str| {
        let token = tokens.next()?;
        match crate::measurement::parse_number(token, false) {
            Ok(v) if (low..=high).contains(&v) => Some(v),
            _ => {
                problems.push(format!(
                    "ENVIRONMENT:: `{}` {which} value `{}` (line {}) is not a number between {low} and {high}; left out",
                    shown(key),
                    shown(token),
                    line.number
                ));
                None
            }
        }
    };
    let start = take("start");
    let end = take("end");
    StartEnd { start, end }
}

/// The two quoted date-times of `Date Time`; an unquoted value is the start.
fn date_times(value: &str) -> (Option<String>, Option<String>) {
    let quoted: Vec<&str> = value.split('"').skip(1).step_by(2).collect();
    let text = |s: &str| {
        let s = s.trim();
        (!s.is_empty()).then(|| s.to_string())
    };
    match quoted[..] {
        [] => (text(value), None),
        [start] => (text(start), None),
        [start, end, ..] => (text(start), text(end)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn date_times_quoted_or_not() {
        assert_eq!(
            date_times("\"10:46 Dec 12 2016\" \"11:01 Dec 12 2016\""),
            (
                Some("10:46 Dec 12 2016".into()),
                Some("11:01 Dec 12 2016".into())
            )
        );
        assert_eq!(
            date_times("2016-12-12 10:46"),
            (Some("2016-12-12 10:46".into()), None)
        );
        assert_eq!(date_times(""), (None, None));
    }

    #[test]
    fn means() {
        let both = StartEnd {
            start: Some(20.0),
            end: Some(21.0),
        };
        assert_eq!(both.mean(), Some(20.5));
        assert_eq!(StartEnd::default().mean(), None);
    }
}
