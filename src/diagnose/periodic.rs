//! Periodic error along the axis (Hemingray et al. 1971, §4: lead-screw and scale errors
//! that repeat along the travel, which a coarse or evenly spaced plan cannot see).
//!
//! The bidirectional target means X̄i (ISO 230-2 2.11: the reversal cancels; with the
//! standard cycle so does a drift) are the systematic deviation. Its smooth part — the
//! progressive error of Hemingray et al. 1971 — is a cubic in position; what is left is
//! searched for a sinusoid with a generalised Lomb–Scargle periodogram (Zechmeister &
//! Kürster 2009, with a floating cubic instead of a floating mean; targets are unevenly
//! spaced, ISO 230-2 clause 4.2). At each trial period the sinusoid's share of the
//! residual is an F-statistic, F(2, m − 6) under white scatter; the false-alarm
//! probability of the highest peak accounts for the number of independent periods
//! searched. When the scatter is known (n ≥ 2) the peak must also be significant against
//! it: χ²₂ of the peak's reduction in weighted residual.
//!
//! What a plan can resolve: periods from twice the typical target spacing (shorter ones
//! alias) to a third of the measured travel (at least three repeats, so a periodic error
//! is not mistaken for the progressive one). A plan whose range is narrower than a factor
//! of two resolves nothing, and the diagnosis says which plan would (Hemingray et al.
//! 1971, §4: a short travel of about 25 mm with about 0.5 mm steps).

use super::stats::{chi2_upper, f_upper, max_of, to_unit_interval};
use crate::units::AxisKind;
use std::cell::RefCell;
use std::f64::consts::TAU;

