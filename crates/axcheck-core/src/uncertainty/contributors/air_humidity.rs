//! `air_humidity`: the laser's humidity sensor.
//!
//! Input: the sensor's half-width a_h (%RH), rectangular, u = a_h/√3 (GUM 4.3.7). The
//! wavelength in air changes by 0.0085 ppm per %RH near 20 °C (Edlén): over a length L
//! (m) the sensitivity is 0.0085·L µm/%RH. Grows with L; ranges on a linear axis
//! measured by a laser only.

use super::{Context, Contributor, edlen};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct AirHumidity;

impl Contributor for AirHumidity {
    fn name(&self) -> &'static str {
        "air_humidity"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let air = ctx.setup.air.as_ref().filter(|_| ctx.linear_range())?;
        Some(Input {
            value: air.humidity_sensor_pct,
            unit: "%RH",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        edlen::PPM_PER_PCT_RH * ctx.length_m()
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;

    /// ±6 %RH over 1744.209 mm: u = 3.464102 %RH, c = 0.0085 × 1.744209 = 0.014826
    /// µm/%RH, c·u = 0.051357 µm.
    #[test]
    fn table_2_travel() {
        let l = line_for(&AirHumidity, &Setup::default(), &Extent::range(1744.209)).unwrap();
        assert!((l.u - 3.464_102).abs() < 1e-6);
        assert!((l.sensitivity - 0.014_826).abs() < 1e-6);
        assert!((l.contribution - 0.051_357).abs() < 1e-6);
    }
}
