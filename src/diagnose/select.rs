//! Which found effects the extended model keeps: each term in the order of the vocabulary
//! is kept when it improves held-out prediction ([`super::validate`]); a periodic term
//! when it improves the leave-targets-out RMS of the target means.

use super::ModelFit;
use super::analysis::Analysis;
use super::effects::{Effect, Term};
use super::finding::{Finding, fmt};
use super::periodic::Peak;
use super::validate::{self, ModelTerms, Score};
use serde::Serialize;

/// The held-out scheme that can show a term's gain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Scheme {
    /// k-fold over readings (10 folds stratified by target and direction), RMS of the
    /// held-out readings: terms that change the readings (time, reversal, outliers).
    KFoldRms,
    /// The same folds, mean negative log predictive density per reading: a scatter term
    /// changes no prediction, only how sure it is.
    KFoldDensity,
    /// Leave-one-target-out on the target means, RMS: a periodic error costs between
    /// the targets, which a free mean per target hides from the readings.
    LeaveTargetsOut,
}

impl Scheme {
    /// The scheme in words, for the text and the report.
    pub fn describe(self) -> &'static str {
        match self {
            Scheme::KFoldRms => "k-fold over readings, RMS",
            Scheme::KFoldDensity => "k-fold over readings, log density",
            Scheme::LeaveTargetsOut => "leave-targets-out (h-block), RMS of the target means",
        }
    }
}

/// How one found effect's term was judged.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TermGain {
    pub effect: Effect,
    pub scheme: Scheme,
    /// The scheme's measure without and with the term: an RMS in the deviation unit, or
    /// a mean negative log density per reading (nats).
    pub without: f64,
    pub with: f64,
    /// RMS: (without − with)/without × 100. Density: how much higher the geometric mean
    /// predictive density per reading is, (e^(without − with) − 1) × 100.
    pub gain_pct: f64,
    /// Kept in the extended model: only with a positive gain.
    pub kept: bool,
}

impl TermGain {
    /// `drift: +12.3 % (k-fold over readings, RMS 0.812 → 0.712 µm), kept`.
    pub fn describe(&self, unit: &str) -> String {
        let measure = match self.scheme {
            Scheme::KFoldDensity => format!(
                "{} → {} nats per reading",
                fmt(self.without),
                fmt(self.with)
            ),
            _ => format!("{} → {} {unit}", fmt(self.without), fmt(self.with)),
        };
        format!(
            "{}: {:+.1} % ({}: {measure}), {}",
            self.effect.name(),
            self.gain_pct,
            self.scheme.describe(),
            if self.kept { "kept" } else { "left out" }
        )
    }

    fn new(effect: Effect, scheme: Scheme, without: f64, with: f64) -> TermGain {
        let gain_pct = match scheme {
            Scheme::KFoldDensity => ((without - with).exp() - 1.0) * 100.0,
            _ => (without - with) / without * 100.0,
        };
        TermGain {
            effect,
            scheme,
            without,
            with,
            gain_pct,
            kept: with < without,
        }
    }
}

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
    /// Each judged term under its scheme, in the order of the vocabulary.
    pub term_gains: Vec<TermGain>,
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
    let mut term_gains = Vec::new();
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
        let scheme = if by_density {
            Scheme::KFoldDensity
        } else {
            Scheme::KFoldRms
        };
        term_gains.push(TermGain::new(
            effect,
            scheme,
            measure(&current),
            measure(&s),
        ));
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
    if let (Some(without), Some(with)) = between {
        let gain = TermGain::new(Effect::Periodic, Scheme::LeaveTargetsOut, without, with);
        term_gains.push(gain);
        term_gains.sort_by_key(|g| g.effect);
    }
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
        term_gains,
    }
}

/// The periodic term: the leave-targets-out RMS of the target means without and with
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
            "periodic: found, but the term does not improve the leave-targets-out RMS ({} vs {} {}), so the extended model leaves it out",
            fmt(be),
            fmt(bb),
            a.units.symbol()
        ));
        ((Some(bb), Some(be)), None)
    }
}
