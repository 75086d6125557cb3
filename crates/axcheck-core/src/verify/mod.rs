//! Verification of a compensation: after a table is loaded the axis is measured again, and
//! the re-measurement is compared with the prediction (the measurement before, with the
//! new table's correction in place of the one active then), per target and per parameter.
//!
//! Agreement is judged both ways ([`verdict`], where the criteria and their sources are):
//! on E, the bidirectional systematic positional deviation (ISO 230-2 2.20) a table exists
//! to reduce, an E achieved far better than predicted is as much a disagreement as one far
//! worse (`table_mismatch`: the table on the machine is not the one named); per target, the
//! χ² of the change measured against the change the named table predicts decides when no
//! effect explains the difference, and a named table it rejects is never `effective`.
//! What went wrong is named as the diagnosis names effects ([`effects`]): the change
//! measured (after − before) is tested against the table as loaded and against each
//! effect's candidates ([`explain`]).

pub mod compare;
pub mod effects;
pub mod explain;
pub mod interpolation;
pub mod verdict;

pub use compare::ComparedTarget;
pub use effects::{Key, Other};
pub use verdict::{Effectiveness, Systematic};

use crate::compensate::controllers::Controller;
use crate::compensate::{Table, apply_change};
use crate::evaluate::json::ParameterSet;
use crate::evaluate::{self, Evaluation, StandardId};
use crate::measurement::AxisData;
use crate::units::{AxisKind, fmt_fixed};
use effects::EffectContext;
use serde::Serialize;
use std::collections::BTreeMap;
use verdict::{VerdictBasis, e_uncertainty, judge, systematic};

/// Below this probability the table as loaded does not explain the change measured.
pub const ALPHA: f64 = 0.001;

/// What a verification compares.
pub struct VerifyInput<'a> {
    /// The measurement before the table was loaded.
    pub before: &'a AxisData,
    /// The re-measurement with the table active.
    pub after: &'a AxisData,
    /// The correction active during the measurement before, as the controller added it
    /// (its table and backlash); `None`: nothing.
    pub old: Option<&'a Table>,
    /// The correction loaded since, as the controller adds it.
    pub new: &'a Table,
    /// The tables loaded for the machine's other axes (for `wrong_axis`).
    pub others: &'a [Other],
    /// The controller the tables are loaded on, for the effects of its own parameters
    /// (`backlash_not_loaded`, `backlash_relative`); `None`: not known.
    pub controller: Option<&'a dyn Controller>,
    pub standard: StandardId,
}

/// Why two measurements cannot be compared.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum VerifyError {
    #[error("the measurement before is of a {0} axis, the re-measurement of a {1} one")]
    Kind(AxisKind, AxisKind),
    #[error(
        "{0} has one run per direction (n = 1): a verification needs n ≥ 2 in both measurements to tell a change from the scatter"
    )]
    SingleRun(&'static str),
    #[error("the table is for a {0} axis, the measurements are of a {1} one")]
    TableKind(AxisKind, AxisKind),
}

/// What went wrong, with the evidence.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Cause {
    pub effect: Key,
    pub evidence: String,
    pub params: BTreeMap<&'static str, f64>,
}

/// A verification: the verdict, the findings and the comparison behind them.
#[derive(Debug, Clone)]
pub struct Verification {
    pub verdict: Effectiveness,
    pub e: Systematic,
    pub before: Evaluation,
    pub predicted: Evaluation,
    pub achieved: Evaluation,
    pub findings: Vec<Cause>,
    pub per_target: Vec<ComparedTarget>,
    /// The constant offset between the two measurements (after − predicted), which no
    /// parameter sees.
    pub offset: f64,
    /// χ² of the change measured against the table as loaded, and its degrees of freedom.
    pub chi2: f64,
    pub dof: usize,
    pub notes: Vec<String>,
}

impl Verification {
    /// `effective: E 21.90 µm before, 1.20 predicted, 1.41 achieved (U 1.84); found:
    /// sign_inverted`: the verdict on E (ISO 230-2 2.20) in one line, `unit` its unit.
    pub fn summary(&self, unit: &str) -> String {
        let findings: Vec<&str> = self.findings.iter().map(|f| f.effect.name()).collect();
        let found = match findings.is_empty() {
            true => String::new(),
            false => format!("; found: {}", findings.join(", ")),
        };
        let e = &self.e;
        format!(
            "{}: E {} {unit} before, {} predicted, {} achieved (U {}){found}",
            self.verdict.name(),
            fmt_fixed(e.before, 2),
            fmt_fixed(e.predicted, 2),
            fmt_fixed(e.achieved, 2),
            fmt_fixed(e.uncertainty, 2)
        )
    }
}

