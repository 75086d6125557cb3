//! The JSON of the commands that take one measurement file (`eval --json`,
//! `diagnose --json`, `verify --json`), composed once for the command line and the Python
//! package so that both print the same keys in the same order.

use crate::crosscheck::OtherTool;
use crate::evaluate::json::EvaluationJson;
use crate::measurement::Recognised;
use crate::nde::NdeCorrection;
use crate::uncertainty::Uncertainty;
use serde::Serialize;

/// What `eval` applied to the readings and what it did not (`applied`): a result printed
/// without a campaign's corrections must say so.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Applied {
    /// The correction to 20 °C (ISO 230-2 3.1), when asked.
    pub nde: Option<NdeCorrection>,
    /// Always empty: one file's evaluation applies no tolerance and no decision rule.
    pub tolerance: Option<()>,
    pub decision_rule: Option<()>,
}

/// `eval --json`: the evaluation, what was applied, the file's name, what it was read as
/// (`recognised`), the comparison with the results of the tool that wrote it
/// (`other_tool`, when it printed any) and, from Python, U per parameter (`uncertainty`).
#[derive(Serialize)]
pub struct EvalJson<'a> {
    #[serde(flatten)]
    pub evaluation: EvaluationJson<'a>,
    pub applied: &'a Applied,
    pub file: &'a str,
    pub recognised: &'a Recognised,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_tool: Option<&'a OtherTool>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub uncertainty: Option<&'a Uncertainty>,
}

/// `value`'s JSON with the measurement's `file` after it, as `diagnose --json` and
/// `verify --json` print it.
#[derive(Serialize)]
pub struct WithFile<'a, T> {
    #[serde(flatten)]
    pub value: T,
    pub file: &'a str,
}
