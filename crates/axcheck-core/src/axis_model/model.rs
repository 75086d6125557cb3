//! The axis error model: what the deviation X_ij of one reading is made of.
//!
//! Terms (Hemingray, Cowley and Burdekin 1971: progressive and periodic error, lost motion, drift,
//! thermal growth, scatter): a linear scale error, a smooth systematic shape, periodic
//! errors, a reversal value (constant or varying linearly along the axis), a drift in
//! time uniform along the axis, a thermal growth proportional to position × time, a
//! warm-up (an exponential approach to a new level, uniform and in proportion to
//! position; ISO 230-2 clause 3.3), per-run offsets, random scatter (constant or varying along the axis) and outliers.
//! Deviations in the axis's deviation unit (µm or arcsec), positions in mm or deg.

use super::geometry::GeometryModel;
use crate::units::{AxisKind, Direction};
use serde::{Deserialize, Serialize};

/// A periodic error along the axis, e.g. lead-screw pitch error (Hemingray et al. 1971, §4).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PeriodicTerm {
    /// Period, mm or deg.
    #[serde(alias = "pitch_mm", alias = "pitch_deg")]
    pub pitch: f64,
    /// Amplitude (half peak-to-peak), µm or arcsec.
    #[serde(alias = "amplitude_um", alias = "amplitude_arcsec")]
    pub amplitude: f64,
    /// Phase at position 0, degrees of the period.
    #[serde(default)]
    pub phase_deg: f64,
}

/// One reading made an outlier on purpose.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlantedOutlier {
    /// Run j, 1-based.
    pub run: u32,
    pub direction: Direction,
    /// Target index i, 1-based.
    pub target: usize,
    /// Added deviation, µm or arcsec.
    #[serde(alias = "size_um", alias = "size_arcsec")]
    pub size: f64,
}

/// The error model. Every term defaults to zero (absent).
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ErrorModel {
    /// Linear scale error, ppm (µm/m on a linear axis).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "scale_um_per_m")]
    pub scale_ppm: f64,
    /// Smooth systematic shape: knots [position, deviation], interpolated by a C¹ cubic.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub shape: Vec<[f64; 2]>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub periodic: Vec<PeriodicTerm>,
    /// Reversal value B = X↑ − X↓ at the start of the travel (or everywhere).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "reversal_um", alias = "reversal_arcsec")]
    pub reversal: f64,
    /// Reversal value at the end of the travel; linear in between.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(alias = "reversal_end_um", alias = "reversal_end_arcsec")]
    pub reversal_end: Option<f64>,
    /// Reversal value B along the travel as knots [position, B], linear between them and
    /// constant beyond (a worn section, one value per target); replaces `reversal` and
    /// `reversal_end` where given.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    #[serde(alias = "reversal_knots_um", alias = "reversal_knots_arcsec")]
    pub reversal_knots: Vec<[f64; 2]>,
    /// Drift in time, uniform along the axis, per hour.
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "drift_um_per_h", alias = "drift_arcsec_per_h")]
    pub drift_per_h: f64,
    /// Thermal growth, ppm per hour (µm/m per hour): error = rate · t · (P − origin).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "thermal_growth_um_per_m_per_h")]
    pub thermal_growth_ppm_per_h: f64,
    /// Fixed end of the thermal growth (position where it is zero).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "thermal_origin_mm", alias = "thermal_origin_deg")]
    pub thermal_origin: f64,
    /// Warm-up: the deviations approach a new level, A·(1 − exp(−t/τ)) with t from the
    /// start of the test (a first-order thermal response; ISO 230-2 clause 3.3). A, µm or
    /// arcsec.
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "warm_up_um", alias = "warm_up_arcsec")]
    pub warm_up: f64,
    /// Position-dependent warm-up: ppm (µm/m) at the end state about `thermal_origin`,
    /// approached with the same time constant.
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "warm_up_um_per_m")]
    pub warm_up_ppm: f64,
    /// Time constant τ of the warm-up, minutes.
    #[serde(skip_serializing_if = "is_zero")]
    pub warm_up_tau_min: f64,
    /// Offset of each whole run, in run order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    #[serde(alias = "run_offsets_um", alias = "run_offsets_arcsec")]
    pub run_offsets: Vec<f64>,
    /// Standard deviation of random run offsets.
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "run_offset_sd_um", alias = "run_offset_sd_arcsec")]
    pub run_offset_sd: f64,
    /// Standard deviation of the random scatter at the start of the travel (or everywhere).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "scatter_um", alias = "scatter_arcsec")]
    pub scatter: f64,
    /// Scatter at the end of the travel; linear in between.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[serde(alias = "scatter_end_um", alias = "scatter_end_arcsec")]
    pub scatter_end: Option<f64>,
    /// Scatter σ along the travel as knots [position, σ], linear between them and constant
    /// beyond (a section that scatters more); replaces `scatter` and `scatter_end` where
    /// given.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    #[serde(alias = "scatter_knots_um", alias = "scatter_knots_arcsec")]
    pub scatter_knots: Vec<[f64; 2]>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub outliers: Vec<PlantedOutlier>,
    /// Probability that a reading is an outlier.
    #[serde(skip_serializing_if = "is_zero")]
    pub outlier_rate: f64,
    /// Size of random outliers (random sign).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "outlier_size_um", alias = "outlier_size_arcsec")]
    pub outlier_size: f64,
    /// Instrument resolution: readings are rounded to multiples of it (0: none).
    #[serde(skip_serializing_if = "is_zero")]
    #[serde(alias = "resolution_um", alias = "resolution_arcsec")]
    pub resolution: f64,
    /// Straightness, rotations and the beam's offset from the tool point (linear axes).
    #[serde(skip_serializing_if = "GeometryModel::is_empty")]
    pub geometry: GeometryModel,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// Linear interpolation weight of `position` between the ends of the travel.
