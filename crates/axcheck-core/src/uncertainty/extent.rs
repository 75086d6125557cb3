//! What a parameter spans, and the statistical uncertainty of the estimates it is built
//! from.
//!
//! A range parameter (A, E, M and their unidirectional forms) is the difference of two
//! terms at two targets: the instrument's and the environment's length-dependent errors
//! act over the distance between those targets. A repeatability (R) is a width of scatter
//! at one target and a reversal (B, B̄) a difference at one position: errors proportional
//! to the position cancel there, so only the reading errors and the scatter of the
//! estimates remain.
//!
//! The statistical part (Type A, GUM 4.2) is computed for the parameters of ISO 230-2 and
//! GOST 27843 from the per-target results: a mean X̄ of n readings has u = s/√n (GUM
//! 4.2.3) and an estimate s of σ, distributed as σ·χ(n−1)/√(n−1), has the standard
//! deviation σ·√(1 − c4²) with E\[s\] = c4·σ, so u(s) = s·√(1 − c4²)/c4 (GUM E.4.3 gives
//! the first-order form 1/√(2(n−1))).
//!
//! With n = 1 (one run per direction: the long-axis tests of clauses 4.3.3 and 4.3.5)
//! no target has a scatter of its own, and leaving the statistical part out would make
//! U of a reversal, where the length-dependent errors cancel, about 0: under ISO 14253-1
//! a U that small proves conformance the test never showed. What the test has is m
//! reversals Bi = Xi↑ − Xi↓, each the difference of two single readings. Assuming the
//! reversal is the same at every target, their standard deviation over the targets is
//! √2 times the scatter σ of one reading, so ŝ = s(Bi)/√2 (m − 1 degrees of freedom) is
//! a pooled estimate of σ in the sense of GUM 4.2.4 and stands for s wherever a mean of
//! n = 1 readings enters (u = ŝ/√1). A real change of the reversal along the axis counts
//! as scatter too, so ŝ errs high: on the safe side for whoever must prove conformance
//! (ISO 14253-1 puts U against the one who claims). The report states this assumption
//! and ŝ ([`single_reading_s`]). With fewer than 3 targets no estimate is made and the
//! note says the statistical part is left out.

use crate::evaluate::catalogue::{Approach, Quantity, Spread};
use crate::evaluate::{Evaluation, Parameter, StandardId, TargetResult};
use crate::units::Direction;

/// What sort of difference a parameter is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExtentShape {
    /// `max − min` of two terms at two targets: length-dependent errors act over the
    /// distance between them.
    Range,
    /// A width of scatter at one target (R, 6σ …).
    Scatter,
    /// A difference at one position (B), or the mean of such differences (B̄).
    Reversal,
}

/// A parameter's extent and its statistical uncertainty.
#[derive(Debug, Clone, PartialEq)]
pub struct Extent {
    pub shape: ExtentShape,
    /// Distance between the two targets of a range, mm or deg; 0 at one position.
    pub length: f64,
    /// How one reading's error enters the parameter: 1, or 2k for a repeatability 2kS.
    pub(crate) reading_gain: f64,
    /// Standard uncertainty of the parameter from the means' scatter, s/√n terms.
    pub(crate) means_u: Option<f64>,
    /// Standard uncertainty of the parameter from the estimates of s (chi distribution).
    pub(crate) scatter_u: Option<f64>,
}

impl Extent {
    /// A range over `length` with no statistical part: the instrument-and-environment
    /// budget of the full measurement travel.
    pub fn range(length: f64) -> Extent {
        Extent {
            shape: ExtentShape::Range,
            length,
            reading_gain: 1.0,
            means_u: None,
            scatter_u: None,
        }
    }
}

/// c4(n) = √(2/(n−1))·Γ(n/2)/Γ((n−1)/2): E\[s\] = c4·σ for n normal readings (n ≥ 2).
pub(crate) fn c4(n: usize) -> f64 {
    let n = n as f64;
    (2.0 / (n - 1.0)).sqrt() * (libm::lgamma(n / 2.0) - libm::lgamma((n - 1.0) / 2.0)).exp()
}

