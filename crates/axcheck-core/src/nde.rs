//! Nominal differential expansion (NDE) correction to 20 °C (ISO 230-2 clause 3.1).
//!
//! A positioning system (screw, scale) at temperature T is longer by α(T − 20) per unit
//! length, so a commanded position P is reached at P·(1 + α(T − 20)): the measured
//! deviation holds α(T − 20)·P more than it would at 20 °C. The correction subtracts it:
//! X₂₀ = X − α·(T − 20 °C)·P, with α in µm/(m·°C) and P in m. Linear axes only.

use crate::measurement::AxisData;
use crate::units::AxisKind;
use serde::Serialize;

/// What was corrected, for the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NdeCorrection {
    /// Effective expansion coefficient, µm/(m·°C).
    pub coefficient_um_per_m_c: f64,
    /// Mean temperature of the positioning system used, °C.
    pub mean_temperature_c: f64,
    /// Where the temperatures came from.
    pub source: String,
    /// Largest correction applied to a reading, µm.
    pub max_correction_um: f64,
}

/// Temperatures for the correction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Temperature {
    /// One temperature for the whole test (sensors' start/end mean), °C.
    Constant(f64),
    /// Each reading's own temperature from the file's `temp_*_c` columns (mean of the
    /// columns that are not air sensors).
    PerReading,
}

/// Corrects a linear axis test to 20 °C; `None` for rotary axes or when `PerReading` is
/// asked of data without temperature columns.
pub fn correct(
    data: &AxisData,
    coefficient_um_per_m_c: f64,
    temperature: Temperature,
) -> Option<(AxisData, NdeCorrection)> {
    if data.kind != AxisKind::Linear {
        return None;
    }
    let material: Vec<usize> = data
        .temperature_names
        .iter()
        .enumerate()
        .filter(|(_, name)| !name.to_ascii_lowercase().contains("air"))
        .map(|(k, _)| k)
        .collect();
    let per_reading = |k: usize| -> f64 {
        let t = &data.temperatures_c[k];
        material.iter().map(|&c| t[c]).sum::<f64>() / material.len() as f64
    };
    let source = match temperature {
        Temperature::Constant(_) => {
            "temperature sensors (mean of start and end readings)".to_string()
        }
        Temperature::PerReading if !material.is_empty() => format!(
            "each reading's temperature (columns {})",
            material
                .iter()
                .map(|&c| format!("temp_{}_c", data.temperature_names[c]))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Temperature::PerReading => return None,
    };
    let mut k = 0usize;
    let mut max_correction = 0.0f64;
    let mut sum_t = 0.0;
    let corrected = data.map_deviations(|r| {
        let t = match temperature {
            Temperature::Constant(t) => t,
            Temperature::PerReading => per_reading(k),
        };
        k += 1;
        sum_t += t;
        let correction = coefficient_um_per_m_c * (t - 20.0) * data.targets[r.target] / 1000.0;
        max_correction = max_correction.max(correction.abs());
        r.deviation - correction
    });
    Some((
        corrected,
        NdeCorrection {
            coefficient_um_per_m_c,
            mean_temperature_c: sum_t / data.readings.len() as f64,
            source,
            max_correction_um: max_correction,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::measurement::RawReading;
    use crate::units::Direction;

    #[test]
    fn corrects_to_20_degrees() {
        let raw = vec![
            RawReading {
                target: 0.0,
                direction: Direction::Up,
                run: 1,
                deviation: 0.0,
                time_s: None,
                temps_c: vec![22.0, 30.0],
                line: 2,
            },
            RawReading {
                target: 0.0,
                direction: Direction::Down,
                run: 1,
                deviation: 0.0,
                time_s: None,
                temps_c: vec![22.0, 30.0],
                line: 3,
            },
            RawReading {
                target: 1000.0,
                direction: Direction::Up,
                run: 1,
                deviation: 23.0,
                time_s: None,
                temps_c: vec![22.0, 30.0],
                line: 4,
            },
            RawReading {
                target: 1000.0,
                direction: Direction::Down,
                run: 1,
                deviation: 22.0,
                time_s: None,
                temps_c: vec![24.0, 30.0],
                line: 5,
            },
        ];
        let d = AxisData::from_raw(
            AxisKind::Linear,
            raw,
            vec!["screw".into(), "air".into()],
            "t",
        )
        .unwrap();
        // α = 11 µm/(m·°C), 2 °C over 20 °C at 1 m: 22 µm.
        let (c, info) = correct(&d, 11.0, Temperature::Constant(22.0)).unwrap();
        assert!((c.deviation(1, Direction::Up, 0) - 1.0).abs() < 1e-12);
        assert_eq!(c.deviation(0, Direction::Up, 0), 0.0);
        assert!((info.max_correction_um - 22.0).abs() < 1e-12);
        let (c, info) = correct(&d, 11.0, Temperature::PerReading).unwrap();
        assert!((c.deviation(1, Direction::Down, 0) - (22.0 - 44.0)).abs() < 1e-12);
        assert!(info.source.contains("temp_screw_c") && !info.source.contains("temp_air_c"));
    }
}
