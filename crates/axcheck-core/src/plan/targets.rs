//! The target positions of a plan: as many as the standard asks for over the measurement
//! travel, the ends and (on rotary axes) the principal positions among them, the others
//! spread evenly between them with an offset r each (ISO 230-2 4.2: Pᵢ = (i − 1)P + r, r
//! different at each target so that periodic errors of the lead screw or the scale are
//! sampled at varying phases). Of many offset sets drawn from the seed, the one that
//! spreads the targets' phases best over every declared period is kept.

use crate::axis_model::rng::Rng;
use crate::evaluate::StandardId;
use crate::rules::{LINEAR_SHORT_MM, ROTARY_SHORT_DEG};
use crate::units::AxisKind;

/// Offset sets drawn to find the best spread of phases.
const CANDIDATES: u64 = 256;

/// Positions are recorded to 0.001 mm or degree.
pub fn recorded(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0 + 0.0
}

/// The least number of targets over `travel` (mm or deg) the standard asks for, and the
/// widest gap it allows between two neighbours (`None`: no such limit).
///
/// ISO 230-2:1997 (and the standards axcheck judges by its plan): 4.3.2 five per metre and
/// five in all up to 2000 mm; 4.3.3 a mean spacing of at most 250 mm beyond; 4.3.4 Table 1,
/// 3, 5 or 8 targets up to 90°, 180°, 360°; 4.3.5 every spacing at most 45° beyond 360°.
/// GOST 27843-88 2.7: at least 11 targets on any two metres of a linear axis.
pub fn least(kind: AxisKind, standard: StandardId, travel: f64) -> (usize, Option<f64>) {
    let eps = 1e-9;
    let ceil = |x: f64| (x - eps).ceil().max(0.0) as usize;
    match (kind, standard) {
        (AxisKind::Linear, StandardId::Gost27843) => {
            // Every gap under 200 mm puts 11 targets on any two metres.
            (ceil(travel / 180.0).max(10) + 1, Some(199.0))
        }
        (AxisKind::Linear, _) if travel <= LINEAR_SHORT_MM + eps => {
            (ceil(5.0 * travel / 1000.0).max(5), None)
        }
        (AxisKind::Linear, _) => (ceil(travel / 250.0) + 1, None),
        (AxisKind::Rotary, _) if travel <= ROTARY_SHORT_DEG + eps => {
            let table_1 = if travel <= 90.0 + eps {
                3
            } else if travel <= 180.0 + eps {
                5
            } else {
                8
            };
            (table_1, None)
        }
        (AxisKind::Rotary, _) => (ceil(travel / 45.0) + 1, Some(45.0)),
    }
}

