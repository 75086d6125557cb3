//! `material_temperature`: the sensors of the NDE correction.
//!
//! With the NDE correction (ISO 230-2 3.1) the deviations are corrected by α·(T − 20 °C)·L
//! for the measured temperature T of the positioning system; an error of the sensor is
//! an error of the correction of α·L per °C. Input: the sensor's half-width a_T (°C),
//! rectangular, u = a_T/√3 (GUM 4.3.7); sensitivity α·L (α in µm/(m·°C), L in m): µm per
//! °C, growing with L. Ranges on a linear axis with the correction applied only (without
//! it, see `uncorrected_expansion`).

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct MaterialTemperature;

impl Contributor for MaterialTemperature {
    fn name(&self) -> &'static str {
        "material_temperature"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let t = &ctx.setup.thermal;
        (ctx.linear_range() && t.nde_corrected).then_some(Input {
            value: t.sensor_c,
            unit: "°C",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        ctx.expansion_per_c()
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;

    /// α = 11 µm/(m·°C), ±0.1 °C, over 1744.209 mm: u = 0.057735 °C,
    /// c = 11 × 1.744209 = 19.186299 µm/°C, c·u = 1.107721 µm.
    #[test]
    fn with_the_nde_correction() {
        let mut setup = Setup::default();
        setup.thermal.coefficient_um_per_m_c = 11.0;
        let extent = Extent::range(1744.209);
        assert!(line_for(&MaterialTemperature, &setup, &extent).is_none());
        setup.thermal.nde_corrected = true;
        let l = line_for(&MaterialTemperature, &setup, &extent).unwrap();
        assert!((l.sensitivity - 19.186_299).abs() < 1e-6);
        assert!((l.contribution - 1.107_721).abs() < 1e-6);
    }
}
