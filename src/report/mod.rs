//! PDF reports: per-axis test reports and the campaign summary, typeset by Typst from the
//! templates in `templates/` with charts drawn by plotters.
//!
//! Report data reach the templates only as virtual files, never spliced into markup:
//! `/data.json` (read with `json(...)`; a machine named `#read("/etc/passwd")` is printed
//! as those characters) and per chart its drawing and labels (see [`Files::chart`]). Every
//! document uses the same virtual paths, so Typst's global file-id table does not grow
//! with the number of reports.

// The rooms: typesetting (Typst's world, text shaped directly, lines of text, drawings)
// here; the chart kit (a canvas, scenes and their labels, shared plotting helpers), one
// file per chart, and the data each document reads in `axcheck-charts`, below.
pub mod typeset;
pub use axcheck_charts::{chart_kit, charts, data, figures::iso_charts};

use crate::history::{AxisTrends, history_of};
use crate::results::{AxisTest, CampaignResult};
use crate::trend::{Series, Trend};
use axcheck_charts::figures::{CHART_HEIGHT_PX, CHART_WIDTH_PX, TREND_STYLE};
use axcheck_charts::words::Words;
use chart_kit::{labels, scene::Scene};
use charts::{
    check as check_chart, compensation as compensation_chart, diagnosis as diagnosis_charts,
    trend as trend_chart, verification as verification_chart,
};
use data::diagnosis as diagnosis_data;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;
use typeset::world::{DocumentWorld, Typesetter};
use typst::diag::{Severity, SourceDiagnostic};
use typst::foundations::Smart;
use typst_layout::PagedDocument;

/// Template files, embedded at build time (the source tree's `templates/`).
pub const TEMPLATES: &[(&str, &str)] = &[
    ("style.typ", include_str!("../../templates/style.typ")),
    (
        "axis-report.typ",
        include_str!("../../templates/axis-report.typ"),
    ),
    ("summary.typ", include_str!("../../templates/summary.typ")),
    ("trends.typ", include_str!("../../templates/trends.typ")),
    (
        "other-report.typ",
        include_str!("../../templates/other-report.typ"),
    ),
    (
        "certificate.typ",
        include_str!("../../templates/certificate.typ"),
    ),
];

/// Templates a customised copy may lack (added after the copy was made): the built-in
/// one is used.
const NEWER_TEMPLATES: &[&str] = &["trends.typ", "other-report.typ", "certificate.typ"];

/// A report that could not be produced.
#[derive(Debug, thiserror::Error)]
pub enum ReportError {
    #[error("cannot read the templates: {0}")]
    Templates(String),
    #[error("typesetting {document}: {message}")]
    Typeset { document: String, message: String },
    #[error("writing the data of {document}: {cause}")]
    Data {
        document: String,
        cause: serde_json::Error,
    },
}

/// `/words.json` of `lang`: `{"lang": …, "t": {key: message}}`, made once per language.
fn words_json(lang: crate::lang::Lang) -> Vec<u8> {
    use std::sync::LazyLock;
    #[derive(serde::Serialize)]
    struct WordsFile {
        lang: &'static str,
        t: &'static std::collections::BTreeMap<String, String>,
    }
    static ALL: LazyLock<Vec<(crate::lang::Lang, Vec<u8>)>> = LazyLock::new(|| {
        (crate::lang::Lang::ALL.into_iter())
            .map(|lang| {
                let words = Words::new(lang);
                let file = WordsFile {
                    lang: lang.code(),
                    t: words.all(),
                };
                let bytes = serde_json::to_vec(&file).expect("the catalogues serialise");
                (lang, bytes)
            })
            .collect()
    });
    (ALL.iter().find(|(l, _)| *l == lang))
        .map(|(_, bytes)| bytes.clone())
        .expect("every language")
}

/// A document's files (virtual path → bytes) and charts (name → scene).
#[derive(Default)]
struct Files {
    files: Vec<(String, Vec<u8>)>,
    charts: Vec<(String, Arc<Scene>)>,
}

