//! Test-plan rules: does the measured test follow the standard's plan?
//!
//! Each rule has an id, the clause it enforces, a severity and a message that says what to
//! change. Rules count what was measured (targets and runs in the data), not what the
//! campaign claims. Which travel rules apply follows the measured travel: a linear test
//! over ≤ 2000 mm is a clause 4.3.2 test (also the working-range test of a longer axis,
//! 4.3.3), a longer one a clause 4.3.3 test; rotary tests over ≤ 360° follow 4.3.4,
//! longer ones 4.3.5.

use crate::evaluate::StandardId;
use crate::measurement::AxisData;
use crate::units::Travel;
use crate::units::{AxisKind, Direction, fmt_position};
use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// The test does not follow the standard: the verdict is `noncompliant`.
    Error,
    /// Worth fixing; the result stands.
    Warning,
}

/// A broken rule.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Finding {
    pub id: &'static str,
    pub clause: &'static str,
    pub severity: Severity,
    pub message: String,
}

/// What the campaign says about the axis, besides its data.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlanContext {
    pub kind: AxisKind,
    pub standard: StandardId,
    pub axis_travel: Option<Travel>,
    pub measurement_travel: Option<[f64; 2]>,
    /// Lead-screw or encoder pitch, mm or deg.
    pub pitch: Option<f64>,
}

const EPS: f64 = 1e-9;

/// Linear tests over at most this measured travel follow clause 4.3.2.
pub const LINEAR_SHORT_MM: f64 = 2000.0;
/// Rotary tests over at most this measured travel follow clause 4.3.4.
pub const ROTARY_SHORT_DEG: f64 = 360.0;

