//! `summary.xlsx`: the campaign as a workbook for the spreadsheet users of a plant.
//!
//! - `Tests`: one row per axis test, the columns of `summary.csv` with the same values
//!   (numbers typed, units in the header), then the headline parameters' expanded
//!   uncertainty U (k = 2), the decision rule, the compensation's predicted E and, with a
//!   history, the flagged trends. Verdict cells coloured (and written out), header
//!   frozen, autofilter on.
//! - `Plan rules`: one row per finding of a test-plan rule.
//! - `Diagnosis`: one row per effect the diagnosis found, with its advice.
//!
//! The same input gives the same bytes: the document's creation time is the campaign's
//! date (or 2000-01-01), and the archive's entries carry a fixed time.

use super::overview::{self, HEADLINES};
use super::table::{self, Cell};
use super::{ExportError, Exporter, OutputFile};
use crate::history::AxisTrends;
use crate::judge::Verdict;
use crate::results::CampaignResult;
use crate::units::AxisKind;
use rust_xlsxwriter::{
    Color, DocProperties, ExcelDateTime, Format, Workbook, Worksheet, XlsxError,
};
use std::sync::Arc;

pub(crate) struct XlsxExporter {
    /// The trends of the run's axes, when the run keeps a history.
    pub trends: Option<Arc<AxisTrends>>,
}

impl Exporter for XlsxExporter {
    fn name(&self) -> &'static str {
        "xlsx"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let bytes = workbook(result, self.trends.as_deref()).map_err(|e| ExportError::Format {
            format: "xlsx",
            message: e.to_string(),
        })?;
        Ok(vec![OutputFile::new("summary.xlsx", bytes)])
    }
}

/// Excel's limit on a cell's text.
const MAX_CELL_CHARS: usize = 32_767;

fn workbook(result: &CampaignResult, trends: Option<&AxisTrends>) -> Result<Vec<u8>, XlsxError> {
    let mut book = Workbook::new();
    let created = created(result.info.date.as_deref())?;
    book.set_properties(
        &DocProperties::new()
            .set_title(format!(
                "{}: axis tests",
                crate::safe_text::visible(&result.info.name)
            ))
            .set_creation_datetime(&created),
    );
    tests_sheet(book.add_worksheet(), result, trends)?;
    rules_sheet(book.add_worksheet(), result)?;
    diagnosis_sheet(book.add_worksheet(), result)?;
    book.save_to_buffer()
}

/// The campaign's date (`YYYY-MM-DD`), else 2000-01-01.
fn created(date: Option<&str>) -> Result<ExcelDateTime, XlsxError> {
    let parsed = date
        .and_then(|d| chrono::NaiveDate::parse_from_str(d, "%Y-%m-%d").ok())
        .filter(|d| (1900..=9999).contains(&chrono::Datelike::year(d)));
    match parsed {
        Some(d) => {
            use chrono::Datelike;
            ExcelDateTime::from_ymd(d.year() as u16, d.month() as u8, d.day() as u8)
        }
        None => ExcelDateTime::from_ymd(2000, 1, 1),
    }
}

fn header_format() -> Format {
    Format::new()
        .set_bold()
        .set_background_color(Color::RGB(0xF3F3F6))
}

/// Background and text colour of a verdict's cell (the word is written too).
fn verdict_format(verdict: Verdict) -> Format {
    let (background, ink) = match verdict {
        Verdict::Pass => (0xE3F1E6, 0x1C5A2C),
        Verdict::Fail => (0xF8DCDC, 0x8E1B1B),
        Verdict::Noncompliant => (0xFBE6CF, 0x7A3E00),
        Verdict::Inconclusive => (0xFDF3C4, 0x5E4B00),
        Verdict::Error => (0xE7E2F3, 0x3E2A75),
        Verdict::NotJudged => (0xE4ECF2, 0x2C4A5E),
    };
    Format::new()
        .set_bold()
        .set_background_color(Color::RGB(background))
        .set_font_color(Color::RGB(ink))
}

/// A header's unit: `(µm)`, `(arcsec)`, or both when the campaign has linear and rotary
/// axes (the row's `unit` column tells which).
fn unit_note(kinds: &[AxisKind], linear: &str, rotary: &str) -> String {
    let has = |k: AxisKind| kinds.contains(&k);
    match (has(AxisKind::Linear), has(AxisKind::Rotary)) {
        (true, true) => format!(" ({linear} or {rotary}: see unit)"),
        (false, true) => format!(" ({rotary})"),
        _ => format!(" ({linear})"),
    }
}

/// The header of `summary.csv`'s column `name`, with its unit.
fn csv_header(name: &str, kinds: &[AxisKind]) -> String {
    let deviation = || unit_note(kinds, "µm", "arcsec");
    match name {
        "travel" => format!("travel{}", unit_note(kinds, "mm", "deg")),
        _ if (crate::evaluate::catalogue::summary_keys().iter()).any(|k| k.as_str() == name) => {
            format!("{name}{}", deviation())
        }
        _ => name.to_string(),
    }
}

