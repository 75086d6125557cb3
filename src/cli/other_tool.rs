//! The console's account of another tool's results beside axcheck's (`eval`).

use super::text::{left, right, width};
use axcheck::crosscheck::OtherTool;
use axcheck::units::fmt_fixed;
use std::fmt::Write;

/// `name`'s printed results, each beside axcheck's ISO 230-2 value: agreeing within its
/// rounding, or differing with the cause (or that none is known).
pub fn render(out: &mut String, tool: &OtherTool) {
    let unit = tool.unit;
    let _ = writeln!(
        out,
        "\nThe {}'s own results in the file, beside axcheck's ISO 230-2 values ({unit})",
        tool.name
    );
    if let Some(state) = &tool.state {
        let _ = writeln!(out, "  its state: {state}");
    }
    let labels: Vec<String> = (tool.parameters.iter())
        .map(|c| format!("{} ({})", c.label, c.parameter))
        .collect();
    let w = labels.iter().map(|l| width(l)).max().unwrap_or(0);
    for (c, label) in tool.parameters.iter().zip(&labels) {
        let verdict = match c.agree {
            true => format!("agree (within {}, the roundings)", fmt_fixed(c.rounding, 3)),
            false => "DIFFER".to_string(),
        };
        let _ = writeln!(
            out,
            "  {}  theirs {}  ours {}  {verdict}",
            left(label, w),
            right(&fmt_fixed(c.theirs, 2), 8),
            right(&fmt_fixed(c.ours, 2), 8),
        );
    }
    for d in &tool.differences {
        let _ = writeln!(out, "  {} ({}): {}", d.label, d.parameter, d.message);
    }
    if !tool.not_compared.is_empty() {
        let items: Vec<String> = (tool.not_compared.iter())
            .map(|n| format!("{} {} ({})", n.label, n.printed, n.what))
            .collect();
        let _ = writeln!(
            out,
            "  not ISO 230-2 parameters, not compared: {}",
            items.join("; ")
        );
    }
}
