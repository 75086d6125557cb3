//! `summary.html`: the campaign as one self-contained web page (no network access of any
//! kind), for a file share, a CI artifact or an e-mail.
//!
//! The page is a fixed template (`page.html`, `page.css`, `page.js`) and the campaign's
//! data, embedded once as JSON in a `<script type="application/json">` whose `<`, `>` and
//! `&` are written as `\u003c`, `\u003e` and `\u0026`: no text of a campaign, a file or a
//! name can end the script or become markup. The script builds the page from the data
//! with `textContent` and `createElement` only.
//!
//! The table's rows come first and are read at once, by column ([`rows`]). Each test's
//! detail (parameters, findings, charts) is larger, so the details are kept in blocks of
//! [`BLOCK`] tests after the script, each deflated (zlib) and written in [`base85`]: the
//! page inflates a block when one of its rows is opened. A block is its JSON (the tests'
//! details, and the tables of their charts: paints, text styles, strings) and then its
//! charts' numbers as bytes ([`scene`]). A 10 000-axis page so takes about 1.3 kB a test.

mod base85;
mod detail;
mod rows;
mod scene;

use super::overview;
use super::{ExportError, Exporter, OutputFile};
use crate::history::AxisTrends;
use crate::judge::Verdict;
use crate::results::CampaignResult;
use axcheck_charts::words::Words;
use serde::Serialize;
use std::io::Write;
use std::sync::Arc;

/// Tests per block of details.
pub(crate) const BLOCK: usize = 64;

const PAGE: &str = include_str!("page.html");
const STYLE: &str = include_str!("page.css");
const SCRIPT: &str = include_str!("page.js");

pub(crate) struct HtmlExporter {
    /// Whether the run writes the axis reports (`reports/…pdf`), which the page links to.
    pub reports: bool,
    /// The trends of the run's axes, when the run keeps a history.
    pub trends: Option<Arc<AxisTrends>>,
    /// `--lang`: the page's language over `campaign.report.lang`.
    pub lang: Option<crate::lang::Lang>,
}

/// What the script reads first: the header, the counts and the table.
#[derive(Serialize)]
struct Page<'a> {
    generator: String,
    campaign: axcheck_charts::data::CampaignHeader<'a>,
    /// Tests per verdict, in the order of attention (fail first); inconclusive only when
    /// a test was judged by ISO 14253-1, not judged only when a test had no limit.
    counts: Vec<(Verdict, usize)>,
    /// Whether the run keeps a history (the table's trend column).
    history: bool,
    block: usize,
    /// The number of rows, then the rows by column.
    count: usize,
    rows: rows::Columns<'a>,
    /// The files the run read with their SHA-256 and how it was run, under the footer.
    inputs: Option<axcheck_charts::data::inputs::InputsList>,
    /// The page's language and its words (`tr` in page.js).
    lang: &'static str,
    t: std::collections::BTreeMap<&'static str, &'static str>,
}

/// The catalogue's keys page.js reads beside its own `html-…` and `verdict-…` ones.
const PAGE_KEYS: &[&str] = &[
    "col-clause",
    "col-parameter",
    "col-unit",
    "fact-axis",
    "fact-inspector",
    "fact-machine",
    "fact-standard",
    "sensor-kind",
    "summary-campaign-file",
    "summary-date",
    "summary-diagnosis",
    "summary-file",
    "summary-purpose",
    "summary-site",
    "summary-tests",
    "summary-travel",
    "summary-verdict",
    "summary-worst",
];

/// The words of `words` that page.js uses: the page carries those, not the catalogue.
fn page_words(words: &Words) -> std::collections::BTreeMap<&'static str, &'static str> {
    (words.all().iter())
        .filter(|(k, _)| {
            k.starts_with("html-")
                || k.starts_with("verdict-")
                || k.starts_with("purpose-")
                || PAGE_KEYS.contains(&k.as_str())
        })
        .map(|(k, v)| (k.as_str(), v.as_str()))
        .collect()
}

/// Input files listed under the page's footer before "… and N more".
const INPUTS_LISTED: usize = 200;

impl Exporter for HtmlExporter {
    fn name(&self) -> &'static str {
        "html"
    }

    fn export<'a>(&self, result: &'a CampaignResult) -> Result<Vec<OutputFile<'a>>, ExportError> {
        let words = Words::new(crate::campaign::report_lang(
            self.lang,
            result.info.report.as_ref(),
            None,
        ));
        words.scope(|| self.export_in(result, words))
    }
}

impl HtmlExporter {
    /// The page in `words`' language.
    fn export_in(
        &self,
        result: &CampaignResult,
        words: Words,
    ) -> Result<Vec<OutputFile<'static>>, ExportError> {
        let trends = self.trends.as_deref();
        let table = overview::rows(result, trends);
        let page = Page {
            generator: format!("axcheck {}", env!("CARGO_PKG_VERSION")),
            campaign: axcheck_charts::data::CampaignHeader::new(result),
            counts: counts(result),
            history: trends.is_some(),
            block: BLOCK,
            count: table.len(),
            rows: rows::columns(&table),
            inputs: axcheck_charts::data::inputs::inputs_list(&result.inputs, INPUTS_LISTED, 64),
            lang: words.lang().code(),
            t: page_words(&words),
        };
        let details = details(result, trends, self.reports, words)?;
        Ok(vec![OutputFile::new(
            "summary.html",
            page_html(&script_json(&page)?, &script_json(&details)?).into_bytes(),
        )])
    }
}

