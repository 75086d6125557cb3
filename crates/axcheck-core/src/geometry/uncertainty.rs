//! U of the other tests (GUM, as [`crate::uncertainty`] does for positioning): what the
//! scatter of the readings leaves uncertain in each result, the optics' accuracy when it
//! is stated, and for squareness the optical square's calibration.
//!
//! - A range (a straightness, an angular deviation) is a difference of two means, at the
//!   targets where it is largest and smallest: u = √(u(x̄_max)² + u(x̄_min)²), u(x̄) = s/√n
//!   at that target and direction (a bidirectional mean: √(s↑² + s↓²)/(2√n)); the
//!   reference line's own uncertainty is left out (it moves every residual alike to
//!   first order).
//! - A slope by least squares from means of standard uncertainty u: u(m) = u/√Σ(Pᵢ − P̄)²;
//!   through the end points: u(m) = √2·u/L (each end's mean).
//! - The optics' accuracy, as the laser's specification states it (a fraction of the
//!   value, a fixed part, a part per metre of travel and one per square metre), is a
//!   rectangular bound. No specification of straightness or angular optics could be
//!   sourced legibly (docs/optics-specifications.md): unstated, the budget has no such
//!   line and says so. The HP 5528A's squareness specifications (User's Guide, section 13,
//!   short- and long-range optics) are presets ([`super::optics`]).

use super::line::ReferenceLine;
pub use super::optics::Accuracy;
use super::optics::Optics;
use super::straightness::Extreme;
use crate::evaluate::stats::sample_sd;
use crate::measurement::AxisData;
use crate::uncertainty::{Budget, BudgetLine, Distribution, Input};
use crate::units::{ARCSEC_PER_RAD, Direction};
use serde::Serialize;

/// Coverage factor of U.
pub const K: f64 = 2.0;

/// U of one result with its budget and what it leaves out.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Uncertain {
    pub k: f64,
    #[serde(rename = "U")]
    pub expanded: f64,
    pub budget: Budget,
    pub notes: Vec<String>,
}

fn uncertain(length: f64, lines: Vec<BudgetLine>, notes: Vec<String>) -> Uncertain {
    let budget = Budget::new(length, lines, K);
    Uncertain {
        k: K,
        expanded: budget.expanded,
        budget,
        notes,
    }
}

/// u(x̄) of each target's bidirectional mean, and of each direction's means; `None` for
/// one run (no s).
fn mean_u(data: &AxisData) -> Option<(Vec<f64>, [Vec<f64>; 2])> {
    let n = data.runs() as f64;
    let s = |i, d| sample_sd(data.deviations(i, d)).map(|s| s / n.sqrt());
    let (mut both, mut up, mut down) = (Vec::new(), Vec::new(), Vec::new());
    for i in 0..data.target_count() {
        let (u, d) = (s(i, Direction::Up)?, s(i, Direction::Down)?);
        both.push((u * u + d * d).sqrt() / 2.0);
        up.push(u);
        down.push(d);
    }
    Some((both, [up, down]))
}

/// The scatter's line of a range whose extremes are the means at `at` (target,
/// direction), or the note that it cannot be computed.
fn scatter_line(
    data: &AxisData,
    at: [(usize, Direction); 2],
    unit: &'static str,
) -> Result<BudgetLine, String> {
    let Some((_, per)) = mean_u(data) else {
        return Err("one run: the scatter of the means cannot be estimated (no s)".into());
    };
    let u_of = |(i, d): (usize, Direction)| per[d.index()][i];
    let u = (u_of(at[0]).powi(2) + u_of(at[1]).powi(2)).sqrt();
    let input = Input {
        value: u,
        unit,
        distribution: Distribution::STANDARD,
    };
    Ok(BudgetLine::new("repeatability", input, 1.0))
}

