//! Other tools' results, checked: where a measurement file carries the results the tool
//! that wrote it computed (the ecmc ISO 230 app's Status list), each is set beside
//! axcheck's ISO 230-2 value of the same readings, with the difference and, where they
//! differ beyond the tool's rounding, its cause when it is known (a formula that is not
//! the standard's: [`causes`]). A difference with no known cause is said as such.
//!
//! Agreement: within the two roundings. The tool rounds its result once (half a unit of
//! its last printed digit) from readings it held unrounded; axcheck evaluates the
//! readings as the file prints them, each off by up to h (half a unit of their last
//! digit). Through the standard's formulas (ISO 230-2 2.10–2.23) h moves a mean by up to
//! h, a standard deviation by up to h·√(n/(n − 1)) (s is a norm of the deviations from
//! their mean, divided by √(n − 1)), and each parameter by the sum of what it is made of
//! ([`propagated`]).

pub mod causes;

use crate::evaluate::{Evaluation, ParamKey, StandardId, evaluate};
use crate::measurement::AxisData;
use crate::measurement::reported::{Family, Reported, ReportedQuantity, ToolResults};
use serde::Serialize;

/// The comparison of one file's other-tool results with axcheck's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OtherTool {
    /// The tool (`ecmc ISO 230 app`).
    pub name: String,
    /// The state the tool gave its results, when it gives one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub state: Option<String>,
    /// The unit of `theirs`, `ours` and `difference`: µm (linear axes) or arcsec.
    pub unit: &'static str,
    /// Every result of the tool that names an ISO 230-2 quantity.
    pub parameters: Vec<Compared>,
    /// Those that differ beyond the tool's rounding, with the cause when known.
    pub differences: Vec<Difference>,
    /// The tool's results that are not ISO 230-2 parameters, and what they are.
    pub not_compared: Vec<NotCompared>,
    /// What the tool says of its formulas, verbatim.
    pub formulas: Vec<String>,
}

/// One result of the tool beside axcheck's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Compared {
    /// The tool's label.
    pub label: String,
    /// axcheck's parameter (`R`, or `max(R_up, R_down)`).
    pub parameter: String,
    /// The tool's value as printed, in its unit.
    pub printed: String,
    pub theirs: f64,
    pub ours: f64,
    /// theirs − ours.
    pub difference: f64,
    /// The largest difference the two roundings explain: half a unit of the tool's last
    /// digit and what the readings' rounding does to the parameter.
    pub rounding: f64,
    /// |difference| ≤ rounding.
    pub agree: bool,
}

/// A result that differs beyond rounding.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Difference {
    pub parameter: String,
    pub label: String,
    pub theirs: f64,
    pub ours: f64,
    /// Why, when the tool's value is what a known other formula gives.
    pub cause: Option<String>,
    /// The cause in words, or that none is known.
    pub message: String,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NotCompared {
    pub label: String,
    pub printed: String,
    pub what: &'static str,
}

/// Compares `tool`'s results with the ISO 230-2 evaluation of `data` (the standard the
/// tools that print these results follow). A result whose parameter the data cannot give
/// (repeatability with n = 1) is left out.
pub fn compare(tool: &ToolResults, data: &AxisData) -> OtherTool {
    let e = evaluate(data, StandardId::Iso230_2);
    let mut out = OtherTool {
        name: tool.tool.clone(),
        state: tool.state.clone(),
        unit: data.kind.deviation_symbol(),
        parameters: Vec::new(),
        differences: Vec::new(),
        not_compared: Vec::new(),
        formulas: tool.formulas.clone(),
    };
    for r in &tool.values {
        match r.quantity {
            ReportedQuantity::NotIso(what) => out.not_compared.push(NotCompared {
                label: r.label.clone(),
                printed: format!("{} {}", r.text, r.unit).trim_end().to_string(),
                what,
            }),
            quantity => {
                let Some((parameter, ours)) = ours(&e, quantity) else {
                    continue;
                };
                let rounding = r.rounding_um() + propagated(quantity, tool.readings_rounding, e.n);
                let compared = compared(r, parameter, ours, rounding);
                if !compared.agree {
                    out.differences
                        .push(difference(r, &compared, tool.family, &e));
                }
                out.parameters.push(compared);
            }
        }
    }
    out
}

/// The most a quantity moves when each of n readings moves by up to `h`: a mean by h, a
/// standard deviation by h·√(n/(n − 1)), a parameter by the sum of its parts' bounds.
pub(crate) fn propagated(quantity: ReportedQuantity, h: f64, n: usize) -> f64 {
    let n = n as f64;
    let s = match n > 1.0 {
        true => h * (n / (n - 1.0)).sqrt(),
        false => 0.0,
    };
    let key = match quantity {
        ReportedQuantity::Parameter(key) => key,
        ReportedQuantity::LargerOf(..) => ParamKey::RUp,
        ReportedQuantity::NotIso(_) => return 0.0,
    };
    use ParamKey::*;
    match key {
        // Ranges and differences of two means.
        E | EUp | EDown | M | B | BMean => 2.0 * h,
        // 4s at one target.
        RUp | RDown => 4.0 * s,
        // 2s↑ + 2s↓ + |B_i|.
        R => 4.0 * s + 2.0 * h,
        // (x̄ + 2s) at one target − (x̄ − 2s) at another.
        A | AUp | ADown => 2.0 * h + 4.0 * s,
        _ => 2.0 * h,
    }
}

/// axcheck's value of a quantity, and its name.
fn ours(e: &Evaluation, quantity: ReportedQuantity) -> Option<(String, f64)> {
    match quantity {
        ReportedQuantity::Parameter(key) => Some((key.to_string(), e.value(key)?)),
        ReportedQuantity::LargerOf(a, b) => {
            let name = format!("max({a}, {b})");
            Some((name, e.value(a)?.max(e.value(b)?)))
        }
        ReportedQuantity::NotIso(_) => None,
    }
}

fn compared(r: &Reported, parameter: String, ours: f64, rounding: f64) -> Compared {
    let theirs = r.value_um();
    let difference = theirs - ours;
    Compared {
        label: r.label.clone(),
        parameter,
        printed: format!("{} {}", r.text, r.unit),
        theirs,
        ours,
        difference,
        rounding,
        // A hair over still agrees: the digits were printed from binary doubles.
        agree: difference.abs() <= rounding * (1.0 + 1e-6),
    }
}

fn difference(r: &Reported, c: &Compared, family: Family, e: &Evaluation) -> Difference {
    let printed = causes::Printed {
        family,
        quantity: r.quantity,
        theirs: c.theirs,
        rounding: c.rounding,
    };
    let cause = causes::explain(&printed, e);
    let message = match &cause {
        Some(cause) => cause.clone(),
        None => format!(
            "differs beyond the tool's rounding ({} against {}) and no known formula of the tool gives its value: no known cause",
            fmt(c.theirs),
            fmt(c.ours)
        ),
    };
    Difference {
        parameter: c.parameter.clone(),
        label: r.label.clone(),
        theirs: c.theirs,
        ours: c.ours,
        cause,
        message,
    }
}

fn fmt(x: f64) -> String {
    crate::units::fmt_fixed(x, 2)
}
