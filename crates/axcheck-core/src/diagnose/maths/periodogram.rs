//! The periodogram of unevenly spaced target means: a generalised Lomb–Scargle scan
//! (Zechmeister & Kürster 2009) with a floating cubic instead of a floating mean, what a
//! plan's target spacing can resolve, and the highest peak. The maths only; the periodic
//! effect's test and what it reports are in `diagnose/periodic.rs`.

use super::stats::{chi2_upper, f_upper, to_unit_interval};
use std::cell::RefCell;
use std::f64::consts::TAU;

/// Degree of the smooth (progressive) trend.
pub(crate) const TREND_DEGREE: usize = 3;
/// Frequency grid oversampling over the natural resolution 1/L.
const OVERSAMPLE: f64 = 10.0;
/// Most grid frequencies.
const MAX_GRID: usize = 4000;
/// Most targets searched (a larger plan is not a positioning test of one axis).
const MAX_TARGETS: usize = 5000;

/// The periods a plan can resolve.
#[derive(Debug, Clone)]
pub(crate) struct Resolution {
    /// Typical (median) target spacing.
    pub spacing: f64,
    /// Length of the measured travel.
    pub length: f64,
    pub(crate) p_min: f64,
    pub(crate) p_max: f64,
    pub applicable: bool,
}

/// What the plan of targets at `positions` can resolve.
pub(crate) fn resolution(positions: &[f64]) -> Resolution {
    let m = positions.len();
    let mut gaps: Vec<f64> = positions.windows(2).map(|w| w[1] - w[0]).collect();
    gaps.sort_by(f64::total_cmp);
    let spacing = if gaps.is_empty() {
        f64::NAN
    } else {
        gaps[gaps.len() / 2]
    };
    let length = if m > 0 {
        positions[m - 1] - positions[0]
    } else {
        0.0
    };
    let p_min = 2.0 * spacing;
    let p_max = length / 3.0;
    let applicable = (TREND_DEGREE + 1 + 2 + 4..=MAX_TARGETS).contains(&m)
        && p_max >= 2.0 * p_min
        && spacing > 0.0;
    Resolution {
        spacing,
        length,
        p_min,
        p_max,
        applicable,
    }
}

/// A fitted sinusoid.
#[derive(Debug, Clone)]
pub(crate) struct Peak {
    pub period: f64,
    /// Amplitude (half peak-to-peak).
    pub amplitude: f64,
    /// Phase at position 0, degrees: A·sin(2πP/period + phase).
    pub phase_deg: f64,
    pub(crate) f_stat: f64,
    /// Single-frequency p-values: of F and (when the scatter is known) of χ².
    pub(crate) p_f: f64,
    pub(crate) p_chi2: Option<f64>,
}

/// The smooth trend's basis at fixed positions and weights: what every test of the same
/// plan shares, so that many tests (the Monte-Carlo checks) are scanned without
/// rebuilding it.
#[derive(Debug, Clone)]
pub(crate) struct Trend {
    positions: Vec<f64>,
    /// √weight per target.
    sw: Vec<f64>,
    /// Orthonormal basis (weighted) of the trend.
    basis: Vec<Vec<f64>>,
    /// True when the weights are 1/variance (the scatter known).
    absolute: bool,
}

/// The systematic deviation along the axis, ready for trial periods.
#[derive(Debug)]
pub(crate) struct Scanner<'a> {
    trend: &'a Trend,
    /// Weighted residual of the trend.
    resid: Vec<f64>,
    pub(crate) rss_trend: f64,
    dof: f64,
    /// Scratch for the projected sine and cosine of a trial frequency.
    scratch: RefCell<Vec<[f64; 2]>>,
}

/// The projected sine and cosine columns of one trial frequency and their products:
/// everything of a fit that does not depend on the data.
#[derive(Debug, Clone)]
struct Column {
    /// [sine, cosine] per target.
    sc_cols: Vec<[f64; 2]>,
    ss: f64,
    sc: f64,
    cc: f64,
    det: f64,
    /// False when the two columns are (nearly) collinear after the trend: no fit.
    ok: bool,
}

