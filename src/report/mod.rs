//! PDF reports: per-axis test reports and the campaign summary, typeset by Typst from the
//! templates in `templates/` with charts drawn by plotters.
//!
//! Report data reach the templates only as the virtual file `/data.json` (read with
//! `json(...)`), never spliced into markup: a machine named `#read("/etc/passwd")` is
//! printed as those characters. Every document uses the same virtual paths, so Typst's
//! global file-id table does not grow with the number of reports.

pub(crate) mod chart_kit;
pub mod charts;
pub mod compact;
pub mod data;
pub mod diagnosis_charts;
pub mod diagnosis_data;
pub mod labels;
pub mod world;

use crate::batch::{AxisTest, CampaignResult};
use std::collections::HashMap;
use std::path::Path;
use typst::diag::{Severity, SourceDiagnostic};
use typst::foundations::Smart;
use typst_layout::PagedDocument;
use world::{DocumentWorld, SANS_FAMILY, Typesetter};

/// Template files, embedded at build time (the source tree's `templates/`).
pub const TEMPLATES: &[(&str, &str)] = &[
    ("style.typ", include_str!("../../templates/style.typ")),
    (
        "axis-report.typ",
        include_str!("../../templates/axis-report.typ"),
    ),
    ("summary.typ", include_str!("../../templates/summary.typ")),
];

/// A report that could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error("cannot read the templates: {0}")]
    Templates(String),
    #[error("typesetting {document}: {message}")]
    Typeset { document: String, message: String },
}

/// A compiled PDF and the warnings Typst gave.
pub struct Rendered {
    pub pdf: Vec<u8>,
    pub warnings: Vec<String>,
}

/// Renders reports; build once, use from many threads.
pub struct Reports {
    typesetter: Typesetter,
}

/// Chart sizes in SVG pixels, shown about 16 cm wide (the chart module's design size).
const CHART_WIDTH_PX: u32 = 900;
const CHART_HEIGHT_PX: u32 = 420;
const UNIDIRECTIONAL_HEIGHT_PX: u32 = 600;

impl Reports {
    /// With the built-in templates, or those in `dir` (a customised copy of `templates/`).
    pub fn new(dir: Option<&Path>) -> Result<Reports, ReportError> {
        let mut templates = HashMap::new();
        for (name, text) in TEMPLATES {
            let text = match dir {
                None => text.to_string(),
                Some(dir) => std::fs::read_to_string(dir.join(name)).map_err(|e| {
                    ReportError::Templates(format!("{}: {e}", dir.join(name).display()))
                })?,
            };
            templates.insert(format!("/{name}"), text);
        }
        Ok(Reports {
            typesetter: Typesetter::new(templates).ok_or_else(|| {
                ReportError::Templates("a template name is not a valid virtual path".into())
            })?,
        })
    }

    fn compile(
        &self,
        document: &str,
        main: &str,
        files: Vec<(String, Vec<u8>)>,
        date: Option<&str>,
        ident: String,
    ) -> Result<Rendered, ReportError> {
        let fail = |message: String| ReportError::Typeset {
            document: document.to_string(),
            message,
        };
        let today = date.and_then(parse_date);
        let world = DocumentWorld::new(&self.typesetter, main, files, today)
            .ok_or_else(|| fail("bad virtual path".into()))?;
        let warned = typst::compile::<PagedDocument>(&world);
        let warnings: Vec<String> = warned.warnings.iter().map(diagnostic).collect();
        let doc = warned
            .output
            .map_err(|errors| fail(errors.iter().map(diagnostic).collect::<Vec<_>>().join("; ")))?;
        let options = typst_pdf::PdfOptions {
            ident: Smart::Custom(ident),
            timestamp: None,
            // Untagged: the structure tree and a marked-content span around every text run
            // were 3 % of a report's time and a third of its page content; the reports are
            // data sheets, not documents that claim PDF/UA (text stays searchable).
            tagged: false,
            ..typst_pdf::PdfOptions::default()
        };
        let pdf = typst_pdf::pdf(&doc, &options)
            .map_err(|errors| fail(errors.iter().map(diagnostic).collect::<Vec<_>>().join("; ")))?;
        Ok(Rendered { pdf, warnings })
    }

