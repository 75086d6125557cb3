//! `uncorrected_expansion`: the NDE left uncorrected.
//!
//! Without the correction of ISO 230-2 3.1, the deviations hold the expansion of the
//! positioning system α·(T − 20 °C)·L. It tilts the error curve, which changes a range
//! parameter by anything between −α·|T − 20|·L and +α·|T − 20|·L depending on the
//! curve's shape: input |T − 20 °C| (the recorded mean, else the assumed band), taken as
//! the half-width of a rectangular distribution (GUM 4.3.7); sensitivity α·L: µm per °C,
//! growing with L. Ranges on a linear axis without the correction only. (The GUM asks
//! for known corrections to be applied, 3.2.4: apply the NDE correction rather than live
//! with this line.)

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct UncorrectedExpansion;

impl Contributor for UncorrectedExpansion {
    fn name(&self) -> &'static str {
        "uncorrected_expansion"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let t = &ctx.setup.thermal;
        (ctx.linear_range() && !t.nde_corrected).then(|| Input {
            value: t.offset_from_20_c(),
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

    /// α = 11.5 µm/(m·°C), T = 21.15 °C, over 980 mm: a = 1.15 °C, u = 0.663953 °C,
    /// c = 11.5 × 0.98 = 11.27 µm/°C, c·u = 7.482748 µm; not recorded: the ±1 °C band,
    /// u = 0.577350 °C, c·u = 6.506738 µm.
    #[test]
    fn without_the_nde_correction() {
        let mut setup = Setup::default();
        let extent = Extent::range(980.0);
        let l = line_for(&UncorrectedExpansion, &setup, &extent).unwrap();
        assert!((l.value - 1.0).abs() < 1e-12);
        assert!((l.contribution - 6.506_738).abs() < 1e-6);
        setup.thermal.mean_c = Some(21.15);
        let l = line_for(&UncorrectedExpansion, &setup, &extent).unwrap();
        assert!((l.value - 1.15).abs() < 1e-12);
        assert!((l.contribution - 7.482_748).abs() < 1e-6);
        setup.thermal.nde_corrected = true;
        assert!(line_for(&UncorrectedExpansion, &setup, &extent).is_none());
    }
}