/// Checks the plan of one test.
pub fn check(ctx: &PlanContext, data: &AxisData) -> Vec<Finding> {
    let mut out = Vec::new();
    let m = data.target_count();
    let n = data.runs();
    let (first, last) = data.measurement_travel();
    let travel = last - first;
    let unit = ctx.kind.position_unit();
    // `10 mm` or `40°`.
    let at = |x: f64| match ctx.kind {
        AxisKind::Linear => format!("{} mm", fmt_position(x)),
        AxisKind::Rotary => format!("{}°", fmt_position(x)),
    };
    let gost = ctx.standard == StandardId::Gost27843;
    let mut push = |id, clause, severity, message: String| {
        out.push(Finding {
            id,
            clause,
            severity,
            message,
        })
    };
    use Severity::{Error, Warning};

    match (ctx.kind, gost) {
        (AxisKind::Linear, false) if travel <= LINEAR_SHORT_MM + EPS => {
            let need = ((5.0 * travel / 1000.0) - EPS).ceil().max(5.0) as usize;
            if m < need {
                push(
                    "iso-4.3.2-targets",
                    "ISO 230-2 4.3.2",
                    Error,
                    format!(
                        "{m} targets over {} mm of measurement travel; at least 5 per metre and 5 in all are needed ({need}): add {} target(s)",
                        fmt_position(travel),
                        need - m
                    ),
                );
            }
            if n < 5 {
                push(
                    "iso-4.3.2-runs",
                    "ISO 230-2 4.3.2",
                    Error,
                    format!(
                        "n = {n} approaches per direction; a linear axis up to 2000 mm needs 5 at every target"
                    ),
                );
            }
        }
        (AxisKind::Linear, false) => {
            let spacing = travel / (m.max(2) - 1) as f64;
            if spacing > 250.0 + EPS {
                let need = (travel / 250.0 - EPS).ceil() as usize + 1;
                push(
                    "iso-4.3.3-spacing",
                    "ISO 230-2 4.3.3",
                    Error,
                    format!(
                        "mean target spacing {} mm over {} mm; an axis over 2000 mm needs a mean spacing of at most 250 mm: use at least {need} targets",
                        fmt_position((spacing * 10.0).round() / 10.0),
                        fmt_position(travel)
                    ),
                );
            }
            if (2..5).contains(&n) {
                push(
                    "iso-4.3.3-runs",
                    "ISO 230-2 4.3.3",
                    Error,
                    format!(
                        "n = {n}: a test over more than 2000 mm uses n = 1 (clause 4.3.3) or n = 5 (clause 4.3.2)"
                    ),
                );
            }
        }
        (AxisKind::Rotary, false) if travel <= ROTARY_SHORT_DEG + EPS => {
            let need = if travel <= 90.0 + EPS {
                3
            } else if travel <= 180.0 + EPS {
                5
            } else {
                8
            };
            if m < need {
                push(
                    "iso-4.3.4-targets",
                    "ISO 230-2 4.3.4, Table 1",
                    Error,
                    format!(
                        "{m} targets over {}°; Table 1 asks for at least {need}: add {} target(s)",
                        fmt_position(travel),
                        need - m
                    ),
                );
            }
            cardinal(data, &mut push, "iso-4.3.4-cardinal", "ISO 230-2 4.3.4");
            if n < 5 {
                push(
                    "iso-4.3.4-runs",
                    "ISO 230-2 4.3.4, 5.1",
                    Error,
                    format!(
                        "n = {n} approaches per direction; a rotary axis up to 360° needs 5 at every target"
                    ),
                );
            }
        }
        (AxisKind::Rotary, false) => {
            let widest = data
                .targets
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(0.0, f64::max);
            if widest > 45.0 + EPS {
                push(
                    "iso-4.3.5-spacing",
                    "ISO 230-2 4.3.5",
                    Error,
                    format!(
                        "targets up to {}° apart; a rotary test over more than 360° needs a spacing of at most 45°",
                        fmt_position((widest * 1000.0).round() / 1000.0)
                    ),
                );
            }
            if (2..5).contains(&n) {
                push(
                    "iso-4.3.5-runs",
                    "ISO 230-2 4.3.5",
                    Error,
                    format!(
                        "n = {n}: a test over more than 360° uses n = 1 (clause 4.3.5) or n = 5 (clause 4.3.4)"
                    ),
                );
            }
            if travel > 1800.0 + EPS {
                push(
                    "iso-4.3.5-range",
                    "ISO 230-2 4.3.5",
                    Warning,
                    format!(
                        "measurement travel {}° exceeds the 1800° (5 revolutions) the standard covers; test the normal working range as well",
                        fmt_position(travel)
                    ),
                );
            }
        }
        (AxisKind::Linear, true) => {
            // GOST 27843 clause 2.7: at least 11 targets on any two metres.
            let windows: Vec<usize> = if travel <= 2000.0 + EPS {
                vec![m]
            } else {
                data.targets
                    .iter()
                    .filter(|&&t| t + 2000.0 <= last + EPS)
                    .map(|&t| {
                        data.targets
                            .iter()
                            .filter(|&&x| x >= t - EPS && x <= t + 2000.0 + EPS)
                            .count()
                    })
                    .collect()
            };
            if let Some(&fewest) = windows.iter().min()
                && fewest < 11
            {
                push(
                    "gost-2.7-targets",
                    "GOST 27843 2.7",
                    Error,
                    format!(
                        "{fewest} targets on a 2 m stretch; GOST 27843 asks for at least 11 on any two metres: add {}",
                        11 - fewest
                    ),
                );
            }
        }
        (AxisKind::Rotary, true) => {
            cardinal(data, &mut push, "gost-2.8-cardinal", "GOST 27843 2.8")
        }
    }
    if gost && n < 5 {
        push(
            "gost-2.10-runs",
            "GOST 27843 2.10",
            Error,
            format!(
                "n = {n} measurements per target and direction; GOST 27843 asks for at least 5"
            ),
        );
    }

    // Clause 2.2: the first and last targets must be approachable from both sides.
    if let Some([a, b]) = ctx.measurement_travel
        && (first < a - EPS || last > b + EPS)
    {
        push(
            "iso-2.2-measurement-travel",
            "ISO 230-2 2.2",
            Error,
            format!(
                "targets {}…{} {unit} lie outside the declared measurement travel [{}, {}] {unit}; correct measurement_travel or the data",
                fmt_position(first),
                fmt_position(last),
                fmt_position(a),
                fmt_position(b)
            ),
        );
    }
    let full_turn =
        ctx.kind == AxisKind::Rotary && ctx.axis_travel.is_some_and(|t| t.length() >= 360.0 - EPS);
    match ctx.axis_travel {
        Some(Travel::Length(t)) if !full_turn && travel >= t - EPS => push(
            "iso-2.2-reversal-room",
            "ISO 230-2 2.2",
            Error,
            format!(
                "the measurement travel ({} {unit}) uses the whole axis travel ({} {unit}): the first and last targets cannot be approached from both sides; move them inwards",
                fmt_position(travel),
                fmt_position(t)
            ),
        ),
        Some(Travel::Range([a, b])) if !full_turn && (first <= a + EPS || last >= b - EPS) => push(
            "iso-2.2-reversal-room",
            "ISO 230-2 2.2",
            Error,
            format!(
                "targets {}…{} {unit} reach the ends of the axis travel [{}, {}] {unit}: the first and last targets cannot be approached from both sides; move them inwards",
                fmt_position(first),
                fmt_position(last),
                fmt_position(a),
                fmt_position(b)
            ),
        ),
        _ => {}
    }

    // Clause 4.2: varying spacing, so periodic errors are sampled.
    let gaps: Vec<f64> = data.targets.windows(2).map(|w| w[1] - w[0]).collect();
    if gaps.len() >= 2 {
        let mean_gap = gaps.iter().sum::<f64>() / gaps.len() as f64;
        if gaps
            .iter()
            .all(|g| (g - mean_gap).abs() <= 1e-3 * mean_gap.abs().max(EPS))
        {
            push(
                "iso-4.2-uniform-spacing",
                "ISO 230-2 4.2",
                Warning,
                format!(
                    "all targets are {} apart: periodic errors (lead screw, scale pitch) may alias; vary the spacing with P_i = (i − 1)P + r",
                    at((mean_gap * 1000.0).round() / 1000.0)
                ),
            );
        }
        if let Some(pitch) = ctx.pitch {
            let multiple = |g: f64| {
                let k = g / pitch;
                (k - k.round()).abs() * pitch <= 0.01 * pitch
            };
            if gaps.iter().all(|&g| multiple(g)) {
                push(
                    "iso-4.2-pitch-alias",
                    "ISO 230-2 4.2",
                    Warning,
                    format!(
                        "every target spacing is a multiple of the {} pitch: the periodic error is sampled at one phase and hidden; offset the targets by varying amounts r",
                        at(pitch)
                    ),
                );
            }
        }
    }

    if let Some(f) = thermal_trend(data) {
        push("iso-3.3-thermal", "ISO 230-2 3.3", Warning, f);
    }

    // A column in the wrong unit: mm written into a µm column (or degrees into arcsec)
    // leaves every deviation a thousand (3600) times too small.
    let largest = data
        .readings
        .iter()
        .map(|r| r.deviation.abs())
        .fold(0.0, f64::max);
    let (tiny, wrong, right) = match ctx.kind {
        AxisKind::Linear => (0.05, "mm", "µm"),
        AxisKind::Rotary => (0.01, "degrees", "arcsec"),
    };
    if largest > 0.0 && largest < tiny {
        push(
            "data-unit",
            "ISO 230-2 2.5",
            Warning,
            format!(
                "every deviation is below {tiny} {right}: were the values written in {wrong} into a {right} column? Check the column's unit (deviation_um / deviation_mm, deviation_arcsec / deviation_deg)"
            ),
        );
    }
    out
}