fn optics_line(
    optics: Option<Optics>,
    value: f64,
    travel_mm: f64,
    unit: &'static str,
    notes: &mut Vec<String>,
) -> Option<BudgetLine> {
    let Some(o) = optics else {
        notes.push("the optics' accuracy was not stated: U holds the scatter only".into());
        return None;
    };
    notes.push(o.describe(unit));
    let input = Input {
        value: o.accuracy.bound(value, travel_mm),
        unit,
        distribution: Distribution::Rectangular,
    };
    Some(BudgetLine::new("optics", input, 1.0))
}

/// U of a straightness (bidirectional by default, or one direction's): the scatter of the
/// means at its largest and smallest residual, and the optics.
pub fn straightness(
    data: &AxisData,
    line: ReferenceLine,
    direction: Option<Direction>,
    optics: Option<Optics>,
) -> Option<Uncertain> {
    let p = &data.targets;
    let directions = match direction {
        Some(d) => vec![d],
        None => vec![Direction::Up, Direction::Down],
    };
    let means: Vec<Vec<f64>> = directions.iter().map(|&d| super::means(data, d)).collect();
    let traces: Vec<&[f64]> = means.iter().map(Vec::as_slice).collect();
    let (_, hi, lo) = super::straightness::about_line(line, p, &traces)?;
    let at = |e: Extreme| (e.target, directions[e.trace]);
    let mut notes = Vec::new();
    let mut lines = Vec::new();
    match scatter_line(data, [at(hi), at(lo)], "um") {
        Ok(l) => lines.push(l),
        Err(note) => notes.push(note),
    }
    let travel = p[p.len() - 1] - p[0];
    let value = hi.residual_um - lo.residual_um;
    lines.extend(optics_line(optics, value, travel, "um", &mut notes));
    Some(uncertain(travel, lines, notes))
}

/// U of an angular deviation (both directions' means): the scatter at its largest and
/// smallest mean, and the optics.
pub fn angular(data: &AxisData, optics: Option<Optics>) -> Option<Uncertain> {
    let mut lo = (f64::INFINITY, 0, Direction::Up);
    let mut hi = (f64::NEG_INFINITY, 0, Direction::Up);
    for d in [Direction::Up, Direction::Down] {
        for (i, y) in super::means(data, d).into_iter().enumerate() {
            if y < lo.0 {
                lo = (y, i, d);
            }
            if y > hi.0 {
                hi = (y, i, d);
            }
        }
    }
    if !lo.0.is_finite() {
        return None;
    }
    let mut notes = Vec::new();
    let mut lines = Vec::new();
    match scatter_line(data, [(hi.1, hi.2), (lo.1, lo.2)], "arcsec") {
        Ok(l) => lines.push(l),
        Err(note) => notes.push(note),
    }
    let p = &data.targets;
    let travel = p[p.len() - 1] - p[0];
    lines.extend(optics_line(
        optics,
        hi.0 - lo.0,
        travel,
        "arcsec",
        &mut notes,
    ));
    Some(uncertain(travel, lines, notes))
}

/// u of the misalignment angle θ of one straightness test's reference line, arcsec.
pub fn slope_u_arcsec(data: &AxisData, line: ReferenceLine) -> Option<f64> {
    let (both, _) = mean_u(data)?;
    let p = &data.targets;
    let u_mean = (both.iter().map(|u| u * u).sum::<f64>() / both.len() as f64).sqrt();
    let u_slope_per_mm = match line {
        ReferenceLine::LeastSquares => {
            let mean = p.iter().sum::<f64>() / p.len() as f64;
            u_mean / p.iter().map(|x| (x - mean).powi(2)).sum::<f64>().sqrt()
        }
        ReferenceLine::EndPoint => {
            let (a, b) = (both[0], both[both.len() - 1]);
            (a * a + b * b).sqrt() / (p[p.len() - 1] - p[0])
        }
    };
    // µm per mm is 10⁻³ rad per … : a slope of 1 µm/mm is 10⁻³ rad.
    Some(u_slope_per_mm * 1e-3 * ARCSEC_PER_RAD)
}

