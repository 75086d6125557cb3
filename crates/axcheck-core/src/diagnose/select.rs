//! Which found effects the extended model keeps: each term in the order of the vocabulary
//! is kept when its held-out gain over the terms kept before it ([`super::validate`]; a
//! periodic term on the leave-targets-out RMS of the target means) is positive and larger
//! than that of every one of 19 unrelated terms of the same size ([`super::confirm`]).
//! A finding whose term is left out is reported as [`Unconfirmed`], with its gain; the
//! held-out errors of the base and the extended model as [`ModelFit`].

use super::analysis::Analysis;
use super::confirm::{self, Unrelated};
use super::effects::Finding;
use super::effects::periodic;
use super::effects::warm_up as warm;
use super::effects::{Effect, Term};
use super::finding::{Evidence, Keyed, fmt};
use super::maths::periodogram::Peak;
use super::model_terms::ModelTerms;
use super::prep::{Clocks, Prep};
pub use super::scheme::Scheme;
use super::scheme::gain_pct;
use super::shape::Shape;
use super::shaped::{self, ShapeScore};
use super::validate::{self, Score};
use crate::axis_model::rng::Rng;
use serde::Serialize;
use serde::ser::Serializer;

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
    /// The largest gain, in the same measure, of 19 unrelated terms of the same size on
    /// the same data and folds ([`super::confirm`]: the same term read in a random order,
    /// or as many ordinary readings left out), which a term unrelated to the data beats
    /// in 5 % of data sets; null when none could be scored.
    pub threshold_pct: f64,
    /// Kept in the extended model: only with a gain above `threshold_pct`.
    pub kept: bool,
    /// What the unrelated terms were: the term along the targets, the times or the runs
    /// in random orders, ordinary readings left out, or tests simulated without it.
    pub null: Unrelated,
    /// The shape chosen (a term along the axis that offers shapes), and every shape's
    /// held-out error.
    pub shape: Option<Shape>,
    pub shapes: Vec<ShapeScore>,
}

impl TermGain {
    /// `drift: +12.3 % (k-fold over readings, RMS 0.812 → 0.712 µm; unrelated terms at
    /// most +1.2 %), kept`.
    pub fn describe(&self, unit: &str) -> String {
        let measure = match self.scheme {
            Scheme::KFoldDensity => format!(
                "{} → {} nats per reading",
                fmt(self.without),
                fmt(self.with)
            ),
            _ => format!("{} → {} {unit}", fmt(self.without), fmt(self.with)),
        };
        let threshold = if self.threshold_pct.is_finite() {
            let compared = match self.null {
                Unrelated::SimulatedTests => "tests simulated without it",
                _ => "unrelated terms",
            };
            format!("; {compared} at most {:+.1} %", self.threshold_pct)
        } else {
            String::new()
        };
        let shape = match self.shape {
            Some(shape) => format!(" as {}", shape.name().replace('_', " ")),
            None => String::new(),
        };
        format!(
            "{}{shape}: {:+.1} % ({}: {measure}{threshold}), {}",
            self.effect.name(),
            self.gain_pct,
            self.scheme.describe(),
            if self.kept { "kept" } else { "left out" }
        )
    }

    /// A term judged: kept when its gain is positive and above `threshold_pct`.
    fn new(effect: Effect, scheme: Scheme, without: f64, with: f64, threshold_pct: f64) -> Self {
        let gain_pct = gain_pct(scheme, without, with);
        TermGain {
            effect,
            scheme,
            without,
            with,
            gain_pct,
            threshold_pct,
            kept: gain_pct > 0.0 && gain_pct > threshold_pct,
            null: effect.rule().unrelated(),
            shape: None,
            shapes: Vec::new(),
        }
    }
}

/// The largest gain of the unrelated terms (NaN for none).
fn largest_gain(scheme: Scheme, without: f64, unrelated: &[f64]) -> f64 {
    unrelated
        .iter()
        .map(|&u| gain_pct(scheme, without, u))
        .fold(f64::NAN, f64::max)
}

