//! `expansion_coefficient`: the uncertainty of α in the NDE correction.
//!
//! The correction α·(T − 20 °C)·L is only as good as α: ISO 230-2 3.1 notes that any
//! difference from 20 °C adds an uncertainty through the effective expansion coefficient,
//! typically ±2 µm/(m·°C). Input: that half-width a_α, rectangular, u = a_α/√3 (GUM
//! 4.3.7); sensitivity |T − 20 °C|·L (L in m): µm per µm/(m·°C), growing with L and with
//! the distance from 20 °C (the assumed band when T was not recorded). Ranges on a
//! linear axis with the correction applied only.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct ExpansionCoefficient;

impl Contributor for ExpansionCoefficient {
    fn name(&self) -> &'static str {
        "expansion_coefficient"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let t = &ctx.setup.thermal;
        (ctx.linear_range() && t.nde_corrected).then_some(Input {
            value: t.coefficient_uncertainty_um_per_m_c,
            unit: "um/(m·°C)",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        ctx.setup.thermal.offset_from_20_c() * ctx.length_m()
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;

    /// ±2 µm/(m·°C) at T = 22.55 °C over 1744.209 mm: u = 1.154701 µm/(m·°C),
    /// c = 2.55 × 1.744209 = 4.447733 m·°C, c·u = 5.135800 µm.
    #[test]
    fn table_2_conditions() {
        let mut setup = Setup::default();
        setup.thermal.nde_corrected = true;
        setup.thermal.mean_c = Some(22.55);
        let l = line_for(&ExpansionCoefficient, &setup, &Extent::range(1744.209)).unwrap();
        assert!((l.u - 1.154_701).abs() < 1e-6);
        assert!((l.sensitivity - 4.447_733).abs() < 1e-6);
        assert!((l.contribution - 5.135_800).abs() < 1e-6);
    }

    /// At 20 °C the coefficient does not matter: c = 0, c·u = 0.
    #[test]
    fn nothing_at_20_c() {
        let mut setup = Setup::default();
        setup.thermal.nde_corrected = true;
        setup.thermal.mean_c = Some(20.0);
        let l = line_for(&ExpansionCoefficient, &setup, &Extent::range(1000.0)).unwrap();
        assert_eq!(l.contribution, 0.0);
    }
}
