//! `summary.csv`: the summary table, RFC 4180 quoting, numbers in shortest round-trip form.

use super::table::{Cell, columns, rows};
use super::{ExportError, Exporter, OutputFile};
use crate::batch::CampaignResult;

pub struct Csv;

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

impl Exporter for Csv {
    fn name(&self) -> &'static str {
        "csv"
    }

    fn export(&self, result: &CampaignResult) -> Result<Vec<OutputFile>, ExportError> {
        let mut out = String::new();
        let header: Vec<String> = columns().into_iter().map(|(n, _)| n).collect();
        out.push_str(&header.join(","));
        out.push('\n');
        for row in rows(result) {
            let cells: Vec<String> = row
                .iter()
                .map(|c| match c {
                    Cell::Text(s) => quote(s),
                    Cell::Int(i) => i.to_string(),
                    Cell::Number(x) if x.is_finite() => x.to_string(),
                    Cell::Number(_) | Cell::Empty => String::new(),
                })
                .collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        Ok(vec![OutputFile {
            path: "summary.csv".into(),
            bytes: out.into_bytes(),
        }])
    }
}
