//! What the budget needs to know about a test: the instrument, its environmental
//! compensation, the temperatures and the set-up. Pure data with documented defaults per
//! instrument kind, for whatever the campaign does not say.
//!
//! Sources of the defaults (by title): ISO 230-2:1997 clause 3.1 (the typical ±2 µm/(m·°C)
//! uncertainty of the expansion coefficient); data sheets of laser measurement systems
//! (laser frequency accuracy ±0.05 ppm; compensator sensors ±0.2 °C air, ±1 hPa, ±6 %RH,
//! ±0.1 °C material; e.g. the HP 5528A Laser Measurement System User's Guide, section 6,
//! and the Agilent Laser and Optics User's Manual, chapter "Accuracy and Repeatability",
//! list the same error sources); sealed linear encoders' accuracy grades (±3 µm and ±5 µm
//! over any metre); angle references of about 1″ (Lu et al., "On-axis self-calibration of
//! angle encoders", CIRP Annals 59, 2010: the best commercial angle encoders reach about
//! 1″). Where no source gives a number the default says so ("assumed").

use super::budget::Distribution;
use crate::units::AxisKind;
use serde::Serialize;

/// The measuring instrument's kind: it decides the defaults and which contributors apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum InstrumentKind {
    /// A laser interferometer measuring length in air, with environmental compensation.
    LaserInterferometer,
    /// A linear encoder or reference scale.
    LinearEncoder,
    /// A laser triangulation sensor or another displacement sensor (capacitive, LVDT …).
    DisplacementSensor,
    /// An angular interferometer with a rotary indexer (a rotary calibrator).
    AngularInterferometer,
    /// An autocollimator reading a calibrated polygon.
    AutocollimatorPolygon,
    /// A reference angle encoder.
    AngleEncoder,
    /// Anything else: the defaults are deliberately loose.
    Other,
}

impl InstrumentKind {
    pub const ALL: [InstrumentKind; 7] = [
        InstrumentKind::LaserInterferometer,
        InstrumentKind::LinearEncoder,
        InstrumentKind::DisplacementSensor,
        InstrumentKind::AngularInterferometer,
        InstrumentKind::AutocollimatorPolygon,
        InstrumentKind::AngleEncoder,
        InstrumentKind::Other,
    ];

    /// The axis kind the instrument measures; `None` for [`InstrumentKind::Other`].
    pub fn measures(self) -> Option<AxisKind> {
        match self {
            InstrumentKind::LaserInterferometer
            | InstrumentKind::LinearEncoder
            | InstrumentKind::DisplacementSensor => Some(AxisKind::Linear),
            InstrumentKind::AngularInterferometer
            | InstrumentKind::AutocollimatorPolygon
            | InstrumentKind::AngleEncoder => Some(AxisKind::Rotary),
            InstrumentKind::Other => None,
        }
    }

    /// The instrument's kind guessed from its name in the campaign (`laser interferometer
    /// XL-80`, `encoder (reference system)`, `autocollimator and 12-sided polygon` …).
    pub fn from_name(name: &str) -> Option<InstrumentKind> {
        let name = name.to_lowercase();
        let has = |words: &[&str]| words.iter().any(|w| name.contains(w));
        Some(if has(&["autocollimator", "polygon"]) {
            InstrumentKind::AutocollimatorPolygon
        } else if has(&["angle encoder", "angular encoder"]) {
            InstrumentKind::AngleEncoder
        } else if has(&["angular", "rotary calibrator", "xr20", "rotary indexer"]) {
            InstrumentKind::AngularInterferometer
        } else if has(&[
            "laser interferometer",
            "interferometer",
            "xl-80",
            "ml10",
            "laser",
        ]) {
            if has(&["triangulation"]) {
                InstrumentKind::DisplacementSensor
            } else {
                InstrumentKind::LaserInterferometer
            }
        } else if has(&["encoder", "scale"]) {
            InstrumentKind::LinearEncoder
        } else if has(&[
            "sensor",
            "probe",
            "lvdt",
            "capacitive",
            "displacement",
            "indicator",
        ]) {
            InstrumentKind::DisplacementSensor
        } else {
            return None;
        })
    }

    /// The instrument's defaults (module documentation: sources).
    pub fn defaults(self) -> Instrument {
        let (calibration_fixed, calibration_ppm, resolution) = match self {
            // Laser frequency (vacuum wavelength) accuracy ±0.05 ppm of stabilised He-Ne
            // laser heads; resolution 1 nm. The compensation is separate (AirCompensation).
            InstrumentKind::LaserInterferometer => (0.0, 0.05, 0.001),
            // An accuracy grade of ±3 µm (over any metre of a sealed scale); 0.1 µm steps.
            InstrumentKind::LinearEncoder => (3.0, 0.0, 0.1),
            // Assumed: ±1 µm linearity over a short range (0.1 % of 1 mm), 0.1 µm steps.
            InstrumentKind::DisplacementSensor => (1.0, 0.0, 0.1),
            // ±1″ for rotary calibrators and angle encoders (about the best commercial
            // angle encoders, Lu et al. 2010); 0.1″ steps.
            InstrumentKind::AngularInterferometer | InstrumentKind::AngleEncoder => (1.0, 0.0, 0.1),
            // Assumed: ±0.5″ for a calibrated polygon read by an autocollimator; 0.1″.
            InstrumentKind::AutocollimatorPolygon => (0.5, 0.0, 0.1),
            // Assumed, loose: ±(1 + 1 ppm), in µm or arcsec.
            InstrumentKind::Other => (1.0, 1.0, 0.1),
        };
        Instrument {
            kind: self,
            calibration_fixed,
            calibration_ppm,
            calibration_distribution: Distribution::Rectangular,
            resolution,
            repeatability: None,
        }
    }
}