/// A finding of an effect's test whose term the held-out prediction does not confirm: its
/// gain is no larger than what a term unrelated to the data gains
/// ([`super::confirm`]). Reported beside the findings, not as one.
#[derive(Debug, Clone, PartialEq)]
pub struct Unconfirmed {
    pub finding: Finding,
    /// How the term was judged, its gain and the largest gain of the unrelated terms
    /// (see [`TermGain`]).
    pub scheme: Scheme,
    pub gain_pct: f64,
    pub threshold_pct: f64,
    /// What the gain was compared with (see [`TermGain::null`]).
    pub null: Unrelated,
}

impl Unconfirmed {
    /// Splits the findings of the tests into those whose term is kept (or was not
    /// judged: no held-out validation) and those whose term is left out.
    pub(crate) fn split(
        seen: Vec<Finding>,
        gains: &[TermGain],
    ) -> (Vec<Finding>, Vec<Unconfirmed>) {
        let mut findings = Vec::new();
        let mut unconfirmed = Vec::new();
        for f in seen {
            match gains.iter().find(|g| g.effect == f.effect() && !g.kept) {
                Some(g) => unconfirmed.push(Unconfirmed {
                    finding: f,
                    scheme: g.scheme,
                    gain_pct: g.gain_pct,
                    threshold_pct: g.threshold_pct,
                    null: g.null,
                }),
                None => findings.push(f),
            }
        }
        (findings, unconfirmed)
    }

    /// `+0.8 % held out (k-fold over readings, RMS); 19 unrelated terms of the same size
    /// up to +1.9 %`.
    pub fn describe(&self) -> String {
        let threshold = if self.threshold_pct.is_finite() {
            format!("up to {:+.1} %", self.threshold_pct)
        } else {
            "not scored".to_string()
        };
        let shaped = matches!(
            self.finding.effect().rule().term(),
            Term::Shaped(_) | Term::ShapedDensity(_)
        );
        let compared = match self.null {
            Unrelated::SimulatedTests if shaped => {
                "19 tests simulated without it, each in its best shape"
            }
            Unrelated::SimulatedTests => "19 tests simulated without it",
            _ => "19 unrelated terms of the same size",
        };
        format!(
            "{:+.1} % held out ({}); {compared} {threshold}",
            self.gain_pct,
            self.scheme.describe()
        )
    }
}

/// An unconfirmed finding as the stable JSON has it.
#[derive(serde::Serialize)]
struct UnconfirmedJson<'a> {
    effect: Effect,
    params: Keyed<String, f64>,
    labels: Keyed<&'static str, &'static str>,
    evidence: &'a Evidence,
    message: &'a str,
    scheme: Scheme,
    gain_pct: f64,
    threshold_pct: f64,
    null: Unrelated,
}

impl Serialize for Unconfirmed {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let f = &self.finding;
        UnconfirmedJson {
            effect: f.effect(),
            params: Keyed(f.params()),
            labels: Keyed(f.labels()),
            evidence: &f.evidence,
            message: &f.message,
            scheme: self.scheme,
            gain_pct: self.gain_pct,
            threshold_pct: self.threshold_pct,
            null: self.null,
        }
        .serialize(s)
    }
}

/// A model and its held-out error.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelFit {
    pub terms: Vec<String>,
    /// Held-out RMS prediction error of the readings, µm or arcsec (NaN for n = 1).
    pub heldout_rms: f64,
    /// Held-out mean negative log predictive density per reading (judges the scatter term).
    pub(crate) heldout_nlpd: f64,
    /// Leave-one-target-out RMS of the target means (when a periodic term was judged).
    pub(crate) between_targets_rms: Option<f64>,
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
    pub(crate) gain_between_targets_pct: Option<f64>,
    /// Each judged term under its scheme, in the order of the vocabulary.
    pub term_gains: Vec<TermGain>,
}

