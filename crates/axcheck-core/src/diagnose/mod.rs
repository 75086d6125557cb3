//! Model check and diagnosis (issue 5): what the standard's model of an axis gets wrong
//! for one measurement, named from a fixed vocabulary, with evidence and fitted terms.
//!
//! ISO 230-2's numbers rest on a model the standard never states: a systematic deviation
//! at each target, one reversal value, independent scatter that does not depend on time.
//! Hemingray, Cowley & Burdekin (1971), the critique of the NMTBA and VDI 3441 tests, list
//! what breaks it and ask that each be measured and separated: progressive and periodic
//! error, lost motion, drift, thermal growth and the unidirectional scatter; ISO 230-2
//! clause 3.3 adds the warm-up a test should follow. This module
//!
//! 1. runs the tests once ([`analysis`]);
//! 2. lets each effect of the vocabulary ([`Effect`], one file each in [`effects`]) name
//!    its findings, each at level [`ALPHA`] (eight effects: the chance that data the base
//!    model explains get any finding is below 8 × 0.1 % = 0.8 %; at 0.2 % the sweep of
//!    clean data had 1.3 % with a finding);
//! 3. extends the model with the terms found, keeps a term only when it improves held-out
//!    prediction by more than a term unrelated to the data would ([`select`],
//!    [`validate`], [`confirm`]; a finding whose term is not kept is reported apart, as
//!    seen by its test but not confirmed by prediction), and gives the extended model as a
//!    simulation file, so the loop closes ([`fitted`]);
//! 4. fits the base model — the axis model ([`crate::axis_model`]) with only the standard's
//!    assumptions — and compares measured statistics with tests simulated from it
//!    ([`Diagnosis::checks`]);
//! 5. shows the standard's parameters as measured and, beside them, with each kept effect
//!    removed ([`corrected`]).
//!
//! Pure: no file I/O; deterministic for [`Options::seed`].

pub mod abbe;
mod analysis;
mod basis;
mod checks;
mod confirm;
mod corrected;
mod detectable;
pub use detectable::Detectable;
pub mod cross;
pub mod effects;
mod extended;
mod finding;
mod fitted;
mod json;
pub use json::{DiagnosisJson, ModelText};
mod model;
mod model_terms;
mod options;
mod prep;
mod residuals;
mod scheme;
mod select;
pub mod shape;
mod shaped;
pub use select::{Scheme, TermGain, Unconfirmed};
pub use shaped::ShapeScore;
mod maths;
pub use maths::stats;
mod time;
mod time_fit;
mod timeline;
mod validate;
mod verdict;
pub use verdict::{ModelVerdict, Outside, VerdictKind};

pub use checks::ModelCheck;
pub use corrected::{Corrected, CorrectedParameter};
pub use effects::{Effect, Estimate, Finding, Typed};
pub use finding::{Evidence, Units};
pub use options::{ALPHA, Options};
pub use prep::TimeUnit;
pub use residuals::{AxisPoint, PeriodogramPoint, ResidualPoint, Residuals};
pub use select::ModelFit;
pub use timeline::{CurvePoint, RunMean, TimeEffect};

use crate::axis_model::Simulation;
use crate::evaluate::StandardId;
use crate::measurement::AxisData;
use crate::units::AxisKind;
use analysis::Analysis;
use fitted::Fitted;

/// The result of a diagnosis.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    pub kind: AxisKind,
    pub standard: StandardId,
    pub time_unit: TimeUnit,
    /// The findings whose term earns its place in the extended model (and, without
    /// held-out validation, n = 1, every finding of the tests).
    pub findings: Vec<Finding>,
    /// Findings of the tests whose term the held-out prediction does not confirm.
    pub unconfirmed: Vec<Unconfirmed>,
    pub base: ModelFit,
    pub extended: ModelFit,
    /// (base − extended)/base × 100 on the held-out RMS of the readings.
    pub gain_pct: f64,
    /// The same on the leave-targets-out RMS of the target means, when a periodic term
    /// was judged (a periodic error costs between the targets, not at them).
    pub(crate) gain_between_targets_pct: Option<f64>,
    /// Each found effect's term judged under the held-out scheme that can show it.
    pub term_gains: Vec<TermGain>,
    pub validation: &'static str,
    pub checks: Vec<ModelCheck>,
    /// What the findings and the checks say together, in one sentence.
    pub model_check: ModelVerdict,
    /// The smallest effect of each kind this plan confirms ([`detectable`]).
    pub detectable: Vec<Detectable>,
    pub residuals: Residuals,
    pub corrected: Vec<Corrected>,
    /// The fitted base model (the standard's assumptions), as simulated for the checks.
    pub base_model: Simulation,
    /// The extended model with the kept terms; its plan is the file's plan.
    pub extended_model: Simulation,
    pub notes: Vec<String>,
}

