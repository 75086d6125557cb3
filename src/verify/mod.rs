//! Verification of a compensation: after a table is loaded the axis is measured again, and
//! the re-measurement is compared with the prediction (the measurement before, with the
//! new table's correction in place of the one active then), per target and per parameter.
//!
//! The verdict is on E, the bidirectional systematic positional deviation (ISO 230-2 2.20),
//! which a table exists to reduce: `effective` when the achieved E is within the
//! prediction's uncertainty of the predicted one; else `made_worse` when it is beyond that
//! uncertainty above the E before, `partly_effective` when beyond it below, and
//! `not_effective` in between. What went wrong is named as the diagnosis names effects
//! ([`effects`]): the change measured (after − before) is tested against the table as
//! loaded and against each effect's candidates.

pub mod compare;
pub mod effects;

pub use compare::Row;
pub use effects::{Key, Other};

use crate::compensate::{Table, apply_change};
use crate::diagnose::stats::chi2_upper;
use crate::evaluate::json::ParameterSet;
use crate::evaluate::stats::normal_cdf;
use crate::evaluate::{self, Evaluation, StandardId};
use crate::measurement::AxisData;
use crate::units::{AxisKind, fmt_fixed};
use effects::{Candidate, Context, EFFECTS, chi2, fitted_factor};
use serde::Serialize;
use std::collections::BTreeMap;

/// Below this probability the table as loaded does not explain the change measured.
pub const ALPHA: f64 = 0.001;

/// How much better (χ²) a later effect must explain the change to be preferred to an
/// earlier, simpler one.
const PREFERENCE: f64 = 9.0;

/// What a verification compares.
pub struct Input<'a> {
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

/// The verdict on a compensation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// E achieved within the prediction's uncertainty of the E predicted.
    Effective,
    /// E reduced beyond the uncertainty, but not to the prediction.
    PartlyEffective,
    /// E not changed beyond the uncertainty.
    NotEffective,
    /// E grown beyond the uncertainty.
    MadeWorse,
}

impl Verdict {
    /// The verdict and what it means, for the console and the report.
    pub fn words(self) -> &'static str {
        match self {
            Verdict::Effective => "effective: E achieved within the prediction's uncertainty",
            Verdict::PartlyEffective => "partly effective: E reduced, but not to the prediction",
            Verdict::NotEffective => "not effective: E not changed beyond the uncertainty",
            Verdict::MadeWorse => "made worse: E grown beyond the uncertainty",
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Verdict::Effective => "effective",
            Verdict::PartlyEffective => "partly_effective",
            Verdict::NotEffective => "not_effective",
            Verdict::MadeWorse => "made_worse",
        }
    }
}

/// E (ISO 230-2 2.20) before, predicted and achieved, µm or arcsec, and the expanded
/// uncertainty (95 %) of a difference between two of them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Systematic {
    pub before: f64,
    pub predicted: f64,
    pub achieved: f64,
    /// The largest difference of two E that the two measurements' scatter allows: twice
    /// the Šidák–Bonferroni bound (95 % over all the means compared) of a difference of
    /// two target means, each with its standard uncertainty (GUM, normal distribution).
    pub uncertainty: f64,
}

/// What went wrong, with the evidence.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    pub effect: Key,
    pub evidence: String,
    pub params: BTreeMap<&'static str, f64>,
}

/// A verification: the verdict, the findings and the comparison behind them.
#[derive(Debug, Clone)]
pub struct Verification {
    pub verdict: Verdict,
    pub e: Systematic,
    pub before: Evaluation,
    pub predicted: Evaluation,
    pub achieved: Evaluation,
    pub findings: Vec<Finding>,
    pub per_target: Vec<Row>,
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
pub fn verify(input: &Input) -> Result<Verification, VerifyError> {
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
    let ctx = Context {
        rows: &rows,
        old: input.old,
        new: input.new,
        others: input.others,
    };
    let applied = ctx.applied();
    let chi2_loaded = chi2(&rows, &applied);
    let dof = rows.len().saturating_sub(1);
    let findings = find(&ctx, chi2_loaded, dof).into_iter().collect();
    Ok(Verification {
        verdict: verdict(&e),
        e,
        notes: notes(before, after),
        before: evaluated_before,
        predicted,
        achieved,
        findings,
        offset: compare::weighted_mean(rows.iter().map(|r| (r.achieved - r.predicted, r.u))),
        per_target: rows,
        chi2: chi2_loaded,
        dof,
    })
}

/// E of an evaluation: the largest mean deviation of either direction less the smallest
/// (ISO 230-2 2.20), from its target means (so for every standard).
pub fn systematic(e: &Evaluation) -> f64 {
    let means = e.targets.iter().flat_map(|t| [t.up.mean, t.down.mean]);
    let (lo, hi) = means.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), m| {
        (lo.min(m), hi.max(m))
    });
    hi - lo
}

