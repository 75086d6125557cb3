//! The report's view of another tool's results in the measurement file, beside axcheck's
//! ([`crate::crosscheck`]): one row per result, the differences with their causes.

use super::num;
use crate::crosscheck::OtherTool;
use crate::evaluate::{StandardId, catalogue};
use serde::Serialize;

#[derive(Serialize)]
pub(crate) struct OtherToolSection<'a> {
    name: &'a str,
    state: Option<&'a str>,
    unit: &'static str,
    rows: Vec<Row<'a>>,
    /// `R: the tool computes …`, or that no cause is known.
    differences: Vec<String>,
    not_compared: Vec<String>,
    formulas: &'a [String],
}

#[derive(Serialize)]
struct Row<'a> {
    label: &'a str,
    symbol: String,
    printed: &'a str,
    theirs: String,
    ours: String,
    difference: String,
    agree: bool,
}

/// The section of `tool`'s comparison.
pub(crate) fn other_tool_section(tool: &OtherTool) -> OtherToolSection<'_> {
    OtherToolSection {
        name: &tool.name,
        state: tool.state.as_deref(),
        unit: tool.unit,
        rows: (tool.parameters.iter())
            .map(|c| Row {
                label: &c.label,
                symbol: symbol(&c.parameter),
                printed: &c.printed,
                theirs: num(c.theirs),
                ours: num(c.ours),
                difference: num(c.difference),
                agree: c.agree,
            })
            .collect(),
        differences: (tool.differences.iter())
            .map(|d| format!("{} ({}): {}", d.label, symbol(&d.parameter), d.message))
            .collect(),
        not_compared: (tool.not_compared.iter())
            .map(|n| format!("{} {} ({})", n.label, n.printed, n.what))
            .collect(),
        formulas: &tool.formulas,
    }
}

/// A parameter's symbol (`B̄`), or the name as given (`max(R_up, R_down)` as `max(R↑, R↓)`).
fn symbol(parameter: &str) -> String {
    if let Some(def) = catalogue::find(StandardId::Iso230_2, parameter) {
        return def.symbol.to_string();
    }
    parameter.replace("R_up", "R↑").replace("R_down", "R↓")
}
