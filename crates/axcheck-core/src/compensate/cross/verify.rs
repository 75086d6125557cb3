//! A straightness test re-measured after a cross table was loaded, compared with what the
//! table predicts (as `crate::verify` does for pitch tables): the residuals about the
//! reference line after should be those before plus the table's corrections. A table
//! loaded with the wrong sign leaves the residuals before *minus* the corrections; a table
//! loaded on another output axis leaves this test as it was and moves that axis's
//! straightness by the corrections instead. Each hypothesis is scored by the RMS of the
//! re-measured residuals' difference from it, against the scatter of the means.

use super::CrossTable;
use crate::geometry::{
    self,
    line::{ReferenceLine, fit},
};
use crate::measurement::AxisData;
use crate::units::Direction;
use serde::Serialize;

/// What the re-measurement shows of the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CrossVerdict {
    /// As predicted, within the scatter.
    Effective,
    /// Nearer the prediction than the test before, but not within the scatter.
    PartlyEffective,
    /// As before: the table did not act on this axis.
    NotEffective,
    /// Further from straight than before.
    MadeWorse,
}

impl CrossVerdict {
    /// The verdict's key, as the JSON writes it.
    pub fn key(self) -> &'static str {
        match self {
            CrossVerdict::Effective => "effective",
            CrossVerdict::PartlyEffective => "partly_effective",
            CrossVerdict::NotEffective => "not_effective",
            CrossVerdict::MadeWorse => "made_worse",
        }
    }
}

impl CrossFinding {
    /// The effect's key, as the JSON writes it.
    pub fn key(&self) -> &'static str {
        match self {
            CrossFinding::SignInverted => "sign_inverted",
            CrossFinding::WrongAxis { .. } => "wrong_axis",
        }
    }
}

/// Why the table did not act as predicted, when the tests say.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "effect", rename_all = "snake_case")]
pub enum CrossFinding {
    /// The re-measurement is the test before minus the corrections.
    SignInverted,
    /// This test is unchanged and `output`'s straightness moved by the corrections.
    WrongAxis { output: String },
}

/// The comparison, with each hypothesis's RMS distance (µm) and the straightness (range
/// of the residuals) before, predicted and achieved.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CrossVerification {
    pub verdict: CrossVerdict,
    pub findings: Vec<CrossFinding>,
    pub before_um: f64,
    pub predicted_um: f64,
    pub achieved_um: f64,
    /// The scatter of a residual (the standard uncertainty of a mean), µm.
    pub scatter_um: f64,
}

/// Another output axis's straightness along the same input, before and after: where a
/// table loaded on the wrong axis shows.
#[derive(Debug, Clone, Copy)]
pub struct OtherOutput<'a> {
    pub output: &'a str,
    pub before: &'a AxisData,
    pub after: &'a AxisData,
    /// That axis's own cross table loaded between its two tests (and the one active
    /// before), whose change is taken out of its re-measurement first.
    pub own: Option<(&'a CrossTable, Option<&'a CrossTable>)>,
}

/// The bidirectional mean at each target (as the straightness's reference line is fitted
/// to).
fn means(data: &AxisData) -> Vec<f64> {
    let (up, down) = (
        geometry::means(data, Direction::Up),
        geometry::means(data, Direction::Down),
    );
    up.iter().zip(&down).map(|(u, d)| (u + d) / 2.0).collect()
}

/// `values` about their own reference line.
fn residuals(line: ReferenceLine, positions: &[f64], values: &[f64]) -> Option<Vec<f64>> {
    let l = fit(line, positions, values)?;
    Some(
        positions
            .iter()
            .zip(values)
            .map(|(x, y)| y - l.at(*x))
            .collect(),
    )
}

fn rms(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len()).max(1) as f64;
    (a.iter().zip(b).map(|(x, y)| (x - y).powi(2)).sum::<f64>() / n).sqrt()
}

fn range(v: &[f64]) -> f64 {
    v.iter().cloned().fold(f64::MIN, f64::max) - v.iter().cloned().fold(f64::MAX, f64::min)
}

