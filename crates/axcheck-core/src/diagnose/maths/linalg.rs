//! Least squares for the small designs of the diagnosis: modified Gram–Schmidt with
//! re-orthogonalisation; a column that adds nothing new (collinear with the earlier ones,
//! e.g. a drift in time that the run effects already span) is dropped, not an error.
//!
//! Kept by hand after looking at the maintained crates (issue 12): the time model needs
//! the columns judged in their order (the later of two collinear terms is the one
//! dropped, so the run effects keep what they span and the drift gets 0), which
//! nalgebra's column-pivoted QR does not do (it orders the columns by norm) and which
//! would take as much code on top of its unpivoted QR as this file has; nalgebra 0.35
//! also costs about 17 s of clean build on two cores (nalgebra, simba, wide,
//! matrixmultiply …), faer 0.24 about 3 minutes.

/// A column is taken as collinear with the earlier ones when they leave less than this
/// share of its norm. Times recorded to 1 ms make a drift that the run effects span
/// (regular timing: each reading's time is its run's start plus its place in the cycle)
/// differ from their span by about 1e-6 of its norm; kept, its coefficient would be that
/// rounding amplified a million times, and its predictions noise (a held-out RMS of
/// 1e4 µm was seen). Time stamps to the second leave about 1e-3: kept.
const COLLINEAR: f64 = 1e-5;

/// A least-squares fit y ≈ X b.
#[derive(Debug, Clone)]
pub struct LeastSquares {
    /// Coefficient per input column (0 for a dropped column).
    pub(crate) coef: Vec<f64>,
    /// Which input columns were kept.
    pub kept: Vec<bool>,
    /// Residual sum of squares.
    pub(crate) rss: f64,
    /// Number of kept columns.
    pub rank: usize,
    pub residuals: Vec<f64>,
    /// (XᵀX)⁻¹ over all input columns (zero rows and columns for dropped ones).
    pub(crate) cov: Vec<Vec<f64>>,
    /// Orthonormal basis of the kept columns (for leverages).
    q: Vec<Vec<f64>>,
}

pub(crate) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

fn axpy(alpha: f64, x: &[f64], y: &mut [f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += alpha * xi;
    }
}

/// Fits `y` on the columns `cols` (each of `y.len()` rows); no intercept is added.
pub(crate) fn least_squares(cols: &[Vec<f64>], y: &[f64]) -> LeastSquares {
    let p = cols.len();
    let mut q: Vec<Vec<f64>> = Vec::new();
    // r[k] holds column k of R (entries 0..=k) for the k-th kept column.
    let mut r: Vec<Vec<f64>> = Vec::new();
    let mut kept_idx = Vec::new();
    for (j, col) in cols.iter().enumerate() {
        let norm0 = dot(col, col).sqrt();
        if !(norm0 > 0.0 && norm0.is_finite()) {
            continue;
        }
        let mut v = col.clone();
        let mut rcol = vec![0.0; q.len()];
        for _ in 0..2 {
            for (k, qk) in q.iter().enumerate() {
                let c = dot(qk, &v);
                rcol[k] += c;
                axpy(-c, qk, &mut v);
            }
        }
        let nv = dot(&v, &v).sqrt();
        if nv.is_nan() || nv <= COLLINEAR * norm0 {
            continue;
        }
        for x in &mut v {
            *x /= nv;
        }
        rcol.push(nv);
        q.push(v);
        r.push(rcol);
        kept_idx.push(j);
    }
    let kk = q.len();
    let mut resid = y.to_vec();
    let mut qty = vec![0.0; kk];
    for _ in 0..2 {
        for (k, qk) in q.iter().enumerate() {
            let c = dot(qk, &resid);
            qty[k] += c;
            axpy(-c, qk, &mut resid);
        }
    }
    let mut b = vec![0.0; kk];
    for i in (0..kk).rev() {
        let mut s = qty[i];
        for k in i + 1..kk {
            s -= r[k][i] * b[k];
        }
        b[i] = s / r[i][i];
    }
    // R⁻¹ (upper triangular), then (XᵀX)⁻¹ = R⁻¹R⁻ᵀ.
    let mut rinv = vec![vec![0.0; kk]; kk];
    for j in 0..kk {
        rinv[j][j] = 1.0 / r[j][j];
        for i in (0..j).rev() {
            let mut s = 0.0;
            for k in i + 1..=j {
                s += r[k][i] * rinv[k][j];
            }
            rinv[i][j] = -s / r[i][i];
        }
    }
    let mut cov = vec![vec![0.0; p]; p];
    let mut coef = vec![0.0; p];
    let mut kept = vec![false; p];
    for (a, &ja) in kept_idx.iter().enumerate() {
        coef[ja] = b[a];
        kept[ja] = true;
        for (c, &jc) in kept_idx.iter().enumerate() {
            let s: f64 = (a.max(c)..kk).map(|k| rinv[a][k] * rinv[c][k]).sum();
            cov[ja][jc] = s;
        }
    }
    LeastSquares {
        coef,
        kept,
        rss: dot(&resid, &resid),
        rank: kk,
        residuals: resid,
        cov,
        q,
    }
}

