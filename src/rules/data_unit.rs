//! `data-unit`: deviations so small that the column's unit is likely wrong.

use super::{Plan, Rule, Severity};
use crate::units::AxisKind;

/// ISO 230-2:1997 2.5: the positional deviation X_ij is the actual minus the target
/// position, reported in µm (arcsec on a rotary axis). A column in the wrong unit, mm
/// written into a µm column (or degrees into arcsec), leaves every deviation a thousand
/// (3600) times too small.
pub const RULE: Rule = Rule {
    id: "data-unit",
    clause: "ISO 230-2 2.5",
    severity: Severity::Warning,
    checks: "every deviation below 0.05 µm (0.01″): values written in mm (degrees) into a µm (arcsec) column?",
    check,
};

fn check(plan: &Plan) -> Option<String> {
    let largest = plan
        .data
        .readings
        .iter()
        .map(|r| r.deviation.abs())
        .fold(0.0, f64::max);
    let (tiny, wrong, right) = match plan.ctx.kind {
        AxisKind::Linear => (0.05, "mm", "µm"),
        AxisKind::Rotary => (0.01, "degrees", "arcsec"),
    };
    (largest > 0.0 && largest < tiny).then(|| {
        format!(
            "every deviation is below {tiny} {right}: were the values written in {wrong} into a {right} column? Check the column's unit (deviation_um / deviation_mm, deviation_arcsec / deviation_deg)"
        )
    })
}