impl Files {
    /// `/data.json`: `data`; and `/words.json`: the document's language (`lang`) and its
    /// words (`t`: every message of its catalogue, which the templates' `tr` reads).
    ///
    /// The words are a file of their own, the same bytes in every document of a language:
    /// `style.typ` reads them, so Typst evaluates it once per language and reuses its
    /// functions' layout from one report to the next. With the words in `/data.json`,
    /// which differs in every report, it was evaluated again each time and every call of
    /// `tr` hashed the whole catalogue: two thirds more time per report.
    fn data(
        document: &str,
        data: &impl serde::Serialize,
        words: &Words,
    ) -> Result<Files, ReportError> {
        let mut files = Files::default();
        files.push(document, "/data.json".into(), data)?;
        files
            .files
            .push(("/words.json".into(), words_json(words.lang())));
        Ok(files)
    }

    /// `data` as JSON at `path`.
    fn push(
        &mut self,
        document: &str,
        path: String,
        data: &impl serde::Serialize,
    ) -> Result<(), ReportError> {
        // Hidden characters of names and notes as text: a report shows them, never acts on
        // them (U+202E would print a name backwards).
        let bytes = crate::safe_text::shown_json(data).map_err(|cause| ReportError::Data {
            document: document.to_string(),
            cause,
        })?;
        self.files.push((path, bytes));
        Ok(())
    }

    /// A chart's file, for the templates' `chart("NAME")` in `style.typ`:
    /// `/charts/NAME.drawing` (the shapes and the labels, laid out by `chart-drawing`).
    /// For templates that set the labels themselves or show a chart as an image,
    /// `/charts/NAME.json` (the labels: see [`labels`]), `/charts/NAME.svg` (the whole
    /// chart) and `/charts/NAME-plot.svg` (without its labels) are written when read.
    fn chart(&mut self, name: &str, scene: Scene) {
        let labels = labels::ChartLabels::of(&scene);
        let mut bytes = scene.drawing.encode();
        labels.encode(&mut bytes);
        self.files.push((format!("/charts/{name}.drawing"), bytes));
        self.charts.push((name.to_string(), Arc::new(scene)));
    }
}

/// The template `name` of the folder `root`: its real path inside the folder, and the file
/// opened inside it (a link swapped after the check is refused).
fn read_template(root: &crate::files::Root, name: &str) -> Result<String, ReportError> {
    let path = root.dir().join(name);
    root.check(Path::new(name)).map_err(|outside| {
        ReportError::Templates(format!(
            "{outside}; copy the template into the folder instead of linking it"
        ))
    })?;
    root.read_to_string(&path)
        .map_err(|e| ReportError::Templates(format!("{}: {e}", path.display())))
}

/// A compiled PDF and the warnings Typst gave.
pub struct Rendered {
    pub pdf: Vec<u8>,
    pub warnings: Vec<String>,
    /// Time spent laying the document out (Typst's compile) and writing it as PDF, for
    /// the benchmark of what a report costs (`benches/reports.rs`).
    pub typeset_time: std::time::Duration,
    pub export_time: std::time::Duration,
}

/// Renders reports; build once, use from many threads.
pub struct Reports {
    typesetter: Typesetter,
    /// The templates read from the customised copy, with their SHA-256 (empty with the
    /// built-in ones): inputs of the run.
    read: Vec<crate::files::InputFile>,
    /// `--lang`: the language of every report, over the machines' and the campaign's
    /// `report.lang`.
    lang: Option<crate::lang::Lang>,
}

