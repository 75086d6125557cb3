//! `iso-3.3-thermal`: deviations that drift run after run.

use super::{Plan, Rule, Severity};
use crate::units::Direction;

/// ISO 230-2:1997 3.3: the machine is warmed up before the test so that it is thermally
/// stable. Deviations at the targets forming an ordered sequence over the runs show one
/// that was not. Each (target, direction) cell whose n ≥ 3 readings are strictly monotonic
/// in run order counts; under independent scatter a cell is increasing with probability
/// 1/n!. The rule fires when the cells increasing (or decreasing) are too many for
/// chance: a binomial tail below 0.001.
pub(crate) const RULE: Rule = Rule {
    id: "iso-3.3-thermal",
    clause: "ISO 230-2 3.3",
    severity: Severity::Warning,
    checks: "deviations form an ordered sequence over the runs (binomial test, p < 0.001)",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let n = plan.runs;
    if n < 3 {
        return None;
    }
    let cells = plan.targets * 2;
    let (up, down) = monotonic_cells(plan);
    let p = 1.0 / (1..=n).map(|k| k as f64).product::<f64>();
    let (count, word) = if up >= down {
        (up, "increase")
    } else {
        (down, "decrease")
    };
    (count >= 2 && binomial_tail(cells, count, p) < 1e-3).then(|| {
        format!(
            "at {count} of {cells} targets and directions the deviations {word} run after run: the machine was not thermally stable; warm it up before the test"
        )
    })
}

/// How many (target, direction) cells increase, and how many decrease, strictly over the runs.
fn monotonic_cells(plan: &Plan) -> (usize, usize) {
    let (mut up, mut down) = (0usize, 0usize);
    for i in 0..plan.targets {
        for d in Direction::BOTH {
            let x = plan.data.deviations(i, d);
            if x.windows(2).all(|w| w[1] > w[0]) {
                up += 1;
            } else if x.windows(2).all(|w| w[1] < w[0]) {
                down += 1;
            }
        }
    }
    (up, down)
}

/// P(X ≥ k) for X ~ Binomial(n, p).
fn binomial_tail(n: usize, k: usize, p: f64) -> f64 {
    let mut term = (1.0 - p).powi(n as i32); // P(X = 0)
    let mut below = 0.0;
    for j in 0..k {
        below += term;
        term *= (n - j) as f64 / (j + 1) as f64 * p / (1.0 - p);
    }
    (1.0 - below).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomial_tail_values() {
        assert!((binomial_tail(10, 0, 0.3) - 1.0).abs() < 1e-12);
        assert!((binomial_tail(2, 2, 0.5) - 0.25).abs() < 1e-12);
        assert!((binomial_tail(3, 1, 0.5) - 0.875).abs() < 1e-12);
    }
}
