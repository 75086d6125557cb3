//! Out-of-test prediction: the models fitted on one test of an axis predict the readings of
//! another test of the same axis (a campaign axis with several data files).
//!
//! The in-test held-out error asks a model to predict readings of the test it was fitted
//! on; another test asks whether what it learnt about the axis holds on another day, over
//! another plan. Only the position-dependent part transfers (systematic deviation,
//! reversal, periodic error): time effects restart with each test and are left out, and
//! the laser's datum is set anew for each test, so one constant (the datum offset) is
//! fitted; the RMS divides by the readings less that one constant.

use super::Diagnosis;
use crate::axis_model::ErrorModel;
use crate::measurement::AxisData;
use serde::Serialize;

/// How well the models of one test predict another test of the same axis.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OutOfTest {
    /// The test whose models predict (1-based among the axis's tests) and its file.
    pub from_test: usize,
    pub from_file: Option<String>,
    /// Readings of this test inside the other test's measured travel (the ones predicted).
    pub readings: usize,
    /// Deviation unit of the figures below: `um` or `arcsec`.
    pub unit: &'static str,
    /// Datum difference between the tests: mean of reading − prediction.
    pub datum_offset: f64,
    /// RMS prediction error of the base model (the standard's assumptions).
    pub base_rms: f64,
    /// RMS prediction error of the extended model (the kept terms).
    pub extended_rms: f64,
    /// The extended model's in-test held-out RMS, for comparison.
    pub in_test_rms: f64,
}

/// Predicts `data` (another test of the axis) from the diagnosis `from` of test
/// `from_test`; None when no reading lies within the travel `from` measured, or fewer
/// than two (one constant is fitted).
pub fn out_of_test(
    from: &Diagnosis,
    from_test: usize,
    from_file: Option<String>,
    data: &AxisData,
) -> Option<OutOfTest> {
    let base = prediction_errors(&from.base_model.model, data)?;
    let extended = prediction_errors(&from.extended_model.model, data)?;
    let offset = mean(&extended);
    Some(OutOfTest {
        from_test,
        from_file,
        readings: extended.len(),
        unit: data.kind.deviation_unit(),
        datum_offset: offset,
        base_rms: rms_about_mean(&base),
        extended_rms: rms_about_mean(&extended),
        in_test_rms: from.extended.heldout_rms,
    })
}

/// Reading − the model's position-dependent prediction, for the readings inside the
/// model's travel (its shape's first and last knot: the targets it was fitted on).
fn prediction_errors(model: &ErrorModel, data: &AxisData) -> Option<Vec<f64>> {
    let model = position_part(model);
    let (first, last) = (model.shape.first()?[0], model.shape.last()?[0]);
    let tolerance = 1e-6 * (last - first).abs().max(1.0);
    let inside = |p: f64| p >= first - tolerance && p <= last + tolerance;
    let errors: Vec<f64> = data
        .readings
        .iter()
        .filter(|r| inside(data.targets[r.target]))
        .map(|r| {
            let p = data.targets[r.target];
            r.deviation - model.expected(data.kind, p, r.direction, 0.0, (first, last))
        })
        .collect();
    (errors.len() >= 2).then_some(errors)
}

/// The model without its time terms (they restart with each test).
fn position_part(model: &ErrorModel) -> ErrorModel {
    ErrorModel {
        drift_per_h: 0.0,
        thermal_growth_ppm_per_h: 0.0,
        run_offsets: Vec::new(),
        run_offset_sd: 0.0,
        warm_up: 0.0,
        warm_up_ppm: 0.0,
        ..model.clone()
    }
}

fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// RMS about the mean, one degree of freedom taken by the mean (the datum offset).
fn rms_about_mean(values: &[f64]) -> f64 {
    let m = mean(values);
    let ss: f64 = values.iter().map(|v| (v - m).powi(2)).sum();
    (ss / (values.len() - 1) as f64).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rms_about_the_mean_by_hand() {
        // Mean 2, squares 1 + 0 + 1 = 2 over 3 − 1 = 2 → 1.
        assert_eq!(mean(&[1.0, 2.0, 3.0]), 2.0);
        assert_eq!(rms_about_mean(&[1.0, 2.0, 3.0]), 1.0);
    }

    /// Readings = the model + a datum of 2 µm ± 0.1 µm (run 1 +, run 2 −) at targets 0, 50
    /// and 100 mm, and a target at 150 mm outside the model's travel (not predicted).
    #[test]
    fn prediction_by_hand() {
        use crate::measurement::RawReading;
        use crate::units::{AxisKind, Direction};
        let model = ErrorModel {
            shape: vec![[0.0, 1.0], [100.0, 3.0]],
            reversal: 2.0,
            drift_per_h: 50.0,
            ..ErrorModel::default()
        };
        let mut raw = Vec::new();
        for target in [0.0f64, 50.0, 100.0, 150.0] {
            for direction in [Direction::Up, Direction::Down] {
                for run in [1u32, 2] {
                    // 1 + 2·P/100 (shape) ± 1 (half the reversal) + 2 (datum) ± 0.1.
                    let systematic = 1.0 + 2.0 * target.min(100.0) / 100.0;
                    let half_b = if direction == Direction::Up {
                        1.0
                    } else {
                        -1.0
                    };
                    let noise = if run == 1 { 0.1 } else { -0.1 };
                    raw.push(RawReading {
                        target,
                        direction,
                        run,
                        deviation: systematic + half_b + 2.0 + noise,
                        time_s: Some(3600.0 * f64::from(run)),
                        temps_c: Vec::new(),
                        line: 0,
                    });
                }
            }
        }
        let data = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "hand").unwrap();
        let errors = prediction_errors(&model, &data).unwrap();
        assert_eq!(
            errors.len(),
            12,
            "the 150 mm target lies outside the travel"
        );
        assert!((mean(&errors) - 2.0).abs() < 1e-12, "{}", mean(&errors));
        // 12 residuals ±0.1 about 2: sqrt(12 · 0.01 / 11).
        let want = (12.0 * 0.01f64 / 11.0).sqrt();
        assert!((rms_about_mean(&errors) - want).abs() < 1e-12);
    }

    #[test]
    fn time_terms_are_left_out() {
        let model = ErrorModel {
            drift_per_h: 3.0,
            thermal_growth_ppm_per_h: 2.0,
            run_offsets: vec![1.0, -1.0],
            warm_up: 5.0,
            warm_up_ppm: 3.0,
            warm_up_tau_min: 20.0,
            reversal: 4.0,
            ..ErrorModel::default()
        };
        let p = position_part(&model);
        assert_eq!((p.drift_per_h, p.thermal_growth_ppm_per_h), (0.0, 0.0));
        assert!(p.run_offsets.is_empty());
        assert_eq!((p.warm_up, p.warm_up_ppm), (0.0, 0.0));
        assert_eq!(p.reversal, 4.0);
    }
}
