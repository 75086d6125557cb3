//! Small statistics shared by the standards.

use std::sync::OnceLock;

/// Arithmetic mean (ISO 230-2 clause 2.10).
pub fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// Sample standard deviation with n − 1 (ISO 230-2 clause 2.15, GOST 27843 formula (5));
/// `None` for fewer than two values.
pub(crate) fn sample_sd(values: &[f64]) -> Option<f64> {
    if values.len() < 2 {
        return None;
    }
    let m = mean(values);
    let ss: f64 = values.iter().map(|v| (v - m) * (v - m)).sum();
    Some((ss / (values.len() - 1) as f64).sqrt())
}

/// Range max − min (GOST 27843 formula (4), VDI 3441's R_i); `None` for fewer than two.
pub fn range(values: &[f64]) -> Option<f64> {
    if values.len() < 2 {
        return None;
    }
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    Some(hi - lo)
}

/// Index and value of the largest item; the first one on ties (the lowest target index,
/// as the standards' worked examples report).
pub(crate) fn argmax(values: impl IntoIterator<Item = f64>) -> Option<(usize, f64)> {
    let mut best: Option<(usize, f64)> = None;
    for (k, v) in values.into_iter().enumerate() {
        if best.is_none_or(|(_, b)| v > b) {
            best = Some((k, v));
        }
    }
    best
}

/// Standard normal cumulative distribution.
pub(crate) fn normal_cdf(x: f64) -> f64 {
    0.5 * libm::erfc(-x / std::f64::consts::SQRT_2)
}

/// d2(n): expected range of n independent standard normal values, from
/// d2(n) = ∫ (1 − Φ(x)ⁿ − (1 − Φ(x))ⁿ) dx. Used for range coefficients the standards do
/// not print (e.g. VDI 3441's N = 9 and 11).
pub fn d2(n: usize) -> f64 {
    static TABLE: OnceLock<Vec<f64>> = OnceLock::new();
    const MAX: usize = 64;
    if n < 2 {
        return f64::NAN;
    }
    if n > MAX {
        return d2_integral(n);
    }
    TABLE.get_or_init(|| (0..=MAX).map(d2_integral).collect())[n]
}

fn d2_integral(n: usize) -> f64 {
    if n < 2 {
        return f64::NAN;
    }
    // Simpson's rule on [-12, 12]; the integrand vanishes beyond.
    let steps = 4800;
    let (a, b) = (-12.0f64, 12.0f64);
    let h = (b - a) / steps as f64;
    let f = |x: f64| {
        let p = normal_cdf(x);
        1.0 - p.powi(n as i32) - (1.0 - p).powi(n as i32)
    };
    let mut sum = f(a) + f(b);
    for k in 1..steps {
        let x = a + k as f64 * h;
        sum += if k % 2 == 1 { 4.0 } else { 2.0 } * f(x);
    }
    sum * h / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn d2_matches_the_published_table() {
        // ASTM / Montgomery d2 values to 3 decimals.
        let published = [
            (2, 1.128),
            (3, 1.693),
            (4, 2.059),
            (5, 2.326),
            (6, 2.534),
            (7, 2.704),
            (8, 2.847),
            (9, 2.970),
            (10, 3.078),
            (11, 3.173),
            (12, 3.258),
            (25, 3.931),
        ];
        for (n, d) in published {
            assert!((d2(n) - d).abs() < 0.0006, "d2({n}) = {} vs {d}", d2(n));
        }
    }

    #[test]
    fn basic_statistics() {
        assert_eq!(mean(&[1.0, 2.0, 3.0]), 2.0);
        assert_eq!(sample_sd(&[1.0, 2.0, 3.0]), Some(1.0));
        assert_eq!(sample_sd(&[1.0]), None);
        assert_eq!(range(&[1.0, -2.0, 3.0]), Some(5.0));
        assert_eq!(argmax([1.0, 3.0, 3.0, 2.0]), Some((1, 3.0)));
        assert!((normal_cdf(1.96) - 0.975).abs() < 1e-4);
    }
}
