//! The Theil–Sen slope and Sen's (1968) rank-based confidence interval for it.
//!
//! Theil (1950) and Sen (1968): the slope is the median of the pairwise slopes
//! (y_j − y_i)/(t_j − t_i) over the pairs with t_i ≠ t_j, so one odd point moves at most
//! n − 1 of the n(n − 1)/2 slopes and not their median. Sen's interval inverts Kendall's
//! test of S (concordant minus discordant pairs of t and y − βt): it is the range
//! between two order statistics of the pairwise slopes, [b₍ₖ₊₁₎, b₍N−ₖ₎]. The number k
//! trimmed on each side comes from the exact null distribution of S when the dates are
//! distinct (Kendall's permutation distribution, so small series get an interval that
//! truly covers), and otherwise from the normal approximation with Kendall's variance of
//! S corrected for tied dates (Gilbert 1987, §16.5): C = z·√Var(S), ranks (N ∓ C)/2,
//! interpolated between order statistics.

/// Pairs up to which the exact distribution of S is used (n = 50 dates: 1 225 pairs).
const EXACT_UP_TO: usize = 50;

/// The pairwise slopes b_ij = (y_j − y_i)/(t_j − t_i) for the pairs with distinct t,
/// sorted ascending.
pub(crate) fn pairwise_slopes(points: &[(f64, f64)]) -> Vec<f64> {
    let mut slopes = Vec::with_capacity(points.len() * points.len().saturating_sub(1) / 2);
    for (i, &(ti, yi)) in points.iter().enumerate() {
        for &(tj, yj) in &points[i + 1..] {
            if tj != ti {
                slopes.push((yj - yi) / (tj - ti));
            }
        }
    }
    slopes.sort_by(f64::total_cmp);
    slopes
}

/// The median of sorted values (None when empty).
pub(crate) fn median_sorted(sorted: &[f64]) -> Option<f64> {
    let n = sorted.len();
    match n {
        0 => None,
        _ if n % 2 == 1 => Some(sorted[n / 2]),
        _ => Some((sorted[n / 2 - 1] + sorted[n / 2]) / 2.0),
    }
}

/// The median of values in any order.
pub fn median(values: &[f64]) -> Option<f64> {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    median_sorted(&sorted)
}

/// Sizes of the groups of equal dates with more than one member.
fn tie_groups(times: &[f64]) -> Vec<usize> {
    let mut sorted = times.to_vec();
    sorted.sort_by(f64::total_cmp);
    let mut groups = Vec::new();
    let mut run = 1;
    for w in sorted.windows(2) {
        if w[0] == w[1] {
            run += 1;
        } else {
            if run > 1 {
                groups.push(run);
            }
            run = 1;
        }
    }
    if run > 1 {
        groups.push(run);
    }
    groups
}

/// Kendall's variance of S for n points with the given groups of tied dates.
pub(crate) fn kendall_variance(n: usize, ties: &[usize]) -> f64 {
    let term = |m: usize| {
        let m = m as f64;
        m * (m - 1.0) * (2.0 * m + 5.0)
    };
    (term(n) - ties.iter().map(|&t| term(t)).sum::<f64>()) / 18.0
}

/// P(S ≥ s) under independence for n distinct dates: S = N − 2I where I, the number of
/// inversions of a random permutation, follows the Mahonian distribution (built one
/// element at a time: the k-th element adds 0…k−1 inversions, each equally likely).
fn exact_upper_tail(n: usize, s: i64) -> f64 {
    let pairs = n * n.saturating_sub(1) / 2;
    let mut dist = vec![0.0; pairs + 1];
    dist[0] = 1.0;
    for k in 1..=n {
        let mut next = vec![0.0; pairs + 1];
        for (inv, &p) in dist.iter().enumerate().filter(|(_, p)| **p > 0.0) {
            for add in 0..k {
                if inv + add <= pairs {
                    next[inv + add] += p / k as f64;
                }
            }
        }
        dist = next;
    }
    // S ≥ s ⇔ I ≤ (N − s)/2.
    let most = (pairs as i64 - s).div_euclid(2);
    if most < 0 {
        return 0.0;
    }
    dist.iter().take(most as usize + 1).sum()
}

