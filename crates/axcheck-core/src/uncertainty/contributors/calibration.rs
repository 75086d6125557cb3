//! `calibration`: the instrument's stated accuracy ±(fixed + ppm·L).
//!
//! Input: the error of the instrument over the length L a range parameter spans,
//! a = fixed + ppm·L (the form manufacturers state and calibration certificates give),
//! in µm or arcsec; rectangular for a ±specification (u = a/√3, GUM 4.3.7), normal with
//! the certificate's k for a calibration's expanded uncertainty (u = a/k, GUM 4.3.3).
//! Sensitivity 1. Only for ranges: at one position (B, R) the instrument's error is the
//! same for every reading and cancels. Angle references have no length-proportional
//! part: their accuracy does not grow with the angle.

use super::{Context, Contributor};
use crate::uncertainty::budget::Input;
use crate::uncertainty::extent::ExtentShape;

pub(crate) struct Calibration;

impl Contributor for Calibration {
    fn name(&self) -> &'static str {
        "calibration"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        if ctx.extent.shape != ExtentShape::Range {
            return None;
        }
        let i = &ctx.setup.instrument;
        Some(Input {
            value: i.calibration_fixed
                + ctx
                    .kind
                    .ppm_to_deviation(i.calibration_ppm, ctx.extent.length),
            unit: ctx.unit(),
            distribution: i.calibration_distribution,
        })
    }

    fn sensitivity(&self, _: &Context) -> f64 {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::budget::Distribution;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::{InstrumentKind, Setup};

    /// Laser: ±0.05 ppm over 1744.209 mm = ±0.087210 µm, u = 0.087210/√3 = 0.050351 µm.
    #[test]
    fn laser_over_the_table_2_travel() {
        let setup = Setup::default();
        let l = line_for(&Calibration, &setup, &Extent::range(1744.209)).unwrap();
        assert!((l.value - 0.087_210).abs() < 1e-6);
        assert!((l.u - 0.050_351).abs() < 1e-6);
        assert_eq!(l.unit, "um");
    }

    /// A certificate's U = 0.5 µm + 0.4 ppm (k = 2) over 500 mm: a = 0.7 µm, u = 0.35 µm.
    #[test]
    fn certificate_with_k_2() {
        let mut setup = Setup::for_instrument(InstrumentKind::LinearEncoder);
        setup.instrument.calibration_fixed = 0.5;
        setup.instrument.calibration_ppm = 0.4;
        setup.instrument.calibration_distribution = Distribution::Normal { k: 2.0 };
        let l = line_for(&Calibration, &setup, &Extent::range(500.0)).unwrap();
        assert!((l.value - 0.7).abs() < 1e-12 && (l.u - 0.35).abs() < 1e-12);
        assert_eq!(l.distribution.name(), "normal");
    }

    #[test]
    fn not_at_one_position() {
        let mut extent = Extent::range(0.0);
        extent.shape = ExtentShape::Reversal;
        let setup = Setup::for_instrument(InstrumentKind::LinearEncoder);
        assert!(line_for(&Calibration, &setup, &extent).is_none());
    }
}