impl Column {
    fn new(sc_cols: Vec<[f64; 2]>) -> Column {
        let (mut ss, mut sc, mut cc) = (-0.0, -0.0, -0.0);
        for [si, ci] in &sc_cols {
            ss += si * si;
            sc += si * ci;
            cc += ci * ci;
        }
        let det = ss * cc - sc * sc;
        let scale = ss.max(cc);
        let ok = !(scale.is_nan() || scale <= 0.0 || det.is_nan() || det <= 1e-10 * scale * scale);
        Column {
            sc_cols,
            ss,
            sc,
            cc,
            det,
            ok,
        }
    }
}

/// A frequency grid over [f_lo, f_hi] with its projected columns, for the scans of all
/// tests of one plan.
#[derive(Debug, Clone)]
pub(crate) struct Grid {
    freqs: Vec<f64>,
    columns: Vec<Column>,
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// `project_out` of the sine and the cosine columns, stored as [sine, cosine] per
/// target: each column's sums and updates are those of `project_out` alone (sums in the
/// same order from the same −0.0 as `Iterator::sum` in `dot`), so the bits are the same,
/// but the two columns share each pass (and a vector register).
fn project_out_pairs(basis: &[Vec<f64>], v: &mut [[f64; 2]]) {
    for _ in 0..2 {
        for q in basis {
            let mut c = [-0.0, -0.0];
            for (vi, qi) in v.iter().zip(q) {
                c[0] += qi * vi[0];
                c[1] += qi * vi[1];
            }
            for (vi, qi) in v.iter_mut().zip(q) {
                vi[0] -= c[0] * qi;
                vi[1] -= c[1] * qi;
            }
        }
    }
}

fn project_out(basis: &[Vec<f64>], v: &mut [f64]) {
    for _ in 0..2 {
        for q in basis {
            let c = dot(q, v);
            for (vi, qi) in v.iter_mut().zip(q) {
                *vi -= c * qi;
            }
        }
    }
}

/// The least-squares sinusoid a·sin + b·cos of the residual `resid` given the projected
/// columns (shared by the cached grid and the on-the-fly fits, so both agree to the bit).
fn solve(col: &Column, resid: &[f64]) -> (f64, f64, f64) {
    let (mut sy, mut cy) = (-0.0, -0.0);
    for ([si, ci], ri) in col.sc_cols.iter().zip(resid) {
        sy += si * ri;
        cy += ci * ri;
    }
    from_products(col.ss, col.sc, col.cc, col.det, sy, cy)
}

fn from_products(ss: f64, sc: f64, cc: f64, det: f64, sy: f64, cy: f64) -> (f64, f64, f64) {
    let a = (cc * sy - sc * cy) / det;
    let b = (ss * cy - sc * sy) / det;
    ((a * sy + b * cy).max(0.0), a, b)
}

impl Trend {
    /// The trend basis at `positions` with variances `var` (None: equal weights,
    /// unknown scatter).
    pub fn new(positions: &[f64], var: Option<&[f64]>) -> Trend {
        let m = positions.len();
        let sw: Vec<f64> = (0..m)
            .map(|i| var.map_or(1.0, |v| 1.0 / v[i].sqrt()))
            .collect();
        let z = to_unit_interval(positions);
        let degree = TREND_DEGREE.min(m.saturating_sub(1));
        let mut basis: Vec<Vec<f64>> = Vec::new();
        for k in 0..=degree {
            let mut v: Vec<f64> = z
                .iter()
                .zip(&sw)
                .map(|(zi, s)| s * legendre(k, *zi))
                .collect();
            project_out(&basis, &mut v);
            let norm = dot(&v, &v).sqrt();
            if norm > 1e-9 {
                for x in &mut v {
                    *x /= norm;
                }
                basis.push(v);
            }
        }
        Trend {
            positions: positions.to_vec(),
            sw,
            basis,
            absolute: var.is_some(),
        }
    }

