//! Outliers: readings inconsistent with the rest (Hemingray et al. 1971, §5.3: the scatter
//! estimate is only as good as its readings). Found (below) by
//! externally studentised residuals in the full time model, Bonferroni over all readings.
//!
//! The test: each reading's externally studentised residual in the full time model (cell effects,
//! run effects, drift, thermal growth and a warm-up found, so that a drift does not make the first and last
//! runs look like outliers): t = r / (s₍₋ₖ₎ √(1 − h)), with s₍₋ₖ₎ the scatter without the
//! reading and h its leverage; t follows Student's t with df − 1 degrees of freedom.
//! The largest |t| is tested with a Bonferroni correction over all readings; a reading
//! found is set aside and the search repeats. A cell needs n ≥ 3 readings: with two, either
//! could be the odd one.

use super::{Effect, Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::{ErrorModel, PlantedOutlier};
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, plan_words, t_shift, with_unit};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::stats::t_two_sided;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::time_fit::{Terms, fit};
use crate::measurement::fmt_target;
use crate::units::Direction;

/// One reading off by more than the rest explain.
#[derive(Debug, Clone, PartialEq)]
pub struct Outlier {
    /// Run label as in the file.
    pub run: u32,
    /// Target number, from 1.
    pub target: usize,
    pub direction: Direction,
    /// Target position, mm or deg.
    pub position: f64,
    /// The reading minus what the rest predict, deviation unit.
    pub size: f64,
}

impl Fields for Outlier {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        vec![
            ("run".into(), f64::from(self.run)),
            ("target".into(), self.target as f64),
            (format!("position_{}", u.pos()), self.position),
            (format!("size_{}", u.dev()), self.size),
        ]
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        vec![("direction", self.direction.name())]
    }

    fn advice(&self, u: Units) -> String {
        format!(
            "re-measure the {} approach to target {} ({}) in run {}; where its cause is known (a disturbed beam, a knock) exclude that reading with a note in the test report: the parameters here include it",
            self.direction.name(),
            self.target,
            fmt_target(u.kind, self.position),
            self.run
        )
    }
}

fn direction(d: usize) -> Direction {
    if d == 0 {
        Direction::Up
    } else {
        Direction::Down
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    pub(crate) fn find(&self, a: &Basis, hits: &[Hit]) -> Vec<Finding> {
        let u = a.units;
        hits
            .iter()
            .map(|h| {
                let r = &a.prep.rows[h.row];
                let dir = direction(r.d);
                let run = a.data.run_labels[r.run];
                let position = a.prep.positions[r.i];
                let message = format!(
                    "reading of run {run}, {}, target {} ({}) is off by {} {} from what the rest predict (t = {}, adjusted p = {})",
                    dir.name(),
                    r.i + 1,
                    fmt_target(u.kind, position),
                    fmt(h.size),
                    u.symbol(),
                    fmt(h.t),
                    fmt_p(h.p_adj)
                );
                Finding {
                    estimate: Outlier {
                        run,
                        target: r.i + 1,
                        direction: dir,
                        position,
                        size: h.size,
                    }
                    .into(),
                    units: u,
                    evidence: Evidence {
                        statistic: "externally studentised residual (Bonferroni over all readings)"
                            .into(),
                        value: h.t,
                        p_value: Some(h.p_adj),
                        effect_size: relative(h.size.abs(), a.sigma),
                    },
                    message,
                }
            })
            .collect()
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Readings(|t| t.outliers = true)
    }

    /// Readings left out of the fit: compared with as many ordinary readings left out.
    fn unrelated(&self) -> Unrelated {
        Unrelated::OrdinaryReadings
    }

    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.outliers = fit
            .outliers
            .iter()
            .map(|&(row, size)| {
                let r = &a.prep.rows[row];
                PlantedOutlier {
                    run: r.run as u32 + 1,
                    direction: direction(r.d),
                    target: r.i + 1,
                    size: r4(size),
                }
            })
            .collect();
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        let mut v = vec![0.0; a.x.len()];
        for &(row, size) in &fit.outliers {
            v[row] = size;
        }
        Some(v)
    }
}