fn counts(result: &CampaignResult) -> Vec<(Verdict, usize)> {
    let counts = result.counts();
    let mut verdicts: Vec<Verdict> = counts.keys().copied().collect();
    verdicts.sort_by_key(|v| v.attention_rank());
    (verdicts.into_iter())
        .filter(|v| *v != Verdict::Inconclusive || result.uses_uncertainty_rule())
        .filter(|v| *v != Verdict::NotJudged || counts[v] > 0)
        .map(|v| (v, counts[&v]))
        .collect()
}

/// A block of details as the page reads it (see the module docs).
#[derive(Serialize)]
struct Block<'a> {
    tests: Vec<detail::Detail<'a>>,
    #[serde(flatten)]
    tables: &'a scene::Tables,
}

/// The details in blocks of [`BLOCK`] tests, each deflated and in base 85: the block's
/// JSON and its charts' byte streams, each after its length (LEB128).
fn details(
    result: &CampaignResult,
    trends: Option<&AxisTrends>,
    reports: bool,
    words: Words,
) -> Result<Vec<String>, ExportError> {
    let report_paths = super::paths::test_paths(result, "reports", "pdf");
    let table_paths = super::compensation::table_paths(result);
    let slash = |p: &std::path::Path| p.to_string_lossy().replace('\\', "/");
    let tests: Vec<_> = (result.tests.iter().zip(report_paths).zip(table_paths))
        .map(|((t, report), table)| (t, report, table))
        .collect();
    let encode = |block: &[(
        &crate::results::AxisTest,
        std::path::PathBuf,
        Option<std::path::PathBuf>,
    )]| {
        let details: Vec<detail::Detail> = (block.iter())
            .map(|(t, report, table)| {
                let links = detail::Links {
                    report: (reports && (t.evaluated().is_some() || t.other().is_some()))
                        .then(|| slash(report)),
                    table: table.as_deref().map(slash),
                };
                // On this worker's thread, in the page's language.
                words.scope(|| detail::detail(t, trends, links, &words))
            })
            .collect();
        let mut scenes = scene::SceneBlock::default();
        for chart in details.iter().flat_map(|d| &d.charts) {
            scenes.push(&chart.scene);
        }
        let block = Block {
            tests: details,
            tables: &scenes.tables,
        };
        let json = crate::safe_text::shown_json(&block).map_err(json_error)?;
        let s = &scenes.streams;
        let mut bytes = Vec::with_capacity(json.len() + s.ops.len() + s.xs.len() * 3);
        for part in [&json, &s.ops, &s.xs, &s.ys, &s.texts] {
            scene::put_uv(&mut bytes, part.len() as u64);
        }
        for part in [&json, &s.ops, &s.xs, &s.ys, &s.texts] {
            bytes.extend_from_slice(part);
        }
        let mut deflate = flate2::write::ZlibEncoder::new(Vec::new(), flate2::Compression::best());
        deflate.write_all(&bytes).map_err(io_error)?;
        Ok(base85::encode(&deflate.finish().map_err(io_error)?))
    };
    use rayon::prelude::*;
    tests.par_chunks(BLOCK).map(encode).collect()
}

fn json_error(e: serde_json::Error) -> ExportError {
    ExportError::Format {
        format: "html",
        message: e.to_string(),
    }
}

fn io_error(e: std::io::Error) -> ExportError {
    ExportError::Format {
        format: "html",
        message: e.to_string(),
    }
}

/// `data` as JSON that can stand inside a `<script>` element: `<`, `>`, `&` and the line
/// separators U+2028/U+2029 as `\u` escapes (JSON has them only inside strings, where the
/// escape means the same character); hidden characters of the strings as text
/// ([`crate::safe_text::shown_json`]), so the page shows them.
pub(crate) fn script_json(data: &impl Serialize) -> Result<String, ExportError> {
    let json = crate::safe_text::shown_json(data).map_err(json_error)?;
    let json = String::from_utf8(json).map_err(|e| io_error(std::io::Error::other(e)))?;
    let mut out = String::with_capacity(json.len() + json.len() / 64);
    for c in json.chars() {
        match c {
            '<' => out.push_str("\\u003c"),
            '>' => out.push_str("\\u003e"),
            '&' => out.push_str("\\u0026"),
            '\u{2028}' => out.push_str("\\u2028"),
            '\u{2029}' => out.push_str("\\u2029"),
            c => out.push(c),
        }
    }
    Ok(out)
}

/// The template with its style, script and data in place (each marker once, in order).
fn page_html(page: &str, details: &str) -> String {
    let mut out =
        String::with_capacity(PAGE.len() + STYLE.len() + SCRIPT.len() + page.len() + details.len());
    let mut rest = PAGE;
    for (marker, text) in [
        ("/*STYLE*/", STYLE),
        ("/*PAGE*/", page),
        ("/*SCRIPT*/", SCRIPT),
        ("/*DETAILS*/", details),
    ] {
        let (before, after) = rest
            .split_once(marker)
            .expect("each marker once in page.html");
        out.push_str(before);
        out.push_str(text);
        rest = after;
    }
    out.push_str(rest);
    out
}
