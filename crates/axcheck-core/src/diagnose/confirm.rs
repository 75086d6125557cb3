//! Whether a found effect's term earns its place in the extended model.
//!
//! Each effect's own test names it at level [`super::ALPHA`]; its term then has to predict
//! held-out readings better. Any positive held-out gain is not enough: a term unrelated to
//! the data also gains now and then, by the chance split of the folds, and weak extra
//! findings stood beside the right one (a reversal variation kept at +0.5 % on data with
//! run offsets only). So unrelated terms of the same size are made, [`UNRELATED`] of
//! them: the same term, with the same columns and the same fit, read in a random order
//! ([`Unrelated`]):
//!
//! * a drift, a thermal growth or a warm-up at the readings' times in a random order
//!   (only the columns the term adds; the terms kept before it read the real times);
//! * for outliers, as many ordinary readings left out of the fit;
//! * for a reversal variation, which may take one value per target (unchanged by any
//!   order of the targets), for run offsets, a scatter line and the periodic sinusoid,
//!   tests simulated from the model without the term ([`super::shaped`]; the periodic
//!   one on the target means, `select::judge_periodic`). Random orders served these
//!   first and kept too much of the real order: readings dealt to 3 runs at random
//!   within a cell stay in their own run one time in three, and a line along 5 targets
//!   in a random order fits as the real order or its reverse does one time in 60, so
//!   that run offsets of the size the F test finds in 80 % of tests were confirmed in
//!   30 % (a periodic error's, against shuffled targets, in 14 %).
//!
//! Each is cross-validated on the same folds (the periodic term on the same targets) as
//! the term, and the term is kept when its gain is larger than all of theirs: when the
//! term itself is unrelated to the data, its gain and theirs are exchangeable, and it
//! beats all [`UNRELATED`] with probability 1/(1 + [`UNRELATED`]) = 5 %. This is the
//! Monte Carlo permutation test (Dwass 1957, "Modified Randomization Tests for
//! Nonparametric Hypotheses": the permutation test with randomly drawn permutations in
//! place of all of them), the statistic the held-out gain. A paired t test over the ten
//! folds was tried first and left: the gain of a term that acts on a few targets or
//! readings (a short warm-up, an outlier, a periodic error between targets) lies in a
//! few folds, and that test could not confirm it (most of 400 hidden outliers).
//!
//! The orders and draws come from a seed derived from the test's plan ([`plan_seed`]), so
//! that the same data give the same decision. Cost: only a found effect's term is judged, so clean
//! axes pay nothing; the terms along the axis refit only what depends on the order (the
//! time model is fitted once per fold for all of them); a warm-up's unrelated curves
//! take the time constant that fits each best on all the readings instead of profiling
//! it in every fold (which favours them: a conservative threshold).

use crate::axis_model::rng::Rng;

/// Unrelated terms per judged term: with the term's own, 20 exchangeable gains, so that
/// beating all of them has probability 1/20 for a term that is itself unrelated.
pub(crate) const UNRELATED: usize = 19;

/// The unrelated terms a found effect's term is compared with (`null` of a term's gain in
/// the JSON).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Unrelated {
    /// The columns the term adds read at the readings' times in random orders
    /// ([`row_orders`]): drift, thermal growth, warm-up.
    TimeOrders,
    /// As many ordinary readings left out of the fit ([`ordinary_draws`]).
    OrdinaryReadings,
    /// The term (in the shape each test chooses, for a shaped term) on tests simulated
    /// from the model without it with the test's own plan ([`super::shaped`]): for terms
    /// that take one value per target, which no order of the targets changes, and for
    /// run offsets and a scatter line, whose random orders keep much of the real one.
    SimulatedTests,
}

/// The seed of the unrelated terms, from the test's plan (its target positions and its
/// readings' runs) and the diagnosis seed: FNV-1a over their bits. Not from the
/// deviations: a permutation test's orders must not depend on the values they permute,
/// and a test read with another datum (every deviation shifted) is judged alike.
pub(crate) fn plan_seed(positions: &[f64], runs: &[usize], seed: u64) -> u64 {
    let mut h: u64 = 0xCBF2_9CE4_8422_2325;
    let words = (positions.iter().map(|p| p.to_bits())).chain(runs.iter().map(|&r| r as u64));
    for word in words {
        for byte in word.to_le_bytes() {
            h ^= u64::from(byte);
            h = h.wrapping_mul(0x0100_0000_01B3);
        }
    }
    h ^ seed
}

/// A random permutation of 0..n (Fisher–Yates).
fn permutation(n: usize, rng: &mut Rng) -> Vec<usize> {
    let mut order: Vec<usize> = (0..n).collect();
    for a in (1..n).rev() {
        let b = ((rng.uniform() * (a + 1) as f64) as usize).min(a);
        order.swap(a, b);
    }
    order
}

/// [`UNRELATED`] random orders of `rows` rows: row k reads row `order[k]`'s time.
pub(crate) fn row_orders(rows: usize, seed: u64) -> Vec<Vec<usize>> {
    let mut rng = Rng::new(seed, 0x7133);
    (0..UNRELATED)
        .map(|_| permutation(rows, &mut rng))
        .collect()
}

/// [`UNRELATED`] draws of as many ordinary readings as `outlier` marks: each a mask of
/// the readings left out, the outliers themselves never among them.
pub(crate) fn ordinary_draws(outlier: &[bool], seed: u64) -> Vec<Vec<bool>> {
    let mut rng = Rng::new(seed, 0x0DD5);
    let ordinary: Vec<usize> = (0..outlier.len()).filter(|&k| !outlier[k]).collect();
    let count = (outlier.len() - ordinary.len()).min(ordinary.len());
    (0..UNRELATED)
        .map(|_| {
            let order = permutation(ordinary.len(), &mut rng);
            let mut mask = vec![false; outlier.len()];
            for &k in &order[..count] {
                mask[ordinary[k]] = true;
            }
            mask
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each order is a permutation; the same seed gives the same orders, another seed
    /// others.
    #[test]
    fn orders_are_permutations() {
        let orders = row_orders(30, 1);
        assert_eq!(orders.len(), UNRELATED);
        assert_eq!(orders, row_orders(30, 1));
        assert_ne!(orders, row_orders(30, 2));
        assert!(orders.iter().any(|o| *o != (0..30).collect::<Vec<_>>()));
        for o in orders {
            let mut sorted = o.clone();
            sorted.sort();
            assert_eq!(sorted, (0..30).collect::<Vec<_>>());
        }
    }

    /// Each draw leaves out as many ordinary readings as there are outliers, never an
    /// outlier; the seed depends on the plan.
    #[test]
    fn draws_leave_out_ordinary_readings() {
        let mut outlier = vec![false; 40];
        outlier[3] = true;
        outlier[17] = true;
        for d in ordinary_draws(&outlier, 7) {
            assert_eq!(d.iter().filter(|&&b| b).count(), 2);
            assert!(!d[3] && !d[17]);
        }
        assert_ne!(
            plan_seed(&[1.0, 2.0], &[0, 1], 0),
            plan_seed(&[1.0, 2.5], &[0, 1], 0)
        );
        assert_ne!(
            plan_seed(&[1.0, 2.0], &[0, 1], 0),
            plan_seed(&[1.0, 2.0], &[0, 0], 0)
        );
        assert_eq!(plan_seed(&[1.0], &[0], 3), plan_seed(&[1.0], &[0], 0) ^ 3);
    }
}