/// What the judging of the terms shares: the readings, folds and outliers.
struct Judge<'a> {
    a: &'a Analysis<'a>,
    fold: Vec<usize>,
    outlier: Vec<bool>,
    /// Seed of the unrelated terms, from the plan.
    seed: u64,
}

impl Judge<'_> {
    fn score(&self, terms: ModelTerms) -> Score {
        validate::score(
            &self.a.basis.prep,
            &self.a.basis.x,
            &self.fold,
            &self.outlier,
            terms,
        )
    }

    /// The candidate `terms` (the `kept` ones and the effect's) cross-validated, and the
    /// scores of the [`confirm::UNRELATED`] unrelated terms of the same size.
    fn judge(
        &self,
        unrelated: Unrelated,
        kept: ModelTerms,
        terms: ModelTerms,
    ) -> (Score, Vec<Score>) {
        let (p, x) = (&self.a.basis.prep, &self.a.basis.x);
        match unrelated {
            Unrelated::TimeOrders => {
                let others = confirm::row_orders(p.rows.len(), self.seed)
                    .iter()
                    .map(|order| {
                        let q = p.with_clocks(shuffled_time(p, order, kept, terms));
                        let terms = self.fixed_tau(&q, kept, terms);
                        validate::score(&q, x, &self.fold, &self.outlier, terms)
                    })
                    .collect();
                (self.score(terms), others)
            }
            Unrelated::SimulatedTests => {
                unreachable!("judged by `simulated_threshold`, `shaped` or `judge_periodic`")
            }
            Unrelated::OrdinaryReadings => {
                let others = confirm::ordinary_draws(&self.outlier, self.seed)
                    .iter()
                    .map(|draw| {
                        let rows = validate::Rows {
                            scored: &self.outlier,
                            left_out: draw,
                        };
                        validate::scores(p, x, &self.fold, rows, kept, &[]).swap_remove(0)
                    })
                    .collect();
                (self.score(terms), others)
            }
        }
    }

    /// The largest gain of `terms` over `kept` on [`confirm::UNRELATED`] tests simulated
    /// from the model without the term, with this test's plan, folds and scored readings:
    /// the scatter alone, of one σ. The gains are ratios, and every fit is linear in the
    /// readings with the cell means free, so neither the σ nor the kept terms' values
    /// change them ([`shaped`]; a kept warm-up is profiled on each as on the readings).
    /// For run offsets and a scatter line, whose unrelated orders keep much of the real
    /// order: runs dealt at random within a cell of 3 runs leave each reading in its own
    /// run one time in three, and on 5 targets a random order is a line's real order, or
    /// its reverse, about one time in 60.
    fn simulated_threshold(&self, scheme: Scheme, kept: ModelTerms, terms: ModelTerms) -> f64 {
        let p = &self.a.basis.prep;
        let mut rng = Rng::new(self.seed, 0x51AD);
        (0..confirm::UNRELATED)
            .map(|_| {
                let sim: Vec<f64> = (0..p.rows.len()).map(|_| rng.normal()).collect();
                let without = validate::score(p, &sim, &self.fold, &self.outlier, kept);
                let with = validate::score(p, &sim, &self.fold, &self.outlier, terms);
                gain_pct(scheme, scheme.measure(&without), scheme.measure(&with))
            })
            .fold(f64::NAN, f64::max)
    }

    /// The shaped term `set` over the `kept` terms: the shape with the smallest held-out
    /// error, against tests simulated without the term ([`shaped`]).
    fn shaped(
        &self,
        effect: Effect,
        kept: ModelTerms,
        current: Score,
        set: fn(&mut ModelTerms, Shape),
        scheme: Scheme,
    ) -> Option<(TermGain, ModelTerms, Score)> {
        let (p, x) = (&self.a.basis.prep, &self.a.basis.x);
        let left_out: Vec<bool> = (self.outlier.iter()).map(|&o| o && kept.outliers).collect();
        let mut fixed = kept;
        if kept.warm && kept.warm_tau.is_none() {
            let train: Vec<bool> = left_out.iter().map(|l| !l).collect();
            fixed.warm_tau = validate::fit_time(p, x, &train, kept).tau;
        }
        let setup = shaped::Setup {
            prep: p,
            fold: &self.fold,
            rows: validate::Rows {
                scored: &self.outlier,
                left_out: &left_out,
            },
            kept: fixed,
            set,
            scheme,
        };
        let judged = shaped::judge(&setup, x, self.seed)?;
        let threshold = (judged.null_gains_pct.iter()).fold(f64::NAN, |a, &b| a.max(b));
        let (now, with) = (scheme.measure(&current), scheme.measure(&judged.score));
        let mut gain = TermGain::new(effect, scheme, now, with, threshold);
        gain.shape = Some(judged.shape);
        gain.shapes = judged.shapes;
        let mut terms = kept;
        set(&mut terms, judged.shape);
        Some((gain, terms, judged.score))
    }

    /// An unrelated warm-up curve (the warm-up judged, not one kept before) takes the
    /// time constant of the profile's grid that fits it best on all the readings
    /// (profiling and refining it in every fold, as the term does, would cost 19 × 10
    /// refined profiles); other terms as they are.
    fn fixed_tau(&self, q: &Prep, kept: ModelTerms, terms: ModelTerms) -> ModelTerms {
        if !terms.warm || kept.warm {
            return terms;
        }
        let train: Vec<bool> = (self.outlier.iter())
            .map(|&o| !(o && terms.outliers))
            .collect();
        let without = ModelTerms {
            warm: false,
            ..terms
        };
        let base = validate::fit_time(q, &self.a.basis.x, &train, without);
        let ones = vec![1.0; q.cells()];
        ModelTerms {
            warm_tau: warm::profile(q, &base, &ones, false).map(|w| w.tau),
            ..terms
        }
    }
}

