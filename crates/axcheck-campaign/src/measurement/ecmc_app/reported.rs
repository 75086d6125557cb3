//! The results the ecmc ISO 230 app printed in its report's `## Status` list, as printed,
//! each tied to the ISO 230-2 quantity its label names (the app's help text maps them:
//! "BiDir Accuracy = A", "Uni Repeat = max(R^+, R^-)", …). [`crate::crosscheck`] sets
//! them beside axcheck's.

use crate::measurement::reported::{Family, Reported, ReportedQuantity, ToolResults};
use crate::param_key::ParamKey;

/// Status labels, the quantity each names, in the report's order.
const LABELS: &[(&str, ReportedQuantity)] = &[
    (
        "Bidirectional accuracy",
        ReportedQuantity::Parameter(ParamKey::A),
    ),
    (
        "Bidirectional systematic deviation",
        ReportedQuantity::Parameter(ParamKey::E),
    ),
    (
        "Range of mean bidirectional positional deviation",
        ReportedQuantity::Parameter(ParamKey::M),
    ),
    (
        "Bidirectional repeatability",
        ReportedQuantity::Parameter(ParamKey::R),
    ),
    (
        "Unidirectional repeatability",
        ReportedQuantity::LargerOf(ParamKey::RUp, ParamKey::RDown),
    ),
    (
        "Mean reversal value",
        ReportedQuantity::Parameter(ParamKey::BMean),
    ),
    (
        "Maximum reversal value",
        ReportedQuantity::Parameter(ParamKey::B),
    ),
    (
        "Mean bias",
        ReportedQuantity::NotIso("the mean of every deviation"),
    ),
    (
        "Linearity residual",
        ReportedQuantity::NotIso("the largest residual of a straight line fitted to the points"),
    ),
    (
        "Linear fit slope",
        ReportedQuantity::NotIso("the slope of that straight line"),
    ),
    (
        "Linear fit intercept",
        ReportedQuantity::NotIso("the intercept of that straight line"),
    ),
];

/// One `- Label: \`value\`` item of the Status list (line `line`), or `None` when its
/// label is not a result (`State`) or its value is not a number (an empty result).
pub(crate) fn status_item(label: &str, value: &str, line: usize) -> Option<Reported> {
    let (_, quantity) = LABELS.iter().find(|(l, _)| *l == label)?;
    let text = value.trim();
    let number: f64 = text.parse().ok().filter(|x: &f64| x.is_finite())?;
    let decimals = text.split_once('.').map_or(0, |(_, d)| d.len() as u32);
    // The fit's slope is mm per mm: a number.
    let unit = if label == "Linear fit slope" {
        ""
    } else {
        "mm"
    };
    Some(Reported {
        label: label.to_string(),
        quantity: *quantity,
        text: text.to_string(),
        value: number,
        decimals,
        unit,
        to_um: super::UM_PER_UNIT,
        line,
    })
}

/// The app's results in one report, whose readings are printed with `decimals` digits
/// after the point.
pub(crate) fn results(
    values: Vec<Reported>,
    state: Option<String>,
    formulas: Vec<String>,
    decimals: u32,
) -> Option<ToolResults> {
    if values.is_empty() {
        return None;
    }
    Some(ToolResults {
        tool: super::APP.to_string(),
        family: Family::EcmcApp,
        state,
        values,
        formulas,
        readings_rounding: 0.5 * 10f64.powi(-(decimals as i32)) * super::UM_PER_UNIT,
    })
}