/// One outlier.
#[derive(Debug, Clone)]
pub(crate) struct Hit {
    /// Row index in `Prep::rows`.
    pub row: usize,
    pub t: f64,
    /// Bonferroni-adjusted p-value.
    pub(crate) p_adj: f64,
    /// Deleted residual: the reading minus what the rest predicts, µm or arcsec.
    pub size: f64,
}

/// Finds outliers among `values` at family-wise level `alpha`; `scale` is the relative
/// scatter per cell; `warm` the time constant of a warm-up found, whose curve within the
/// first run would otherwise leave its first readings as outliers.
pub(crate) fn detect(
    prep: &Prep,
    values: &[f64],
    scale: &[f64],
    warm: Option<f64>,
    alpha: f64,
) -> Vec<Hit> {
    let mut hits = Vec::new();
    if prep.n < 3 {
        return hits;
    }
    let total = prep.rows.len();
    let mut active = vec![true; total];
    // At most one reading in twenty, and 50 in all: beyond that the scatter itself is
    // the problem, not single readings.
    let cap = (total / 20).clamp(1, 50);
    let terms = Terms {
        thermal: true,
        runs: true,
        drift: true,
        warm,
        thermal_about: None,
    };
    while hits.len() < cap {
        let f = fit(prep, values, &active, scale, terms);
        let df = f.df;
        if df < 3.0 || f.rss <= 0.0 {
            break;
        }
        let mut count = vec![0usize; prep.cells()];
        for &k in &f.rows {
            count[prep.cell(&prep.rows[k])] += 1;
        }
        let mut best: Option<(usize, f64, f64)> = None;
        for (idx, &k) in f.rows.iter().enumerate() {
            let c = prep.cell(&prep.rows[k]);
            if count[c] < 3 {
                continue;
            }
            let h = 1.0 / count[c] as f64 + f.ls.leverage(idx);
            if 1.0 - h <= 1e-9 {
                continue;
            }
            let r = f.ls.residuals[idx];
            let s2 = (f.rss - r * r / (1.0 - h)) / (df - 1.0);
            if s2 <= 0.0 {
                continue;
            }
            let t = r / (s2 * (1.0 - h)).sqrt();
            if best.is_none_or(|(_, bt, _)| t.abs() > bt.abs()) {
                best = Some((k, t, r / (1.0 - h) * scale[c]));
            }
        }
        let Some((k, t, size)) = best else { break };
        let p_adj = (t_two_sided(t, df - 1.0) * total as f64).min(1.0);
        if p_adj.is_nan() || p_adj >= alpha {
            break;
        }
        hits.push(Hit {
            row: k,
            t,
            p_adj,
            size,
        });
        active[k] = false;
    }
    hits
}

/// What this plan confirms: one reading off by a size whose externally studentised
/// residual reaches the t shift of [`crate::diagnose::detectable::POWER`] at the
/// Bonferroni level over all readings. The residual keeps √(1 − h) of the size, h being
/// the reading's leverage: 1/n for its cell's mean and about (n + 1)/N for the run
/// effects, the drift and the thermal growth of the time model.
pub(crate) fn detectable(p: &Prep, u: Units, sigma2: f64, df: f64) -> Detectable {
    let measure = format!("size_{}", u.dev());
    if p.n < 3 {
        return Detectable::untestable(
            Effect::Outlier,
            measure,
            "an odd reading needs at least three runs (of two readings, either could be it)",
        );
    }
    if !(df >= 3.0 && sigma2 > 0.0) {
        return Detectable::untestable(
            Effect::Outlier,
            measure,
            "too few readings beyond the time model",
        );
    }
    let total = p.rows.len() as f64;
    let h = 1.0 / p.n as f64 + (p.n as f64 + 1.0) / total;
    let size = t_shift(ALPHA / total, df - 1.0) * sigma2.sqrt() / (1.0 - h).sqrt();
    let advice = format!(
        "{} a single reading off by less than {} may go unconfirmed",
        plan_words(p.m, p.n),
        with_unit(size, u)
    );
    Detectable::sized(Effect::Outlier, measure, size, advice)
}