impl Reports {
    /// With the built-in templates, or those in `dir` (a customised copy of `templates/`):
    /// regular files whose real paths stay in `dir` (a link in a shared templates folder
    /// does not put another file into the reports).
    pub fn new(dir: Option<&Path>) -> Result<Reports, ReportError> {
        let mut templates = HashMap::new();
        let root = dir.map(|dir| crate::files::Root::folder(dir, "templates folder").recording());
        for (name, text) in TEMPLATES {
            let text = match &root {
                None => text.to_string(),
                // A copy made before a template existed lacks it: the built-in one.
                Some(root)
                    if NEWER_TEMPLATES.contains(name)
                        && std::fs::symlink_metadata(root.dir().join(name)).is_err() =>
                {
                    text.to_string()
                }
                Some(root) => read_template(root, name)?,
            };
            templates.insert(format!("/{name}"), text);
        }
        Ok(Reports {
            typesetter: Typesetter::new(templates).ok_or_else(|| {
                ReportError::Templates("a template name is not a valid virtual path".into())
            })?,
            read: root.map_or_else(Vec::new, |root| root.recorded()),
            lang: None,
        })
    }

    /// With every report in `lang` (`--lang`), when given.
    pub fn with_lang(mut self, lang: Option<crate::lang::Lang>) -> Reports {
        self.lang = lang;
        self
    }

    /// The words of `machine`'s reports (of the summary with `None`): `--lang`, else the
    /// machine's `report.lang`, else the campaign's, else English.
    pub fn words(
        &self,
        result: &CampaignResult,
        machine: Option<&crate::campaign::MachineInfo>,
    ) -> Words {
        Words::new(crate::campaign::report_lang(
            self.lang,
            result.info.report.as_ref(),
            machine.and_then(|m| m.report.as_ref()),
        ))
    }

    /// The templates read from the customised copy with their SHA-256, sorted by path
    /// (relative to its folder); empty with the built-in templates.
    pub fn templates_read(&self) -> &[crate::files::InputFile] {
        &self.read
    }

    fn compile(
        &self,
        document: &str,
        main: &str,
        files: Files,
        date: Option<&str>,
        ident: String,
    ) -> Result<Rendered, ReportError> {
        let fail = |message: String| ReportError::Typeset {
            document: document.to_string(),
            message,
        };
        let today = date.and_then(parse_date);
        let world = DocumentWorld::new(&self.typesetter, main, files.files, files.charts, today)
            .ok_or_else(|| fail("bad virtual path".into()))?;
        let started = std::time::Instant::now();
        let warned = typst::compile::<PagedDocument>(&world);
        let warnings: Vec<String> = warned.warnings.iter().map(diagnostic).collect();
        let mut doc = warned
            .output
            .map_err(|errors| fail(errors.iter().map(diagnostic).collect::<Vec<_>>().join("; ")))?;
        if doc.info_mut().title.is_none() {
            doc.info_mut().title = page_title(&doc).map(Into::into);
        }
        let typeset_time = started.elapsed();
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
        Ok(Rendered {
            pdf,
            warnings,
            export_time: started.elapsed() - typeset_time,
            typeset_time,
        })
    }

    /// The report of one axis test.
    pub fn axis(&self, result: &CampaignResult, test: &AxisTest) -> Result<Rendered, ReportError> {
        self.axis_with_history(result, test, None)
    }

    /// The report of one axis test, with its history section when `trends` has the axis.
    pub(crate) fn axis_with_history(
        &self,
        result: &CampaignResult,
        test: &AxisTest,
        trends: Option<&AxisTrends>,
    ) -> Result<Rendered, ReportError> {
        if test.other().is_some() {
            return self.other(result, test);
        }
        let words = self.words(result, Some(&test.machine));
        words.scope(|| self.axis_in(result, test, trends, &words))
    }

