//! The verdict: agreement of the re-measurement with the prediction judged both ways, on E
//! (ISO 230-2 2.20, the parameter a table exists to reduce) and per target (χ²).
//!
//! - **E, both ways.** E achieved and E predicted agree when they differ by no more than U,
//!   the expanded uncertainty (95 %) of a difference of two E ([`e_uncertainty`]). This is
//!   the normalised error of proficiency testing, |E_n| ≤ 1 with E_n = (x − X)/√(U_x² + U_X²),
//!   here U the expanded uncertainty of the difference itself (ISO 13528,
//!   "E_n score"; NIST Dataplot reference manual, "ISO 13528 EN SCORE",
//!   itl.nist.gov/div898/software/dataplot/refman2/auxillar/enscore.htm): two-sided, so an
//!   E achieved far *below* the one predicted disagrees as much as one far above. A table
//!   that acted as named cannot leave the axis better than its prediction beyond the scatter
//!   of the two measurements; when it does, the table on the machine is not the one named
//!   (another axis's, an older or newer file): `table_mismatch`.
//! - **Per target, χ².** The change measured (after − before) at each target and direction
//!   is compared with the change the named table predicts, each difference weighted by its
//!   standard uncertainty (from the two measurements' pooled repeatability, s/√n, GUM 4.2)
//!   and a constant offset fitted (a laser datum, which no ISO 230-2 parameter sees):
//!   χ² = Σ ((Δx − c − offset)/u)² on ν = N − 1 degrees of freedom. This is the consistency
//!   test of a set of results with their uncertainties against one model, as key
//!   comparisons test their weighted mean (M. G. Cox, "The evaluation of key comparison
//!   data", Metrologia 39 (2002) 589–595, its Procedure A failing the check when
//!   P(χ²_ν > χ²_obs) < 5 %, as recalled: its text was not read here; Cox, "… determining
//!   the largest consistent subset", Metrologia 44 (2007) 187–200, whose abstract,
//!   eprintspublications.npl.co.uk/3861, states the test). Its uncertainties here are Type
//!   A standard deviations of means of repeated readings, the case the test is made for
//!   (R. N. Kacker, R. Kessel, K.-D. Sommer, "Assessing differences between results
//!   determined according to the GUM", J. Res. NIST 115 (2010) 453–459,
//!   pmc.ncbi.nlm.nih.gov/articles/PMC4548867, warn against it for results whose
//!   uncertainties are not sampling standard deviations). The named table is rejected when
//!   P(χ²_ν ≥ χ²) < [`super::ALPHA`] = 0.1 % (stricter than 5 %: a verdict that stops a
//!   machine should not come from one seed in twenty). Where the targets differ, each
//!   difference's uncertainty holds the interpolation's ([`super::interpolation`]).
//!   Measured on 500 simulated re-measurements of a table acting as named (21 targets,
//!   five runs, a TwinCAT list every 50 mm): at the same targets χ²/ν 1.01 on average, 2
//!   seeds beyond the 0.1 % point and 496 `effective`; at targets jittered anew 0.18, none
//!   and 500 (the interpolation's uncertainty is conservative there).
//!
//! The verdict, in this order:
//! 1. E achieved below E predicted by more than U: `table_mismatch` (whatever an effect
//!    found says of what acted instead).
//! 2. χ² rejects the named table and no effect of the vocabulary explains the change: the
//!    per-target test decides; `made_worse` when E grew beyond U above E before (the
//!    urgent fact), else `table_mismatch`: the change does not follow the table named.
//! 3. Otherwise on E, one-sided as before: `effective` within U of the prediction (never
//!    when χ² rejects the named table: then `table_mismatch`), `made_worse` beyond U above
//!    E before, `partly_effective` beyond U below it, `not_effective` in between.
//!
//! The χ² assumes the machine's own deviations unchanged between the two measurements but
//! for the offset: a machine that warmed, wore or was adjusted in between is rejected too,
//! and the finding says so.

use super::compare::ComparedTarget;
use crate::evaluate::Evaluation;
use crate::evaluate::stats::normal_cdf;
use serde::Serialize;

/// The verdict on a compensation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Effectiveness {
    /// E achieved within the prediction's uncertainty of the E predicted, and the change
    /// per target follows the table named.
    Effective,
    /// E reduced beyond the uncertainty, but not to the prediction.
    PartlyEffective,
    /// E not changed beyond the uncertainty.
    NotEffective,
    /// E grown beyond the uncertainty.
    MadeWorse,
    /// The re-measurement does not follow the table named: E far better than predicted, or
    /// the change per target beyond what the scatter allows with nothing to explain it.
    TableMismatch,
}

