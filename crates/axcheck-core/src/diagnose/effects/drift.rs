//! Drift: the deviations move with time, uniformly along the axis (warm-up; ISO 230-2
//! 3.3; Hemingray et al. 1971, §5.4). Its test (below; run in order
//! by the joint time tests of `time.rs`) takes the drift
//! rate of the trend model, against the scatter or, when the run offsets are real, against
//! the run-to-run variation.

use super::{Effect, Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, plan_words, span_words, t_shift, with_unit};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::time_fit::DriftTest;
use crate::diagnose::time_fit::{CoefTest, TimeFit};

/// A drift: its rate per time unit (hour, or run without time stamps).
#[derive(Debug, Clone, PartialEq)]
pub struct Drift {
    /// Deviation unit per time unit.
    pub rate: f64,
    /// Standard error of the rate.
    pub(crate) rate_se: f64,
    /// Over the test: the rate times its time span, deviation unit.
    pub total: f64,
    /// The position where the drift is the time effect, when thermal growth is found too.
    pub at: Option<f64>,
    /// What the rate was tested against: `scatter` or `run-to-run variation`.
    pub(crate) tested_against: &'static str,
}

impl Fields for Drift {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let (du, tk) = (u.dev(), u.time());
        let mut params = vec![
            (format!("rate_{du}_per_{tk}"), self.rate),
            (format!("rate_se_{du}_per_{tk}"), self.rate_se),
            (format!("total_{du}"), self.total),
        ];
        if let Some(o) = self.at {
            params.push((format!("at_{}", u.pos()), o));
        }
        params
    }

    /// ISO 230-2 3.3: approaches that form an ordered series mean the machine is not
    /// thermally stable; under the standard cycle a drift shows in B and R (Annex A).
    fn advice(&self, u: Units) -> String {
        format!(
            "re-test once the machine is thermally stable: warm it up as its supplier specifies and keep the room temperature steady (ISO 230-2 3.1, 3.3); the {} {} it moved during the test are not an error of position, so a compensation table cannot remove them, and they enlarge R and B",
            fmt(self.total.abs()),
            u.symbol()
        )
    }

    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        vec![("tested_against", self.tested_against)]
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    /// `warm_up_under`: the smallest warm-up this plan confirms, when none was found: a
    /// warm-up under it shows only its trend, as this drift (Hemingray et al. 1971, §5.4:
    /// a machine warming up drifts until it settles).
    pub(crate) fn find(
        &self,
        a: &Basis,
        drift: Option<&DriftTest>,
        warm_up_under: Option<f64>,
    ) -> Vec<Finding> {
        let Some(d) = drift.filter(|d| d.test.p < ALPHA) else {
            return Vec::new();
        };
        let u = a.units;
        let rate = d.test.estimate;
        let total = rate * a.prep.t_span;
        let warm_up = warm_up_under.map_or(String::new(), |level| {
            format!(
                "; a warm-up approaching a level under {}, which this plan cannot tell from a drift, would read so",
                with_unit(level, u)
            )
        });
        let message = format!(
            "the deviations drift by {} {ds} per {} uniformly along the axis ({} {ds} over the test; t = {}, p = {}, against the {}){}{warm_up}",
            fmt(rate),
            u.per(),
            fmt(total),
            fmt(d.test.t),
            fmt_p(d.test.p),
            d.against,
            if a.prep.n == 2 {
                "; with two runs this may as well be a zero shift between them"
            } else {
                ""
            },
            ds = u.symbol(),
        );
        vec![Finding {
            estimate: Drift {
                rate,
                rate_se: d.test.se,
                total,
                at: d.origin,
                tested_against: d.against,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic: format!(
                    "t of the drift rate (df {}, against the {})",
                    d.test.df, d.against
                ),
                value: d.test.t,
                p_value: Some(d.test.p),
                effect_size: relative(total.abs(), a.sigma),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Readings(|t| t.drift = true)
    }

    /// A column in time: compared with the same column at the readings' times in random
    /// orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TimeOrders
    }

    fn extend(&self, _: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.drift_per_h = r4(fit.drift_rate / fit.hours_per_unit);
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        Some(
            a.prep
                .rows
                .iter()
                .map(|r| fit.drift_rate * (r.t - a.prep.tbar))
                .collect(),
        )
    }
}

/// The test: the trend model's β (with γ), against `reference` (the scatter or, when the
/// run offsets are real, the run-to-run variation: mean square, degrees of freedom,
/// name); at the declared thermal origin, or with a thermal growth found at its fitted
/// origin.
pub(crate) fn test(
    prep: &Prep,
    trend: &TimeFit,
    reference: (f64, f64, &'static str),
    thermal_found: bool,
) -> Option<DriftTest> {
    let bc = trend.drift_col.filter(|&c| trend.ls.kept[c])?;
    let (err_ms, err_df, against) = reference;
    let tc = trend.thermal_col.filter(|&c| trend.ls.kept[c]);
    // The origin: declared, or where the time effect vanishes when a growth is found (a
    // screw's fixed end lies at or near the measured travel, so within a quarter of the
    // travel beyond its ends the effect is all thermal growth). A declared origin holds
    // still under a growth found or not: the drift is what moves it.
    let origin = match (prep.thermal_origin, thermal_found, tc) {
        (Some(o), _, Some(_)) => Some(o),
        (None, true, Some(_)) if trend.gamma != 0.0 => {
            let p0 = prep.pbar - trend.beta / trend.gamma;
            let margin = 0.25 * prep.length();
            Some(p0.clamp(prep.lo - margin, prep.hi + margin))
        }
        _ => None,
    };
    let (estimate, var, origin) = match origin.and_then(|o| trend.drift_at(prep, o)) {
        Some((estimate, var)) => (estimate, var, origin),
        None => (trend.beta, trend.ls.cov[bc][bc], None),
    };
    Some(DriftTest {
        test: CoefTest::of(estimate, var, (err_ms, err_df)),
        origin,
        against,
    })
}

/// What this plan confirms: a drift whose total over the test reaches the t shift of
/// [`crate::diagnose::detectable::POWER`] at the level, in standard errors of the rate
/// (against the scatter, or the run-to-run variation when run offsets are real) times
/// the test's span.
pub(crate) fn detectable(p: &Prep, u: Units, d: Option<&DriftTest>) -> Detectable {
    let measure = format!("total_{}", u.dev());
    let Some(d) = d else {
        return Detectable::untestable(
            Effect::Drift,
            measure,
            "a drift needs at least two runs and readings left beyond the time model",
        );
    };
    let size = t_shift(ALPHA, d.test.df) * d.test.se * p.t_span;
    let advice = format!(
        "{} over {} a drift under {} over the test may go unconfirmed",
        plan_words(p.m, p.n),
        span_words(p),
        with_unit(size, u)
    );
    Detectable::sized(Effect::Drift, measure, size, advice)
}
