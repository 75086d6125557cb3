//! `air_pressure`: the laser's air pressure sensor.
//!
//! Input: the sensor's half-width a_p (kPa), rectangular, u = a_p/√3 (GUM 4.3.7). The
//! wavelength in air changes by 2.7 ppm per kPa (0.27 ppm per hPa, Edlén): over a length
//! L (m) the sensitivity is 2.7·L µm/kPa. Grows with L; ranges on a linear axis measured
//! by a laser only.

use super::{Context, Contributor, edlen};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct AirPressure;

impl Contributor for AirPressure {
    fn name(&self) -> &'static str {
        "air_pressure"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let air = ctx.setup.air.as_ref().filter(|_| ctx.linear_range())?;
        Some(Input {
            value: air.pressure_sensor_kpa,
            unit: "kPa",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        edlen::PPM_PER_KPA * ctx.length_m()
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;

    /// ±0.1 kPa over 1744.209 mm: u = 0.057735 kPa, c = 2.7 × 1.744209 = 4.709364 µm/kPa,
    /// c·u = 0.271895 µm.
    #[test]
    fn table_2_travel() {
        let l = line_for(&AirPressure, &Setup::default(), &Extent::range(1744.209)).unwrap();
        assert!((l.u - 0.057_735).abs() < 1e-6);
        assert!((l.sensitivity - 4.709_364).abs() < 1e-6);
        assert!((l.contribution - 0.271_895).abs() < 1e-6);
    }
}