impl Effectiveness {
    /// The verdict and what it means, for the console and the report.
    pub fn words(self) -> &'static str {
        match self {
            Effectiveness::Effective => "effective: E achieved within the prediction's uncertainty",
            Effectiveness::PartlyEffective => {
                "partly effective: E reduced, but not to the prediction"
            }
            Effectiveness::NotEffective => "not effective: E not changed beyond the uncertainty",
            Effectiveness::MadeWorse => "made worse: E grown beyond the uncertainty",
            Effectiveness::TableMismatch => {
                "table mismatch: the re-measurement does not follow the table named; the table on the machine is not that one"
            }
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Effectiveness::Effective => "effective",
            Effectiveness::PartlyEffective => "partly_effective",
            Effectiveness::NotEffective => "not_effective",
            Effectiveness::MadeWorse => "made_worse",
            Effectiveness::TableMismatch => "table_mismatch",
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
    /// two target means, each with its standard uncertainty (GUM, normal distribution),
    /// and the interpolation's where the targets differ ([`super::interpolation`]).
    pub uncertainty: f64,
}

impl Systematic {
    /// E achieved below E predicted by more than U: better than the named table can make
    /// the axis.
    pub(crate) fn far_better(&self) -> bool {
        self.achieved < self.predicted - self.uncertainty
    }
}

/// What the verdict is decided on.
pub struct VerdictBasis<'a> {
    pub e: &'a Systematic,
    /// χ² rejects the table as named.
    pub rejected: bool,
    /// An effect of the vocabulary explains the change.
    pub(crate) explained: bool,
}

/// The verdict (see the module's order).
pub fn judge(evidence: &VerdictBasis) -> Effectiveness {
    let e = evidence.e;
    let by_e = on_e(e);
    if e.far_better() {
        return Effectiveness::TableMismatch;
    }
    if evidence.rejected && (!evidence.explained || by_e == Effectiveness::Effective) {
        return match by_e {
            Effectiveness::MadeWorse => Effectiveness::MadeWorse,
            _ => Effectiveness::TableMismatch,
        };
    }
    by_e
}

/// The verdict from E before, predicted and achieved, one-sided.
fn on_e(e: &Systematic) -> Effectiveness {
    if e.achieved <= e.predicted + e.uncertainty {
        Effectiveness::Effective
    } else if e.achieved > e.before + e.uncertainty {
        Effectiveness::MadeWorse
    } else if e.achieved < e.before - e.uncertainty {
        Effectiveness::PartlyEffective
    } else {
        Effectiveness::NotEffective
    }
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

/// The expanded uncertainty of a difference of two E (see [`Systematic::uncertainty`]),
/// from the largest standard uncertainty of the rows: where the targets differ it holds
/// the interpolation's, E predicted being of the targets before and E achieved of those
/// after, each sampling the axis's error at its own positions.
pub(crate) fn e_uncertainty(rows: &[ComparedTarget]) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn e(before: f64, predicted: f64, achieved: f64) -> Systematic {
        Systematic {
            before,
            predicted,
            achieved,
            uncertainty: 2.0,
        }
    }

    fn verdict(e: &Systematic, rejected: bool, explained: bool) -> Effectiveness {
        judge(&VerdictBasis {
            e,
            rejected,
            explained,
        })
    }

    /// MILL-3 X verified against Y's table (the numbers): E 23.70 predicted, 1.07
    /// achieved, U 1.84: far better than the named table can do, whatever the χ² says.
    #[test]
    fn far_better_than_predicted_is_a_mismatch() {
        let x_as_y = Systematic {
            before: 21.9,
            predicted: 23.70,
            achieved: 1.07,
            uncertainty: 1.84,
        };
        for (rejected, explained) in [(true, false), (true, true), (false, false)] {
            assert_eq!(
                verdict(&x_as_y, rejected, explained),
                Effectiveness::TableMismatch
            );
        }
    }

    /// E as predicted: effective only while χ² accepts the named table; rejected, it is a
    /// mismatch with or without an effect named.
    #[test]
    fn a_rejected_table_is_never_effective() {
        let as_predicted = e(20.0, 1.0, 2.5);
        assert_eq!(
            verdict(&as_predicted, false, false),
            Effectiveness::Effective
        );
        assert_eq!(
            verdict(&as_predicted, true, false),
            Effectiveness::TableMismatch
        );
        assert_eq!(
            verdict(&as_predicted, true, true),
            Effectiveness::TableMismatch
        );
    }

    /// Rejected and unexplained: a mismatch unless E grew (made worse says more); an effect
    /// named keeps the verdict on E.
    #[test]
    fn the_chi2_decides_when_nothing_explains() {
        assert_eq!(
            verdict(&e(20.0, 1.0, 30.0), true, false),
            Effectiveness::MadeWorse
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 10.0), true, false),
            Effectiveness::TableMismatch
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 19.0), true, false),
            Effectiveness::TableMismatch
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 10.0), true, true),
            Effectiveness::PartlyEffective
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 19.0), true, true),
            Effectiveness::NotEffective
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 30.0), true, true),
            Effectiveness::MadeWorse
        );
        assert_eq!(
            verdict(&e(20.0, 1.0, 10.0), false, false),
            Effectiveness::PartlyEffective
        );
    }

    /// The 97.5 % point of the standard normal is 1.959964.
    #[test]
    fn normal_quantile_by_bisection() {
        assert!((normal_quantile(0.975) - 1.959964).abs() < 1e-6);
    }
}
