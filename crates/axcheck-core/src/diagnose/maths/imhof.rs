//! The distribution of a linear combination of independent χ² variables, Q = Σ λⱼ χ²(hⱼ),
//! by Imhof's inversion of its characteristic function (Imhof 1961, "Computing the
//! distribution of quadratic forms in normal variables", Biometrika 48, eq. 3.2):
//!
//! P(Q > 0) = ½ + (1/π) ∫₀^∞ sin θ(u) / (u ρ(u)) du,
//! θ(u) = ½ Σ hⱼ atan(λⱼ u),  ρ(u) = Π (1 + λⱼ² u²)^(hⱼ/4).
//!
//! A ratio of such sums (the scatter test's share of the squares along the axis) has its
//! exact tail from it: P(Σ aⱼ Xⱼ / Σ Xⱼ > r) = P(Σ (aⱼ − r) Xⱼ > 0). The integral is
//! taken in s = ln u, where the integrand sin θ / ρ is smooth and bounded by 1, from a
//! small u₀ (below which it is θ′(0) u₀ to within the tolerance) to Imhof's truncation
//! point for an error under the tolerance asked (his eq. 3.3). Its elementary functions
//! are the `libm` crate's, not the platform's: the same bits on Linux and Windows (the
//! platforms' maths libraries round a few results apart, and a root found through these
//! integrals moved by 47 units in the last place).

use std::f64::consts::PI;

/// The absolute error aimed at in a p-value.
pub(crate) const TOLERANCE: f64 = 1e-10;

/// P(Σ λⱼ χ²(hⱼ) > 0) for the terms (λⱼ, hⱼ), hⱼ > 0 degrees of freedom (not necessarily
/// whole), to an absolute error of about `tolerance`.
pub(crate) fn combination_positive(terms: &[(f64, f64)], tolerance: f64) -> f64 {
    static MEMO: super::memo::Memo = super::memo::Memo::new();
    let key: Vec<f64> = (terms.iter().flat_map(|&(l, h)| [l, h]))
        .chain([tolerance])
        .collect();
    MEMO.get_or(&key, || integrate(terms, tolerance))
}

/// [`combination_positive`], computed.
fn integrate(terms: &[(f64, f64)], tolerance: f64) -> f64 {
    let scale = terms.iter().map(|t| t.0.abs()).fold(0.0, f64::max);
    if !(scale > 0.0 && scale.is_finite()) {
        return f64::NAN;
    }
    let terms: Vec<(f64, f64)> = (terms.iter())
        .filter(|t| t.1 > 0.0)
        .map(|&(l, h)| (l / scale, h))
        .collect();
    if terms.iter().all(|t| t.0 >= 0.0) {
        return 1.0;
    }
    if terms.iter().all(|t| t.0 <= 0.0) {
        return 0.0;
    }
    let upper = truncation(&terms, tolerance);
    // The scatter test's two cells at a target (up and down) share their λ: atan and log1p
    // are taken once per distinct λ and summed term by term as before (the same bits, at
    // half the cost of the integrand).
    let distinct = Distinct::of(&terms);
    let g = |s: f64| {
        let u = libm::exp(s);
        let (mut theta, mut ln_rho) = (0.0, 0.0);
        distinct.each(u, |h, atan, log1p| {
            theta += 0.5 * h * atan;
            ln_rho += 0.25 * h * log1p;
        });
        libm::sin(theta) * libm::exp(-ln_rho)
    };
    // Near 0 the integrand (in u) is θ′(0) + O(u²) with θ′(0) = ½ Σ hⱼ λⱼ, and its u²
    // term is at most about (½ Σ hⱼ)³ / 6: up to u₀ the head is θ′(0) u₀ within a
    // quarter of the tolerance.
    let half_df: f64 = terms.iter().map(|t| 0.5 * t.1).sum();
    let slope: f64 = terms.iter().map(|t| 0.5 * t.1 * t.0).sum();
    let u0 = (libm::cbrt(tolerance / 4.0) / half_df.max(1.0)).min(upper / 2.0);
    let integral = slope * u0 + adaptive(&g, libm::log(u0), libm::log(upper), tolerance / 4.0);
    (0.5 + integral / PI).clamp(0.0, 1.0)
}

/// The terms' λ without repeats, and for each term the index of its λ.
struct Distinct {
    lambdas: Vec<f64>,
    terms: Vec<(usize, f64)>,
    /// (atan(λ u), log1p(λ² u²)) per distinct λ, refilled at each u.
    values: std::cell::RefCell<Vec<(f64, f64)>>,
}

impl Distinct {
    fn of(terms: &[(f64, f64)]) -> Distinct {
        let mut lambdas: Vec<f64> = Vec::with_capacity(terms.len());
        let terms = (terms.iter())
            .map(|&(l, h)| {
                let k = (lambdas.iter().position(|&x| x.to_bits() == l.to_bits())).unwrap_or_else(
                    || {
                        lambdas.push(l);
                        lambdas.len() - 1
                    },
                );
                (k, h)
            })
            .collect();
        let values = std::cell::RefCell::new(vec![(0.0, 0.0); lambdas.len()]);
        Distinct {
            lambdas,
            terms,
            values,
        }
    }

