//! `dead_path`: the air between the interferometer and the reflector at the datum.
//!
//! The laser is zeroed with the reflector at the datum, a dead path D away from the
//! interferometer. The compensation corrects the wavelength over the measured length
//! only, so a change of the air during the test changes the optical length of D
//! uncorrected (HP 5528A User's Guide, section 6; Agilent 5530 Getting Started Guide,
//! "deadpath error"). Input: the change of the refractive index during the test,
//! Δn = 0.93 ppm/°C × |Δt_air| (Edlén; the pressure is recorded once, so its change is
//! not known), as a half-width, rectangular (GUM 4.3.7). Sensitivity: D in m, µm per
//! ppm. Independent of the parameter's length; it drifts the readings, so it applies to
//! every parameter of a linear axis measured by a laser. Set D = 0 when the laser's
//! software compensated the dead path.

use super::{Context, Contributor, edlen};
use crate::uncertainty::budget::{Distribution, Input};
use crate::units::AxisKind;

pub(crate) struct DeadPath;

impl Contributor for DeadPath {
    fn name(&self) -> &'static str {
        "dead_path"
    }

    fn input(&self, ctx: &Context) -> Option<Input> {
        let air = ctx
            .setup
            .air
            .as_ref()
            .filter(|_| ctx.kind == AxisKind::Linear)?;
        (ctx.setup.dead_path_mm > 0.0).then(|| Input {
            value: edlen::PPM_PER_C * air.temperature_change_c.abs(),
            unit: "ppm",
            distribution: Distribution::Rectangular,
        })
    }

    fn sensitivity(&self, ctx: &Context) -> f64 {
        ctx.setup.dead_path_mm / 1000.0
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::line_for;
    use super::*;
    use crate::uncertainty::extent::Extent;
    use crate::uncertainty::setup::Setup;

    /// Air 20.6 → 20.9 °C, D = 100 mm: Δn = 0.93 × 0.3 = 0.279 ppm, u = 0.161081 ppm,
    /// c = 0.1 µm/ppm, c·u = 0.016108 µm, whatever the length.
    #[test]
    fn air_change_over_the_dead_path() {
        let mut setup = Setup::default();
        let extent = Extent::range(0.0);
        assert!(
            line_for(&DeadPath, &setup, &extent).is_none(),
            "no change, no line"
        );
        setup.air.as_mut().unwrap().temperature_change_c = 0.3;
        let l = line_for(&DeadPath, &setup, &extent).unwrap();
        assert!((l.value - 0.279).abs() < 1e-12);
        assert!((l.contribution - 0.016_108).abs() < 1e-6);
        setup.dead_path_mm = 0.0;
        assert!(line_for(&DeadPath, &setup, &extent).is_none());
    }
}
