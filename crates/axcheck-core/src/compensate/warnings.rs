//! When not to compensate: what the diagnosis finds that a static table cannot fix, or
//! that the table would bake in. A table corrects the mean deviation at each position; it
//! holds only if that mean is a property of the position (Hemingray et al. 1971, §4).

use super::Table;
use crate::diagnose::Diagnosis;
use crate::diagnose::effects::Effect;
use crate::diagnose::effects::periodic::Periodic;
use crate::diagnose::effects::reversal_variation::ReversalVariation;
use crate::measurement::AxisData;
use crate::units::fmt_fixed;
use serde::Serialize;

/// A reason the table may not achieve its prediction on the machine, or cannot be loaded
/// as written.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Warning {
    /// Stable key: `time_effect`, `aliased_periodic`, `single_run`, `outliers`,
    /// `reversal_variation` (a reversal that one backlash value cannot follow),
    /// `axis_placeholder` (the file names no axis: what to replace), and those of the
    /// active state ([`super::active`]).
    pub key: &'static str,
    pub message: String,
}

/// The warnings for a table built from `data`, given its diagnosis.
pub fn warnings(
    data: &AxisData,
    diagnosis: &Diagnosis,
    table: &Table,
    pitch: Option<f64>,
) -> Vec<Warning> {
    let mut out = Vec::new();
    out.extend(time_effects(diagnosis));
    out.extend(reversal_variation(diagnosis, table));
    out.extend(aliased_periodic(diagnosis, table).or_else(|| aliased_pitch(pitch, table)));
    if data.runs() < 2 {
        out.push(Warning {
            key: "single_run",
            message: "one run per direction (n = 1): the table follows the scatter of a single approach, and no repeatability says how much of it will recur (ISO 230-2 4.3.2: five approaches per direction); repeat the test before compensating".into(),
        });
    }
    let outliers = diagnosis.of(Effect::Outlier).count();
    if outliers > 0 {
        out.push(Warning {
            key: "outliers",
            message: format!(
                "outlying readings in the data used ({outliers}): the table follows them at their targets; re-measure or remove them before compensating"
            ),
        });
    }
    out
}

/// A reversal value that changes along the axis, where the table has one correction per
/// position for both directions (the controller's single backlash value takes the
/// reversal): that value removes the mean reversal and leaves half the range of the Bi on
/// either side (Hemingray et al. 1971, §5.2: lost motion measured at every position).
fn reversal_variation(diagnosis: &Diagnosis, table: &Table) -> Option<Warning> {
    let r = diagnosis.estimates::<ReversalVariation>().next()?;
    let gaps: Vec<f64> = table
        .up
        .iter()
        .zip(&table.down)
        .map(|(u, d)| u - d)
        .collect();
    let spread = gaps.iter().fold(f64::NEG_INFINITY, |a, &g| a.max(g))
        - gaps.iter().fold(f64::INFINITY, |a, &g| a.min(g));
    if spread > 1e-9 {
        return None;
    }
    let symbol = table.kind.deviation_symbol();
    let f = |v: f64| fmt_fixed(v, 2);
    Some(Warning {
        key: "reversal_variation",
        message: format!(
            "the reversal value changes along the axis (Bi range {} {symbol}): one backlash value for the axis removes the mean reversal and leaves up to ±{} {symbol}, half that range, on either side (Hemingray et al. 1971, §5.2); compensate per position and direction where the control has direction-dependent tables, or repair the cause where the reversal is largest",
            f(r.range),
            f(r.range / 2.0)
        ),
    })
}

/// Drift, warm-up and thermal growth change the deviations with time: a table records
/// them at the moment of the test (ISO 230-2 3.3: the machine at thermal equilibrium).
fn time_effects(diagnosis: &Diagnosis) -> Option<Warning> {
    let found: Vec<String> = [Effect::Drift, Effect::WarmUp, Effect::ThermalGrowth]
        .into_iter()
        .filter(|e| diagnosis.has(*e))
        .map(|e| e.name().replace('_', " "))
        .collect();
    if found.is_empty() {
        return None;
    }
    Some(Warning {
        key: "time_effect",
        message: format!(
            "{} during the test: the deviations changed with time, and a static table fixes them as they were at one moment (ISO 230-2 3.3; Hemingray et al. 1971, §4); bring the machine to thermal equilibrium and measure again, or compensate the time effect separately",
            found.join(", ")
        ),
    })
}

/// A periodic error shorter than four table intervals: linear interpolation between points
/// cannot follow it, and from a coarser table it aliases into a slower error that is not
/// on the machine.
fn aliased_periodic(diagnosis: &Diagnosis, table: &Table) -> Option<Warning> {
    let spacing = widest_spacing(table);
    let p = diagnosis
        .estimates::<Periodic>()
        .find(|p| p.period < 4.0 * spacing)?;
    let unit = table.kind.position_unit();
    Some(Warning {
        key: "aliased_periodic",
        message: format!(
            "periodic error of period {} {unit} (amplitude {} {}): the table's points up to {} {unit} apart cannot follow it (it needs at most a quarter period, {} {unit}) and interpolating it aliases; correct it with a finer --interval if the plan resolves it, or leave it to the scatter",
            fmt_fixed(p.period, 3),
            fmt_fixed(p.amplitude, 2),
            table.kind.deviation_symbol(),
            fmt_fixed(spacing, 3),
            fmt_fixed(p.period / 4.0, 3)
        ),
    })
}

/// The widest interval between the table's points.
fn widest_spacing(table: &Table) -> f64 {
    table
        .positions
        .windows(2)
        .map(|w| w[1] - w[0])
        .fold(0.0, f64::max)
}

/// A declared pitch the table's points cannot follow: whatever periodic error the screw or
/// scale has at that pitch, the readings sampled it at the targets and the table carries
/// those samples between them (Hemingray et al. 1971, §4).
fn aliased_pitch(pitch: Option<f64>, table: &Table) -> Option<Warning> {
    let pitch = pitch.filter(|p| *p > 0.0)?;
    let spacing = widest_spacing(table);
    if pitch >= 4.0 * spacing {
        return None;
    }
    let unit = table.kind.position_unit();
    Some(Warning {
        key: "aliased_periodic",
        message: format!(
            "the declared pitch {} {unit} is shorter than four table intervals ({} {unit}): a periodic error of that pitch is sampled at the points and interpolated between them, so the table would alias it; measure the pitch separately (a short test over a few pitches) before compensating it",
            fmt_fixed(pitch, 3),
            fmt_fixed(4.0 * spacing, 3)
        ),
    })
}