fn along(position: f64, travel: (f64, f64)) -> f64 {
    let (a, b) = travel;
    if b > a {
        ((position - a) / (b - a)).clamp(0.0, 1.0)
    } else {
        0.0
    }
}

impl ErrorModel {
    /// The systematic (direction-free, time-free) deviation at `position`.
    pub fn systematic(&self, kind: AxisKind, position: f64) -> f64 {
        let mut value =
            kind.ppm_to_deviation(self.scale_ppm, position) + interpolate(&self.shape, position);
        for p in &self.periodic {
            let phase = p.phase_deg.to_radians();
            value += p.amplitude * (std::f64::consts::TAU * position / p.pitch + phase).sin();
        }
        value
    }

    /// The reversal value B at `position`.
    pub(crate) fn reversal_at(&self, position: f64, travel: (f64, f64)) -> f64 {
        if !self.reversal_knots.is_empty() {
            return piecewise_linear(&self.reversal_knots, position);
        }
        match self.reversal_end {
            Some(end) => self.reversal + (end - self.reversal) * along(position, travel),
            None => self.reversal,
        }
    }

    /// The scatter σ at `position`.
    pub(crate) fn scatter_at(&self, position: f64, travel: (f64, f64)) -> f64 {
        if !self.scatter_knots.is_empty() {
            return piecewise_linear(&self.scatter_knots, position);
        }
        match self.scatter_end {
            Some(end) => self.scatter + (end - self.scatter) * along(position, travel),
            None => self.scatter,
        }
    }

    /// The share of the warm-up reached `time_s` after the start of the test.
    pub(crate) fn warm_up_reached(&self, time_s: f64) -> f64 {
        if self.warm_up_tau_min > 0.0 {
            -(-time_s / 60.0 / self.warm_up_tau_min).exp_m1()
        } else {
            0.0
        }
    }

    /// The deterministic part of a reading: systematic + reversal/2 + drift + thermal
    /// growth + warm-up (without run offsets, scatter and outliers).
    pub fn expected(
        &self,
        kind: AxisKind,
        position: f64,
        direction: Direction,
        time_s: f64,
        travel: (f64, f64),
    ) -> f64 {
        let hours = time_s / 3600.0;
        self.systematic(kind, position)
            + direction.sign() * self.reversal_at(position, travel) / 2.0
            + self.drift_per_h * hours
            + kind.ppm_to_deviation(
                self.thermal_growth_ppm_per_h * hours,
                position - self.thermal_origin,
            )
            + self.warm_up_part(kind, position, time_s)
    }