    /// [`Reports::axis_with_history`] in `words`' language.
    fn axis_in(
        &self,
        result: &CampaignResult,
        test: &AxisTest,
        trends: Option<&AxisTrends>,
        words: &Words,
    ) -> Result<Rendered, ReportError> {
        let document = test.label();
        let mut report = data::axis_report(result, test, words);
        let mut history_charts = Vec::new();
        if let Some(history) = history_of(test, trends) {
            report = report.with_history(history.section);
            history_charts = history.charts;
        }
        let mut files = Files::data(&document, &report, words)?;
        for chart in history_charts {
            files.chart(&chart.name, chart.scene);
        }
        if let Some(e) = test.evaluated().map(|e| &e.evaluation) {
            let style = |height_px| charts::Style {
                width_px: CHART_WIDTH_PX,
                height_px,
            };
            let [bidirectional, unidirectional] = iso_charts(e);
            files.chart("bidirectional", bidirectional);
            files.chart("unidirectional", unidirectional);
            if let Some(d) = test.evaluated().and_then(|e| e.diagnosis.as_deref()) {
                diagnosis_files(&mut files, d);
            }
            let bars = data::decision_bars(test);
            let height = check_chart::model_checks_height(bars.len());
            let zones = check_chart::decision_zones(&bars, &style(height));
            files.chart("decision", zones);
            let done = test
                .evaluated()
                .and_then(|e| e.compensation.as_deref())
                .and_then(|c| c.outcome.as_ref().ok());
            if let Some(done) = done {
                let chart = data::compensation_chart(e, done);
                let scene = compensation_chart::compensation(&chart, &style(CHART_HEIGHT_PX));
                files.chart("compensation", scene);
            }
            if let Some(Ok(v)) = test.evaluated().and_then(|e| e.verification.as_deref()) {
                let chart = data::verification_chart(v, e.kind);
                let scene = verification_chart::verification(&chart, &style(CHART_HEIGHT_PX));
                files.chart("verification", scene);
            }
        }
        let ident = format!(
            "axcheck/{}/{}/{}/{}",
            result.info.name, test.machine.id, test.axis, test.test
        );
        let date = result.info.date.as_deref();
        self.compile(&document, "/axis-report.typ", files, date, ident)
    }

    /// The report of a straightness, angular or squareness test (ISO 230-1).
    fn other(&self, result: &CampaignResult, test: &AxisTest) -> Result<Rendered, ReportError> {
        let words = self.words(result, Some(&test.machine));
        words.scope(|| self.other_in(result, test, &words))
    }

    /// [`Reports::other`] in `words`' language.
    fn other_in(
        &self,
        result: &CampaignResult,
        test: &AxisTest,
        words: &Words,
    ) -> Result<Rendered, ReportError> {
        let document = test.label();
        let Some(report) = data::other_report(result, test) else {
            return Err(ReportError::Typeset {
                document,
                message: "not one of the other laser tests".into(),
            });
        };
        let mut files = Files::data(&document, &report, words)?;
        if let Some(chart) = test.other().and_then(data::other_chart) {
            let style = charts::Style {
                width_px: CHART_WIDTH_PX,
                height_px: CHART_HEIGHT_PX,
            };
            files.chart("geometry", charts::geometry::geometry(&chart, &style));
        }
        let ident = format!(
            "axcheck/{}/{}/{}/{}",
            result.info.name,
            test.machine.id,
            test.axis_label(),
            test.test
        );
        let date = result.info.date.as_deref();
        self.compile(&document, "/other-report.typ", files, date, ident)
    }

    /// The campaign summary.
    pub fn summary(&self, result: &CampaignResult) -> Result<Rendered, ReportError> {
        self.summary_with_trends(result, None)
    }

    /// The campaign summary, listing the flagged series of `trends`.
    pub(crate) fn summary_with_trends(
        &self,
        result: &CampaignResult,
        trends: Option<&AxisTrends>,
    ) -> Result<Rendered, ReportError> {
        let words = self.words(result, None);
        words.scope(|| self.summary_in(result, trends, &words))
    }

