//! GOST 27843-88 (ST SEV 6052-87): coverage factor 3.
//!
//! Per target j: X̄j↑, X̄j↓ (formula (2)), Bj (3), ranges Wj (4), Sj by formula (5) or
//! from the ranges by formula (6) `S = W·a_n`, the limits X̄ ± 3S (3.1.4), Rj↑ = 6Sj↑ (7),
//! Rj = max(3S↑ + 3S↓ + |Bj|; 6S↑; 6S↓) (8). Per axis: A (10), A↑, A↓, R_max (1.11,
//! 1.13), R↑, R↓ (1.10, 1.13), R̄ (9), B_max (1.16), B̄ (1.15).
//!
//! Errata handled: the printed a_n for n = 10 is 0.3429; the coefficient is 1/d2(10) =
//! 1/3.078 = 0.3249 (the printed a_n for n = 5…9 are 1/d2(n)). In the worked example the
//! R row at position 7 prints 3S↑ + 3S↓ + |B| = 6.90 where 6S↑ = 7.36 is larger; formula
//! (8) gives 7.36.

use super::band;
use super::catalogue::gost27843 as gost;
use super::stats::{range, sample_sd};
use super::{Evaluation, Parameter, Standard, StandardId, TargetResult};
use crate::measurement::AxisData;

/// Coverage factor: limits X̄ ± 3S (clause 3.1.4).
pub const K: f64 = 3.0;

/// How S is estimated (clause 1.9).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum SMethod {
    /// Formula (5): sample standard deviation.
    #[default]
    Formula5,
    /// Formula (6): S = W · a_n from the range W.
    Ranges,
}

/// The range coefficient a_n of formula (6) for n = 2…10: 1/d2(n). The standard prints
/// n = 5…10; n = 10 is printed as 0.3429, an erratum for 0.3249. n = 2…4 are 1/d2(n)
/// from the same d2 table (1.128, 1.693, 2.059).
pub(crate) fn a_n(n: usize) -> Option<f64> {
    match n {
        2 => Some(0.8865),
        3 => Some(0.5907),
        4 => Some(0.4857),
        5 => Some(0.4299),
        6 => Some(0.3946),
        7 => Some(0.3698),
        8 => Some(0.3512),
        9 => Some(0.3367),
        10 => Some(0.3249),
        _ => None,
    }
}

/// The GOST 27843 evaluator.
#[derive(Debug, Clone, Copy, Default)]
pub struct Gost27843 {
    pub s_method: SMethod,
}

impl Standard for Gost27843 {
    fn id(&self) -> StandardId {
        StandardId::Gost27843
    }

    fn evaluate(&self, data: &AxisData) -> Evaluation {
        let n = data.runs();
        let mut notes = Vec::new();
        let use_ranges = match self.s_method {
            SMethod::Formula5 => false,
            SMethod::Ranges if a_n(n).is_some() => {
                notes.push(format!(
                    "S from ranges, formula (6), a_n = {:.4}",
                    a_n(n).unwrap_or(f64::NAN)
                ));
                true
            }
            SMethod::Ranges => {
                notes.push(format!(
                    "S from ranges needs 2 ≤ n ≤ 10 (formula (6)); n = {n}, so S is by formula (5)"
                ));
                false
            }
        };
        let targets = band::per_target(data, K, |x| {
            if use_ranges {
                Some(range(x)? * a_n(x.len())?)
            } else {
                sample_sd(x)
            }
        });
        let p = parameters(&targets);
        if n == 1 {
            notes.push(
                "n = 1: S, R and A are not applicable; GOST 27843 asks for n ≥ 5 (clause 2.10)"
                    .into(),
            );
        } else if n < 5 {
            notes.push(format!("n = {n}: GOST 27843 asks for n ≥ 5 (clause 2.10)"));
        }
        Evaluation {
            standard: StandardId::Gost27843,
            kind: data.kind,
            n,
            coverage_factor: K,
            parameters: p,
            targets,
            notes,
        }
    }
}

/// Clause 1's parameters in the standard's order; those that need S are left out when
/// n = 1.
fn parameters(targets: &[TargetResult]) -> Vec<Parameter> {
    let mut p = band::accuracies(targets, [&gost::A, &gost::A_UP, &gost::A_DOWN]);
    p.extend(band::repeatabilities(
        targets,
        [&gost::R_MAX, &gost::R_UP, &gost::R_DOWN],
    ));
    // Formula (9): the mean of the 2m unidirectional repeatabilities 6S.
    let unidirectional: Option<Vec<f64>> = targets
        .iter()
        .flat_map(|t| [t.up.repeatability, t.down.repeatability])
        .collect();
    if let Some(values) = unidirectional {
        let r_mean = values.iter().sum::<f64>() / values.len() as f64;
        p.push(Parameter::plain(&gost::R_MEAN, r_mean));
    }
    p.push(Parameter::located(
        &gost::B_MAX,
        band::max_reversal(targets),
    ));
    p.push(Parameter::plain(
        &gost::B_MEAN,
        band::mean_reversal(targets),
    ));
    p
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::evaluate::stats::d2;

    #[test]
    fn range_coefficients_are_one_over_d2() {
        for n in 2..=10 {
            let a = a_n(n).unwrap();
            assert!(
                (a - 1.0 / d2(n)).abs() < 0.0003,
                "a_{n} = {a} vs {}",
                1.0 / d2(n)
            );
        }
        assert_eq!(a_n(10), Some(0.3249), "erratum 0.3429 corrected");
        assert_eq!(a_n(11), None);
    }
}