    /// `add(h, atan(λ u), log1p(λ² u²))` for each term in order.
    fn each(&self, u: f64, mut add: impl FnMut(f64, f64, f64)) {
        let mut values = self.values.borrow_mut();
        for (v, &l) in values.iter_mut().zip(&self.lambdas) {
            *v = (libm::atan(l * u), libm::log1p(l * l * u * u));
        }
        for &(k, h) in &self.terms {
            add(h, values[k].0, values[k].1);
        }
    }
}

/// Imhof's truncation point U (eq. 3.3): the integral beyond it is at most
/// 1 / (π k U^k Π |λⱼ|^(hⱼ/2)), k = ½ Σ hⱼ, set to `tolerance`/4. Terms with a tiny λ
/// are left out of the bound (each factor of ρ is at least 1, so the bound holds).
fn truncation(terms: &[(f64, f64)], tolerance: f64) -> f64 {
    let kept = terms.iter().filter(|t| t.0.abs() > 1e-6);
    let k: f64 = kept.clone().map(|t| 0.5 * t.1).sum();
    let ln_prod: f64 = kept.map(|t| 0.5 * t.1 * libm::log(t.0.abs())).sum();
    let ln_u = (-libm::log(PI * k * tolerance / 4.0) - ln_prod) / k;
    libm::exp(ln_u.clamp(0.0, 200.0))
}

/// ∫ₐᵇ f to an absolute `tolerance` by adaptive Gauss–Kronrod (7 and 15 points, the
/// difference of the two as the error; Piessens et al. 1983, "QUADPACK", QK15): the
/// integrand is smooth, so a few panels suffice where Simpson's rule took a thousand
/// evaluations.
fn adaptive(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    // Eight panels first: the integrand may change sign a few times.
    let panels = 8;
    let h = (b - a) / panels as f64;
    (0..panels)
        .map(|i| {
            let (x0, x1) = (a + i as f64 * h, a + (i + 1) as f64 * h);
            kronrod(f, x0, x1, tolerance / panels as f64, 30)
        })
        .sum()
}

/// Kronrod's 15 nodes on [−1, 1] (the positive half and 0) and their weights, and the
/// weights of the 7-point Gauss rule on every other node.
const XK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const WK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_18,
    0.140_653_259_715_525_92,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_83,
];
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

fn kronrod(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64, depth: u32) -> f64 {
    let (c, h) = ((a + b) / 2.0, (b - a) / 2.0);
    let (mut k, mut g) = (0.0, 0.0);
    for (j, (&x, &w)) in XK.iter().zip(&WK).enumerate() {
        let fx = if x == 0.0 {
            f(c)
        } else {
            f(c - h * x) + f(c + h * x)
        };
        k += w * fx;
        if j % 2 == 1 {
            g += WG[j / 2] * fx;
        }
    }
    let (k, g) = (k * h, g * h);
    if depth == 0 || (k - g).abs() <= tolerance {
        return k;
    }
    kronrod(f, a, c, tolerance / 2.0, depth - 1) + kronrod(f, c, b, tolerance / 2.0, depth - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnose::maths::stats::f_upper;

    /// χ²(a)/a over χ²(b)/b is F(a, b): P(F > f) = P(χ²(a) − (a f / b) χ²(b) > 0), and the
    /// F tail here is held to mpmath (stats.rs); whole and fractional df, both tails.
    #[test]
    fn a_difference_of_two_chi_squares_is_an_f_tail() {
        for &(a, b, f) in &[
            (1.0, 10.0, 4.96),
            (2.0, 17.0, 10.7),
            (3.4, 1.7, 0.3),
            (8.0, 8.0, 1.0),
            (1.7, 6.8, 25.0),
            (5.0, 40.0, 0.05),
        ] {
            let want = f_upper(f, a, b);
            let got = combination_positive(&[(1.0, a), (-a * f / b, b)], TOLERANCE);
            assert!(
                (got - want).abs() < 1e-8,
                "F({a}, {b}) > {f}: {got} vs {want}"
            );
        }
    }

    /// Terms with the same λ are one χ² of their summed df: P(χ²(4) − 2 χ²(6) > 0) is the
    /// F(4, 6) tail at 3, here split over five terms.
    #[test]
    fn equal_weights_add_their_degrees_of_freedom() {
        let want = f_upper(3.0, 4.0, 6.0);
        let terms = [
            (1.0, 1.5),
            (1.0, 2.5),
            (-2.0, 2.0),
            (-2.0, 3.0),
            (-2.0, 1.0),
        ];
        let got = combination_positive(&terms, TOLERANCE);
        assert!((got - want).abs() < 1e-8, "{got} vs {want}");
        assert_eq!(
            combination_positive(&[(1.0, 2.0), (0.5, 1.0)], TOLERANCE),
            1.0
        );
        assert_eq!(combination_positive(&[(-1.0, 2.0)], TOLERANCE), 0.0);
    }
}