impl Diagnosis {
    /// Whether any finding names `effect`.
    pub fn has(&self, effect: Effect) -> bool {
        self.findings.iter().any(|f| f.effect() == effect)
    }

    /// The effects the findings name, e.g. `drift outlier`, or `none`.
    pub fn effects_label(&self) -> String {
        let mut effects: Vec<&str> = self.findings.iter().map(|f| f.effect().name()).collect();
        effects.dedup();
        if effects.is_empty() {
            "none".to_string()
        } else {
            effects.join(" ")
        }
    }

    /// The estimates of type `T` (e.g. [`effects::periodic::Periodic`]) of the findings.
    pub fn estimates<T: Typed + 'static>(&self) -> impl Iterator<Item = &T> {
        self.findings.iter().filter_map(|f| T::of(&f.estimate))
    }

    /// The findings that name `effect`.
    pub fn of(&self, effect: Effect) -> impl Iterator<Item = &Finding> {
        self.findings.iter().filter(move |f| f.effect() == effect)
    }
}

/// Validation used for `heldout_rms`.
pub(crate) const VALIDATION: &str = "k-fold cross-validation over readings (10 folds, stratified by target and direction); periodic term: leave-targets-out on the target means (each inner target predicted without a block of about a quarter period around it)";

/// Diagnoses one measurement: the tests, each effect's findings, the terms kept by
/// held-out prediction, the fitted models, the model checks and the parameters with the
/// kept effects removed.
pub fn diagnose(data: &AxisData, options: &Options) -> Diagnosis {
    let mut notes = Vec::new();
    let a = Analysis::run(data, options, &mut notes);
    let (mut seen, withheld) = a.findings();
    notes.extend(withheld.iter().map(|w| w.note.clone()));
    seen.sort_by_key(Finding::effect);
    let selection = select::select(&a, &seen, options.seed);
    for g in &selection.term_gains {
        if let Some(shape) = g.shape {
            for f in seen.iter_mut().filter(|f| f.effect() == g.effect) {
                match g.effect {
                    Effect::ScatterVariation => {
                        effects::scatter_variation::ScatterVariation::reshape(f, shape)
                    }
                    _ => effects::reversal_variation::ReversalVariation::reshape(f, shape),
                }
            }
        }
    }
    let (findings, unconfirmed) = Unconfirmed::split(seen, &selection.term_gains);
    let fit = Fitted::new(&a, &selection);
    notes.extend(fit.guess.notes.iter().cloned());
    let extended_model = fit.extended_model(&a, &selection.effects, options.seed);
    let base_model = checks::base_model(&a, &fit.guess.plan, options.seed);
    let simulable = fit.guess.simulable;
    let checks = checks::check_base_model(&a, &base_model, simulable, options, &mut notes);
    let read_as_warm_up: Vec<Effect> = withheld.iter().map(|w| w.effect).collect();
    let model_check = verdict::verdict(&checks, &findings, &unconfirmed, &read_as_warm_up);
    let detectable = a.detectable();
    let residuals = residuals::residuals(&a, &fit, &selection.effects);
    let corrected =
        corrected::corrected(&a, &fit, &selection.effects, options.standard, &mut notes);
    Diagnosis {
        kind: data.kind,
        standard: options.standard,
        time_unit: a.basis.prep.time_unit,
        findings,
        unconfirmed,
        base: selection.base,
        extended: selection.extended,
        gain_pct: selection.gain_pct,
        gain_between_targets_pct: selection.gain_between_targets_pct,
        term_gains: selection.term_gains,
        validation: VALIDATION,
        checks,
        model_check,
        detectable,
        residuals,
        corrected,
        base_model,
        extended_model,
        notes,
    }
}
