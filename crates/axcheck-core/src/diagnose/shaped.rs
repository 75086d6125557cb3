//! Judging a term that takes a shape along the axis (the reversal variation and the
//! scatter variation, issue 43): the shape chosen by held-out error (RMS, or log density
//! for the scatter) among those the plan offers ([`Shape`]), and its gain compared with
//! the same choice made on tests simulated from the model without the term.
//!
//! Why simulated tests and not the targets in random orders ([`super::confirm`]): one
//! value per target is the same term in every order of the targets, and with 5 targets a
//! line has only 60 distinct fits, many of which fit a worn section as well as the real
//! order does. A test simulated from the model of the terms kept so far, with this test's
//! own plan, times and folds and the standard's one σ, is a test the term is
//! unrelated to. Every fit here is linear in the readings with the cell means free, so
//! the target means and the kept terms' values drop out of the held-out errors and only
//! the scatter matters: the simulated readings are the scatter alone (a parametric
//! bootstrap of the null model; Davison & Hinkley 1997, "Bootstrap Methods and their
//! Application", §4.2.3). The kept warm-up's time constant is fixed at its value on the
//! real readings, so that the fit stays linear.
//!
//! The statistic is the gain of the best shape, and each simulated test chooses its best
//! shape too, so the choice among shapes costs what it costs on data without the effect:
//! the term is kept when its gain beats all [`UNRELATED`] simulated ones (5 % for a term
//! unrelated to the data).

use super::confirm::UNRELATED;
use super::model_terms::ModelTerms;
use super::prep::Prep;
use super::scheme::{Scheme, gain_pct};
use super::shape::Shape;
use super::validate::{self, Rows, Score};
use crate::axis_model::rng::Rng;
use serde::Serialize;

/// One shape's held-out error on the real readings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ShapeScore {
    pub shape: Shape,
    pub parameters: usize,
    /// Held-out RMS of the readings with the term in this shape.
    pub heldout_rms: f64,
    /// Their held-out negative log density, nats per reading, where the shape is chosen
    /// by it (a scatter's term).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heldout_nlpd: Option<f64>,
}

/// The judgement of a shaped term.
pub(crate) struct Shaped {
    /// The shape with the smallest held-out error.
    pub shape: Shape,
    /// The model with the term in that shape.
    pub(crate) score: Score,
    /// Every shape offered.
    pub shapes: Vec<ShapeScore>,
    /// The best shape's gain on each simulated test, %.
    pub(crate) null_gains_pct: Vec<f64>,
}

/// What a cross-validation of the shaped term needs: the plan, its folds and which
/// readings are scored and trained on.
pub(crate) struct Setup<'a> {
    pub(crate) prep: &'a Prep,
    pub fold: &'a [usize],
    pub rows: Rows<'a>,
    /// The terms kept before (their warm-up's τ fixed), without the term.
    pub kept: ModelTerms,
    /// Turns the term on in a shape.
    pub set: fn(&mut ModelTerms, Shape),
    /// What the shapes are scored by: held-out RMS, or log density for a scatter.
    pub(crate) scheme: Scheme,
}

impl Setup<'_> {
    /// The held-out scores of `x`: without the term, then with it in each shape of
    /// `shapes`.
    fn scores(&self, x: &[f64], shapes: &[Shape]) -> Vec<Score> {
        let along = self.prep.positions.as_slice();
        let variants: Vec<(&[f64], ModelTerms)> = std::iter::once(self.kept)
            .chain(shapes.iter().map(|&s| {
                let mut t = self.kept;
                (self.set)(&mut t, s);
                t
            }))
            .map(|t| (along, t))
            .collect();
        validate::variants_scores(self.prep, x, self.fold, self.rows, self.kept, &variants)
    }

    /// The best shape's gain over the model without the term, % of its held-out RMS (or
    /// density), and its index in `shapes` (a later shape must do strictly better than a
    /// simpler one).
    fn best(&self, scores: &[Score]) -> (f64, usize) {
        let without = self.scheme.measure(&scores[0]);
        let mut best = (f64::NEG_INFINITY, 0);
        for (j, s) in scores[1..].iter().enumerate() {
            let gain = gain_pct(self.scheme, without, self.scheme.measure(s));
            if gain > best.0 {
                best = (gain, j);
            }
        }
        best
    }
}

/// Judges the shaped term on the readings `x`; `seed` draws the simulated tests.
pub(crate) fn judge(setup: &Setup, x: &[f64], seed: u64) -> Option<Shaped> {
    let shapes = Shape::offered_on(setup.prep.m);
    if shapes.is_empty() {
        return None;
    }
    let real = setup.scores(x, &shapes);
    let (_, j) = setup.best(&real);
    // One σ, the standard's model: its scale drops out of the gains. The readings
    // diagnosed as outliers are not scored, and a scatter that changes along the axis is
    // judged after this term, so neither shapes the null.
    let rows = setup.prep.rows.len();
    let mut rng = Rng::new(seed, 0x5A9E);
    let null_gains_pct = (0..UNRELATED)
        .map(|_| {
            let sim: Vec<f64> = (0..rows).map(|_| rng.normal()).collect();
            setup.best(&setup.scores(&sim, &shapes)).0
        })
        .collect();
    Some(Shaped {
        shape: shapes[j],
        score: real[j + 1],
        shapes: (shapes.iter().zip(&real[1..]))
            .map(|(&shape, s)| ShapeScore {
                shape,
                parameters: shape.parameters(setup.prep.m),
                heldout_rms: s.rms,
                heldout_nlpd: (setup.scheme == Scheme::KFoldDensity).then_some(s.nlpd),
            })
            .collect(),
        null_gains_pct,
    })
}