    /// The report of one axis test.
    pub fn axis(&self, result: &CampaignResult, test: &AxisTest) -> Result<Rendered, ReportError> {
        let data = data::axis_report(result, test);
        let mut files = vec![(
            "/data.json".to_string(),
            serde_json::to_vec(&data).unwrap_or_default(),
        )];
        if let Some(e) = &test.evaluation {
            let (chart, up, down) = data::axis_chart(e);
            let style = charts::Style {
                font_family: SANS_FAMILY.to_string(),
                width_px: CHART_WIDTH_PX,
                height_px: CHART_HEIGHT_PX,
            };
            push_chart(
                &mut files,
                "bidirectional",
                charts::bidirectional(&chart, &style),
            );
            let tall = charts::Style {
                height_px: UNIDIRECTIONAL_HEIGHT_PX,
                ..style
            };
            push_chart(
                &mut files,
                "unidirectional",
                charts::unidirectional(&chart, &up, &down, &tall),
            );
            if let Some(d) = &test.diagnosis {
                let (checks, in_time, along, periodogram) = diagnosis_data::diagnosis_charts(d);
                let style = |height_px| diagnosis_charts::Style {
                    font_family: SANS_FAMILY.to_string(),
                    width_px: CHART_WIDTH_PX,
                    height_px,
                };
                let height = diagnosis_charts::model_checks_height(checks.len());
                push_chart(
                    &mut files,
                    "checks",
                    diagnosis_charts::model_checks(&checks, &style(height)),
                );
                push_chart(
                    &mut files,
                    "residuals-time",
                    diagnosis_charts::residuals(&in_time, &style(340)),
                );
                push_chart(
                    &mut files,
                    "residuals-position",
                    diagnosis_charts::residuals(&along, &style(340)),
                );
                push_chart(
                    &mut files,
                    "periodogram",
                    diagnosis_charts::periodogram(&periodogram, &style(300)),
                );
            }
        }
        let ident = format!(
            "axcheck/{}/{}/{}/{}",
            result.info.name, test.machine.id, test.axis, test.test
        );
        self.compile(
            &test.label(),
            "/axis-report.typ",
            files,
            result.info.date.as_deref(),
            ident,
        )
    }

    /// The campaign summary.
    pub fn summary(&self, result: &CampaignResult) -> Result<Rendered, ReportError> {
        let data = data::summary(result);
        let bars: Vec<charts::RatioBar> = {
            let mut tests: Vec<&AxisTest> = result.tests.iter().collect();
            tests.sort_by_key(|t| t.verdict.attention_rank());
            tests
                .iter()
                .filter_map(|t| {
                    let worst = t.judgement.as_ref()?.worst()?;
                    Some(charts::RatioBar {
                        label: t.label(),
                        parameter: t
                            .evaluation
                            .as_ref()
                            .and_then(|e| e.parameter(&worst.key))
                            .map_or(worst.key.clone(), |p| p.symbol().to_string()),
                        ratio: worst.ratio(),
                        pass: worst.pass,
                    })
                })
                .collect()
        };
        let style = charts::Style {
            font_family: SANS_FAMILY.to_string(),
            width_px: CHART_WIDTH_PX,
            height_px: charts::ratio_chart_height(bars.len()),
        };
        let mut files = vec![(
            "/data.json".to_string(),
            serde_json::to_vec(&data).unwrap_or_default(),
        )];
        push_chart(&mut files, "usage", charts::tolerance_usage(&bars, &style));
        let ident = format!("axcheck/{}/summary", result.info.name);
        self.compile(
            "summary",
            "/summary.typ",
            files,
            result.info.date.as_deref(),
            ident,
        )
    }
}

/// A chart's files: `/charts/NAME.svg` (the whole chart, for templates that show it as an
/// image), and for the templates' `chart("NAME")`: `/charts/NAME-plot.svg` (the drawing
/// without its labels, like elements merged: see [`compact`]) and `/charts/NAME.json`
/// (the labels, set by Typst: see [`labels`]).
fn push_chart(files: &mut Vec<(String, Vec<u8>)>, name: &str, svg: String) {
    let mut split = labels::split(&svg, SANS_FAMILY);
    split.svg = compact::merge_runs(&split.svg);
    files.push((
        format!("/charts/{name}.json"),
        serde_json::to_vec(&split).unwrap_or_default(),
    ));
    files.push((format!("/charts/{name}-plot.svg"), split.svg.into_bytes()));
    files.push((format!("/charts/{name}.svg"), svg.into_bytes()));
}

fn diagnostic(d: &SourceDiagnostic) -> String {
    let kind = match d.severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
    };
    let hints: Vec<&str> = d.hints.iter().map(|h| h.v.as_str()).collect();
    if hints.is_empty() {
        format!("{kind}: {}", d.message)
    } else {
        format!("{kind}: {} (hint: {})", d.message, hints.join("; "))
    }
}

/// `YYYY-MM-DD` → (year, month, day).
fn parse_date(s: &str) -> Option<(i32, u8, u8)> {
    let mut it = s.split('-');
    let y = it.next()?.parse().ok()?;
    let m = it.next()?.parse().ok()?;
    let d = it.next()?.parse().ok()?;
    Some((y, m, d))
}

/// Frees Typst's memoisation caches (between batches of documents).
pub fn evict_caches() {
    typst::comemo::evict(0);
}
