//! An axis's test conditions completed from what its measurement file says of itself (a
//! Renishaw file's ENVIRONMENT): the campaign's values always win; the file fills only
//! what the campaign leaves out (ISO 230-2 clause 7.1). The correction to 20 °C (clause
//! 3.1) stays the campaign's decision: the file's expansion coefficient is used only
//! where the campaign asks for the correction (`nde:`) without giving one.

use super::AxisSpec;
use super::model::{Air, Conditions, SensorKind, TemperatureSensor};
use crate::measurement::FileInfo;

impl AxisSpec {
    /// This axis with the conditions it lacks taken from `info`, and what was taken (for
    /// the report); None when the file adds nothing.
    pub(crate) fn completed_by(&self, info: &FileInfo) -> Option<(AxisSpec, Vec<&'static str>)> {
        let mut axis = self.clone();
        let taken = complete(&mut axis.raw.conditions, info);
        (!taken.is_empty()).then_some((axis, taken))
    }
}

/// Fills `c` from `info`; the names of what was filled.
fn complete(c: &mut Conditions, info: &FileInfo) -> Vec<&'static str> {
    let mut taken = Vec::new();
    if complete_air(c.air.get_or_insert_with(Air::default), info) {
        taken.push("air temperature, pressure and humidity");
    }
    if c.air.as_ref() == Some(&Air::default()) {
        c.air = None;
    }
    let has_material = (c.temperature_sensors.iter()).any(|s| s.kind == SensorKind::Material);
    if !has_material && !info.material_sensors.is_empty() {
        c.temperature_sensors
            .extend(info.material_sensors.iter().map(|m| TemperatureSensor {
                name: m.name.clone(),
                kind: SensorKind::Material,
                position: None,
                start_c: m.start_c,
                end_c: m.end_c,
            }));
        taken.push("material temperatures");
    }
    let asked = c
        .nde
        .as_mut()
        .filter(|n| n.coefficient_um_per_m_c.is_none());
    if let (Some(nde), Some(alpha)) = (asked, info.expansion_um_per_m_c) {
        nde.coefficient_um_per_m_c = Some(alpha);
        taken.push("expansion coefficient");
    }
    taken
}

/// Fills the air values `air` lacks; whether any was filled.
fn complete_air(air: &mut Air, info: &FileInfo) -> bool {
    let mut filled = false;
    for (slot, value) in [
        (&mut air.temperature_start_c, info.air_temperature_start_c),
        (&mut air.temperature_end_c, info.air_temperature_end_c),
        (&mut air.pressure_kpa, info.air_pressure_kpa),
        (&mut air.humidity_pct, info.air_humidity_pct),
    ] {
        if slot.is_none() && value.is_some() {
            *slot = value;
            filled = true;
        }
    }
    filled
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::campaign::model::Nde;
    use crate::measurement::info::MaterialReading;

    fn info() -> FileInfo {
        FileInfo {
            air_temperature_start_c: Some(20.4),
            air_temperature_end_c: Some(20.9),
            air_pressure_kpa: Some(101.2),
            air_humidity_pct: Some(45.0),
            material_sensors: vec![MaterialReading {
                name: "Renishaw material sensor 1".into(),
                start_c: Some(21.0),
                end_c: Some(21.4),
            }],
            expansion_um_per_m_c: Some(11.7),
            ..FileInfo::default()
        }
    }

    #[test]
    fn the_file_fills_only_what_the_campaign_leaves_out() {
        let mut c = Conditions {
            air: Some(Air {
                temperature_start_c: Some(19.8),
                ..Air::default()
            }),
            nde: Some(Nde::default()),
            ..Conditions::default()
        };
        let taken = complete(&mut c, &info());
        let air = c.air.unwrap();
        assert_eq!(
            air.temperature_start_c,
            Some(19.8),
            "the campaign's value wins"
        );
        assert_eq!(air.temperature_end_c, Some(20.9));
        assert_eq!(air.pressure_kpa, Some(101.2));
        assert_eq!(c.temperature_sensors.len(), 1);
        assert_eq!(c.temperature_sensors[0].end_c, Some(21.4));
        assert_eq!(c.nde.unwrap().coefficient_um_per_m_c, Some(11.7));
        assert_eq!(
            taken,
            [
                "air temperature, pressure and humidity",
                "material temperatures",
                "expansion coefficient"
            ]
        );
    }

    #[test]
    fn no_correction_is_asked_for_by_the_file_alone() {
        let mut c = Conditions::default();
        complete(&mut c, &info());
        assert!(c.nde.is_none());
        let mut silent = Conditions::default();
        assert!(complete(&mut silent, &FileInfo::default()).is_empty());
        assert_eq!(silent, Conditions::default());
    }
}