    /// The values `y` (one per position) scanned against this trend.
    pub fn scanner(&self, y: &[f64]) -> Scanner<'_> {
        let m = self.positions.len();
        let mut resid: Vec<f64> = y.iter().zip(&self.sw).map(|(yi, s)| s * yi).collect();
        project_out(&self.basis, &mut resid);
        let rss_trend = dot(&resid, &resid);
        let dof = m as f64 - self.basis.len() as f64 - 2.0;
        Scanner {
            trend: self,
            resid,
            rss_trend,
            dof,
            scratch: RefCell::new(Vec::with_capacity(m)),
        }
    }

    /// The weighted [sine, cosine] of frequency `f` at the positions, with the trend
    /// projected out, into `v`.
    fn project(&self, f: f64, v: &mut Vec<[f64; 2]>) {
        self.project_at(&self.positions, f, v);
    }

    /// [`Trend::project`] with the sinusoid at `at` (one per position) instead of the
    /// positions.
    fn project_at(&self, at: &[f64], f: f64, v: &mut Vec<[f64; 2]>) {
        v.clear();
        // sin_cos compiles to glibc's sincos, which shares sin's and cos's reduction
        // and kernels and so returns their bits (checked on 10⁸ arguments).
        v.extend(at.iter().zip(&self.sw).map(|(p, w)| {
            let (sin, cos) = (TAU * f * p).sin_cos();
            [w * sin, w * cos]
        }));
        project_out_pairs(&self.basis, v);
    }

    /// The weighted energy a sinusoid of unit amplitude and frequency `f` keeps beyond
    /// the trend, averaged over its phase: an amplitude A adds A² times this to the
    /// reduction of the residual sum of squares its fit makes (the noncentrality of the
    /// test when the weights are 1/variance).
    pub(crate) fn sinusoid_information(&self, f: f64) -> f64 {
        let mut v = Vec::with_capacity(self.positions.len());
        self.project(f, &mut v);
        v.iter().map(|[s, c]| s * s + c * c).sum::<f64>() / 2.0
    }

    /// The grid of [`Scanner::best`] over [f_lo, f_hi] with its columns.
    pub fn grid(&self, f_lo: f64, f_hi: f64, length: f64) -> Grid {
        let step = 1.0 / (OVERSAMPLE * length);
        let count = (((f_hi - f_lo) / step).ceil() as usize + 1).clamp(2, MAX_GRID);
        let step = (f_hi - f_lo) / (count - 1) as f64;
        let freqs: Vec<f64> = (0..count).map(|k| f_lo + k as f64 * step).collect();
        let columns = freqs
            .iter()
            .map(|&f| {
                let mut v = Vec::with_capacity(self.positions.len());
                self.project(f, &mut v);
                Column::new(v)
            })
            .collect();
        Grid { freqs, columns }
    }
}

