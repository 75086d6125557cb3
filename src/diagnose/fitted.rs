//! The extended model fitted on all (non-outlier) readings with the kept terms, as the
//! effects read it ([`Fitted`]; it is fitted and written out as a simulation file in
//! `extended.rs`, above the effects), and the base model (the standard's assumptions,
//! simulated for the model checks) as a simulation file.

use super::analysis::Analysis;
use super::maths::linalg::smooth_trend;
use super::maths::periodogram::Peak;
use super::model::{PlanGuess, r4};
use super::validate::Predictor;
use crate::axis_model::{ErrorModel, Simulation, TestPlan};

/// The extended model's terms as the simulator has them.
pub(crate) struct Fitted {
    pub pred: Predictor,
    pub guess: PlanGuess,
    /// Hours per time unit (1, or the guessed plan's duration of a run).
    pub hours_per_unit: f64,
    /// Drift δ per time unit at the thermal origin.
    pub drift_rate: f64,
    /// Thermal growth γ, deviation per position unit per time unit.
    pub growth: f64,
    /// Where the thermal growth is zero.
    pub origin: f64,
    /// Run offsets, centred (empty without the term).
    pub run_offsets: Vec<f64>,
    /// Reversal value per target, and its mean.
    pub reversal: Vec<f64>,
    pub reversal_mean: f64,
    /// The periodic term, when kept.
    pub periodic: Option<Peak>,
    /// Rows the fit used.
    pub train: Vec<bool>,
}

/// The base model (the standard's assumptions) fitted to the raw readings: smooth
/// systematic deviation, one reversal value, white scatter, nothing in time.
pub(crate) fn base_model(a: &Analysis, plan: &TestPlan, seed: u64) -> Simulation {
    let (p, m) = (&a.prep, a.prep.m);
    let all = vec![true; a.x.len()];
    let (raw_means, _) = p.cell_means(&a.x, &all);
    let raw_bidir: Vec<f64> = (0..m)
        .map(|i| (raw_means[2 * i] + raw_means[2 * i + 1]) / 2.0)
        .collect();
    let raw_b: Vec<f64> = (0..m)
        .map(|i| raw_means[2 * i] - raw_means[2 * i + 1])
        .collect();
    let trend = smooth_trend(&p.positions, &raw_bidir);
    let raw_sigma = if p.n >= 2 {
        let ss: f64 = p
            .rows
            .iter()
            .zip(&a.x)
            .map(|(r, v)| (v - raw_means[p.cell(r)]).powi(2))
            .sum();
        (ss / (a.x.len() - p.cells()) as f64).sqrt()
    } else {
        0.0
    };
    Simulation {
        kind: a.data.kind,
        seed,
        description: Some(
            "base model fitted by axcheck diagnose: smooth systematic deviation, one reversal value, white scatter, nothing in time"
                .to_string(),
        ),
        model: ErrorModel {
            shape: p
                .positions
                .iter()
                .zip(&trend)
                .map(|(p, t)| [*p, r4(*t)])
                .collect(),
            reversal: r4(raw_b.iter().sum::<f64>() / m as f64),
            scatter: r4(raw_sigma),
            ..ErrorModel::default()
        },
        plan: plan.clone(),
    }
}
