//! `resolution`: the indication's smallest step δ.
//!
//! Input: the half-width δ/2 of the rounding of one reading, rectangular, u = δ/(2√3)
//! (GUM F.2.2.1), in µm or arcsec. Sensitivity: 1 for ranges and reversals (one
//! reading's rounding, conservatively not reduced by the averaging of n readings), 2k for
//! a repeatability 2kS (the rounding enters S). Independent of the length.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub struct Resolution;

impl Contributor for Resolution {
    fn name(&self) -> &'static str {
        "resolution"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        Some(Input {
            value: ctx.setup.instrument.resolution / 2.0,
            unit: ctx.unit(),
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        ctx.extent.reading_gain
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::{InstrumentKind, Setup};

    /// An encoder read in 0.1 µm steps: a = 0.05 µm, u = 0.05/√3 = 0.028868 µm; in a
    /// repeatability 4S (ISO, k = 2) its contribution is 4u = 0.115470 µm.
    #[test]
    fn half_a_step_rectangular() {
        let setup = Setup::for_instrument(InstrumentKind::LinearEncoder);
        let mut extent = Extent::range(300.0);
        let l = line_for(&Resolution, &setup, &extent).unwrap();
        assert!((l.value - 0.05).abs() < 1e-12);
        assert!((l.u - 0.028_868).abs() < 1e-6);
        extent.reading_gain = 4.0;
        let l = line_for(&Resolution, &setup, &extent).unwrap();
        assert!((l.contribution - 0.115_470).abs() < 1e-6);
    }
}