/// Compares the re-measurement with the prediction.
pub fn verify(input: &VerifyInput) -> Result<Verification, VerifyError> {
    let (before, after) = (input.before, input.after);
    if before.kind != after.kind {
        return Err(VerifyError::Kind(before.kind, after.kind));
    }
    if input.new.kind != after.kind {
        return Err(VerifyError::TableKind(input.new.kind, after.kind));
    }
    let s_before =
        compare::pooled_s(before).ok_or(VerifyError::SingleRun("the measurement before"))?;
    let s_after = compare::pooled_s(after).ok_or(VerifyError::SingleRun("the re-measurement"))?;
    let rows = compare::rows(before, after, input.old, input.new, (s_before, s_after));
    let predicted = evaluate::evaluate(&apply_change(input.new, input.old, before), input.standard);
    let (evaluated_before, achieved) = (
        evaluate::evaluate(before, input.standard),
        evaluate::evaluate(after, input.standard),
    );
    let e = Systematic {
        before: systematic(&evaluated_before),
        predicted: systematic(&predicted),
        achieved: systematic(&achieved),
        uncertainty: e_uncertainty(&rows),
    };
    let ctx = EffectContext {
        rows: &rows,
        old: input.old,
        new: input.new,
        others: input.others,
        controller: input.controller,
    };
    let test = explain::Test::of(&rows, &ctx.applied());
    let found = explain::effect(&ctx, &test);
    let verdict = judge(&VerdictBasis {
        e: &e,
        rejected: test.rejected(),
        explained: found.is_some(),
    });
    let findings = found
        .or_else(|| explain::mismatch(&rows, &test, &e, verdict))
        .into_iter()
        .collect();
    Ok(Verification {
        verdict,
        e,
        notes: notes(before, after),
        before: evaluated_before,
        predicted,
        achieved,
        findings,
        offset: compare::weighted_mean(rows.iter().map(|r| (r.achieved - r.predicted, r.u))),
        per_target: rows,
        chi2: test.chi2,
        dof: test.dof,
    })
}

/// What the comparison assumed: targets that differ between the measurements.
fn notes(before: &AxisData, after: &AxisData) -> Vec<String> {
    let unit = after.kind.position_unit();
    let far = after
        .targets
        .iter()
        .map(|p| {
            before
                .targets
                .iter()
                .map(|q| (p - q).abs())
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    let mut notes = Vec::new();
    if far > 1e-3 {
        notes.push(format!(
            "the targets of the two measurements differ (by up to {} {unit}): the means before are interpolated at the re-measurement's targets, the interpolation's uncertainty (a cubic's difference from the linear value) added to each target's; an error shorter than the targets resolve is not seen: re-measure at the same targets",
            fmt_fixed(far, 3)
        ));
    }
    notes
}

/// The JSON view: `{verdict, e, before, predicted, achieved, findings, per_target, …}`,
/// each set of parameters as `{parameters: {KEY: value}}`.
#[derive(Serialize)]
pub struct VerificationJson<'a> {
    pub verdict: Effectiveness,
    pub e: &'a Systematic,
    pub before: ParameterSet<'a>,
    pub predicted: ParameterSet<'a>,
    pub achieved: ParameterSet<'a>,
    pub findings: &'a [Cause],
    pub offset: f64,
    pub chi2: f64,
    pub dof: usize,
    pub per_target: &'a [ComparedTarget],
    pub notes: &'a [String],
}

impl Verification {
    pub fn json(&self) -> VerificationJson<'_> {
        let params = ParameterSet::of;
        VerificationJson {
            verdict: self.verdict,
            e: &self.e,
            before: params(&self.before),
            predicted: params(&self.predicted),
            achieved: params(&self.achieved),
            findings: &self.findings,
            offset: self.offset,
            chi2: self.chi2,
            dof: self.dof,
            per_target: &self.per_target,
            notes: &self.notes,
        }
    }
}
