//! Thermal growth: an error proportional to position that grows with time (screw or scale
//! expansion; Hemingray et al. 1971, §5.4 and conclusion 1). Its test (below; run in
//! order by the joint time tests of `time.rs`) takes the position × time coefficient of the full time model,
//! against the pure scatter.

use super::{Effect, Finding, Rule as EffectRule, Term, Unrelated};
use crate::axis_model::ErrorModel;
use crate::diagnose::basis::Basis;
use crate::diagnose::detectable::{Detectable, plan_words, span_words, t_shift, with_unit};
use crate::diagnose::finding::{Evidence, Fields, Units, fmt, fmt_p, relative};
use crate::diagnose::fitted::Fitted;
use crate::diagnose::maths::stats::t_two_sided;
use crate::diagnose::model::r4;
use crate::diagnose::options::ALPHA;
use crate::diagnose::prep::Prep;
use crate::diagnose::time_fit::CoefTest;
use crate::diagnose::time_fit::TimeFit;
use crate::measurement::fmt_target;
use crate::units::AxisKind;

/// A thermal growth: ppm of the position per time unit (hour, or run), about an origin.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalGrowth {
    /// ppm (µm per m, or for a rotary axis ppm of the angle) per time unit.
    pub(crate) growth_ppm: f64,
    /// Standard error of `growth_ppm`.
    pub(crate) growth_se_ppm: f64,
    /// The position where the growth is zero, mm or deg.
    pub origin: f64,
    /// Whether `origin` was declared ([`crate::diagnose::Options::thermal_origin`]), not
    /// fitted.
    pub(crate) origin_declared: bool,
    /// Over the measured travel and the test, deviation unit.
    pub(crate) over_travel_and_test: f64,
}

impl Fields for ThermalGrowth {
    fn params(&self, u: Units) -> Vec<(String, f64)> {
        let tk = u.time();
        let (key, se_key) = match u.kind {
            AxisKind::Linear => (
                format!("growth_um_per_m_per_{tk}"),
                format!("growth_se_um_per_m_per_{tk}"),
            ),
            AxisKind::Rotary => (
                format!("growth_ppm_per_{tk}"),
                format!("growth_se_ppm_per_{tk}"),
            ),
        };
        vec![
            (key, self.growth_ppm),
            (se_key, self.growth_se_ppm),
            (format!("origin_{}", u.pos()), self.origin),
            (
                format!("growth_over_travel_and_test_{}", u.dev()),
                self.over_travel_and_test,
            ),
        ]
    }

    /// `origin: declared` when the origin was given, not fitted.
    fn labels(&self) -> Vec<(&'static str, &'static str)> {
        if self.origin_declared {
            vec![("origin", "declared")]
        } else {
            Vec::new()
        }
    }

    /// ISO 230-2 3.1 (temperatures of the positioning system, NDE) and 3.3 (warm-up).
    fn advice(&self, u: Units) -> String {
        format!(
            "the axis grew by {} {} over its travel during the test: let the screw or scale reach a steady temperature before testing (ISO 230-2 3.3) and check the temperature correction (the sensor on the positioning system and its expansion coefficient, ISO 230-2 3.1); a linear (scale) compensation holds at one temperature only",
            fmt(self.over_travel_and_test.abs()),
            u.symbol()
        )
    }
}

pub(crate) struct Rule;

impl Rule {
    /// The findings of this effect from its test (each at level [`crate::diagnose::ALPHA`]).
    /// `drift_origin`: where the drift test put the origin of the time effect, if it did.
    pub(crate) fn find(
        &self,
        a: &Basis,
        thermal: Option<&CoefTest>,
        drift_origin: Option<f64>,
    ) -> Vec<Finding> {
        let Some(t) = thermal.filter(|t| t.p < ALPHA) else {
            return Vec::new();
        };
        let u = a.units;
        let ppm = t.estimate / a.prep.ppm_factor();
        // The drift is read at the declared origin whenever one is given (`drift::test`).
        let declared = a.prep.thermal_origin.is_some() && drift_origin.is_some();
        let origin = drift_origin.unwrap_or(a.prep.pbar);
        let over = t.estimate * a.length() * a.prep.t_span;
        let message = format!(
            "an error proportional to position grows with time: {} ppm per {} ({} {} over the measured travel and the test), zero at {}{} (t = {}, p = {})",
            fmt(ppm),
            u.per(),
            fmt(over),
            u.symbol(),
            fmt_target(u.kind, origin),
            if declared {
                ", the declared origin"
            } else {
                ""
            },
            fmt(t.t),
            fmt_p(t.p)
        );
        vec![Finding {
            estimate: ThermalGrowth {
                growth_ppm: ppm,
                growth_se_ppm: t.se / a.prep.ppm_factor(),
                origin,
                origin_declared: declared,
                over_travel_and_test: over,
            }
            .into(),
            units: u,
            evidence: Evidence {
                statistic: format!("t of the position × time coefficient (df {})", t.df),
                value: t.t,
                p_value: Some(t.p),
                effect_size: relative(over.abs(), a.sigma),
            },
            message,
        }]
    }
}

impl EffectRule for Rule {
    fn term(&self) -> Term {
        Term::Readings(|t| t.thermal = true)
    }

    /// A column in time: compared with the same column at the readings' times in random
    /// orders.
    fn unrelated(&self) -> Unrelated {
        Unrelated::TimeOrders
    }

    fn extend(&self, a: &Basis, fit: &Fitted, model: &mut ErrorModel) {
        model.thermal_growth_ppm_per_h = r4(fit.growth / a.prep.ppm_factor() / fit.hours_per_unit);
        model.thermal_origin = r4(fit.origin);
    }

    fn removed(&self, a: &Basis, fit: &Fitted) -> Option<Vec<f64>> {
        let p = &a.prep;
        Some(
            p.rows
                .iter()
                .map(|r| fit.growth * (p.positions[r.i] - fit.origin) * (r.t - p.tbar))
                .collect(),
        )
    }
}

/// The test: γ in the full model, against the pure scatter.
pub(crate) fn test(full: &TimeFit, sigma2: f64, df: f64) -> Option<CoefTest> {
    let c = full.thermal_col.filter(|&c| full.ls.kept[c])?;
    let se = (sigma2 * full.ls.cov[c][c]).sqrt();
    let t = full.gamma / se;
    Some(CoefTest {
        estimate: full.gamma,
        se,
        t,
        p: t_two_sided(t, df),
        df,
    })
}

/// What this plan confirms: a growth over the measured travel and the test whose
/// position × time coefficient reaches the t shift of
/// [`crate::diagnose::detectable::POWER`] at the level, in its standard errors.
pub(crate) fn detectable(p: &Prep, u: Units, t: Option<&CoefTest>) -> Detectable {
    let measure = format!("growth_over_travel_and_test_{}", u.dev());
    let Some(t) = t else {
        return Detectable::untestable(
            Effect::ThermalGrowth,
            measure,
            "a growth with time along the axis needs two runs, two targets and readings left beyond the time model",
        );
    };
    let size = t_shift(ALPHA, t.df) * t.se * p.length() * p.t_span;
    let advice = format!(
        "{} over {} a growth under {} over the measured travel and the test may go unconfirmed",
        plan_words(p.m, p.n),
        span_words(p),
        with_unit(size, u)
    );
    Detectable::sized(Effect::ThermalGrowth, measure, size, advice)
}