/// The clocks with the columns `terms` adds to `kept` read at the times of the rows in
/// `order` (row k at row `order[k]`'s time): a drift (and the drift column a thermal
/// growth brings when no drift is kept), a thermal growth, a warm-up.
fn shuffled_time(p: &Prep, order: &[usize], kept: ModelTerms, terms: ModelTerms) -> Clocks {
    let mut c = p.clocks.clone();
    let shuffle = |v: &[f64]| -> Vec<f64> { order.iter().map(|&k| v[k]).collect() };
    let drift_column = |t: ModelTerms| t.drift || t.thermal;
    if drift_column(terms) && !drift_column(kept) {
        c.drift = shuffle(&p.clocks.drift);
    }
    if terms.thermal && !kept.thermal {
        c.thermal = shuffle(&p.clocks.thermal);
    }
    if terms.warm && !kept.warm {
        c.warm = shuffle(&p.clocks.warm);
    }
    c
}

/// Judges the terms of the `findings` in the order of the vocabulary, each against the
/// model of the terms kept before it (a finding whose term is left out is listed apart:
/// [`super::Unconfirmed`]).
pub(crate) fn select(a: &Analysis, findings: &[Finding], seed: u64) -> Selection {
    let p = &a.basis.prep;
    let judge = Judge {
        a,
        fold: validate::folds(p, seed),
        outlier: a.basis.active.iter().map(|x| !x).collect(),
        seed: confirm::plan_seed(&p.positions, &p.clocks.run, seed),
    };
    let base_score = judge.score(ModelTerms::default());
    let (mut kept, mut current) = (ModelTerms::default(), base_score);
    let mut effects = Vec::new();
    let mut term_gains = Vec::new();
    let found = |e: Effect| findings.iter().any(|f| f.effect() == e);
    for &effect in Effect::ALL.iter().filter(|e| found(**e) && p.n >= 2) {
        let shaped = match effect.rule().term() {
            Term::Readings(set) => Err(set),
            Term::TargetMeans => continue,
            Term::Shaped(set) => Ok((set, Scheme::KFoldRms)),
            Term::ShapedDensity(set) => Ok((set, Scheme::KFoldDensity)),
        };
        let set = match shaped {
            Err(set) => set,
            Ok((set, scheme)) => {
                if let Some((gain, terms, s)) = judge.shaped(effect, kept, current, set, scheme) {
                    if gain.kept {
                        (kept, current) = (terms, s);
                        effects.push(effect);
                    }
                    term_gains.push(gain);
                }
                continue;
            }
        };
        let mut terms = kept;
        set(&mut terms);
        let scheme = Scheme::KFoldRms;
        let measure = |s: &Score| scheme.measure(s);
        let (s, threshold) = match effect.rule().unrelated() {
            Unrelated::SimulatedTests => {
                let threshold = judge.simulated_threshold(scheme, kept, terms);
                (judge.score(terms), threshold)
            }
            unrelated => {
                let (s, others) = judge.judge(unrelated, kept, terms);
                let others: Vec<f64> = others.iter().map(measure).collect();
                (s, largest_gain(scheme, measure(&current), &others))
            }
        };
        let gain = TermGain::new(effect, scheme, measure(&current), measure(&s), threshold);
        if gain.kept {
            (kept, current) = (terms, s);
            effects.push(effect);
        }
        term_gains.push(gain);
    }
    let (between, periodic) = judge_periodic(a, judge.seed, &mut effects, &mut term_gains);
    term_gains.sort_by_key(|g| g.effect);
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

/// The largest leave-targets-out gain of a sinusoid of `period` on [`confirm::UNRELATED`]
/// sets of target means simulated from the base model (`without`: the smooth trend and
/// the scatter of the means), with the real ones' `weights`.
fn simulated_between_targets(
    positions: &[f64],
    without: &periodic::MeansModel,
    weights: &[f64],
    period: f64,
    seed: u64,
) -> f64 {
    let mut rng = Rng::new(seed, 0x9E71);
    (0..confirm::UNRELATED)
        .map(|_| {
            let y: Vec<f64> = (without.trend.iter().zip(&without.sd))
                .map(|(t, s)| t + s * rng.normal())
                .collect();
            let (b, e) = validate::between_targets(positions, &y, period, weights).rms();
            gain_pct(Scheme::LeaveTargetsOut, b, e)
        })
        .fold(f64::NAN, f64::max)
}

/// The periodic term, judged on the leave-targets-out errors of the target means (each
/// weighted by the inverse variance of its mean) against the same sinusoid on target
/// means simulated without it: the RMS without and with it, and the term when it earns
/// its place.
fn judge_periodic(
    a: &Analysis,
    seed: u64,
    effects: &mut Vec<Effect>,
    term_gains: &mut Vec<TermGain>,
) -> ((Option<f64>, Option<f64>), Option<Peak>) {
    let Some(peak) = a.periodic.peak.as_ref() else {
        return ((None, None), None);
    };
    let positions = &a.basis.prep.positions;
    let without = &a.periodic.without;
    let weights = without.weights();
    let errors = validate::between_targets(positions, &a.basis.means, peak.period, &weights);
    let (bb, be) = errors.rms();
    let threshold = simulated_between_targets(positions, without, &weights, peak.period, seed);
    let gain = TermGain::new(Effect::Periodic, Scheme::LeaveTargetsOut, bb, be, threshold);
    let kept = gain.kept;
    term_gains.push(gain);
    if kept {
        effects.push(Effect::Periodic);
        ((Some(bb), Some(be)), Some(peak.clone()))
    } else {
        ((Some(bb), Some(be)), None)
    }
}