impl Scanner<'_> {
    /// The trend's residual per target, unweighted.
    pub(crate) fn trend_residuals(&self) -> Vec<f64> {
        self.resid
            .iter()
            .zip(&self.trend.sw)
            .map(|(r, s)| r / s)
            .collect()
    }

    /// Degrees of freedom left by the trend.
    pub(crate) fn trend_dof(&self) -> f64 {
        self.dof + 2.0
    }

    /// The sinusoid of frequency `f` fitted jointly with the trend: (ΔRSS, a, b) with
    /// a·sin + b·cos.
    fn fit(&self, f: f64) -> (f64, f64, f64) {
        self.fit_at(&self.trend.positions, f)
    }

    /// [`Scanner::fit`] with the sinusoid at `at` (one per position).
    fn fit_at(&self, at: &[f64], f: f64) -> (f64, f64, f64) {
        let mut v = self.scratch.borrow_mut();
        self.trend.project_at(at, f, &mut v);
        // The sums of `Column::new` and `solve` in one pass.
        let (mut ss, mut sc, mut cc, mut sy, mut cy) = (-0.0, -0.0, -0.0, -0.0, -0.0);
        for ([si, ci], ri) in v.iter().zip(&self.resid) {
            ss += si * si;
            sc += si * ci;
            cc += ci * ci;
            sy += si * ri;
            cy += ci * ri;
        }
        let det = ss * cc - sc * sc;
        let scale = ss.max(cc);
        if scale.is_nan() || scale <= 0.0 || det.is_nan() || det <= 1e-10 * scale * scale {
            return (0.0, 0.0, 0.0);
        }
        from_products(ss, sc, cc, det, sy, cy)
    }

    /// [`Scanner::fit`] at the `k`-th frequency of `grid` (built from this scanner's
    /// trend), from its cached columns.
    fn fit_grid(&self, grid: &Grid, k: usize) -> (f64, f64, f64) {
        let col = &grid.columns[k];
        if !col.ok {
            return (0.0, 0.0, 0.0);
        }
        solve(col, &self.resid)
    }

    /// The F-statistic at frequency `f`.
    pub(crate) fn f_stat(&self, f: f64) -> f64 {
        let (d, _, _) = self.fit(f);
        self.f_of(d)
    }

    fn f_of(&self, delta: f64) -> f64 {
        let rest = (self.rss_trend - delta).max(1e-300);
        if self.dof <= 0.0 {
            return 0.0;
        }
        (delta / 2.0) / (rest / self.dof)
    }

    /// The fitted sinusoid at frequency `f`.
    pub fn peak(&self, f: f64) -> Peak {
        self.peak_at(&self.trend.positions, f)
    }

    /// The sinusoid of frequency `f` fitted at `at` (one per position: the positions, or
    /// an unrelated order of them) jointly with the trend at the positions; its phase is
    /// at `at` = 0.
    pub(crate) fn peak_at(&self, at: &[f64], f: f64) -> Peak {
        let (delta, a, b) = self.fit_at(at, f);
        let f_stat = self.f_of(delta);
        Peak {
            period: 1.0 / f,
            amplitude: (a * a + b * b).sqrt(),
            phase_deg: b.atan2(a).to_degrees(),
            f_stat,
            p_f: if self.dof > 0.0 {
                f_upper(f_stat, 2.0, self.dof)
            } else {
                1.0
            },
            p_chi2: self.trend.absolute.then(|| chi2_upper(delta, 2.0)),
        }
    }

    /// The highest F over the frequencies of `grid` (see [`Trend::grid`]), then a
    /// golden-section refine: the refined frequency and (f, ΔRSS, F) per grid frequency.
    pub fn best(&self, grid: &Grid) -> (f64, Vec<(f64, f64, f64)>) {
        let (a, b, scan) = self.bracket(grid);
        (self.refine(a, b), scan)
    }

    /// The grid neighbours of the highest F over the frequencies of `grid`, and (f, ΔRSS,
    /// F) per grid frequency.
    fn bracket(&self, grid: &Grid) -> (f64, f64, Vec<(f64, f64, f64)>) {
        let count = grid.freqs.len();
        let scan: Vec<(f64, f64, f64)> = (0..count)
            .map(|k| {
                let (d, _, _) = self.fit_grid(grid, k);
                (grid.freqs[k], d, self.f_of(d))
            })
            .collect();
        let (kbest, _) =
            scan.iter()
                .enumerate()
                .fold((0, f64::NEG_INFINITY), |(kb, fb), (k, &(_, _, v))| {
                    if v > fb { (k, v) } else { (kb, fb) }
                });
        let a = scan[kbest.saturating_sub(1)].0;
        let b = scan[(kbest + 1).min(count - 1)].0;
        (a, b, scan)
    }

    /// Golden-section search for the highest F in [a, b].
    pub(crate) fn refine(&self, a: f64, b: f64) -> f64 {
        Golden::after(self, a, b, REFINE_STEPS).middle()
    }

    /// The F at the refined frequency of [`Scanner::best`] (`None`), or the highest F the
    /// refine has seen after its first `steps` steps (`Some(steps)`): a bound that the
    /// refine's remaining steps raise by a tiny fraction ([`PARTIAL_REL`]).
    pub(crate) fn max_f(&self, grid: &Grid, steps: Option<usize>) -> f64 {
        let (a, b, _) = self.bracket(grid);
        match steps {
            None => self.f_stat(self.refine(a, b)),
            Some(steps) => {
                let search = Golden::after(self, a, b, steps.min(REFINE_STEPS));
                search.fc.max(search.fd)
            }
        }
    }
}