fn tests_sheet(
    sheet: &mut Worksheet,
    result: &CampaignResult,
    trends: Option<&AxisTrends>,
) -> Result<(), XlsxError> {
    sheet.set_name("Tests")?;
    let kinds: Vec<AxisKind> = result.tests.iter().filter_map(|t| t.kind()).collect();
    let mut headers: Vec<String> = (table::columns().iter())
        .map(|(name, _)| csv_header(name, &kinds))
        .collect();
    let deviation = unit_note(&kinds, "µm", "arcsec");
    for (key, _) in HEADLINES {
        headers.push(format!("U_{key}{deviation}"));
    }
    headers.push("decision_rule".into());
    headers.push("compensation_controller".into());
    headers.push(format!("E_predicted{deviation}"));
    if trends.is_some() {
        headers.push("trend_flagged".into());
    }
    let bold = header_format();
    for (col, header) in headers.iter().enumerate() {
        sheet.write_string_with_format(0, col as u16, header, &bold)?;
    }
    let verdict_col = table::columns().iter().position(|(n, _)| n == "verdict");
    let overview = overview::rows(result, trends);
    for (i, (cells, row)) in table::rows(result).iter().zip(&overview).enumerate() {
        let r = i as u32 + 1;
        for (col, cell) in cells.iter().enumerate() {
            let col16 = col as u16;
            match cell {
                Cell::Text(s) if Some(col) == verdict_col => {
                    sheet.write_string_with_format(r, col16, s, &verdict_format(row.verdict))?;
                }
                Cell::Text(s) => write_text(sheet, r, col16, s)?,
                Cell::Int(n) => write_number(sheet, r, col16, *n as f64)?,
                Cell::Number(x) => write_number(sheet, r, col16, *x)?,
                Cell::Bool(b) => {
                    sheet.write_boolean(r, col16, *b)?;
                }
                Cell::Empty => {}
            }
        }
        let mut col = cells.len() as u16;
        for (key, _) in HEADLINES {
            if let Some(u) = row.values.get(key).and_then(|h| h.u) {
                write_number(sheet, r, col, u)?;
            }
            col += 1;
        }
        if let Some(rule) = row.decision_rule {
            write_text(sheet, r, col, rule)?;
        }
        if let Some(c) = &row.compensation {
            write_text(sheet, r, col + 1, c.controller)?;
            write_number(sheet, r, col + 2, c.predicted)?;
        }
        if let Some(flagged) = &row.trend {
            write_text(sheet, r, col + 3, &flagged.join(" "))?;
        }
    }
    finish_table(sheet, headers.len(), result.tests.len())
}

fn rules_sheet(sheet: &mut Worksheet, result: &CampaignResult) -> Result<(), XlsxError> {
    sheet.set_name("Plan rules")?;
    let headers = [
        "machine", "axis", "test", "rule", "clause", "severity", "message",
    ];
    write_headers(sheet, &headers)?;
    let mut r = 1;
    for t in &result.tests {
        for f in t.findings() {
            write_test(sheet, r, t)?;
            write_text(sheet, r, 3, f.id)?;
            write_text(sheet, r, 4, f.clause)?;
            write_text(sheet, r, 5, f.severity.name())?;
            write_text(sheet, r, 6, &f.message)?;
            r += 1;
        }
    }
    finish_table(sheet, headers.len(), r as usize - 1)
}

fn diagnosis_sheet(sheet: &mut Worksheet, result: &CampaignResult) -> Result<(), XlsxError> {
    sheet.set_name("Diagnosis")?;
    let headers = [
        "machine", "axis", "test", "effect", "estimate", "message", "advice",
    ];
    write_headers(sheet, &headers)?;
    let mut r = 1;
    for t in &result.tests {
        for f in t
            .evaluated()
            .and_then(|e| e.diagnosis.as_deref())
            .into_iter()
            .flat_map(|d| &d.findings)
        {
            write_test(sheet, r, t)?;
            write_text(sheet, r, 3, f.effect().name())?;
            write_text(sheet, r, 4, &f.params_text(|x| x.to_string()))?;
            write_text(sheet, r, 5, &f.message)?;
            write_text(sheet, r, 6, &f.advice())?;
            r += 1;
        }
    }
    finish_table(sheet, headers.len(), r as usize - 1)
}

fn write_headers(sheet: &mut Worksheet, headers: &[&str]) -> Result<(), XlsxError> {
    let bold = header_format();
    for (col, header) in headers.iter().enumerate() {
        sheet.write_string_with_format(0, col as u16, *header, &bold)?;
    }
    Ok(())
}

/// Machine, axis and test number in the first three columns.
fn write_test(
    sheet: &mut Worksheet,
    r: u32,
    t: &crate::results::AxisTest,
) -> Result<(), XlsxError> {
    write_text(sheet, r, 0, &t.machine.id)?;
    write_text(sheet, r, 1, &t.axis_label())?;
    write_number(sheet, r, 2, t.test as f64)
}

/// Text, written as a string (never a formula, whatever it starts with), hidden characters
/// shown ([`crate::safe_text::visible`]), cut at Excel's limit with `…` (an error message
/// can be long).
fn write_text(sheet: &mut Worksheet, r: u32, col: u16, text: &str) -> Result<(), XlsxError> {
    let text = crate::safe_text::visible(text);
    let text = text.as_ref();
    if text.chars().count() <= MAX_CELL_CHARS {
        sheet.write_string(r, col, text)?;
    } else {
        let cut: String = text.chars().take(MAX_CELL_CHARS - 1).chain(['…']).collect();
        sheet.write_string(r, col, cut)?;
    }
    Ok(())
}

/// A number; one that is not finite (a ratio to a zero limit) is left empty, as in
/// `summary.csv` (Excel has no such number).
fn write_number(sheet: &mut Worksheet, r: u32, col: u16, x: f64) -> Result<(), XlsxError> {
    if x.is_finite() {
        sheet.write_number(r, col, x)?;
    }
    Ok(())
}

/// Header frozen, autofilter over the table, columns fitted to their text.
fn finish_table(sheet: &mut Worksheet, columns: usize, rows: usize) -> Result<(), XlsxError> {
    sheet.set_freeze_panes(1, 0)?;
    sheet.autofilter(0, 0, rows as u32, columns.saturating_sub(1) as u16)?;
    sheet.autofit();
    Ok(())
}