/// U of a squareness: each line's inclination from the scatter of its means, the optical
/// square's calibration (`square_u_arcsec`, a standard uncertainty) and the optics.
pub fn squareness(
    first: &AxisData,
    second: &AxisData,
    line: ReferenceLine,
    error_arcsec: f64,
    square_u_arcsec: Option<f64>,
    optics: Option<Optics>,
) -> Uncertain {
    let mut notes = Vec::new();
    let mut lines = Vec::new();
    for (key, data) in [("first_line", first), ("second_line", second)] {
        match slope_u_arcsec(data, line) {
            Some(u) => lines.push(BudgetLine::new(
                key,
                Input {
                    value: u,
                    unit: "arcsec",
                    distribution: Distribution::STANDARD,
                },
                1.0,
            )),
            None => notes.push(format!(
                "{key}: one run, the scatter of its means cannot be estimated"
            )),
        }
    }
    match square_u_arcsec {
        Some(u) => lines.push(BudgetLine::new(
            "square",
            Input {
                value: u,
                unit: "arcsec",
                distribution: Distribution::STANDARD,
            },
            1.0,
        )),
        None => notes.push("the optical square's calibration uncertainty was not stated".into()),
    }
    // The optics' part per metre on the longer of the two travels (conservative: HP
    // states M as the moving optic's travel, and each axis moves it over its own).
    let travel_of = |d: &AxisData| d.targets[d.targets.len() - 1] - d.targets[0];
    let travel = travel_of(first).max(travel_of(second));
    lines.extend(optics_line(
        optics,
        error_arcsec,
        travel,
        "arcsec",
        &mut notes,
    ));
    uncertain(travel, lines, notes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::straightness::tests::test;

    #[test]
    fn a_range_by_hand() {
        // Runs j = 1, 2, 3 add −0.3, 0, +0.3 to every reading: s = 0.3 everywhere,
        // u(x̄) = 0.3/√3 = 0.1732 per direction. A straight line with one target 5 µm up
        // (both directions) gives its largest residual there and its smallest elsewhere.
        let targets: Vec<f64> = (0..=4).map(|k| k as f64 * 100.0).collect();
        let mut data = test(&targets, 3, |x| if x == 200.0 { 5.0 } else { 0.0 }, 0.0);
        data = data.map_deviations(|r| r.deviation + 0.3 * (r.run as f64 - 1.0));
        let u = straightness(&data, ReferenceLine::EndPoint, None, None).unwrap();
        // The extremes are single-direction means: √(2 · 0.1732²) = 0.2449; U = 0.4899.
        assert_eq!(format!("{:.4}", u.expanded), "0.4899");
        assert!(u.notes[0].contains("optics' accuracy was not stated"));
        // 0.5 µm fixed and 0.2 % of the 5 µm: bound 0.51, u = 0.51/√3 = 0.2944.
        let optics = Accuracy {
            fraction: 0.002,
            fixed: 0.5,
            per_m: 0.0,
            per_m2: 0.0,
        };
        let u = straightness(&data, ReferenceLine::EndPoint, None, Some(optics.into())).unwrap();
        let c = (0.2449f64.powi(2) + 0.2944f64.powi(2)).sqrt() * 2.0;
        assert!((u.expanded - c).abs() < 1e-3, "{} {c}", u.expanded);
        assert_eq!(
            u.notes,
            ["the optics as stated: ±(0.2 % of the value + 0.5) µm"]
        );
    }

    #[test]
    fn a_term_per_square_metre_by_hand() {
        // A specification ±(0.5 % of the value + 0.5 + 0.15·M²) µm over 0 … 400 mm for a
        // straightness of 5 µm: 0.025 + 0.5 + 0.15 · 0.16 = 0.549 µm; u = 0.549/√3 =
        // 0.31697 µm. With the scatter's √2·0.3/√3 = 0.24495 µm: U = 2·√(0.24495² +
        // 0.31697²) = 2·√0.160467 = 0.8012.
        let targets: Vec<f64> = (0..=4).map(|k| k as f64 * 100.0).collect();
        let mut data = test(&targets, 3, |x| if x == 200.0 { 5.0 } else { 0.0 }, 0.0);
        data = data.map_deviations(|r| r.deviation + 0.3 * (r.run as f64 - 1.0));
        let optics = Accuracy {
            fraction: 0.005,
            fixed: 0.5,
            per_m: 0.0,
            per_m2: 0.15,
        };
        assert!((optics.bound(5.0, 400.0) - 0.549).abs() < 1e-12);
        assert!((optics.bound(-5.0, 2000.0) - (0.025 + 0.5 + 0.6)).abs() < 1e-12);
        let u = straightness(&data, ReferenceLine::EndPoint, None, Some(optics.into())).unwrap();
        let line = u.budget.line("optics").unwrap();
        assert!((line.value - 0.549).abs() < 1e-12, "{}", line.value);
        assert!((line.u - 0.549 / 3f64.sqrt()).abs() < 1e-12);
        assert_eq!(format!("{:.4}", u.expanded), "0.8012");
        assert!(u.notes[0].contains("0.15·M²"), "{:?}", u.notes);
    }

    #[test]
    fn one_run_says_why_its_u_is_short() {
        let targets = [0.0, 500.0, 1000.0];
        let data = test(&targets, 1, |x| 0.01 * x, 0.0);
        let u = angular(&data, None).unwrap();
        assert_eq!(u.expanded, 0.0);
        assert!(u.notes[0].contains("one run"), "{:?}", u.notes);
    }

    #[test]
    fn a_slope_by_hand_and_the_hp_squareness_preset() {
        // s = 0.3 in both directions, n = 3: the bidirectional mean's u = √2·0.1732/2 =
        // 0.12247 µm; least squares over 0, 250, …, 1000 mm (Σ(P − P̄)² = 625 000 mm²):
        // u(m) = 0.12247/790.57 µm/mm = 1.549·10⁻⁴ µm/mm → 0.03195″.
        let targets: Vec<f64> = (0..=4).map(|k| k as f64 * 250.0).collect();
        let mut data = test(&targets, 3, |x| 0.01 * x, 0.0);
        data = data.map_deviations(|r| r.deviation + 0.3 * (r.run as f64 - 1.0));
        let u = slope_u_arcsec(&data, ReferenceLine::LeastSquares).unwrap();
        assert_eq!(format!("{u:.5}"), "0.03195");
        // HP 5528A short range over 1 m for θ = −5.2″: 0.5 + 0.1 + 0.052 = 0.652″.
        let s = squareness(
            &data,
            &data,
            ReferenceLine::LeastSquares,
            -5.2,
            Some(0.1),
            Some(Accuracy::HP_5528A_SQUARENESS_SHORT.into()),
        );
        let optics = s.budget.line("optics").unwrap();
        assert!((optics.value - 0.652).abs() < 1e-12);
        assert_eq!(s.budget.lines.len(), 4);
        // The long-range optics, named: 2.5 % of 5.2 = 0.13, 0.5, 0.01: 0.64″, and the note
        // names the preset and its source.
        let preset = super::super::optics::Preset::find("hp5528a-squareness-long").unwrap();
        let s = squareness(
            &data,
            &data,
            ReferenceLine::LeastSquares,
            -5.2,
            Some(0.1),
            Some(preset.into()),
        );
        let optics = s.budget.line("optics").unwrap();
        assert!((optics.value - 0.64).abs() < 1e-12, "{}", optics.value);
        assert!(
            s.notes
                .iter()
                .any(|n| n.contains("long-range") && n.contains("section 13"))
        );
    }
}