/// Standard uncertainty of an estimate `s` from `n` readings: s·√(1 − c4²)/c4.
pub fn u_of_s(s: f64, n: usize) -> f64 {
    let c = c4(n);
    s * (1.0 - c * c).sqrt() / c
}

/// The measurement travel of `e`: from its first to its last target, mm or deg.
pub fn travel(e: &Evaluation) -> f64 {
    match (e.targets.first(), e.targets.last()) {
        (Some(a), Some(b)) => (b.position - a.position).abs(),
        _ => 0.0,
    }
}

/// The extent of parameter `p` of `e`; `None` for a level, which takes no tolerance.
pub fn of(e: &Evaluation, p: &Parameter) -> Option<Extent> {
    if p.def.quantity == Quantity::Level {
        return None;
    }
    let band = matches!(
        e.standard,
        StandardId::Iso230_2 | StandardId::Gbt17421_2 | StandardId::Gost27843
    );
    let k = e.coverage_factor;
    let single = single_reading_s(e);
    Some(match (band, p.def.spread) {
        (true, Spread::Band) => range(e, p, Term::Band, single),
        (true, Spread::Mean) => range(e, p, Term::Mean, single),
        (true, Spread::Bidirectional) => range(e, p, Term::Bidirectional, single),
        (true, Spread::Repeatability) => repeatability(e, p),
        (true, Spread::MeanRepeatability) => mean_repeatability(e),
        (true, Spread::ReversalAtTarget) => {
            reversal(e, p.at_target.and_then(|i| e.targets.get(i..=i)), single)
        }
        (true, Spread::ReversalMean) => reversal(e, Some(&e.targets), single),
        // VDI 3441 and NMTBA: no statistical part (see the README).
        (false, Spread::Scatter { factor, of_k }) => {
            scatter_only(if of_k { factor * k } else { factor })
        }
        (false, Spread::LostMotion) => reversal(e, None, None),
        _ => Extent::range(travel(e)),
    })
}

/// Fewest targets from which the scatter of one reading is estimated when n = 1.
pub(crate) const SINGLE_READING_MIN_TARGETS: usize = 3;

/// n = 1: the scatter of one reading estimated from the reversals' spread over the
/// targets, ŝ = s(Bi)/√2 (see the module's doc); `None` when n ≥ 2 (each target has its
/// own s) or fewer than [`SINGLE_READING_MIN_TARGETS`] targets.
pub(crate) fn single_reading_s(e: &Evaluation) -> Option<f64> {
    let m = e.targets.len();
    if e.n >= 2 || m < SINGLE_READING_MIN_TARGETS {
        return None;
    }
    let mean = e.targets.iter().map(|t| t.reversal).sum::<f64>() / m as f64;
    let ss: f64 = e.targets.iter().map(|t| (t.reversal - mean).powi(2)).sum();
    let s = (ss / (m - 1) as f64).sqrt() / std::f64::consts::SQRT_2;
    s.is_finite().then_some(s)
}

/// Which term of a target a range's ends are.
#[derive(Debug, Clone, Copy)]
enum Term {
    /// X̄ ± kS of one direction (A).
    Band,
    /// X̄ of one direction (E).
    Mean,
    /// X̄i = (X̄i↑ + X̄i↓)/2 (M).
    Bidirectional,
}

fn directions(approach: Approach) -> &'static [Direction] {
    match approach {
        Approach::Both => &Direction::BOTH,
        Approach::Up => &[Direction::Up],
        Approach::Down => &[Direction::Down],
    }
}

/// One end of a range: the target, its term's value, and that term's (u of X̄, u of kS).
struct End {
    position: f64,
    value: f64,
    means_u: Option<f64>,
    scatter_u: Option<f64>,
}