/// The measuring instrument.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Instrument {
    pub kind: InstrumentKind,
    /// Fixed part of the stated accuracy ±(fixed + ppm·L), in the deviation unit (µm or
    /// arcsec).
    pub calibration_fixed: f64,
    /// Length-proportional part of the stated accuracy, ppm of the measured length (0 for
    /// angle references: their accuracy does not grow with the angle).
    pub calibration_ppm: f64,
    /// Rectangular for a manufacturer's ±specification; `Normal { k: 2.0 }` for the
    /// expanded uncertainty of a calibration certificate.
    pub calibration_distribution: Distribution,
    /// Reading resolution (the smallest step of the indication), deviation unit.
    pub resolution: f64,
    /// Standard deviation of the instrument's readings with the set-up at rest for the
    /// duration of a test (a drift check), deviation unit; `None` when not measured.
    pub repeatability: Option<f64>,
}

/// The laser's environmental compensation: the uncertainties of its air sensors, which
/// become an uncertainty of the wavelength in air (Edlén).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AirCompensation {
    /// Half-width of the air temperature sensor's uncertainty, °C (default ±0.2).
    pub(crate) temperature_sensor_c: f64,
    /// Half-width of the air pressure sensor's uncertainty, kPa (default ±0.1 = ±1 hPa).
    pub(crate) pressure_sensor_kpa: f64,
    /// Half-width of the humidity sensor's uncertainty, %RH (default ±6).
    pub(crate) humidity_sensor_pct: f64,
    /// Change of the air temperature during the test (end − start), °C: what the dead
    /// path's refractive index changes by.
    pub temperature_change_c: f64,
}

impl Default for AirCompensation {
    fn default() -> Self {
        AirCompensation {
            temperature_sensor_c: 0.2,
            pressure_sensor_kpa: 0.1,
            humidity_sensor_pct: 6.0,
            temperature_change_c: 0.0,
        }
    }
}

/// Temperatures and thermal expansion (ISO 230-2 clause 3.1).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Thermal {
    /// The nominal differential expansion coefficient between the axis's positioning
    /// system and the instrument, µm/(m·°C): the machine's own for a laser (default 11.5,
    /// steel); the difference of the two for a scale.
    pub coefficient_um_per_m_c: f64,
    /// Half-width of the coefficient's uncertainty, µm/(m·°C): ISO 230-2 3.1 gives ±2 as
    /// the typical value.
    pub(crate) coefficient_uncertainty_um_per_m_c: f64,
    /// The deviations were corrected to 20 °C (NDE correction, clause 3.1).
    pub nde_corrected: bool,
    /// Mean temperature of the positioning system during the test (the mean of the
    /// material sensors' start and end readings), °C; `None` when not recorded.
    pub mean_c: Option<f64>,
    /// Change of that temperature during the test (end − start), °C; 0 when the
    /// correction followed each reading's own temperature.
    pub change_c: f64,
    /// Half-width of the material temperature sensors' uncertainty, °C (default ±0.1).
    pub(crate) sensor_c: f64,
    /// Half-width assumed for |T − 20 °C| when the temperature was not recorded, °C
    /// (default ±1: a test meant to be made at 20 °C, clause 3.1, in a room held near it).
    pub(crate) unrecorded_band_c: f64,
}

impl Default for Thermal {
    fn default() -> Self {
        Thermal {
            coefficient_um_per_m_c: 11.5,
            coefficient_uncertainty_um_per_m_c: 2.0,
            nde_corrected: false,
            mean_c: None,
            change_c: 0.0,
            sensor_c: 0.1,
            unrecorded_band_c: 1.0,
        }
    }
}

impl Thermal {
    /// Sets the mean and the change from the material sensors' (start, end) readings, °C:
    /// the mean of all readings (as the NDE correction uses it) and the change of the
    /// sensors' mean from start to end. No readings: left as they are.
    pub fn set_from_sensors(&mut self, readings: &[(f64, f64)]) {
        if readings.is_empty() {
            return;
        }
        let count = readings.len() as f64;
        let start = readings.iter().map(|r| r.0).sum::<f64>() / count;
        let end = readings.iter().map(|r| r.1).sum::<f64>() / count;
        self.mean_c = Some((start + end) / 2.0);
        self.change_c = end - start;
    }

