//! `data-unit`: deviations so small that the column's unit is likely wrong, or all zero.

use super::{Plan, Rule, Severity};
use crate::units::AxisKind;

/// ISO 230-2:1997 2.5: the positional deviation X_ij is the actual minus the target
/// position, reported in µm (arcsec on a rotary axis). A column in the wrong unit, mm
/// written into a µm column (or degrees into arcsec), leaves every deviation a thousand
/// (3600) times too small. Every deviation exactly 0 is no measurement at all (a laser
/// reads noise at 0.01 µm): an empty column filled with zeros, or the target written
/// into the actual position's column; such a test would otherwise pass every limit.
pub(crate) const RULE: Rule = Rule {
    id: "data-unit",
    clause: "ISO 230-2 2.5",
    severity: Severity::Warning,
    checks: "every deviation below 0.05 µm (0.01″): values written in mm (degrees) into a µm (arcsec) column? Every deviation exactly 0: no measurement?",
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
    if largest == 0.0 && !plan.data.readings.is_empty() {
        return Some(format!(
            "every deviation is exactly 0 {right}: no instrument reads that; the deviation column is empty, zero-filled or a copy of the targets. Check the file's deviation (or actual position) column"
        ));
    }
    (largest > 0.0 && largest < tiny).then(|| {
        format!(
            "every deviation is below {tiny} {right}: were the values written in {wrong} into a {right} column? Check the column's unit (deviation_um / deviation_mm, deviation_arcsec / deviation_deg)"
        )
    })
}
