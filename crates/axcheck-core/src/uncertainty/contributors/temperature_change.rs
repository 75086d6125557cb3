//! `temperature_change`: the temperature drifting during the test.
//!
//! The correction to 20 °C (or the uncorrected expansion) uses one temperature, the mean
//! of the start and end readings; the positioning system's temperature during the test
//! lay anywhere between them, so the temperature that applied to a reading is known only
//! within ±|ΔT|/2 of that mean (ΔT = end − start). Input: |ΔT|/2 (°C), rectangular
//! (GUM 4.3.7); sensitivity α·L: µm per °C, growing with L. Ranges on a linear axis
//! only: at one position (B, R) the drift is part of what the machine did, which the
//! standard's test cycle shows in B and R (ISO 230-2:1997 Annex A). Conservative for the
//! means of a standard cycle, which average over the test; 0 when the correction followed
//! each reading's own temperature.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct TemperatureChange;

impl Contributor for TemperatureChange {
    fn name(&self) -> &'static str {
        "temperature_change"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        ctx.linear_range().then(|| Input {
            value: ctx.setup.thermal.change_c.abs() / 2.0,
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

    /// Table 2: the material sensors' mean goes from 22.1 to 23.0 °C, ΔT = 0.9 °C:
    /// a = 0.45 °C, u = 0.259808 °C, c = 11 × 1.744209 = 19.186299 µm/°C,
    /// c·u = 4.984747 µm.
    #[test]
    fn table_2_conditions() {
        let mut setup = Setup::default();
        setup.thermal.coefficient_um_per_m_c = 11.0;
        let extent = Extent::range(1744.209);
        assert!(
            line_for(&TemperatureChange, &setup, &extent).is_none(),
            "no change"
        );
        setup.thermal.change_c = 0.9;
        let l = line_for(&TemperatureChange, &setup, &extent).unwrap();
        assert!((l.u - 0.259_808).abs() < 1e-6);
        assert!((l.contribution - 4.984_747).abs() < 1e-6);
    }
}
