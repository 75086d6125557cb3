//! axcheck's own cross table: a CSV any controller's engineer can take over by hand.
//!
//! ```text
//! # axcheck cross-axis table: output Y1 as a function of input X1
//! # correction_um is added to the output axis's commanded position
//! input_mm,correction_um
//! 0,0.000
//! 100,-2.100
//! ```

use super::{CrossFormat, CrossTable, Part, check_rising};
use crate::compensate::controllers::{Refused, Unreadable};

pub struct Csv;

const HEAD: &str = "# axcheck cross-axis table: output ";

impl CrossFormat for Csv {
    fn name(&self) -> &'static str {
        "csv"
    }

    fn write(&self, t: &CrossTable, _stem: &str) -> Result<Vec<Part>, Refused> {
        check_rising(t)?;
        let mut text = format!(
            "{HEAD}{} as a function of input {}\n# correction_um is added to the output axis's commanded position\ninput_mm,correction_um\n",
            t.output, t.input
        );
        for (p, c) in t.positions_mm.iter().zip(&t.corrections_um) {
            text.push_str(&format!("{p},{c:.3}\n"));
        }
        Ok(vec![Part {
            extension: "csv",
            text,
        }])
    }

    fn read(&self, parts: &[&str]) -> Result<CrossTable, Unreadable> {
        let text = parts.first().ok_or_else(|| Unreadable::file("no file"))?;
        let mut axes = None;
        let mut table = CrossTable {
            input: String::new(),
            output: String::new(),
            positions_mm: Vec::new(),
            corrections_um: Vec::new(),
        };
        for (k, line) in text.lines().enumerate().map(|(k, l)| (k + 1, l.trim())) {
            if let Some(rest) = line.strip_prefix(HEAD) {
                let (output, input) =
                    rest.split_once(" as a function of input ").ok_or_else(|| {
                        Unreadable::at(k, "expected `output A as a function of input B`")
                    })?;
                axes = Some((output.to_string(), input.to_string()));
            } else if line.is_empty() || line.starts_with('#') || line == "input_mm,correction_um" {
                continue;
            } else {
                let (p, c) = line
                    .split_once(',')
                    .ok_or_else(|| Unreadable::at(k, "expected `input_mm,correction_um`"))?;
                let number = |field: &str, v: &str| {
                    v.trim()
                        .parse::<f64>()
                        .map_err(|_| Unreadable::field(k, field, format!("`{v}` is not a number")))
                };
                table.positions_mm.push(number("input_mm", p)?);
                table.corrections_um.push(number("correction_um", c)?);
            }
        }
        let (output, input) = axes.ok_or_else(|| {
            Unreadable::file("no `# axcheck cross-axis table` line naming the axes")
        })?;
        table.output = output;
        table.input = input;
        Ok(table)
    }

    fn extensions(&self) -> &'static [&'static str] {
        &["csv"]
    }

    fn resolution_um(&self) -> f64 {
        0.0005
    }
}