impl LeastSquares {
    /// What the kept columns leave of `v` (`v` minus its projection on their span): how a
    /// further column would enter the fit, without refitting.
    pub(crate) fn residualize(&self, v: &[f64]) -> Vec<f64> {
        let mut out = v.to_vec();
        for _ in 0..2 {
            for qk in &self.q {
                let c = dot(qk, &out);
                axpy(-c, qk, &mut out);
            }
        }
        out
    }

    /// Leverage h of row `row`: the diagonal of the hat matrix.
    pub(crate) fn leverage(&self, row: usize) -> f64 {
        self.q.iter().map(|qk| qk[row] * qk[row]).sum()
    }

    /// Row `row` of the orthonormal basis of the kept columns (one value per column):
    /// the hat matrix is the sum of their outer products.
    pub(crate) fn basis_row(&self, row: usize) -> Vec<f64> {
        self.q.iter().map(|qk| qk[row]).collect()
    }
}

/// The smooth (cubic, or lower with few targets) least-squares trend of `y`.
pub(crate) fn smooth_trend(positions: &[f64], y: &[f64]) -> Vec<f64> {
    let m = positions.len();
    if m == 0 {
        return Vec::new();
    }
    let z = super::stats::to_unit_interval(positions);
    let degree = 3.min(m.saturating_sub(2));
    let cols: Vec<Vec<f64>> = (0..=degree)
        .map(|k| z.iter().map(|zi| zi.powi(k as i32)).collect())
        .collect();
    let idx: Vec<usize> = (0..m).filter(|&i| y[i].is_finite()).collect();
    if idx.is_empty() {
        return vec![f64::NAN; m];
    }
    let sub: Vec<Vec<f64>> = cols
        .iter()
        .map(|c| idx.iter().map(|&i| c[i]).collect())
        .collect();
    let ys: Vec<f64> = idx.iter().map(|&i| y[i]).collect();
    let fit = least_squares(&sub, &ys);
    (0..m)
        .map(|i| cols.iter().zip(&fit.coef).map(|(c, b)| c[i] * b).sum())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_a_line_and_drops_a_collinear_column() {
        let x: Vec<f64> = (0..10).map(|i| i as f64).collect();
        let one = vec![1.0; 10];
        let twice: Vec<f64> = x.iter().map(|v| 2.0 * v).collect();
        let y: Vec<f64> = x.iter().map(|v| 3.0 + 0.5 * v).collect();
        let fit = least_squares(&[one, x.clone(), twice], &y);
        assert_eq!(fit.rank, 2);
        assert!(!fit.kept[2]);
        assert!((fit.coef[0] - 3.0).abs() < 1e-12);
        assert!((fit.coef[1] - 0.5).abs() < 1e-12);
        assert!(fit.rss < 1e-20);
        // Var(slope) ∝ 1/Σ(x − x̄)² = 1/82.5
        assert!((fit.cov[1][1] - 1.0 / 82.5).abs() < 1e-12);
        let h: f64 = (0..10).map(|i| fit.leverage(i)).sum();
        assert!((h - 2.0).abs() < 1e-12);
    }

    /// A cubic in raw positions up to 50 (condition number of the design 1.8e5):
    /// integer data, so the exact coefficients are known.
    #[test]
    fn recovers_an_exact_cubic_on_an_ill_conditioned_design() {
        let x: Vec<f64> = (0..=50).map(f64::from).collect();
        let cols: Vec<Vec<f64>> = (0..4)
            .map(|k| x.iter().map(|v| v.powi(k)).collect())
            .collect();
        let y: Vec<f64> = x
            .iter()
            .map(|v| 7.0 + 3.0 * v - 2.0 * v * v + v * v * v)
            .collect();
        let fit = least_squares(&cols, &y);
        assert_eq!(fit.rank, 4);
        for (got, want) in fit.coef.iter().zip([7.0, 3.0, -2.0, 1.0]) {
            assert!((got - want).abs() <= 1e-9 * want.abs(), "{got} vs {want}");
        }
        assert!(fit.rss < 1e-12, "{}", fit.rss);
    }
}