/// The standard uncertainty of one bidirectional mean: the pooled s over √(2n).
fn scatter(data: &AxisData) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for i in 0..data.target_count() {
        for d in [Direction::Up, Direction::Down] {
            let x = data.deviations(i, d);
            if x.len() > 1 {
                let m = x.iter().sum::<f64>() / x.len() as f64;
                sum += x.iter().map(|v| (v - m).powi(2)).sum::<f64>();
                count += x.len() - 1;
            }
        }
    }
    let s = if count > 0 {
        (sum / count as f64).sqrt()
    } else {
        0.0
    };
    s / ((2 * data.runs()).max(1) as f64).sqrt()
}

/// The change a table makes at `positions` where `old` was active before (none: the
/// table's own corrections), µm.
pub fn change(new: &CrossTable, old: Option<&CrossTable>, positions: &[f64]) -> Vec<f64> {
    positions
        .iter()
        .map(|x| new.at(*x) - old.map_or(0.0, |o| o.at(*x)))
        .collect()
}

/// The straightness (range of the bidirectional means about their reference line) of
/// `data` as measured and with `change` (µm at its targets) added: what a table predicts.
pub fn predicted(data: &AxisData, change: &[f64], line: ReferenceLine) -> Option<(f64, f64)> {
    let p = &data.targets;
    let m = means(data);
    let moved: Vec<f64> = m.iter().zip(change).map(|(y, c)| y + c).collect();
    Some((
        range(&residuals(line, p, &m)?),
        range(&residuals(line, p, &moved)?),
    ))
}

/// `after` (this output axis re-measured with `new` loaded, `old` loaded before: none
/// when nothing was) against `before`; `None` when the two tests are not at the same
/// targets or have fewer than two.
pub fn verify(
    before: &AxisData,
    after: &AxisData,
    (new, old): (&CrossTable, Option<&CrossTable>),
    line: ReferenceLine,
    others: &[OtherOutput],
) -> Option<CrossVerification> {
    let p = &before.targets;
    if p.len() != after.targets.len()
        || p.iter()
            .zip(&after.targets)
            .any(|(a, b)| (a - b).abs() > 1e-3)
    {
        return None;
    }
    let c = change(new, old, p);
    let m = means(before);
    let shifted = |sign: f64| -> Vec<f64> { m.iter().zip(&c).map(|(y, c)| y + sign * c).collect() };
    let before_r = residuals(line, p, &m)?;
    let predicted = residuals(line, p, &shifted(1.0))?;
    let inverted = residuals(line, p, &shifted(-1.0))?;
    let achieved = residuals(line, p, &means(after))?;
    let u = scatter(before).hypot(scatter(after));
    let (d_pred, d_inv, d_none) = (
        rms(&achieved, &predicted),
        rms(&achieved, &inverted),
        rms(&achieved, &before_r),
    );
    let mut findings = Vec::new();
    let verdict = if d_pred <= d_inv.min(d_none) {
        if d_pred <= 3.0 * u {
            CrossVerdict::Effective
        } else {
            CrossVerdict::PartlyEffective
        }
    } else if d_inv < d_none {
        findings.push(CrossFinding::SignInverted);
        CrossVerdict::MadeWorse
    } else {
        findings.extend(wrong_axis(&c, line, others));
        CrossVerdict::NotEffective
    };
    Some(CrossVerification {
        verdict,
        findings,
        before_um: range(&before_r),
        predicted_um: range(&predicted),
        achieved_um: range(&achieved),
        scatter_um: u,
    })
}

/// The other outputs whose straightness moved by the corrections `c` (nearer a change
/// of `c` than no change at all).
fn wrong_axis(c: &[f64], line: ReferenceLine, others: &[OtherOutput]) -> Vec<CrossFinding> {
    others
        .iter()
        .filter_map(|o| {
            let p = &o.before.targets;
            let (b, a) = (means(o.before), means(o.after));
            if p.len() != c.len() || a.len() != b.len() {
                return None;
            }
            let own = o
                .own
                .map_or(vec![0.0; p.len()], |(n, old)| change(n, old, p));
            let change: Vec<f64> = (a.iter().zip(&b).zip(&own))
                .map(|((a, b), own)| a - b - own)
                .collect();
            let change = residuals(line, p, &change)?;
            let expected = residuals(line, p, c)?;
            let zero = vec![0.0; c.len()];
            (rms(&change, &expected) < rms(&change, &zero)).then(|| CrossFinding::WrongAxis {
                output: o.output.to_string(),
            })
        })
        .collect()
}