/// Degree of the smooth (progressive) trend.
const TREND_DEGREE: usize = 3;
/// Frequency grid oversampling over the natural resolution 1/L.
const OVERSAMPLE: f64 = 10.0;
/// Independent trial frequencies per natural resolution 1/L (see [`trials`]).
const TRIALS_PER_RESOLUTION: f64 = 3.0;
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
    pub p_min: f64,
    pub p_max: f64,
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
    pub f_stat: f64,
    /// Single-frequency p-values: of F and (when the scatter is known) of χ².
    pub p_f: f64,
    pub p_chi2: Option<f64>,
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
    pub rss_trend: f64,
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
    pub fn trend_residuals(&self) -> Vec<f64> {
        self.resid
            .iter()
            .zip(&self.trend.sw)
            .map(|(r, s)| r / s)
            .collect()
    }

    /// Degrees of freedom left by the trend.
    pub fn trend_dof(&self) -> f64 {
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
    pub fn f_stat(&self, f: f64) -> f64 {
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
    pub fn peak_at(&self, at: &[f64], f: f64) -> Peak {
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
        (self.refine(a, b), scan)
    }

    /// Golden-section search for the highest F in [a, b].
    pub fn refine(&self, mut a: f64, mut b: f64) -> f64 {
        let g = (5f64.sqrt() - 1.0) / 2.0;
        let mut c = b - g * (b - a);
        let mut d = a + g * (b - a);
        let (mut fc, mut fd) = (self.f_stat(c), self.f_stat(d));
        for _ in 0..40 {
            if fc > fd {
                b = d;
                d = c;
                fd = fc;
                c = b - g * (b - a);
                fc = self.f_stat(c);
            } else {
                a = c;
                c = d;
                fc = fd;
                d = a + g * (b - a);
                fd = self.f_stat(d);
            }
        }
        (a + b) / 2.0
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

/// The outcome of the periodic search.
#[derive(Debug, Clone)]
pub(crate) struct Search {
    pub resolution: Resolution,
    /// The highest peak (of the declared pitch when it was the one tested and found).
    pub peak: Option<Peak>,
    /// False-alarm probability of `peak` (the larger of the F and χ² ones).
    pub fap: f64,
    /// Whether the declared pitch was the candidate.
    pub from_pitch: bool,
    /// (period, normalised power) over the resolvable range, for charts.
    pub periodogram: Vec<(f64, f64)>,
    /// The highest F over the scan (for the Monte-Carlo check).
    pub max_f: f64,
    /// RMS of the target means about the smooth trend, µm or arcsec.
    pub trend_rms: f64,
}

/// Effective number of independent trial frequencies in [f_lo, f_hi] over a travel of
/// `length`: the natural resolution is 1/L, and searching the continuum of periods (and
/// uneven spacing) is worth about three trials per resolution element (calibrated on
/// white scatter about a cubic: FAP < 0.05 in 5.3 %, < 0.01 in 1.1 % of 3000 searches).
fn trials(f_lo: f64, f_hi: f64, length: f64) -> f64 {
    (TRIALS_PER_RESOLUTION * (f_hi - f_lo) * length).max(1.0)
}

/// Searches the means `y` at `positions` (variances `var`, None when unknown) for a
/// periodic error, testing the declared `pitch` (if resolvable) and the scan at level
/// `alpha` together.
pub(crate) fn search(
    positions: &[f64],
    y: &[f64],
    var: Option<&[f64]>,
    pitch: Option<f64>,
    alpha: f64,
) -> Search {
    let res = resolution(positions);
    let mut out = Search {
        resolution: res.clone(),
        peak: None,
        fap: 1.0,
        from_pitch: false,
        periodogram: Vec::new(),
        max_f: f64::NAN,
        trend_rms: f64::NAN,
    };
    if positions.len() < TREND_DEGREE + 2 {
        return out;
    }
    let trend = Trend::new(positions, var);
    let scanner = trend.scanner(y);
    let r = scanner.trend_residuals();
    let dof = scanner.trend_dof();
    if dof > 0.0 {
        out.trend_rms = (r.iter().map(|v| v * v).sum::<f64>() / dof).sqrt();
    }
    if !res.applicable {
        return out;
    }
    let (f_lo, f_hi) = (1.0 / res.p_max, 1.0 / res.p_min);
    let grid = trend.grid(f_lo, f_hi, res.length);
    let (f_best, scan) = scanner.best(&grid);
    let m_eff = trials(f_lo, f_hi, res.length);
    let every = scan.len().div_ceil(600).max(1);
    out.periodogram = scan
        .iter()
        .step_by(every)
        .map(|&(f, d, _)| {
            let power = if scanner.rss_trend > 0.0 {
                d / scanner.rss_trend
            } else {
                0.0
            };
            (1.0 / f, power)
        })
        .collect();
    let scan_peak = scanner.peak(f_best);
    out.max_f = scan_peak.f_stat;
    let fap_of = |p: &Peak, trials: f64| {
        let f = max_of(p.p_f, trials);
        match p.p_chi2 {
            Some(c) => f.max(max_of(c, trials)),
            None => f,
        }
    };
    let pitch_ok = pitch.filter(|&p| p >= res.p_min && p <= res.length / 2.0 && p > 0.0);
    let scan_alpha = if pitch_ok.is_some() {
        alpha / 2.0
    } else {
        alpha
    };
    if let Some(p) = pitch_ok {
        let at = scanner.peak(1.0 / p);
        let fap = fap_of(&at, 1.0);
        if fap < alpha / 2.0 {
            // Refine within the natural resolution around the pitch.
            let half = 0.5 / res.length;
            let f = scanner.refine((1.0 / p - half).max(f64::MIN_POSITIVE), 1.0 / p + half);
            out.peak = Some(scanner.peak(f));
            out.fap = fap;
            out.from_pitch = true;
            return out;
        }
    }
    out.fap = fap_of(&scan_peak, m_eff);
    if out.fap < scan_alpha {
        out.peak = Some(scan_peak);
    }
    out
}

/// The short fine-step test that measures a periodic error of pitch `pitch` (or looks for
/// one): Hemingray et al. 1971, §4.
pub(crate) fn short_test(kind: AxisKind, pitch: Option<f64>) -> String {
    match (kind, pitch) {
        (AxisKind::Linear, Some(p)) => format!(
            "to measure it, add a short test over about {} mm (at least three pitches) with steps of about {} mm (a tenth of the pitch or finer), as Hemingray et al. 1971, §4 recommend (25 mm with 0.5 mm steps)",
            fmt_position_round((3.0 * p).max(25.0)),
            fmt_position_round((p / 10.0).min(0.5))
        ),
        (AxisKind::Linear, None) => "to look for a lead-screw or scale periodic error, add a short test of about 25 mm with about 0.5 mm steps (Hemingray et al. 1971, §4)".to_string(),
        (AxisKind::Rotary, Some(p)) => format!(
            "to measure it, add a short test over at least three pitches ({} deg) with steps of about {} deg (a tenth of the pitch), after Hemingray et al. 1971, §4",
            fmt_position_round(3.0 * p),
            fmt_position_round(p / 10.0)
        ),
        (AxisKind::Rotary, None) => "to look for a periodic error (worm, encoder), add a short test over a few periods with steps of a tenth of the period (Hemingray et al. 1971, §4)".to_string(),
    }
}

/// Notes on what the plan can resolve of a periodic error (Hemingray et al. 1971, §4).
pub(crate) fn plan_notes(
    res: &Resolution,
    pitch: Option<f64>,
    kind: AxisKind,
    notes: &mut Vec<String>,
) {
    let pu = kind.position_unit();
    let advice = short_test(kind, pitch);
    if !res.applicable {
        let spacing = if res.spacing.is_finite() {
            format!(
                "targets about {} {pu} apart over {} {pu}",
                fmt_position_round(res.spacing),
                fmt_position_round(res.length)
            )
        } else {
            "a single target".to_string()
        };
        notes.push(format!(
            "periodic error not assessed: with {spacing} the plan resolves no period (it would need periods between twice the spacing and a third of the travel, at least a factor of two apart, and at least 10 targets); {advice}"
        ));
    } else if let Some(p) = pitch {
        if p < res.p_min {
            notes.push(format!(
                "the declared pitch {} {pu} is shorter than twice the target spacing ({} {pu}): the plan cannot resolve it; {advice}",
                fmt_position_round(p),
                fmt_position_round(res.spacing)
            ));
        } else if p > res.length / 2.0 {
            notes.push(format!(
                "the declared pitch {} {pu} repeats fewer than twice over the measured travel: it cannot be told from the progressive error",
                fmt_position_round(p)
            ));
        }
    }
}

fn fmt_position_round(v: f64) -> String {
    crate::units::fmt_position((v * 1000.0).round() / 1000.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_a_sinusoid_on_a_trend() {
        let positions: Vec<f64> = (0..51)
            .map(|i| i as f64 * 0.5 + 0.05 * ((i * 7 % 5) as f64))
            .collect();
        let y: Vec<f64> = positions
            .iter()
            .map(|p| 0.02 * p + 0.001 * p * p + 0.8 * (TAU * p / 5.0 + 0.3).sin())
            .collect();
        let s = search(&positions, &y, None, None, 0.01);
        let peak = s.peak.expect("found");
        assert!((peak.period - 5.0).abs() < 0.05, "{peak:?}");
        assert!((peak.amplitude - 0.8).abs() < 0.05, "{peak:?}");
        assert!(
            (peak.phase_deg - 0.3f64.to_degrees()).abs() < 3.0,
            "{peak:?}"
        );
    }

    /// Under white scatter about a cubic, the false-alarm probability of the highest peak
    /// is calibrated: about 5 % of searches have FAP < 0.05 (and fewer below 0.01).
    #[test]
    fn false_alarm_probability_is_calibrated() {
        use crate::axis_model::rng::Rng;
        let mut rng = Rng::new(3, 9);
        let (mut below5, mut below1, mut known5) = (0, 0, 0);
        let trials = 1000;
        for _ in 0..trials {
            let m = 20 + (rng.uniform() * 50.0) as usize;
            let step = rng.range(0.3, 1.0);
            let positions: Vec<f64> = (0..m)
                .map(|i| i as f64 * step + rng.range(-0.2, 0.2) * step)
                .collect();
            let (c1, c2) = (rng.range(-1.0, 1.0), rng.range(-0.05, 0.05));
            let y: Vec<f64> = positions
                .iter()
                .map(|p| c1 * p + c2 * p * p + 0.3 * rng.normal())
                .collect();
            let s = search(&positions, &y, None, None, 0.05);
            if s.fap < 0.05 {
                below5 += 1;
            }
            if s.fap < 0.01 {
                below1 += 1;
            }
            let var = vec![0.09; m];
            if search(&positions, &y, Some(&var), None, 0.05).fap < 0.05 {
                known5 += 1;
            }
        }
        let r5 = below5 as f64 / trials as f64;
        let r1 = below1 as f64 / trials as f64;
        let k5 = known5 as f64 / trials as f64;
        eprintln!("FAP < 0.05: {r5}, < 0.01: {r1}; with known scatter < 0.05: {k5}");
        assert!(r5 < 0.08 && r5 > 0.02, "{r5}");
        assert!(r1 < 0.025, "{r1}");
        assert!(k5 < 0.07, "{k5}");
    }

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