    /// The warm-up's part of a reading at `position`, `time_s` after the start.
    fn warm_up_part(&self, kind: AxisKind, position: f64, time_s: f64) -> f64 {
        if self.warm_up == 0.0 && self.warm_up_ppm == 0.0 {
            return 0.0;
        }
        let reached = self.warm_up_reached(time_s);
        reached
            * (self.warm_up
                + kind.ppm_to_deviation(self.warm_up_ppm, position - self.thermal_origin))
    }

    /// Checks values a simulation cannot use.
    pub(crate) fn validate(&self, runs: usize, targets: usize) -> Result<(), String> {
        self.geometry.validate()?;
        let nonneg = [
            ("scatter", self.scatter),
            ("scatter_end", self.scatter_end.unwrap_or(0.0)),
            ("run_offset_sd", self.run_offset_sd),
            ("outlier_size", self.outlier_size),
            ("resolution", self.resolution),
        ];
        for (name, v) in nonneg {
            if !(v >= 0.0 && v.is_finite()) {
                return Err(format!(
                    "model.{name} must be a finite number ≥ 0, found {v}"
                ));
            }
        }
        self.validate_warm_up()?;
        if !(0.0..=1.0).contains(&self.outlier_rate) {
            return Err(format!(
                "model.outlier_rate must be between 0 and 1, found {}",
                self.outlier_rate
            ));
        }
        for p in &self.periodic {
            if !(p.pitch > 0.0 && p.pitch.is_finite()) {
                return Err(format!(
                    "model.periodic: pitch must be > 0, found {}",
                    p.pitch
                ));
            }
        }
        if !self.run_offsets.is_empty() && self.run_offsets.len() != runs {
            return Err(format!(
                "model.run_offsets has {} values but the plan has {runs} runs",
                self.run_offsets.len()
            ));
        }
        for o in &self.outliers {
            if o.run == 0 || o.run as usize > runs || o.target == 0 || o.target > targets {
                return Err(format!(
                    "model.outliers: run {} target {} is outside the plan ({runs} runs, {targets} targets)",
                    o.run, o.target
                ));
            }
        }
        if self
            .scatter_knots
            .iter()
            .any(|k| k[1].is_nan() || k[1] < 0.0)
        {
            return Err("model.scatter_knots: σ must be ≥ 0 at every knot".into());
        }
        let knotted = [
            ("shape", &self.shape),
            ("reversal_knots", &self.reversal_knots),
            ("scatter_knots", &self.scatter_knots),
        ];
        for (name, knots) in knotted {
            let mut last = f64::NEG_INFINITY;
            for k in knots {
                if k[0].partial_cmp(&last) != Some(std::cmp::Ordering::Greater) {
                    return Err(format!("model.{name}: knot positions must increase"));
                }
                if !k[1].is_finite() {
                    return Err(format!("model.{name}: a knot's value must be finite"));
                }
                last = k[0];
            }
        }
        Ok(())
    }
}

impl ErrorModel {
    /// A warm-up needs finite values and, when it has an amplitude, a time constant.
    fn validate_warm_up(&self) -> Result<(), String> {
        for (name, v) in [("warm_up", self.warm_up), ("warm_up_ppm", self.warm_up_ppm)] {
            if !v.is_finite() {
                return Err(format!("model.{name} must be a finite number, found {v}"));
            }
        }
        let tau = self.warm_up_tau_min;
        if !(tau >= 0.0 && tau.is_finite()) {
            return Err(format!(
                "model.warm_up_tau_min must be a finite number ≥ 0, found {tau}"
            ));
        }
        if tau == 0.0 && (self.warm_up != 0.0 || self.warm_up_ppm != 0.0) {
            let name = if self.warm_up != 0.0 {
                "warm_up"
            } else {
                "warm_up_ppm"
            };
            return Err(format!(
                "model.{name} needs a time constant: add model.warm_up_tau_min (> 0)"
            ));
        }
        Ok(())
    }
}

