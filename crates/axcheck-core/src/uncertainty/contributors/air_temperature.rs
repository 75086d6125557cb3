//! `air_temperature`: the laser's air temperature sensor.
//!
//! Input: the sensor's half-width a_t (°C), rectangular, u = a_t/√3 (GUM 4.3.7). The
//! compensation computes the wavelength in air from the reading (Edlén), so an error of
//! the sensor is an error of the wavelength of 0.93 ppm per °C: over a length L (m) the
//! sensitivity is 0.93·L µm/°C (GUM 5.1.3). Grows with L; ranges on a linear axis
//! measured by a laser only.

use super::{Context, Contributor, edlen};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct AirTemperature;

impl Contributor for AirTemperature {
    fn name(&self) -> &'static str {
        "air_temperature"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let air = ctx.setup.air.as_ref().filter(|_| ctx.linear_range())?;
        Some(Input {
            value: air.temperature_sensor_c,
            unit: "°C",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        edlen::PPM_PER_C * ctx.length_m()
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::{InstrumentKind, Setup};

    /// ±0.2 °C over 1744.209 mm: u = 0.115470 °C, c = 0.93 × 1.744209 = 1.622114 µm/°C,
    /// c·u = 0.187306 µm.
    #[test]
    fn table_2_travel() {
        let l = line_for(&AirTemperature, &Setup::default(), &Extent::range(1744.209)).unwrap();
        assert!((l.u - 0.115_470).abs() < 1e-6);
        assert!((l.sensitivity - 1.622_114).abs() < 1e-6);
        assert!((l.contribution - 0.187_306).abs() < 1e-6);
    }

    #[test]
    fn only_with_an_air_path() {
        let setup = Setup::for_instrument(InstrumentKind::LinearEncoder);
        assert!(line_for(&AirTemperature, &setup, &Extent::range(500.0)).is_none());
    }
}