/// The positions every plan of this axis must hold: the ends of the measurement travel
/// and, on a rotary axis, the principal positions 0°, 90°, 180°, 270° inside it (ISO 230-2
/// 4.3.4 up to 360°, GOST 27843 2.8 in every turn).
pub fn fixed(kind: AxisKind, standard: StandardId, first: f64, last: f64) -> Vec<f64> {
    let mut out = vec![first, last];
    let cardinal = kind == AxisKind::Rotary
        && (standard == StandardId::Gost27843 || last - first <= ROTARY_SHORT_DEG + 1e-9);
    if cardinal {
        let mut k = (first / 90.0).ceil() as i64;
        while k as f64 * 90.0 <= last + 1e-9 {
            out.push(k as f64 * 90.0);
            k += 1;
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
    out
}

/// Targets between `fixed` (ascending, at least two): `count` in all (at least as many as
/// fixed), every gap at most `widest`, the free ones offset, their phases spread over
/// `periods` as well as `CANDIDATES` draws of `seed` allow.
pub fn place(
    fixed: &[f64],
    count: usize,
    widest: Option<f64>,
    periods: &[f64],
    seed: u64,
) -> Vec<f64> {
    let segments = segments(fixed, count, widest);
    let mut best: Option<(f64, Vec<f64>)> = None;
    for draw in 0..CANDIDATES {
        let mut rng = Rng::new(seed, draw);
        let targets = draw_targets(fixed, &segments, widest, periods, &mut rng);
        let score = spread(&targets, periods);
        if best.as_ref().is_none_or(|(b, _)| score < *b - 1e-12) {
            best = Some((score, targets));
        }
    }
    best.map(|(_, t)| t).unwrap_or_default()
}

/// How many free targets each segment between fixed positions gets: in proportion to its
/// length (largest remainders), one at least in a segment as long as the mean spacing, and
/// enough for its gaps to stay within `widest`.
fn segments(fixed: &[f64], count: usize, widest: Option<f64>) -> Vec<usize> {
    let lengths: Vec<f64> = fixed.windows(2).map(|w| w[1] - w[0]).collect();
    let total: f64 = lengths.iter().sum();
    let free = count.saturating_sub(fixed.len());
    let shares: Vec<f64> = lengths.iter().map(|l| free as f64 * l / total).collect();
    let mut n: Vec<usize> = shares.iter().map(|s| s.floor() as usize).collect();
    let mut order: Vec<usize> = (0..n.len()).collect();
    order.sort_by(|&a, &b| (shares[b] - n[b] as f64).total_cmp(&(shares[a] - n[a] as f64)));
    let left = free - n.iter().sum::<usize>();
    for &k in order.iter().take(left) {
        n[k] += 1;
    }
    // A segment as long as the mean spacing gets a target of its own (a whole turn's
    // quarters, not three targets for four of them).
    let mean = total / (count.max(2) - 1) as f64;
    for (k, l) in lengths.iter().enumerate() {
        if n[k] == 0 && *l >= mean - 1e-9 {
            n[k] = 1;
        }
    }
    if let Some(w) = widest {
        // A gap of 0.8 of the widest leaves room for the offsets.
        for (k, l) in lengths.iter().enumerate() {
            let need = ((l / (0.8 * w)) - 1e-9).ceil().max(1.0) as usize - 1;
            n[k] = n[k].max(need);
        }
    }
    n
}

/// One draw: in each segment its free targets evenly spaced, each offset by up to the
/// longest period (enough to reach every phase of it) or a tenth of the spacing, whichever
/// is more (unequal spacing, 4.2); never more than a quarter of the spacing, nor than
/// `widest` leaves room for; to 0.001.
fn draw_targets(
    fixed: &[f64],
    segments: &[usize],
    widest: Option<f64>,
    periods: &[f64],
    rng: &mut Rng,
) -> Vec<f64> {
    let longest = periods.iter().copied().fold(0.0, f64::max);
    let mut out = vec![recorded(fixed[0])];
    for (k, &n) in segments.iter().enumerate() {
        let (a, b) = (fixed[k], fixed[k + 1]);
        let gap = (b - a) / (n + 1) as f64;
        let reach = longest.max(gap / 10.0);
        let mut jitter = reach.min(gap / 4.0);
        if let Some(w) = widest {
            jitter = jitter.min(((w - gap) / 2.0).max(0.0));
        }
        for i in 1..=n {
            let r = rng.range(-jitter, jitter);
            out.push(recorded(a + i as f64 * gap + r));
        }
        out.push(recorded(b));
    }
    out
}

/// How badly the targets sample the periods: the widest gap (a fraction of the period)
/// between their phases on the period's circle, the worst of all periods; 0 without any.
fn spread(targets: &[f64], periods: &[f64]) -> f64 {
    periods
        .iter()
        .filter(|p| **p > 0.0)
        .map(|p| {
            let mut phases: Vec<f64> = targets.iter().map(|t| (t / p).rem_euclid(1.0)).collect();
            phases.sort_by(f64::total_cmp);
            let wrap = phases[0] + 1.0 - phases[phases.len() - 1];
            phases.windows(2).map(|w| w[1] - w[0]).fold(wrap, f64::max)
        })
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Clause 4.3.2: 5 per metre and 5 in all; 4.3.3: mean spacing ≤ 250 mm; Table 1;
    /// 4.3.5: ≤ 45°; GOST: 11 on two metres.
    #[test]
    fn the_least_counts_by_hand() {
        let iso = StandardId::Iso230_2;
        assert_eq!(least(AxisKind::Linear, iso, 500.0), (5, None));
        assert_eq!(least(AxisKind::Linear, iso, 1000.0), (5, None));
        assert_eq!(least(AxisKind::Linear, iso, 1001.0), (6, None));
        assert_eq!(least(AxisKind::Linear, iso, 2000.0), (10, None));
        assert_eq!(least(AxisKind::Linear, iso, 4000.0), (17, None));
        assert_eq!(least(AxisKind::Rotary, iso, 90.0), (3, None));
        assert_eq!(least(AxisKind::Rotary, iso, 170.0), (5, None));
        assert_eq!(least(AxisKind::Rotary, iso, 360.0), (8, None));
        assert_eq!(least(AxisKind::Rotary, iso, 720.0), (17, Some(45.0)));
        assert_eq!(
            least(AxisKind::Linear, StandardId::Gost27843, 1500.0),
            (11, Some(199.0))
        );
    }

    /// A whole turn holds 0°, 90°, 180°, 270° and 360°; −30…120° holds 0° and 90°; three
    /// turns under GOST hold every quarter.
    #[test]
    fn the_principal_positions_are_fixed() {
        let iso = StandardId::Iso230_2;
        assert_eq!(
            fixed(AxisKind::Rotary, iso, 0.0, 360.0),
            [0.0, 90.0, 180.0, 270.0, 360.0]
        );
        assert_eq!(
            fixed(AxisKind::Rotary, iso, -30.0, 120.0),
            [-30.0, 0.0, 90.0, 120.0]
        );
        assert_eq!(fixed(AxisKind::Rotary, iso, 0.0, 1080.0), [0.0, 1080.0]);
        assert_eq!(
            fixed(AxisKind::Rotary, StandardId::Gost27843, 0.0, 1080.0).len(),
            13
        );
        assert_eq!(fixed(AxisKind::Linear, iso, 5.0, 995.0), [5.0, 995.0]);
    }

    /// 11 targets over 0…1000 mm with a 10 mm pitch: the ends fixed, the others near every
    /// 100 mm; their phases cover the pitch with no gap over a third of it.
    #[test]
    fn offsets_spread_the_phases_over_the_pitch() {
        let t = place(&[0.0, 1000.0], 11, None, &[10.0], 1);
        assert_eq!(t.len(), 11);
        assert_eq!((t[0], t[10]), (0.0, 1000.0));
        for (i, x) in t.iter().enumerate() {
            assert!((x - 100.0 * i as f64).abs() <= 25.0, "{t:?}");
        }
        assert!(spread(&t, &[10.0]) < 1.0 / 3.0, "{t:?}");
        assert_eq!(
            t,
            place(&[0.0, 1000.0], 11, None, &[10.0], 1),
            "reproducible"
        );
        assert_ne!(t, place(&[0.0, 1000.0], 11, None, &[10.0], 2));
    }
}
