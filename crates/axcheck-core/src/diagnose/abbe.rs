//! An Abbe error in a positioning test: mean deviations that follow the axis's measured
//! pitch or yaw, as a beam off the line the axis positions on reads them (HP 5528A User's
//! Guide, Appendix B: "Offset distance × tangent (offset angle)"; Hemingray et al. 1971
//! count such errors of alignment among those a positioning test picks up without telling
//! them apart). With the axis's angular tests, the means at each target and direction are
//! fitted on the progressive error (a constant, the reversal, a slope) and on each angle
//! (rad × 1000, so that its coefficient is a lever in mm): the reading gains εᵥ·w − ε_w·v
//! (`geometry::abbe`'s rule), so the fit gives the beam's offset (v, w) from the line
//! where the error has no Abbe part.
//!
//! The angle's share is tested against the pure error of the means (the runs' pooled
//! scatter, ISO 230-2's sᵢ), by F. An angle that is straight along the travel is the
//! slope's twin and cannot be told from a progressive error: it is said, not fitted. A
//! curved scale error can look like a curved angle; the finding needs the angle to carry
//! most of what the progressive error leaves, and says what it is consistent with.

use super::maths::linalg::least_squares;
use super::maths::stats::f_upper;
use crate::evaluate::stats::sample_sd;
use crate::measurement::AxisData;
use crate::units::{ARCSEC_PER_RAD, Direction};
use serde::Serialize;

/// The significance below which the angles' share is a finding.
pub const ALPHA: f64 = 0.001;
/// The share of what the progressive error leaves that the angles must carry.
pub const SHARE: f64 = 0.5;

/// One angular test the positioning test is fitted on.
#[derive(Clone, Copy)]
pub struct Rotation<'a> {
    /// ISO 230-1's symbol, `EBX`.
    pub symbol: &'a str,
    /// The axis along which its lever lies (for EBX of an X axis: Z), and the sign of the
    /// lever in the reading (+1 for a rotation about v, whose lever is w; −1 about w).
    pub lever: char,
    pub sign: f64,
    /// Its mean angle at a position (mm) in a direction, arcsec; `None` outside its
    /// travel (an angular test's trace, `geometry::angular::Trace::at`).
    pub angle_arcsec: &'a dyn Fn(f64, Direction) -> Option<f64>,
}

/// A fitted lever.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lever {
    pub symbol: String,
    /// The axis the offset lies along.
    pub along: char,
    /// The beam's offset from the line without Abbe error, mm, and its standard
    /// uncertainty; `None` where the angle is straight along the travel (not separable).
    pub offset_mm: Option<f64>,
    pub u_mm: Option<f64>,
}

/// What the fit says.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AbbeFit {
    pub levers: Vec<Lever>,
    /// The RMS of the means about the progressive error, and about it with the angles.
    pub rms_progressive_um: f64,
    pub rms_with_angles_um: f64,
    /// F of the angles' share against the means' pure error, its degrees of freedom and
    /// its upper-tail probability.
    pub f: f64,
    pub dof: (usize, usize),
    pub p: f64,
    /// An Abbe error found: significant, carrying at least [`SHARE`] of what the
    /// progressive error leaves, and a lever at least 3 u from zero.
    pub found: bool,
    pub evidence: String,
}

/// The means at each target and direction with their positions, directions and the
/// pooled within-run variance (and its degrees of freedom).
struct Means {
    x: Vec<f64>,
    direction: Vec<Direction>,
    y: Vec<f64>,
    pooled: (f64, usize),
}

fn means(data: &AxisData) -> Means {
    let mut m = Means {
        x: Vec::new(),
        direction: Vec::new(),
        y: Vec::new(),
        pooled: (0.0, 0),
    };
    for (i, &x) in data.targets.iter().enumerate() {
        for d in [Direction::Up, Direction::Down] {
            let r = data.deviations(i, d);
            if r.is_empty() {
                continue;
            }
            m.x.push(x);
            m.direction.push(d);
            m.y.push(r.iter().sum::<f64>() / r.len() as f64);
            if let Some(s) = sample_sd(r) {
                m.pooled.0 += s * s * (r.len() - 1) as f64;
                m.pooled.1 += r.len() - 1;
            }
        }
    }
    m
}

/// The fit of `data`'s means on the progressive error and `rotations`; `None` when the
/// test has too few means or no scatter to test against, or a target lies outside an
/// angular test's travel.
pub fn fit(data: &AxisData, rotations: &[Rotation]) -> Option<AbbeFit> {
    let m = means(data);
    let q = rotations.len();
    let (ss, pure_dof) = m.pooled;
    if q == 0 || m.y.len() < 3 + q + 1 || pure_dof == 0 || ss <= 0.0 {
        return None;
    }
    let sigma2 = ss / pure_dof as f64 / data.runs() as f64;
    let half = |d: &Direction| if *d == Direction::Up { 0.5 } else { -0.5 };
    let mut cols = vec![
        vec![1.0; m.y.len()],
        m.direction.iter().map(half).collect(),
        m.x.clone(),
    ];
    for r in rotations {
        let angle = (m.x.iter().zip(&m.direction))
            .map(|(x, d)| {
                Some(r.sign * ((r.angle_arcsec)(*x, *d)? / ARCSEC_PER_RAD).tan() * 1000.0)
            })
            .collect::<Option<Vec<f64>>>()?;
        cols.push(angle);
    }
    let base = least_squares(&cols[..3], &m.y);
    let full = least_squares(&cols, &m.y);
    let added = full.rank.saturating_sub(base.rank);
    let n = m.y.len() as f64;
    let levers = (rotations.iter().enumerate())
        .map(|(k, r)| {
            let j = 3 + k;
            let kept = full.kept[j];
            Lever {
                symbol: r.symbol.to_string(),
                along: r.lever,
                offset_mm: kept.then(|| full.coef[j]),
                u_mm: kept.then(|| (full.cov[j][j] * sigma2).sqrt()),
            }
        })
        .collect::<Vec<Lever>>();
    let gain = (base.rss - full.rss).max(0.0);
    let f = match added {
        0 => 0.0,
        a => gain / a as f64 / sigma2,
    };
    let p = if added == 0 {
        1.0
    } else {
        f_upper(f, added as f64, pure_dof as f64)
    };
    let share = if base.rss > 0.0 { gain / base.rss } else { 0.0 };
    // Two bowed angles can share one curve between them: a lever must stand on its own.
    let standing =
        |l: &Lever| matches!((l.offset_mm, l.u_mm), (Some(o), Some(u)) if o.abs() >= 3.0 * u);
    let found = added > 0 && p < ALPHA && share >= SHARE && levers.iter().any(standing);
    let evidence = evidence(added, f, (added, pure_dof), p, share);
    Some(AbbeFit {
        levers,
        rms_progressive_um: (base.rss / n).sqrt(),
        rms_with_angles_um: (full.rss / n).sqrt(),
        f,
        dof: (added, pure_dof),
        p,
        found,
        evidence,
    })
}

fn evidence(added: usize, f: f64, dof: (usize, usize), p: f64, share: f64) -> String {
    if added == 0 {
        return "the angles are straight along the travel: an Abbe error would be a progressive (linear) error and cannot be told from one".into();
    }
    format!(
        "the angles carry {:.0} % of what a progressive error leaves of the means; F = {f:.1} on ({}, {}) degrees of freedom against the runs' scatter, P = {}",
        share * 100.0,
        dof.0,
        dof.1,
        super::finding::fmt_p(p)
    )
}

#[cfg(test)]
mod tests;
