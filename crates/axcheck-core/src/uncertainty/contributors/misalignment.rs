//! `misalignment`: the cosine error.
//!
//! A beam (or scale) at an angle θ to the axis measures L·cos θ instead of L: the error
//! is L·(1 − cos θ), one-signed (HP 5528A User's Guide, section 6, "cosine error"). θ
//! follows from the lateral walk d of the beam on its target over the measurement travel
//! T: θ = atan(d/T). Input: (1 − cos θ) in ppm, taken conservatively as the half-width
//! of a rectangular distribution (GUM 4.3.7) although the error is one-signed.
//! Sensitivity L in m, µm per ppm: grows with L (quadratically with the misalignment).
//! Ranges on a linear axis only; a rotary reference's centring is not included.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct Misalignment;

impl Contributor for Misalignment {
    fn name(&self) -> &'static str {
        "misalignment"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let offset = ctx.setup.misalignment_offset_mm;
        if !ctx.linear_range() || offset <= 0.0 || ctx.travel <= 0.0 {
            return None;
        }
        let theta = (offset / ctx.travel).atan();
        Some(Input {
            // 1 − cos θ = 2 sin²(θ/2), exact for small angles.
            value: 2e6 * (theta / 2.0).sin().powi(2),
            unit: "ppm",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        ctx.length_m()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;
    use crate::units::AxisKind;

    /// 0.5 mm over the Table 2 travel of 1744.209 mm: θ = 2.866629e-4 rad,
    /// 1 − cos θ = 0.041088 ppm, u = 0.023722 ppm, c = 1.744209 µm/ppm, c·u = 0.041376 µm.
    #[test]
    fn half_a_millimetre_over_the_travel() {
        let setup = Setup::default();
        let extent = Extent::range(1744.209);
        let ctx = Context {
            setup: &setup,
            kind: AxisKind::Linear,
            travel: 1744.209,
            extent: &extent,
        };
        let l = Misalignment.line(&ctx).unwrap();
        assert!((l.value - 0.041_088).abs() < 1e-6, "{}", l.value);
        assert!(
            (l.contribution - 0.041_376).abs() < 1e-6,
            "{}",
            l.contribution
        );
    }
}
