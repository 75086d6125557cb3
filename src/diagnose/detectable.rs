//! What this plan can confirm (issue 43): per effect, the smallest size its test finds in
//! 80 % of tests with this plan and this scatter, so that "no finding" is read with what
//! it could have found. With few targets or runs a real effect may be unconfirmable, and
//! the metrologist is told the size and what a larger plan would reach.
//!
//! Reversal variation: its test of the slope of Bi along the axis at half the level
//! (a two-sided t on the scatter's df) finds a change Δ over the axis in 80 % of tests
//! when Δ / se(Δ) ≈ t(1 − α/4) + t(0.80), the usual shifted-t approximation of the power
//! of a t-test (Cohen 1988, "Statistical Power Analysis", §2.3); se(Δ) is the slope's
//! standard error times the measured travel. The held-out confirmation that follows
//! rarely refuses an effect that clear: the sweep checks that effects of the stated size
//! are confirmed in 70–90 % of simulated tests on 5-target plans.

use super::effects::Effect;
use super::effects::reversal_variation::ReversalTest;
use super::finding::{Units, fmt};
use super::maths::stats::t_two_sided_quantile;
use super::options::ALPHA;
use super::prep::Prep;
use serde::Serialize;

/// The share of tests in which an effect of the stated size is found.
pub const POWER: f64 = 0.80;

/// The smallest effect of one kind this plan confirms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Detectable {
    pub effect: Effect,
    /// The size found in [`POWER`] of tests, in the unit of `measure`.
    pub size: f64,
    /// What the size measures, with its unit (`change_over_axis_um`).
    pub measure: String,
    /// Targets of a larger plan over the same travel, and the size it would reach (about).
    pub more_targets: Option<usize>,
    pub size_with_more_targets: Option<f64>,
    /// In words, with what a larger plan would reach.
    pub advice: String,
}

/// The smallest confirmable effects of the plan `p` (those whose test ran).
pub(crate) fn detectable(
    p: &Prep,
    units: Units,
    reversal: Option<&ReversalTest>,
) -> Vec<Detectable> {
    reversal
        .and_then(|r| reversal_variation(p, units, r))
        .into_iter()
        .collect()
}

/// A reversal changing linearly by the size over the measured travel.
fn reversal_variation(p: &Prep, units: Units, r: &ReversalTest) -> Option<Detectable> {
    let travel = p.hi - p.lo;
    let t_crit = t_two_sided_quantile(ALPHA / 2.0, r.df);
    let t_power = t_two_sided_quantile(2.0 * (1.0 - POWER), r.df);
    let size = (t_crit + t_power) * r.se_slope * travel;
    if !(size.is_finite() && size > 0.0) {
        return None;
    }
    // Equally spaced targets over the same travel: se(slope) ∝ 1/√Σ(x − x̄)², and
    // Σ(x − x̄)² = L²·m(m + 1)/(12(m − 1)).
    let spread = |m: f64| m * (m + 1.0) / (12.0 * (m - 1.0));
    let more = (p.m < 10).then_some(10);
    let with_more = more.map(|k| size * (spread(p.m as f64) / spread(k as f64)).sqrt());
    let ds = units.symbol();
    let mut advice = format!(
        "with {} targets and {} runs a reversal variation under {} {ds} over the axis may go unconfirmed (a change of that size is found in {:.0} % of tests)",
        p.m,
        p.n,
        fmt(size),
        POWER * 100.0
    );
    if let (Some(k), Some(s)) = (more, with_more) {
        advice += &format!(
            "; {k} targets over the same travel would confirm about {} {ds}",
            fmt(s)
        );
    }
    Some(Detectable {
        effect: Effect::ReversalVariation,
        size,
        measure: format!("change_over_axis_{}", units.dev()),
        more_targets: more,
        size_with_more_targets: with_more,
        advice,
    })
}