/// Linear interpolation through `knots` (positions increasing); constant beyond the ends.
pub(crate) fn piecewise_linear(knots: &[[f64; 2]], x: f64) -> f64 {
    let last = knots.len().saturating_sub(1);
    match knots {
        [] => 0.0,
        _ if x <= knots[0][0] => knots[0][1],
        _ if x >= knots[last][0] => knots[last][1],
        _ => {
            let j = knots.partition_point(|k| k[0] <= x).clamp(1, last);
            let ([x0, y0], [x1, y1]) = (knots[j - 1], knots[j]);
            y0 + (y1 - y0) * (x - x0) / (x1 - x0)
        }
    }
}

/// C¹ cubic Hermite interpolation through `knots` with finite-difference slopes;
/// constant beyond the ends; 0 without knots.
pub(crate) fn interpolate(knots: &[[f64; 2]], x: f64) -> f64 {
    match knots {
        [] => 0.0,
        [only] => only[1],
        _ => {
            let last = knots.len() - 1;
            if x <= knots[0][0] {
                return knots[0][1];
            }
            if x >= knots[last][0] {
                return knots[last][1];
            }
            let k = knots.partition_point(|p| p[0] <= x) - 1;
            let slope =
                |a: usize, b: usize| (knots[b][1] - knots[a][1]) / (knots[b][0] - knots[a][0]);
            let tangent = |i: usize| {
                if i == 0 {
                    slope(0, 1)
                } else if i == last {
                    slope(last - 1, last)
                } else {
                    (slope(i - 1, i) + slope(i, i + 1)) / 2.0
                }
            };
            let (x0, y0) = (knots[k][0], knots[k][1]);
            let (x1, y1) = (knots[k + 1][0], knots[k + 1][1]);
            let h = x1 - x0;
            let t = (x - x0) / h;
            let (t2, t3) = (t * t, t * t * t);
            (2.0 * t3 - 3.0 * t2 + 1.0) * y0
                + (t3 - 2.0 * t2 + t) * h * tangent(k)
                + (-2.0 * t3 + 3.0 * t2) * y1
                + (t3 - t2) * h * tangent(k + 1)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_passes_through_knots() {
        let knots = [[0.0, 1.0], [100.0, 3.0], [300.0, -2.0]];
        for k in knots {
            assert!((interpolate(&knots, k[0]) - k[1]).abs() < 1e-12);
        }
        assert_eq!(interpolate(&knots, -5.0), 1.0);
        assert_eq!(interpolate(&knots, 400.0), -2.0);
        let mid = interpolate(&knots, 50.0);
        assert!(mid > 1.0 && mid < 3.5, "{mid}");
    }

    #[test]
    fn expected_combines_terms() {
        let m = ErrorModel {
            scale_ppm: 10.0,
            reversal: 4.0,
            drift_per_h: 2.0,
            ..ErrorModel::default()
        };
        let travel = (0.0, 1000.0);
        let up = m.expected(AxisKind::Linear, 1000.0, Direction::Up, 1800.0, travel);
        let down = m.expected(AxisKind::Linear, 1000.0, Direction::Down, 1800.0, travel);
        assert!((up - (10.0 + 2.0 + 1.0)).abs() < 1e-12);
        assert!((up - down - 4.0).abs() < 1e-12);
    }

    /// A(1 − e^(−t/τ)) + ppm·(P − origin)·(1 − e^(−t/τ)), by hand: after one time constant
    /// 63.2 % of the way.
    #[test]
    fn warm_up_approaches_its_level() {
        let m = ErrorModel {
            warm_up: 5.0,
            warm_up_ppm: 10.0,
            warm_up_tau_min: 20.0,
            thermal_origin: 100.0,
            ..ErrorModel::default()
        };
        let travel = (0.0, 1000.0);
        let at = |p: f64, s: f64| m.expected(AxisKind::Linear, p, Direction::Up, s, travel);
        assert_eq!(at(100.0, 0.0), 0.0);
        let share = 1.0 - (-1.0f64).exp();
        assert!((at(100.0, 1200.0) - 5.0 * share).abs() < 1e-12);
        assert!((at(1100.0, 1200.0) - (5.0 + 10.0) * share).abs() < 1e-12);
        assert!((at(600.0, 1e9) - 10.0).abs() < 1e-9);
        assert_eq!(m.validate(5, 11), Ok(()));
        let no_tau = ErrorModel {
            warm_up_tau_min: 0.0,
            ..m
        };
        assert!(no_tau.validate(5, 11).is_err());
    }
}