/// `single`: for n = 1, the estimated scatter of one reading ([`single_reading_s`]),
/// used for the means (never for the scatter of s, which n = 1 does not have).
fn ends(
    e: &Evaluation,
    approach: Approach,
    term: Term,
    upper: bool,
    single: Option<f64>,
) -> Vec<End> {
    let n = e.n;
    let k = e.coverage_factor;
    let sign = if upper { 1.0 } else { -1.0 };
    let mut out = Vec::new();
    for t in &e.targets {
        if let Term::Bidirectional = term {
            let means_u = (t.up.s.or(single))
                .zip(t.down.s.or(single))
                .map(|(a, b)| ((a * a + b * b) / (4.0 * n as f64)).sqrt());
            out.push(End {
                position: t.position,
                value: t.mean,
                means_u,
                scatter_u: None,
            });
            continue;
        }
        for &d in directions(approach) {
            let r = t.direction(d);
            let means_u = r.s.or(single).map(|s| s / (n as f64).sqrt());
            let (value, scatter_u) = match term {
                Term::Band => (
                    r.mean + sign * k * r.s.unwrap_or(f64::NAN),
                    r.s.map(|s| k * u_of_s(s, n)),
                ),
                _ => (r.mean, None),
            };
            out.push(End {
                position: t.position,
                value,
                means_u,
                scatter_u,
            });
        }
    }
    out
}

/// The ends whose term is `value` (the evaluator's max or min; several on a tie), or the
/// closest one.
fn matching(ends: Vec<End>, value: f64) -> Vec<End> {
    let off = |x: &End| (x.value - value).abs();
    let tie = 1e-9 * value.abs().max(1.0);
    let best = ends
        .iter()
        .map(off)
        .filter(|d| d.is_finite())
        .fold(f64::INFINITY, f64::min);
    ends.into_iter()
        .filter(|x| off(x) <= best.max(tie))
        .collect()
}

/// The pair of ends farthest apart: on a tie the longer length, the conservative one.
fn farthest(top: &[End], bottom: &[End]) -> Option<(usize, usize)> {
    let mut best: Option<(usize, usize, f64)> = None;
    for (a, x) in top.iter().enumerate() {
        for (b, y) in bottom.iter().enumerate() {
            let length = (x.position - y.position).abs();
            if best.is_none_or(|(_, _, l)| length > l) {
                best = Some((a, b, length));
            }
        }
    }
    best.map(|(a, b, _)| (a, b))
}

fn quadrature(a: Option<f64>, b: Option<f64>) -> Option<f64> {
    a.zip(b).map(|(a, b)| a.hypot(b))
}

fn range(e: &Evaluation, p: &Parameter, term: Term, single: Option<f64>) -> Extent {
    let Some((hi, lo)) = p.span else {
        return Extent::range(travel(e));
    };
    let approach = p.def.approach;
    let top = matching(ends(e, approach, term, true, single), hi);
    let bottom = matching(ends(e, approach, term, false, single), lo);
    let Some((a, b)) = farthest(&top, &bottom) else {
        return Extent::range(travel(e));
    };
    let (top, bottom) = (&top[a], &bottom[b]);
    Extent {
        shape: ExtentShape::Range,
        length: (top.position - bottom.position).abs(),
        reading_gain: 1.0,
        means_u: quadrature(top.means_u, bottom.means_u),
        scatter_u: quadrature(top.scatter_u, bottom.scatter_u),
    }
}

fn scatter_only(reading_gain: f64) -> Extent {
    Extent {
        shape: ExtentShape::Scatter,
        length: 0.0,
        reading_gain,
        means_u: None,
        scatter_u: None,
    }
}

