//! `summary.csv`: the summary table, RFC 4180 quoting, numbers in shortest round-trip form;
//! text cells neutralised against formulas ([`crate::safe_text::csv_text`]).

use super::table::{Cell, columns, rows};
use super::{ExportError, Exporter, OutputFile};
use crate::results::CampaignResult;

pub(crate) struct CsvExporter;

impl Exporter for CsvExporter {
    fn name(&self) -> &'static str {
        "csv"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let mut out = String::new();
        let header: Vec<String> = columns().into_iter().map(|(n, _)| n).collect();
        out.push_str(&header.join(","));
        out.push('\n');
        for row in rows(result) {
            let cells: Vec<String> = row
                .iter()
                .map(|c| match c {
                    Cell::Text(s) => crate::safe_text::csv_text(s),
                    Cell::Int(i) => i.to_string(),
                    Cell::Bool(b) => b.to_string(),
                    Cell::Number(x) if x.is_finite() => x.to_string(),
                    Cell::Number(_) | Cell::Empty => String::new(),
                })
                .collect();
            out.push_str(&cells.join(","));
            out.push('\n');
        }
        Ok(vec![OutputFile::new("summary.csv", out.into_bytes())])
    }
}