    /// |T − 20 °C|: from the recorded mean, else the assumed band.
    pub(crate) fn offset_from_20_c(&self) -> f64 {
        self.mean_c
            .map_or(self.unrecorded_band_c, |t| (t - 20.0).abs())
    }
}

/// Everything the budget needs to know about one axis test.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Setup {
    pub instrument: Instrument,
    /// The laser's environmental compensation; `None` for instruments without an air path.
    pub air: Option<AirCompensation>,
    pub thermal: Thermal,
    /// Lateral walk of the beam on its target (or offset of a scale) over the measurement
    /// travel, mm: the misalignment angle of the cosine error is offset / travel (default
    /// 0.5 mm, assumed: a beam aligned by eye on the target).
    pub misalignment_offset_mm: f64,
    /// Dead path: distance from the interferometer to the reflector at the datum, mm
    /// (default 100 for a laser, assumed; 0 when the laser's software compensates it).
    pub dead_path_mm: f64,
}

impl Setup {
    /// The defaults of an instrument of `kind`.
    pub fn for_instrument(kind: InstrumentKind) -> Setup {
        let laser = kind == InstrumentKind::LaserInterferometer;
        Setup {
            instrument: kind.defaults(),
            air: laser.then(AirCompensation::default),
            thermal: Thermal::default(),
            misalignment_offset_mm: if kind.measures() == Some(AxisKind::Rotary) {
                0.0
            } else {
                0.5
            },
            dead_path_mm: if laser { 100.0 } else { 0.0 },
        }
    }

    /// The defaults for an axis of `kind` when the campaign names no instrument: a laser
    /// interferometer on a linear axis, an angular interferometer on a rotary one.
    pub fn for_axis(kind: AxisKind) -> Setup {
        Setup::for_instrument(match kind {
            AxisKind::Linear => InstrumentKind::LaserInterferometer,
            AxisKind::Rotary => InstrumentKind::AngularInterferometer,
        })
    }
}

impl Default for Setup {
    /// A laser interferometer on a linear axis.
    fn default() -> Self {
        Setup::for_axis(AxisKind::Linear)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn kinds_from_campaign_names() {
        let kind = InstrumentKind::from_name;
        assert_eq!(
            kind("laser interferometer XL-80 (example)"),
            Some(InstrumentKind::LaserInterferometer)
        );
        assert_eq!(
            kind("encoder (reference system)"),
            Some(InstrumentKind::LinearEncoder)
        );
        assert_eq!(
            kind("Autocollimator with 12-sided polygon"),
            Some(InstrumentKind::AutocollimatorPolygon)
        );
        assert_eq!(
            kind("XR20 rotary calibrator"),
            Some(InstrumentKind::AngularInterferometer)
        );
        assert_eq!(
            kind("laser triangulation sensor"),
            Some(InstrumentKind::DisplacementSensor)
        );
        assert_eq!(
            kind("RCN angle encoder"),
            Some(InstrumentKind::AngleEncoder)
        );
        assert_eq!(kind("×××"), None);
    }

    #[test]
    fn defaults_follow_the_instrument() {
        let laser = Setup::default();
        assert_eq!(laser.instrument.kind, InstrumentKind::LaserInterferometer);
        assert!(laser.air.is_some());
        assert_eq!(laser.dead_path_mm, 100.0);
        let rotary = Setup::for_axis(AxisKind::Rotary);
        assert_eq!(rotary.instrument.calibration_ppm, 0.0);
        assert_eq!(rotary.misalignment_offset_mm, 0.0);
        assert!(rotary.air.is_none());
        for kind in InstrumentKind::ALL {
            let i = kind.defaults();
            assert!(i.calibration_fixed >= 0.0 && i.calibration_ppm >= 0.0 && i.resolution > 0.0);
            assert!(
                Setup::for_instrument(kind).air.is_some()
                    == (kind == InstrumentKind::LaserInterferometer)
            );
        }
    }

    /// ISO 230-2 Table 2's sensors: 21.8 → 22.9 and 22.4 → 23.1 °C: T = 22.55 °C,
    /// ΔT = 23.0 − 22.1 = 0.9 °C.
    #[test]
    fn mean_and_change_from_start_and_end_readings() {
        let mut t = Thermal::default();
        t.set_from_sensors(&[]);
        assert_eq!((t.mean_c, t.change_c), (None, 0.0));
        t.set_from_sensors(&[(21.8, 22.9), (22.4, 23.1)]);
        assert!((t.mean_c.unwrap() - 22.55).abs() < 1e-12);
        assert!((t.change_c - 0.9).abs() < 1e-12);
    }

    #[test]
    fn temperature_offset_falls_back_to_the_band() {
        let mut t = Thermal::default();
        assert_eq!(t.offset_from_20_c(), 1.0);
        t.mean_c = Some(22.55);
        assert!((t.offset_from_20_c() - 2.55).abs() < 1e-12);
        t.mean_c = Some(19.5);
        assert!((t.offset_from_20_c() - 0.5).abs() < 1e-12);
    }
}
