//! The lines of an uncertainty budget and their combination (GUM, JCGM 100:2008, 5.1.2
//! and 6.2.1).

use serde::{Serialize, Serializer};

/// How an input quantity's value turns into a standard uncertainty: the divisor of its
/// distribution (GUM 4.3.7 for the rectangular; a stated multiple of a standard deviation
/// is divided by its multiplier, GUM 4.3.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Distribution {
    /// A stated expanded uncertainty U with coverage factor `k` (a calibration
    /// certificate), or with k = 1 a standard deviation (a Type A evaluation, GUM 4.2).
    Normal { k: f64 },
    /// Limits ±a with every value between equally likely: u = a/√3 (GUM 4.3.7). Used for
    /// manufacturers' specifications, sensor tolerances and resolution (GUM F.2.2.1).
    Rectangular,
    /// Limits ±a of a quantity that spends most of its time near them, e.g. a temperature
    /// cycling sinusoidally: u = a/√2 (the arcsine distribution of GUM Supplement 1,
    /// JCGM 101:2008, 6.4.6).
    UShaped,
}

impl Distribution {
    /// A normal distribution with k = 1: the value is already a standard uncertainty.
    pub const STANDARD: Distribution = Distribution::Normal { k: 1.0 };

    /// The value's divisor: u = value / divisor.
    pub(crate) fn divisor(self) -> f64 {
        match self {
            Distribution::Normal { k } => k,
            Distribution::Rectangular => 3f64.sqrt(),
            Distribution::UShaped => 2f64.sqrt(),
        }
    }

    /// `normal`, `rectangular` or `u-shaped`, as in the JSON outputs.
    pub fn name(self) -> &'static str {
        match self {
            Distribution::Normal { .. } => "normal",
            Distribution::Rectangular => "rectangular",
            Distribution::UShaped => "u-shaped",
        }
    }
}

impl Serialize for Distribution {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.name())
    }
}

/// An input quantity as a contributor states it: a value (a half-width, an expanded or a
/// standard uncertainty, as its distribution says) in its own unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Input {
    pub value: f64,
    /// `um`, `arcsec`, `°C`, `kPa`, `%RH`, `ppm`, `um/(m·°C)`.
    pub unit: &'static str,
    pub distribution: Distribution,
}

/// One line of a budget: an input quantity, its standard uncertainty u and what it does
/// to the parameter, c·u (GUM 5.1.3).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BudgetLine {
    /// The contributor's key: `calibration`, `air_temperature` …
    pub contributor: &'static str,
    /// The input's stated value, in `unit`.
    pub value: f64,
    pub unit: &'static str,
    pub distribution: Distribution,
    /// u = value / divisor.
    pub(crate) divisor: f64,
    /// Standard uncertainty of the input, in `unit`.
    pub u: f64,
    /// Sensitivity coefficient c: deviation unit (µm or arcsec) per `unit`.
    pub sensitivity: f64,
    /// |c|·u, in the deviation unit.
    pub contribution: f64,
    /// (c·u)² / u_c²: the line's share of the combined variance (0 when u_c = 0).
    pub share: f64,
}

impl BudgetLine {
    /// The line of `input` with sensitivity `c`; its share is set by [`Budget::new`].
    pub fn new(contributor: &'static str, input: Input, c: f64) -> BudgetLine {
        let divisor = input.distribution.divisor();
        let u = input.value / divisor;
        BudgetLine {
            contributor,
            value: input.value,
            unit: input.unit,
            distribution: input.distribution,
            divisor,
            u,
            sensitivity: c,
            contribution: (c * u).abs(),
            share: 0.0,
        }
    }
}

/// A combined budget: u_c = √Σ(cᵢuᵢ)² for uncorrelated inputs (GUM 5.1.2) and the
/// expanded uncertainty U = k·u_c (GUM 6.2.1).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Budget {
    /// The length the budget is for: mm (linear) or degrees (rotary); 0 at one position.
    pub length: f64,
    /// Combined standard uncertainty u_c, deviation unit.
    pub combined: f64,
    /// U = k·u_c, deviation unit.
    pub expanded: f64,
    pub lines: Vec<BudgetLine>,
}

impl Budget {
    /// Combines `lines` with coverage factor `k` and sets each line's share.
    pub fn new(length: f64, mut lines: Vec<BudgetLine>, k: f64) -> Budget {
        let variance: f64 = lines.iter().map(|l| l.contribution.powi(2)).sum();
        for line in &mut lines {
            line.share = if variance > 0.0 {
                line.contribution.powi(2) / variance
            } else {
                0.0
            };
        }
        let combined = variance.sqrt();
        Budget {
            length,
            combined,
            expanded: k * combined,
            lines,
        }
    }

    /// The line of `contributor`, if the budget has one.
    pub fn line(&self, contributor: &str) -> Option<&BudgetLine> {
        self.lines.iter().find(|l| l.contributor == contributor)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(value: f64, distribution: Distribution) -> Input {
        Input {
            value,
            unit: "um",
            distribution,
        }
    }

    #[test]
    fn divisors_follow_the_gum() {
        assert_eq!(Distribution::Normal { k: 2.0 }.divisor(), 2.0);
        assert!((Distribution::Rectangular.divisor() - 1.732_050_8).abs() < 1e-7);
        assert_eq!(Distribution::UShaped.divisor(), std::f64::consts::SQRT_2);
        assert_eq!(
            serde_json::to_string(&Distribution::UShaped).unwrap(),
            "\"u-shaped\""
        );
    }

    /// Two lines, 3 and 4 µm after their sensitivities: u_c = 5, U = 10, shares 9/25 and
    /// 16/25.
    #[test]
    fn lines_combine_in_quadrature() {
        let a = BudgetLine::new("a", input(6.0, Distribution::Normal { k: 2.0 }), 1.0);
        let b = BudgetLine::new(
            "b",
            input(4.0 * 3f64.sqrt() / 2.0, Distribution::Rectangular),
            -2.0,
        );
        assert!((a.contribution - 3.0).abs() < 1e-12);
        assert!((b.u - 2.0).abs() < 1e-12);
        assert!((b.contribution - 4.0).abs() < 1e-12);
        let budget = Budget::new(100.0, vec![a, b], 2.0);
        assert!((budget.combined - 5.0).abs() < 1e-12);
        assert!((budget.expanded - 10.0).abs() < 1e-12);
        assert!((budget.line("a").unwrap().share - 0.36).abs() < 1e-12);
        assert!((budget.line("b").unwrap().share - 0.64).abs() < 1e-12);
    }

    #[test]
    fn an_empty_budget_is_zero() {
        let budget = Budget::new(0.0, Vec::new(), 2.0);
        assert_eq!((budget.combined, budget.expanded), (0.0, 0.0));
    }
}
