//! What this plan can confirm (issue 43): per effect, the smallest size its test finds in
//! 80 % of tests with this plan and this scatter, so that "no finding" is read with what
//! it could have found. With few targets or runs a real effect may be unconfirmable, and
//! the metrologist is told the size and what a larger plan would reach; an effect this
//! plan cannot test at all is listed with the reason.
//!
//! Each effect's size comes from the power of its own test (in its file, beside the
//! test): the noncentrality at which the test at its level rejects in 80 % of tests
//! ([`noncentrality_for_power`]), turned into the effect's size by the standard error of
//! its estimate on this plan (the scatter variation's from the exact distribution of its
//! statistic). The held-out confirmation that follows rarely refuses an effect that
//! clear, but for the periodic term's: the sweep checks, for every effect, that an effect
//! of the stated size is confirmed in 70–90 % of simulated tests, and prints those not
//! yet there.
//!
//! [`noncentrality_for_power`]: super::maths::stats::noncentrality_for_power

use super::effects::Effect;
use super::finding::{Units, fmt};
use super::maths::stats::{f_upper_quantile, noncentrality_for_power};
use super::prep::{Prep, TimeUnit};
use serde::Serialize;
use std::collections::BTreeMap;

pub use super::options::POWER;

/// The smallest effect of one kind this plan confirms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Detectable {
    pub effect: Effect,
    /// The size found in [`POWER`] of tests, in the unit of `measure`; None when this
    /// plan cannot test the effect (`advice` says why).
    pub size: Option<f64>,
    /// What the size measures, with its unit (`change_over_axis_um`).
    pub measure: String,
    /// The shape the size assumes, keyed with units (`period_mm`, `time_constant_h`);
    /// empty when the size needs none.
    pub assumed: BTreeMap<String, f64>,
    /// Targets of a larger plan over the same travel, and the size it would reach (about).
    pub more_targets: Option<usize>,
    pub size_with_more_targets: Option<f64>,
    /// In words, with what a larger plan would reach.
    pub advice: String,
}

impl Detectable {
    /// A size found in [`POWER`] of tests, described by `advice` (which reads on from
    /// "… may go unconfirmed"); untestable when the size is not a positive number.
    pub(crate) fn sized(effect: Effect, measure: String, size: f64, advice: String) -> Self {
        if !(size.is_finite() && size > 0.0) {
            return Detectable::untestable(effect, measure, "its statistic has no spread here");
        }
        Detectable {
            effect,
            size: Some(size),
            measure,
            assumed: BTreeMap::new(),
            more_targets: None,
            size_with_more_targets: None,
            advice: format!(
                "{advice} (an effect of that size is found in {:.0} % of tests)",
                POWER * 100.0
            ),
        }
    }

    /// An effect this plan cannot test, and why.
    pub(crate) fn untestable(effect: Effect, measure: String, why: &str) -> Self {
        Detectable {
            effect,
            size: None,
            measure,
            assumed: BTreeMap::new(),
            more_targets: None,
            size_with_more_targets: None,
            advice: format!("not testable with this plan: {why}"),
        }
    }

    /// The size assumes `key` = `value` (a period, a time constant).
    pub(crate) fn assuming(mut self, key: String, value: f64) -> Self {
        if self.size.is_some() {
            self.assumed.insert(key, value);
        }
        self
    }
}

/// The shift (in standard errors) at which a two-sided t test at `level` on `df` degrees
/// of freedom finds an effect in [`POWER`] of tests.
pub(crate) fn t_shift(level: f64, df: f64) -> f64 {
    let critical = f_upper_quantile(level, 1.0, df);
    noncentrality_for_power(critical, 1.0, df, POWER).sqrt()
}

/// "with m targets and n runs": the plan, as the advice names it.
pub(crate) fn plan_words(m: usize, n: usize) -> String {
    format!("with {m} targets and {n} runs")
}

/// A size with its unit for the advice.
pub(crate) fn with_unit(size: f64, u: Units) -> String {
    format!("{} {}", fmt(size), u.symbol())
}

/// The test's time span in words: "2.5 h", or its runs without time stamps.
pub(crate) fn span_words(p: &Prep) -> String {
    match p.time_unit {
        TimeUnit::Hours => format!("{} h", fmt(p.t_span)),
        TimeUnit::Runs => format!("{} runs", p.n),
    }
}
