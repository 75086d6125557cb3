//! The contributors to the budget, one file each: what the input quantity is, its
//! distribution, how the parameter depends on it (the sensitivity coefficient, GUM 5.1.3)
//! and for which parameters it applies.
//!
//! The list follows the error sources of laser calibration of machine tools (the
//! instrument, the wavelength compensation, material temperature and expansion, cosine
//! error and dead path: HP 5528A User's Guide, section 6) and the contributors ISO/TR
//! 230-9:2005 and ISO 230-2 (editions from 2006, Annex A) name for positioning tests (the
//! device, the machine temperature measurement, the expansion coefficient, misalignment,
//! the environment's variation), with the Type A part of the estimates themselves.

mod air_humidity;
mod air_pressure;
mod air_temperature;
mod calibration;
mod dead_path;
mod expansion_coefficient;
mod instrument_repeatability;
mod material_temperature;
mod mean_of_n;
mod misalignment;
mod resolution;
mod s_of_n;
mod temperature_change;
mod uncorrected_expansion;

use super::budget::{BudgetLine, Input};
use super::extent::{Extent, ExtentShape};
use super::setup::Setup;
use crate::units::AxisKind;

/// Sensitivities of the refractive index of air (and so of the laser's wavelength in air)
/// near 20 °C, 101.325 kPa and 50 %RH, in ppm per unit, from Edlén's equation in the
/// shop-floor form of Stone and Zimmerman (NIST, "Index of Refraction of Air",
/// Appendix B): n = 1 + 7.86·10⁻⁴·p/(273 + t) − 1.5·10⁻¹¹·RH·(t² + 160), p in kPa.
/// The temperature's is the air density's (dry air); at 50 %RH the water vapour term adds
/// 0.03 ppm/°C. The HP 5528A User's Guide (section 6) rounds them to 1 ppm per 1 °C,
/// per 2.5 mmHg and per 80 %RH.
pub mod edlen {
    /// |∂n/∂t|, ppm per °C.
    pub const PPM_PER_C: f64 = 0.93;
    /// ∂n/∂p, ppm per kPa (0.27 ppm per hPa).
    pub const PPM_PER_KPA: f64 = 2.7;
    /// |∂n/∂RH|, ppm per %RH.
    pub const PPM_PER_PCT_RH: f64 = 0.0085;
}

/// What a contributor sees: the set-up, the axis and the parameter's extent.
#[derive(Debug, Clone, Copy)]
pub struct Context<'a> {
    pub setup: &'a Setup,
    pub kind: AxisKind,
    /// The measurement travel, mm or deg.
    pub travel: f64,
    pub extent: &'a Extent,
}

impl Context<'_> {
    /// The extent's length in metres on a linear axis: the sensitivity of a relative
    /// (ppm) error is L µm per ppm, of a temperature α·L µm per °C.
    pub(crate) fn length_m(&self) -> f64 {
        self.extent.length / 1000.0
    }

    /// α·L, µm per °C: the sensitivity of the range to a temperature error of the
    /// positioning system (ISO 230-2 3.1), shared by the temperature contributors.
    pub(crate) fn expansion_per_c(&self) -> f64 {
        self.setup.thermal.coefficient_um_per_m_c * self.length_m()
    }

    /// A range on a linear axis: where length-proportional errors act.
    pub(crate) fn linear_range(&self) -> bool {
        self.kind == AxisKind::Linear && self.extent.shape == ExtentShape::Range
    }

    /// `um` or `arcsec`.
    pub fn unit(&self) -> &'static str {
        self.kind.deviation_unit()
    }
}

/// One source of uncertainty.
pub trait Contributor: Sync {
    /// Stable key in budgets and JSON: `calibration`, `air_temperature` …
    fn name(&self) -> &'static str;

    /// The input quantity for this parameter; `None` where the contributor does not apply.
    fn input(&self, ctx: &Context) -> Option<Input>;

    /// ∂(parameter)/∂(input): deviation unit per the input's unit.
    fn sensitivity(&self, ctx: &Context) -> f64;

    /// The budget line; none where the contributor does not apply or its value is 0.
    fn line(&self, ctx: &Context) -> Option<BudgetLine> {
        let input = self.input(ctx).filter(|i| i.value != 0.0)?;
        Some(BudgetLine::new(self.name(), input, self.sensitivity(ctx)))
    }
}