/// ISO 4.3.4 / GOST 2.8: 0°, 90°, 180° and 270° must be targets where inside the travel.
fn cardinal(
    data: &AxisData,
    push: &mut impl FnMut(&'static str, &'static str, Severity, String),
    id: &'static str,
    clause: &'static str,
) {
    let (first, last) = data.measurement_travel();
    let mut missing = Vec::new();
    for base in [0.0, 90.0, 180.0, 270.0] {
        // Every turn of the travel that holds this angle.
        let mut k = ((first - base) / 360.0).ceil();
        while base + 360.0 * k <= last + EPS {
            let angle = base + 360.0 * k;
            if !data.targets.iter().any(|t| (t - angle).abs() <= 1e-6) {
                missing.push(fmt_position(angle));
            }
            k += 1.0;
        }
    }
    if !missing.is_empty() {
        push(
            id,
            clause,
            Severity::Error,
            format!(
                "the principal positions {}° are not targets; include 0°, 90°, 180° and 270° where inside the travel",
                missing.join("°, ")
            ),
        );
    }
}

/// Clause 3.3: deviations at the targets forming an ordered sequence over the runs show a
/// machine not yet thermally stable. Each (target, direction) cell whose n ≥ 3 readings
/// are strictly monotonic in run order counts; under independent scatter a cell is
/// increasing with probability 1/n!. The rule fires when the cells increasing (or
/// decreasing) are too many for chance: a binomial tail below 0.001.
fn thermal_trend(data: &AxisData) -> Option<String> {
    let n = data.runs();
    if n < 3 {
        return None;
    }
    let cells = data.target_count() * 2;
    let (mut up, mut down) = (0usize, 0usize);
    for i in 0..data.target_count() {
        for d in Direction::BOTH {
            let x = data.deviations(i, d);
            if x.windows(2).all(|w| w[1] > w[0]) {
                up += 1;
            } else if x.windows(2).all(|w| w[1] < w[0]) {
                down += 1;
            }
        }
    }
    let p = 1.0 / (1..=n).map(|k| k as f64).product::<f64>();
    let (count, word) = if up >= down {
        (up, "increase")
    } else {
        (down, "decrease")
    };
    if count >= 2 && binomial_tail(cells, count, p) < 1e-3 {
        Some(format!(
            "at {count} of {cells} targets and directions the deviations {word} run after run: the machine was not thermally stable; warm it up before the test"
        ))
    } else {
        None
    }
}

/// P(X ≥ k) for X ~ Binomial(n, p).
fn binomial_tail(n: usize, k: usize, p: f64) -> f64 {
    let mut term = (1.0 - p).powi(n as i32); // P(X = 0)
    let mut below = 0.0;
    for j in 0..k {
        below += term;
        term *= (n - j) as f64 / (j + 1) as f64 * p / (1.0 - p);
    }
    (1.0 - below).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomial_tail_values() {
        assert!((binomial_tail(10, 0, 0.3) - 1.0).abs() < 1e-12);
        assert!((binomial_tail(2, 2, 0.5) - 0.25).abs() < 1e-12);
        assert!((binomial_tail(3, 1, 0.5) - 0.875).abs() < 1e-12);
    }
}
