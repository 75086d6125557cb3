//! What another tool computed and printed in the file it wrote, kept as printed so that
//! [`crate::crosscheck`] can set it beside axcheck's own evaluation of the same readings.

use crate::param_key::ParamKey;
use serde::Serialize;

/// The tools whose results axcheck reads, for the formulas each is known to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    /// The ecmc ISO 230 app (2026).
    EcmcApp,
    /// The ecmc ISO 230-2 scripts that wrote the motion system test reports (2021).
    EcmcScripts,
}

/// Another tool's results in a measurement file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ToolResults {
    /// The tool, as axcheck names it (`ecmc ISO 230 app`).
    pub tool: String,
    pub family: Family,
    /// The state the tool gave its results (`Complete`, `Demo` …), when it gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub state: Option<String>,
    /// Its results, in the file's order.
    pub values: Vec<Reported>,
    /// What the tool says of its own formulas, verbatim (its notes).
    pub formulas: Vec<String>,
    /// Half a unit of the last digit the file prints its readings with, µm (or arcsec):
    /// axcheck evaluates the readings as printed, the tool as it held them.
    pub readings_rounding: f64,
}

/// One printed result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Reported {
    /// The tool's label (`Bidirectional repeatability`).
    pub label: String,
    pub quantity: ReportedQuantity,
    /// As printed (`0.00362`).
    pub text: String,
    pub value: f64,
    /// Digits printed after the decimal point: the value is rounded to a unit of the last.
    pub decimals: u32,
    /// The tool's unit (`mm`).
    pub unit: &'static str,
    /// µm (or arcsec) per unit of the tool.
    pub to_um: f64,
    /// Line in the file.
    pub line: usize,
}

impl Reported {
    /// The value in µm (or arcsec).
    pub(crate) fn value_um(&self) -> f64 {
        self.value * self.to_um
    }

    /// Half a unit of the last printed digit (the value's rounding), in µm (or arcsec).
    pub(crate) fn rounding_um(&self) -> f64 {
        0.5 * 10f64.powi(-(self.decimals as i32)) * self.to_um
    }
}

/// The ISO 230-2 quantity a tool's label names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", content = "of", rename_all = "snake_case")]
pub enum ReportedQuantity {
    /// A parameter of the catalogue (`A`, `R`, `B_mean`).
    Parameter(ParamKey),
    /// The larger of two parameters (a tool's "unidirectional repeatability").
    LargerOf(ParamKey, ParamKey),
    /// Not an ISO 230-2 parameter: what it is.
    NotIso(&'static str),
}