/// R↑, R↓ (2kS at the target of the maximum) and R (ISO 2.17, GOST (8): the largest of
/// kS↑ + kS↓ + |Bi|, 2kS↑ and 2kS↓).
fn repeatability(e: &Evaluation, p: &Parameter) -> Extent {
    let k = e.coverage_factor;
    let n = e.n;
    let mut extent = scatter_only(2.0 * k);
    let Some(t) = p.at_target.and_then(|i| e.targets.get(i)) else {
        return extent;
    };
    let (Some(su), Some(sd)) = (t.up.s, t.down.s) else {
        return extent;
    };
    let one = |s: f64| 2.0 * k * u_of_s(s, n);
    match p.def.approach {
        Approach::Up => extent.scatter_u = Some(one(su)),
        Approach::Down => extent.scatter_u = Some(one(sd)),
        Approach::Both => {
            let sum = k * su + k * sd + t.reversal.abs();
            if sum >= 2.0 * k * su && sum >= 2.0 * k * sd {
                extent.scatter_u = Some(k * u_of_s(su, n).hypot(u_of_s(sd, n)));
                extent.means_u = Some(((su * su + sd * sd) / n as f64).sqrt());
            } else {
                extent.scatter_u = Some(one(su.max(sd)));
            }
        }
    }
    extent
}

/// GOST's R̄, formula (9): the mean of the 2m values 2kS.
fn mean_repeatability(e: &Evaluation) -> Extent {
    let k = e.coverage_factor;
    let mut extent = scatter_only(2.0 * k);
    let s: Option<Vec<f64>> = e.targets.iter().flat_map(|t| [t.up.s, t.down.s]).collect();
    if let Some(s) = s.filter(|s| !s.is_empty()) {
        let sum: f64 = s.iter().map(|&s| u_of_s(s, e.n).powi(2)).sum();
        extent.scatter_u = Some(2.0 * k * sum.sqrt() / s.len() as f64);
    }
    extent
}

/// B at one target, or B̄ over `targets` (the mean of Bi = X̄i↑ − X̄i↓); `None`: no
/// statistical part. `single`: for n = 1, the estimated scatter of one reading.
fn reversal(e: &Evaluation, targets: Option<&[TargetResult]>, single: Option<f64>) -> Extent {
    let mut extent = Extent {
        shape: ExtentShape::Reversal,
        length: 0.0,
        reading_gain: 1.0,
        means_u: None,
        scatter_u: None,
    };
    let Some(targets) = targets.filter(|t| !t.is_empty()) else {
        return extent;
    };
    let variances: Option<f64> = targets
        .iter()
        .map(|t| {
            (t.up.s.or(single))
                .zip(t.down.s.or(single))
                .map(|(a, b)| (a * a + b * b) / e.n as f64)
        })
        .sum();
    extent.means_u = variances.map(|v| v.sqrt() / targets.len() as f64);
    extent
}

#[cfg(test)]
mod tests {
    use super::*;

    /// c4 from its closed forms: c4(2) = √(2/π), c4(3) = √π/2, c4(5) = (3/4)·√(π/2) =
    /// 0.939986; tabulated c4(10) = 0.9727.
    #[test]
    fn c4_matches_its_table() {
        assert!((c4(2) - (2.0 / std::f64::consts::PI).sqrt()).abs() < 1e-12);
        assert!((c4(3) - std::f64::consts::PI.sqrt() / 2.0).abs() < 1e-12);
        assert!((c4(5) - 0.939_986).abs() < 1e-6);
        assert!((c4(10) - 0.972_659).abs() < 1e-6);
        assert!(c4(1000) > 0.9997 && c4(1000) < 1.0);
    }

    /// n = 5: u(s)/s = √(1 − 0.939986²)/0.939986 = 0.36300, close to GUM E.4.3's
    /// 1/√(2·4) = 0.35355.
    #[test]
    fn the_uncertainty_of_s_from_five_readings_is_a_third_of_s() {
        assert!((u_of_s(1.0, 5) - 0.363_00).abs() < 1e-5);
        assert!((u_of_s(2.0, 5) - 0.726_00).abs() < 1e-5);
        assert!((u_of_s(1.0, 200) - 1.0 / (2.0f64 * 199.0).sqrt()).abs() < 1e-3);
    }
}