/// Steps of the golden-section refine (the bracket, two grid steps wide, shrinks to
/// 0.618⁴⁰ ≈ 4·10⁻⁹ of itself).
const REFINE_STEPS: usize = 40;

/// Steps after which [`Scanner::max_f`]'s bound is read by the model checks.
pub(crate) const PARTIAL_STEPS: usize = 12;

/// How far, relative to itself, the highest F seen after [`PARTIAL_STEPS`] steps may lie
/// from the F at the end of the refine, with a wide margin. After 12 steps the bracket is
/// 0.618¹² · 2 ≈ 6.2·10⁻³ grid steps wide. A sinusoid's columns turn by 2π/10 of a radian
/// per grid step (the grid oversamples the resolution 1/L tenfold), by 3.9·10⁻³ rad over
/// that bracket: the fit's ΔRSS moves by at most about twice that fraction, and F = (ΔRSS/2)
/// / ((RSS − ΔRSS)/ν) by that times 1 + 2F/ν, under a tenth for F up to 6ν. Measured:
/// at most 6.1·10⁻⁴ on 3 600 simulated tests (`the_partial_refine_is_within_its_bound` in
/// `checks.rs`, which holds it to 1/50 of this bound).
pub(crate) const PARTIAL_REL: f64 = 0.1;

/// A golden-section search for the highest F, step by step.
struct Golden {
    /// (√5 − 1)/2.
    g: f64,
    a: f64,
    b: f64,
    c: f64,
    d: f64,
    fc: f64,
    fd: f64,
}

impl Golden {
    /// The search on [a, b] after `steps` steps.
    fn after(scanner: &Scanner, a: f64, b: f64, steps: usize) -> Golden {
        let g = (5f64.sqrt() - 1.0) / 2.0;
        let c = b - g * (b - a);
        let d = a + g * (b - a);
        let (fc, fd) = (scanner.f_stat(c), scanner.f_stat(d));
        let mut search = Golden {
            g,
            a,
            b,
            c,
            d,
            fc,
            fd,
        };
        for _ in 0..steps {
            search.step(scanner);
        }
        search
    }

    fn step(&mut self, scanner: &Scanner) {
        let g = self.g;
        if self.fc > self.fd {
            self.b = self.d;
            self.d = self.c;
            self.fd = self.fc;
            self.c = self.b - g * (self.b - self.a);
            self.fc = scanner.f_stat(self.c);
        } else {
            self.a = self.c;
            self.c = self.d;
            self.fc = self.fd;
            self.d = self.a + g * (self.b - self.a);
            self.fd = scanner.f_stat(self.d);
        }
    }

    fn middle(&self) -> f64 {
        (self.a + self.b) / 2.0
    }
}

/// Legendre polynomial P_k(z).
fn legendre(k: usize, z: f64) -> f64 {
    let (mut p0, mut p1) = (1.0, z);
    match k {
        0 => p0,
        1 => p1,
        _ => {
            for j in 1..k {
                let jf = j as f64;
                let p2 = ((2.0 * jf + 1.0) * z * p1 - jf * p0) / (jf + 1.0);
                p0 = p1;
                p1 = p2;
            }
            p1
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Trend::project`] relies on `sin_cos` (glibc's sincos) giving the bits of `sin`
    /// and `cos` apart, as the scans computed them before.
    #[test]
    fn sin_cos_is_sin_and_cos() {
        use std::hint::black_box;
        let mut rng = crate::axis_model::rng::Rng::new(5, 5);
        for k in 0..200_000 {
            let x = match k % 3 {
                0 => rng.range(0.0, 10.0),
                1 => rng.range(0.0, 2000.0),
                _ => rng.range(-1e6, 1e6),
            };
            let (s, c) = x.sin_cos();
            assert_eq!(s.to_bits(), black_box(x).sin().to_bits(), "sin {x}");
            assert_eq!(c.to_bits(), black_box(x).cos().to_bits(), "cos {x}");
        }
    }

    #[test]
    fn coarse_plans_resolve_nothing() {
        let positions: Vec<f64> = (0..11).map(|i| i as f64 * 100.0).collect();
        assert!(!resolution(&positions).applicable);
    }
}