/// Every contributor, in the order budgets list them.
pub static ALL: &[&dyn Contributor] = &[
    &calibration::Calibration,
    &resolution::Resolution,
    &instrument_repeatability::InstrumentRepeatability,
    &air_temperature::AirTemperature,
    &air_pressure::AirPressure,
    &air_humidity::AirHumidity,
    &dead_path::DeadPath,
    &misalignment::Misalignment,
    &material_temperature::MaterialTemperature,
    &expansion_coefficient::ExpansionCoefficient,
    &uncorrected_expansion::UncorrectedExpansion,
    &temperature_change::TemperatureChange,
    &mean_of_n::MeanOfN,
    &s_of_n::SOfN,
];

/// The lines of every contributor that applies.
pub fn lines(ctx: &Context) -> Vec<BudgetLine> {
    ALL.iter().filter_map(|c| c.line(ctx)).collect()
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::uncertainty::setup::InstrumentKind;

    /// A linear range of `length_mm` over a travel of 1000 mm with `setup`.
    pub(crate) fn line_for(
        c: &dyn Contributor,
        setup: &Setup,
        extent: &Extent,
    ) -> Option<BudgetLine> {
        c.line(&Context {
            setup,
            kind: AxisKind::Linear,
            travel: 1000.0,
            extent,
        })
    }

    /// The shop-floor refractive index (ppm above 1) at t °C, p kPa, RH %.
    fn shop_floor_ppm(t: f64, p: f64, rh: f64) -> f64 {
        1e6 * (7.86e-4 * p / (273.0 + t) - 1.5e-11 * rh * (t * t + 160.0))
    }

    /// The rounded sensitivities against the shop-floor formula's derivatives at 20 °C,
    /// 101.325 kPa: 0.927 ppm/°C for dry air (0.958 at 50 %RH, where the water vapour
    /// term adds 0.03 ppm/°C: 0.93 is 3 % low there), 2.68 ppm/kPa, 0.0084 ppm/%RH.
    #[test]
    fn edlen_sensitivities_match_the_shop_floor_formula() {
        let (t, p, rh) = (20.0, 101.325, 50.0);
        let h = 1e-3;
        let d = |f: &dyn Fn(f64) -> f64, x: f64| ((f(x + h) - f(x - h)) / (2.0 * h)).abs();
        let dt = d(&|t| shop_floor_ppm(t, p, 0.0), t);
        let dt_humid = d(&|t| shop_floor_ppm(t, p, rh), t);
        let dp = d(&|p| shop_floor_ppm(t, p, rh), p);
        let drh = d(&|rh| shop_floor_ppm(t, p, rh), rh);
        assert!((dt / edlen::PPM_PER_C - 1.0).abs() < 0.005, "{dt}");
        assert!(
            (dt_humid / edlen::PPM_PER_C - 1.0).abs() < 0.035,
            "{dt_humid}"
        );
        assert!((dp / edlen::PPM_PER_KPA - 1.0).abs() < 0.01, "{dp}");
        assert!((drh / edlen::PPM_PER_PCT_RH - 1.0).abs() < 0.015, "{drh}");
    }

    /// The laser's default wavelength part (±0.05 ppm) and compensation sensors (±0.2 °C,
    /// ±0.1 kPa, ±6 %RH), all rectangular, give U (k = 2) = 2·√(0.0289² + 0.1074² +
    /// 0.1559² + 0.0294²) = 0.387 ppm: within the ±0.5 ppm that laser systems state for
    /// their compensated linear accuracy.
    #[test]
    fn laser_defaults_stay_within_the_stated_system_accuracy() {
        let setup = Setup::for_instrument(InstrumentKind::LaserInterferometer);
        let extent = Extent::range(1000.0);
        let names = [
            "calibration",
            "air_temperature",
            "air_pressure",
            "air_humidity",
        ];
        let u: f64 = ALL
            .iter()
            .filter(|c| names.contains(&c.name()))
            .filter_map(|c| line_for(*c, &setup, &extent))
            .map(|l| l.contribution.powi(2))
            .sum::<f64>()
            .sqrt();
        assert!((2.0 * u - 0.3875).abs() < 1e-3, "{}", 2.0 * u);
        assert!(2.0 * u < 0.5);
    }

    #[test]
    fn names_are_unique() {
        let mut names: Vec<&str> = ALL.iter().map(|c| c.name()).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), ALL.len());
    }
}
