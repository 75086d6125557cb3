//! What went wrong, with the evidence: the effect of the vocabulary ([`super::effects`])
//! that explains the change measured when the table as named does not, or, when none
//! does, `table_mismatch` with what the data show.

use super::compare::ComparedTarget;
use super::effects::{Candidate, EFFECTS, EffectContext, Key, chi2, fitted_factor};
use super::verdict::{Effectiveness, Systematic};
use super::{ALPHA, Cause};
use crate::diagnose::stats::chi2_upper;
use crate::units::fmt_fixed;
use std::collections::BTreeMap;

/// How much better (χ²) a later effect must explain the change to be preferred to an
/// earlier, simpler one.
const PREFERENCE: f64 = 9.0;

/// The χ² test of the table as named: its value, degrees of freedom and tail probability.
#[derive(Debug, Clone, Copy)]
pub struct Test {
    pub chi2: f64,
    pub dof: usize,
    /// P(χ²_ν ≥ χ²); NaN without degrees of freedom.
    pub p: f64,
}

impl Test {
    pub fn of(rows: &[ComparedTarget], change: &[f64]) -> Test {
        let chi2 = chi2(rows, change);
        let dof = rows.len().saturating_sub(1);
        let p = chi2_upper(chi2, dof as f64);
        Test { chi2, dof, p }
    }

    /// The table as named does not explain the change (P below [`ALPHA`]).
    pub fn rejected(&self) -> bool {
        self.dof > 0 && self.p < ALPHA
    }
}

/// The effect that explains the change when the table as named does not: the best
/// candidate, an earlier effect kept unless a later one is better by [`PREFERENCE`], and
/// only if it explains the change far better (a quarter of the χ² or less).
pub fn effect(ctx: &EffectContext, test: &Test) -> Option<Cause> {
    if !test.rejected() {
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
    let (c, candidate) = best.filter(|(c, _)| *c <= test.chi2 / 4.0)?;
    let factor = fitted_factor(ctx.rows);
    let mut params: BTreeMap<&'static str, f64> = candidate.params.iter().copied().collect();
    params.insert("chi2", c);
    params.insert("chi2_as_loaded", test.chi2);
    params.insert("fitted_factor", factor);
    Some(Cause {
        effect: candidate.key,
        evidence: format!(
            "{}: the change measured from before to after follows it (χ² = {} on {} degrees of freedom) far better than the table as loaded (χ² = {}; the change is {} × the table's, fitted)",
            candidate.what,
            fmt_fixed(c, 1),
            test.dof,
            fmt_fixed(test.chi2, 1),
            fmt_fixed(factor, 2)
        ),
        params,
    })
}

/// `table_mismatch` when the verdict is one and no effect explains it, or the table as
/// named is rejected with nothing to explain it: what the data show, per target (χ²) and
/// on E (both ways).
pub fn mismatch(
    rows: &[ComparedTarget],
    test: &Test,
    e: &Systematic,
    verdict: Effectiveness,
) -> Option<Cause> {
    if verdict != Effectiveness::TableMismatch && !test.rejected() {
        return None;
    }
    let factor = fitted_factor(rows);
    let on_e = if e.far_better() {
        format!(
            "E achieved ({}) is below E predicted ({}) by more than the uncertainty U = {}, which a table acting as named cannot do",
            fmt_fixed(e.achieved, 2),
            fmt_fixed(e.predicted, 2),
            fmt_fixed(e.uncertainty, 2)
        )
    } else {
        format!(
            "E achieved {} against {} predicted (U = {})",
            fmt_fixed(e.achieved, 2),
            fmt_fixed(e.predicted, 2),
            fmt_fixed(e.uncertainty, 2)
        )
    };
    let per_target = format!(
        "the change measured from before to after {} the table named per target (χ² = {} on {} degrees of freedom, {})",
        if test.rejected() {
            "does not follow"
        } else {
            "is within the scatter of"
        },
        fmt_fixed(test.chi2, 1),
        test.dof,
        fmt_p(test.p)
    );
    let params = BTreeMap::from([
        ("chi2_as_loaded", test.chi2),
        ("dof", test.dof as f64),
        ("p", test.p),
        ("fitted_factor", factor),
        ("e_predicted", e.predicted),
        ("e_achieved", e.achieved),
        ("e_uncertainty", e.uncertainty),
    ]);
    Some(Cause {
        effect: Key::TableMismatch,
        evidence: format!(
            "the table on the machine is not the one named (another axis's, an older or a newer file), or the machine changed between the two measurements: {per_target}, and no effect of the vocabulary explains it; {on_e}; the change is {} × the named table's, fitted",
            fmt_fixed(factor, 2)
        ),
        params,
    })
}

/// `P = 0.927`, `P = 3.1e-5` or `P < 1e-12`: a tail probability for the evidence.
pub fn fmt_p(p: f64) -> String {
    if p < 1e-12 {
        "P < 1e-12".into()
    } else if p < 1e-3 {
        format!("P = {p:.1e}")
    } else {
        format!("P = {}", fmt_fixed(p, 3))
    }
}