/// Sen's two-sided interval for the slope at confidence `1 − alpha`, `z` its normal
/// quantile z₁₋α/₂: (lower, upper), or None when the series is too short for that level
/// (the interval would reach beyond the smallest or largest pairwise slope).
pub fn interval(points: &[(f64, f64)], alpha: f64, z: f64) -> Option<(f64, f64)> {
    let slopes = pairwise_slopes(points);
    let pairs = slopes.len();
    if pairs < 2 {
        return None;
    }
    let times: Vec<f64> = points.iter().map(|p| p.0).collect();
    let ties = tie_groups(&times);
    if ties.is_empty() && points.len() <= EXACT_UP_TO {
        // The largest k with 2·P(S ≥ N − 2k) ≤ α.
        let trimmed = (0..pairs / 2)
            .take_while(|&k| 2.0 * exact_upper_tail(points.len(), (pairs - 2 * k) as i64) <= alpha)
            .last()?;
        return Some((slopes[trimmed], slopes[pairs - 1 - trimmed]));
    }
    let c = z * kendall_variance(points.len(), &ties).sqrt();
    let lower_rank = (pairs as f64 - c) / 2.0;
    let upper_rank = (pairs as f64 + c) / 2.0 + 1.0;
    if lower_rank < 1.0 || upper_rank > pairs as f64 {
        return None;
    }
    Some((
        order_statistic(&slopes, lower_rank),
        order_statistic(&slopes, upper_rank),
    ))
}

/// The `rank`-th smallest of sorted values (1-based), interpolated between neighbours.
fn order_statistic(sorted: &[f64], rank: f64) -> f64 {
    let below = (rank.floor() as usize).clamp(1, sorted.len());
    let above = (rank.ceil() as usize).clamp(1, sorted.len());
    let share = rank - rank.floor();
    sorted[below - 1] + share * (sorted[above - 1] - sorted[below - 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Mahonian numbers for n = 4 (1, 3, 5, 6, 5, 3, 1 permutations with 0…6 inversions):
    /// P(S = 6) = 1/24, P(S ≥ 4) = 4/24, P(S ≥ −6) = 1.
    #[test]
    fn exact_tail_of_kendalls_s() {
        assert!((exact_upper_tail(4, 6) - 1.0 / 24.0).abs() < 1e-15);
        assert!((exact_upper_tail(4, 4) - 4.0 / 24.0).abs() < 1e-15);
        assert!((exact_upper_tail(4, -6) - 1.0).abs() < 1e-15);
        assert_eq!(exact_upper_tail(4, 7), 0.0);
    }

    /// n = 5: P(S = 10) = 1/120, so [min, max] covers 1 − 2/120 = 98.3 % ≥ 95 % but
    /// trimming one slope each side (P(S ≥ 8) = 5/120, 2·5/120 = 8.3 %) does not; n = 4:
    /// [min, max] covers only 1 − 2/24 = 91.7 %, no 95 % interval.
    #[test]
    fn small_series_get_an_interval_only_when_it_covers() {
        let line =
            |n: usize| -> Vec<(f64, f64)> { (0..n).map(|i| (i as f64, (i * i) as f64)).collect() };
        assert_eq!(interval(&line(4), 0.05, 1.96), None);
        // Slopes of i² between i < j are i + j: 1…7; min 1, max 7.
        assert_eq!(interval(&line(5), 0.05, 1.96), Some((1.0, 7.0)));
    }

    /// Var(S) = n(n−1)(2n+5)/18 less each tie group's t(t−1)(2t+5)/18: n = 6 gives
    /// 6·5·17/18 = 28.33; with a pair of tied dates 28.33 − 2·1·9/18 = 27.33.
    #[test]
    fn kendall_variance_with_ties() {
        assert!((kendall_variance(6, &[]) - 510.0 / 18.0).abs() < 1e-12);
        assert!((kendall_variance(6, &[2]) - 492.0 / 18.0).abs() < 1e-12);
        assert_eq!(tie_groups(&[0.0, 1.0, 1.0, 2.0, 3.0, 3.0, 3.0]), vec![2, 3]);
    }
}
