//! The NDE correction (ISO 230-2 3.1) as the campaign states it: the coefficient and the
//! material temperatures, per reading from the file or from the campaign's sensors.

use crate::campaign::{AxisSpec, SensorKind};
use crate::measurement::AxisData;
use crate::nde::{self, NdeCorrection};

/// Applies the NDE correction when the campaign gives the coefficient and temperatures
/// and the data are not already corrected (clause 3.1).
pub fn apply(axis: &AxisSpec, data: AxisData) -> (AxisData, Option<NdeCorrection>) {
    let Some(nde) = &axis.raw.conditions.nde else {
        return (data, None);
    };
    let Some(alpha) = nde.coefficient_um_per_m_c else {
        return (data, None);
    };
    if nde.corrected {
        return (data, None);
    }
    let temperature = if has_material_temperatures(&data) {
        Some(nde::Temperature::PerReading)
    } else {
        let readings: Vec<f64> = axis
            .raw
            .conditions
            .temperature_sensors
            .iter()
            .filter(|s| s.kind == SensorKind::Material)
            .flat_map(|s| [s.start_c, s.end_c])
            .flatten()
            .collect();
        (!readings.is_empty()).then(|| {
            nde::Temperature::Constant(readings.iter().sum::<f64>() / readings.len() as f64)
        })
    };
    match temperature.and_then(|t| nde::correct(&data, alpha, t)) {
        Some((corrected, info)) => (corrected, Some(info)),
        None => (data, None),
    }
}

/// Whether the file gives a material temperature per reading (`temp_<name>_c` columns
/// other than the air's), as the NDE correction reads them.
pub(crate) fn has_material_temperatures(data: &AxisData) -> bool {
    data.temperature_names
        .iter()
        .any(|n| !n.to_ascii_lowercase().contains("air"))
}
