//! Which found effects the extended model keeps: each term in the order of the vocabulary
//! is kept when it improves held-out prediction ([`super::validate`]); a periodic term
//! when it improves the leave-one-target-out RMS of the target means.

use super::ModelFit;
use super::analysis::Analysis;
use super::effects::{Effect, Term};
use super::finding::{Finding, fmt};
use super::periodic::Peak;
use super::validate::{self, ModelTerms, Score};

/// The kept terms and the held-out errors of the base and the extended model.
pub(crate) struct Selection {
    pub terms: ModelTerms,
    /// The kept effects, in the order of the vocabulary.
    pub effects: Vec<Effect>,
    /// The periodic term, when kept.
    pub periodic: Option<Peak>,
    pub base: ModelFit,
    pub extended: ModelFit,
    pub gain_pct: f64,
    pub gain_between_targets_pct: Option<f64>,
}

/// Judges the terms of the `findings`; a term left out gets a note.
pub(crate) fn select(
    a: &Analysis,
    findings: &[Finding],
    seed: u64,
    notes: &mut Vec<String>,
) -> Selection {
    let p = &a.prep;
    let outlier_row: Vec<bool> = a.active.iter().map(|x| !x).collect();
    let fold = validate::folds(p, seed);
    let score = |terms| validate::score(p, &a.x, &fold, &outlier_row, terms);
    let base_score = score(ModelTerms::default());
    let (mut kept, mut current) = (ModelTerms::default(), base_score);
    let mut effects = Vec::new();
    let found = |e: Effect| findings.iter().any(|f| f.effect() == e);
    for &effect in Effect::ALL.iter().filter(|e| found(**e) && p.n >= 2) {
        let (set, by_density): (fn(&mut ModelTerms), bool) = match effect.rule().term() {
            Term::Readings(set) => (set, false),
            Term::Density(set) => (set, true),
            Term::TargetMeans => continue,
        };
        let mut terms = kept;
        set(&mut terms);
        let s = score(terms);
        let measure = |s: &Score| if by_density { s.nlpd } else { s.rms };
        if measure(&s) < measure(&current) {
            (kept, current) = (terms, s);
            effects.push(effect);
        } else {
            notes.push(format!(
                "{}: found, but the term does not improve the held-out {} ({} vs {}), so the extended model leaves it out",
                effect.name(),
                if by_density { "log density" } else { "RMS" },
                fmt(measure(&s)),
                fmt(measure(&current)),
            ));
        }
    }
    let (between, periodic) = judge_periodic(a, &mut effects, notes);
    effects.sort();
    let base_terms: Vec<String> = ["systematic_per_target", "reversal", "scatter"]
        .map(String::from)
        .to_vec();
    let mut ext_terms = base_terms.clone();
    ext_terms.extend(effects.iter().map(|e| e.name().to_string()));
    let base = ModelFit {
        terms: base_terms,
        heldout_rms: base_score.rms,
        heldout_nlpd: base_score.nlpd,
        between_targets_rms: between.0,
    };
    let extended = ModelFit {
        terms: ext_terms,
        heldout_rms: current.rms,
        heldout_nlpd: current.nlpd,
        between_targets_rms: if periodic.is_some() {
            between.1
        } else {
            between.0
        },
    };
    let gain_pct = (base.heldout_rms - extended.heldout_rms) / base.heldout_rms * 100.0;
    let gain_between_targets_pct = match between {
        (Some(b), Some(e)) if b > 0.0 && periodic.is_some() => Some((b - e) / b * 100.0),
        (Some(_), Some(_)) => Some(0.0),
        _ => None,
    };
    Selection {
        terms: kept,
        effects,
        periodic,
        base,
        extended,
        gain_pct,
        gain_between_targets_pct,
    }
}

/// The periodic term: the leave-one-target-out RMS of the target means without and with
/// it, and the term when it lowers that RMS.
fn judge_periodic(
    a: &Analysis,
    effects: &mut Vec<Effect>,
    notes: &mut Vec<String>,
) -> ((Option<f64>, Option<f64>), Option<Peak>) {
    let Some(peak) = a.periodic.peak.as_ref() else {
        return ((None, None), None);
    };
    let (bb, be) = validate::between_targets(&a.prep.positions, &a.means, peak.period);
    if be < bb {
        effects.push(Effect::Periodic);
        ((Some(bb), Some(be)), Some(peak.clone()))
    } else {
        notes.push(format!(
            "periodic: found, but the term does not improve the leave-one-target-out RMS ({} vs {} {}), so the extended model leaves it out",
            fmt(be),
            fmt(bb),
            a.units.symbol()
        ));
        ((Some(bb), Some(be)), None)
    }
}
