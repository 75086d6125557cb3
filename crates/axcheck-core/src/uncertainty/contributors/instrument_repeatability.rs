//! `instrument_repeatability`: the instrument's own scatter, from a drift check.
//!
//! Input: the standard deviation s₀ of the instrument's readings with the set-up at rest
//! for the duration of a test (a Type A evaluation, GUM 4.2; the "environmental variation"
//! of ISO/TR 230-9), in µm or arcsec, normal with k = 1. Sensitivity: 1 for ranges and
//! reversals, 2k for a repeatability 2kS. Applies only when the campaign gives a drift
//! check: otherwise the instrument's scatter is part of the measured S and is already in
//! the statistical lines.

use super::{Context, Contributor};
use crate::uncertainty::budget::{Distribution, Input};

pub(crate) struct InstrumentRepeatability;

impl Contributor for InstrumentRepeatability {
    fn name(&self) -> &'static str {
        "instrument_repeatability"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        ctx.setup.instrument.repeatability.map(|s| Input {
            value: s,
            unit: ctx.unit(),
            distribution: Distribution::STANDARD,
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
    use crate::uncertainty::setup::Setup;

    /// A drift check with s₀ = 0.1 µm: u = 0.1 µm; in R = 4S its contribution is 0.4 µm.
    #[test]
    fn only_with_a_drift_check() {
        let mut setup = Setup::default();
        let mut extent = Extent::range(500.0);
        assert!(line_for(&InstrumentRepeatability, &setup, &extent).is_none());
        setup.instrument.repeatability = Some(0.1);
        extent.reading_gain = 4.0;
        let l = line_for(&InstrumentRepeatability, &setup, &extent).unwrap();
        assert_eq!((l.u, l.divisor), (0.1, 1.0));
        assert!((l.contribution - 0.4).abs() < 1e-12);
    }
}