/// The expanded uncertainty of a difference of two E (see [`Systematic::uncertainty`]).
fn e_uncertainty(rows: &[Row]) -> f64 {
    let u = rows.iter().map(|r| r.u).fold(0.0, f64::max);
    let tail = 0.025 / rows.len().max(1) as f64;
    2.0 * normal_quantile(1.0 - tail) * u
}

/// The standard normal quantile, by bisection of Φ (monotone; 60 halvings reach f64's
/// resolution).
fn normal_quantile(p: f64) -> f64 {
    let (mut lo, mut hi) = (-40.0, 40.0);
    for _ in 0..60 {
        let mid = (lo + hi) / 2.0;
        if normal_cdf(mid) < p {
            lo = mid
        } else {
            hi = mid
        }
    }
    (lo + hi) / 2.0
}

/// The verdict from E before, predicted and achieved.
fn verdict(e: &Systematic) -> Verdict {
    if e.achieved <= e.predicted + e.uncertainty {
        Verdict::Effective
    } else if e.achieved > e.before + e.uncertainty {
        Verdict::MadeWorse
    } else if e.achieved < e.before - e.uncertainty {
        Verdict::PartlyEffective
    } else {
        Verdict::NotEffective
    }
}

/// The effect that explains the change when the table as loaded does not: the best
/// candidate, an earlier effect kept unless a later one is better by [`PREFERENCE`], and
/// only if it explains the change far better (a quarter of the χ² or less).
fn find(ctx: &Context, chi2_loaded: f64, dof: usize) -> Option<Finding> {
    if dof == 0 || chi2_upper(chi2_loaded, dof as f64) >= ALPHA {
        return None;
    }
    let mut best: Option<(f64, Candidate)> = None;
    for effect in EFFECTS {
        for candidate in effect.candidates(ctx) {
            let c = chi2(ctx.rows, &candidate.change);
            if best.as_ref().is_none_or(|(b, _)| c < b - PREFERENCE) {
                best = Some((c, candidate));
            }
        }
    }
    let (c, candidate) = best.filter(|(c, _)| *c <= chi2_loaded / 4.0)?;
    let factor = fitted_factor(ctx.rows);
    let mut params: BTreeMap<&'static str, f64> = candidate.params.iter().copied().collect();
    params.insert("chi2", c);
    params.insert("chi2_as_loaded", chi2_loaded);
    params.insert("fitted_factor", factor);
    Some(Finding {
        effect: candidate.key,
        evidence: format!(
            "{}: the change measured from before to after follows it (χ² = {} on {dof} degrees of freedom) far better than the table as loaded (χ² = {}; the change is {} × the table's, fitted)",
            candidate.what,
            fmt_fixed(c, 1),
            fmt_fixed(chi2_loaded, 1),
            fmt_fixed(factor, 2)
        ),
        params,
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
            "the targets of the two measurements differ (by up to {} {unit}): the means before are interpolated at the re-measurement's targets",
            fmt_fixed(far, 3)
        ));
    }
    notes
}

/// The JSON view: `{verdict, e, before, predicted, achieved, findings, per_target, …}`,
/// each set of parameters as `{parameters: {KEY: value}}`.
#[derive(Serialize)]
pub struct Json<'a> {
    pub verdict: Verdict,
    pub e: &'a Systematic,
    pub before: ParameterSet<'a>,
    pub predicted: ParameterSet<'a>,
    pub achieved: ParameterSet<'a>,
    pub findings: &'a [Finding],
    pub offset: f64,
    pub chi2: f64,
    pub dof: usize,
    pub per_target: &'a [Row],
    pub notes: &'a [String],
}

impl Verification {
    pub fn json(&self) -> Json<'_> {
        let params = ParameterSet::of;
        Json {
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