    /// [`Reports::summary_with_trends`] in `words`' language.
    fn summary_in(
        &self,
        result: &CampaignResult,
        trends: Option<&AxisTrends>,
        words: &Words,
    ) -> Result<Rendered, ReportError> {
        let document = "summary";
        let mut summary = data::summary(result);
        if let Some(t) =
            trends.and_then(|t| data::trends::trends_summary(t.all(), t.options.horizon_years))
        {
            summary = summary.with_trends(t);
        }
        let mut files = Files::data(document, &summary, words)?;
        let bars = ratio_bars(result);
        let style = charts::Style {
            width_px: CHART_WIDTH_PX,
            height_px: charts::ratio_chart_height(bars.len()),
        };
        files.chart("usage", charts::tolerance_usage(&bars, &style));
        let ident = format!("axcheck/{}/summary", result.info.name);
        let date = result.info.date.as_deref();
        self.compile(document, "/summary.typ", files, date, ident)
    }

    /// `trends.pdf`: the series of a history (named `history` in the text), flagged axes
    /// first; `table` names the CSV that holds every row.
    pub fn trends(
        &self,
        history: &str,
        pairs: &[(&Series, &Trend)],
        horizon_years: f64,
        table: &str,
    ) -> Result<Rendered, ReportError> {
        let document = "trends";
        let words = Words::new(self.lang.unwrap_or_default());
        // Built in the language's numbers (charts and table), as the other documents.
        let (doc, files) = words.scope(|| {
            let (doc, charts) = data::trends::trends_document(history, pairs, horizon_years, table);
            let mut files = Files::data(document, &doc, &words)?;
            for (name, chart) in charts {
                files.chart(&name, trend_chart::trend(&chart, &TREND_STYLE));
            }
            Ok::<_, ReportError>((doc, files))
        })?;
        let date = (!doc.last.is_empty()).then_some(doc.last.as_str());
        self.compile(
            document,
            "/trends.typ",
            files,
            date,
            "axcheck/trends".into(),
        )
    }
}

/// The charts of the diagnosis section.
fn diagnosis_files(files: &mut Files, d: &crate::diagnose::Diagnosis) {
    let (checks, in_time, along, periodogram) = diagnosis_data::diagnosis_charts(d);
    let style = |height_px| diagnosis_charts::Style {
        width_px: CHART_WIDTH_PX,
        height_px,
    };
    let height = check_chart::model_checks_height(checks.len());
    let model_checks = check_chart::model_checks(&checks, &style(height));
    files.chart("checks", model_checks);
    let in_time = diagnosis_charts::residuals(&in_time, &style(340));
    files.chart("residuals-time", in_time);
    let along = diagnosis_charts::residuals(&along, &style(340));
    files.chart("residuals-position", along);
    let periodogram = diagnosis_charts::periodogram(&periodogram, &style(300));
    files.chart("periodogram", periodogram);
}

/// The summary chart's bars: each test's worst parameter, needing attention first.
fn ratio_bars(result: &CampaignResult) -> Vec<charts::RatioBar> {
    let mut tests: Vec<&AxisTest> = result.tests.iter().collect();
    tests.sort_by_key(|t| t.verdict().attention_rank());
    tests
        .iter()
        .filter_map(|t| {
            let worst = t.judgement()?.worst()?;
            Some(charts::RatioBar {
                // Drawn as text by the chart, not read from the report's data.
                label: crate::safe_text::visible(&t.label()).into_owned(),
                parameter: data::symbol_of(t, worst.key),
                ratio: worst.ratio(),
                verdict: t.verdict(),
            })
        })
        .collect()
}

/// The title the template gave as `#metadata(..) <page-title>` (see `setup` in
/// `style.typ`): a `set document(title: ..)` would put it into every style chain, which
/// Typst's layout cache is keyed by.
fn page_title(doc: &PagedDocument) -> Option<typst::foundations::Str> {
    use typst::introspection::Introspector;
    let label = typst::foundations::Label::new(typst::utils::PicoStr::intern("page-title"))?;
    let found = doc.introspector().query_label(label).ok()?;
    let meta = found.to_packed::<typst::introspection::MetadataElem>()?;
    match &meta.value {
        typst::foundations::Value::Str(s) => Some(s.clone()),
        _ => None,
    }
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
