//! The Typst `World` behind every report: all I/O of the typesetter goes through it.
//!
//! [`Typesetter`] holds what every document shares — the standard library, the font book
//! and the fonts (typst-assets' faces plus the embedded Inter and its fallbacks) and the templates — and is
//! built once per process; its library has the `chart-drawing` function (see
//! [`crate::report::typeset::drawing`]). [`DocumentWorld`] adds one document's files (its main template,
//! `/data.json`, the charts' drawings and labels), all in memory: a template can read
//! nothing from the disk, and report data reach it only as data.

use crate::report::typeset::drawing::chart_drawing;
use crate::report::typeset::text_lines::{text_columns, text_lines, text_widths};
use axcheck_charts::chart_kit::scene::Scene;
use std::cell::Cell;
use std::collections::HashMap;
use std::sync::{Arc, OnceLock};
use typst::diag::{FileError, FileResult};
use typst::foundations::{Bytes, Datetime};
use typst::syntax::{FileId, RootedPath, Source, VirtualPath, VirtualRoot};
use typst::text::{Font, FontBook};
use typst::utils::LazyHash;
use typst::{Library, LibraryExt, World};

/// The sans-serif face embedded for body text and charts.
pub(crate) const SANS_FAMILY: &str = "Inter";

/// The embedded faces (templates/fonts/README.md): Inter, and for the letters it lacks
/// (names of machines and axes, in any script) Noto Sans Hebrew and Arabic and Droid Sans
/// Fallback (Chinese, Japanese kana), which `templates/style.typ` lists after it. Without
/// them Typst took Hebrew from a serif face of typst-assets, Arabic from a monospace one and
/// printed CJK as empty boxes.
const EMBEDDED: [&[u8]; 9] = [
    include_bytes!("../../../templates/fonts/Inter-Regular.otf"),
    include_bytes!("../../../templates/fonts/Inter-Italic.otf"),
    include_bytes!("../../../templates/fonts/Inter-SemiBold.otf"),
    include_bytes!("../../../templates/fonts/Inter-Bold.otf"),
    include_bytes!("../../../templates/fonts/NotoSansHebrew-Regular.ttf"),
    include_bytes!("../../../templates/fonts/NotoSansHebrew-Bold.ttf"),
    include_bytes!("../../../templates/fonts/NotoSansArabic-Regular.ttf"),
    include_bytes!("../../../templates/fonts/NotoSansArabic-Bold.ttf"),
    include_bytes!("../../../templates/fonts/DroidSansFallbackFull.ttf"),
];

/// Shared, read-only typesetting state.
pub(crate) struct Typesetter {
    library: LazyHash<Library>,
    book: LazyHash<FontBook>,
    fonts: Vec<Font>,
    /// Each further typesetting thread's own copies of the fonts (see [`on_font_lane`]),
    /// made when a document of that thread first asks for one: lane 1's at index 0.
    lanes: Vec<Vec<OnceLock<Font>>>,
    /// The templates by virtual path (`/axis-report.typ` …), parsed once: every document
    /// shares them (parsing them again for each report cost 3 % of its time), and Typst's
    /// caches see the same modules each time.
    sources: HashMap<FileId, Source>,
}

impl Typesetter {
    /// Loads the fonts and the library; `templates` maps virtual paths to Typst sources
    /// (`None` if one is not a valid virtual path).
    pub fn new(templates: HashMap<String, String>) -> Option<Typesetter> {
        let fonts: Vec<Font> = typst_assets::fonts()
            .chain(EMBEDDED)
            .flat_map(|data| Font::iter(Bytes::new(data)))
            .collect();
        let sources = templates
            .into_iter()
            .map(|(name, text)| {
                let id = file_id(&name)?;
                Some((id, Source::new(id, text)))
            })
            .collect::<Option<_>>()?;
        let mut library = Library::default();
        library.global.scope_mut().define_func::<chart_drawing>();
        library.global.scope_mut().define_func::<text_lines>();
        library.global.scope_mut().define_func::<text_columns>();
        library.global.scope_mut().define_func::<text_widths>();
        // At least one lane besides the fonts themselves, so that a test sees two.
        let threads = std::thread::available_parallelism().map_or(2, |n| n.get().max(2));
        let lanes = (1..threads)
            .map(|_| fonts.iter().map(|_| OnceLock::new()).collect())
            .collect();
        Some(Typesetter {
            library: LazyHash::new(library),
            book: LazyHash::new(FontBook::from_fonts(&fonts)),
            fonts,
            lanes,
            sources,
        })
    }

    /// Font `index` of the calling thread's lane.
    fn font(&self, index: usize) -> Option<Font> {
        let font = self.fonts.get(index)?;
        let lane = LANE.get() % (self.lanes.len() + 1);
        let Some(copies) = lane.checked_sub(1).and_then(|l| self.lanes.get(l)) else {
            return Some(font.clone());
        };
        Some(copies[index].get_or_init(|| lane_copy(font, lane)).clone())
    }
}

thread_local! {
    /// The font lane of documents typeset on this thread.
    static LANE: Cell<usize> = const { Cell::new(0) };
}

/// Runs `work` with the documents it typesets on this thread using the fonts of `lane`
/// (e.g. the index of a typesetting thread; 0, the default, is the loaded fonts themselves).
///
/// Why: typst-pdf memoises the PDF font it builds for a Typst font, keyed by the font's
/// bytes, so documents exported at once on several threads shared one font object and
/// incremented and decremented its reference count for every glyph they wrote. On two
/// cores that cache line moving between them cost a third more CPU for the reports
/// (`bench/results.md`, "Reports: one font object per thread"). A lane's fonts are the
/// same faces with `lane` zero bytes appended, which no table points to: other keys, so
/// objects of their own, and the same glyphs, metrics and embedded subsets, so the same
/// PDF whichever thread wrote it.
pub fn on_font_lane<R>(lane: usize, work: impl FnOnce() -> R) -> R {
    let before = LANE.replace(lane);
    let result = work();
    LANE.set(before);
    result
}

/// `font`'s face over its bytes followed by `lane` zero bytes.
fn lane_copy(font: &Font, lane: usize) -> Font {
    let mut data = font.data().as_slice().to_vec();
    data.resize(data.len() + lane, 0);
    Font::new(Bytes::new(data), font.index()).unwrap_or_else(|| font.clone())
}

/// A virtual path's file id.
pub(crate) fn file_id(path: &str) -> Option<FileId> {
    VirtualPath::new(path)
        .ok()
        .map(|vpath| RootedPath::new(VirtualRoot::Project, vpath).intern())
}

/// One document: its main template and its data files.
pub(crate) struct DocumentWorld<'a> {
    typesetter: &'a Typesetter,
    main: FileId,
    /// The document's data files, by id (the templates are the typesetter's).
    files: HashMap<FileId, Bytes>,
    /// Chart pictures, written when a template reads them.
    pictures: HashMap<FileId, Picture>,
    today: Option<Datetime>,
}

/// A chart's labels as JSON (`/charts/NAME.json`), for templates that set them, or the
/// chart as SVG (`/charts/NAME.svg`, or without its texts `/charts/NAME-plot.svg`), for
/// templates that show a chart as an image; the built-in ones read none of these.
struct Picture {
    scene: Arc<Scene>,
    form: Form,
    bytes: OnceLock<FileResult<Bytes>>,
}

#[derive(Clone, Copy)]
enum Form {
    Labels,
    Svg,
    SvgWithoutTexts,
}

impl Picture {
    fn bytes(&self) -> FileResult<Bytes> {
        let scene = &self.scene;
        let made = self.bytes.get_or_init(|| match self.form {
            Form::Labels => {
                serde_json::to_vec(&axcheck_charts::chart_kit::labels::ChartLabels::of(scene))
                    .map(Bytes::new)
                    .map_err(|e| FileError::Other(Some(e.to_string().into())))
            }
            Form::Svg => Ok(Bytes::from_string(scene.svg(SANS_FAMILY))),
            Form::SvgWithoutTexts => Ok(Bytes::from_string(scene.drawing.svg())),
        });
        made.clone()
    }
}

impl<'a> DocumentWorld<'a> {
    /// A document whose entry point is the template `main` (e.g. `/axis-report.typ`),
    /// with `files` (virtual path → bytes), `charts` (name → scene) and the date `today`
    /// as (year, month, day).
    pub fn new(
        typesetter: &'a Typesetter,
        main: &str,
        files: Vec<(String, Vec<u8>)>,
        charts: Vec<(String, Arc<Scene>)>,
        today: Option<(i32, u8, u8)>,
    ) -> Option<DocumentWorld<'a>> {
        let files = files
            .into_iter()
            .map(|(path, bytes)| Some((file_id(&path)?, Bytes::new(bytes))))
            .collect::<Option<_>>()?;
        let mut pictures = HashMap::new();
        for (name, scene) in charts {
            let forms = [
                (".json", Form::Labels),
                (".svg", Form::Svg),
                ("-plot.svg", Form::SvgWithoutTexts),
            ];
            for (suffix, form) in forms {
                let picture = Picture {
                    scene: Arc::clone(&scene),
                    form,
                    bytes: OnceLock::new(),
                };
                pictures.insert(file_id(&format!("/charts/{name}{suffix}"))?, picture);
            }
        }
        Some(DocumentWorld {
            typesetter,
            main: file_id(main)?,
            files,
            pictures,
            today: today.and_then(|(y, m, d)| Datetime::from_ymd(y, m, d)),
        })
    }
}

impl World for DocumentWorld<'_> {
    fn library(&self) -> &LazyHash<Library> {
        &self.typesetter.library
    }

    fn book(&self) -> &LazyHash<FontBook> {
        &self.typesetter.book
    }

    fn main(&self) -> FileId {
        self.main
    }

    fn source(&self, id: FileId) -> FileResult<Source> {
        self.typesetter
            .sources
            .get(&id)
            .cloned()
            .ok_or_else(|| FileError::NotFound(id.get().vpath().get_with_slash().into()))
    }

    fn file(&self, id: FileId) -> FileResult<Bytes> {
        if let Some(bytes) = self.files.get(&id) {
            return Ok(bytes.clone());
        }
        if let Some(p) = self.pictures.get(&id) {
            return p.bytes();
        }
        if let Some(source) = self.typesetter.sources.get(&id) {
            return Ok(Bytes::from_string(source.text().to_string()));
        }
        Err(FileError::NotFound(
            id.get().vpath().get_with_slash().into(),
        ))
    }

    fn font(&self, index: usize) -> Option<Font> {
        self.typesetter.font(index)
    }

    fn today(&self, _offset: Option<typst::foundations::Duration>) -> Option<Datetime> {
        self.today
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A document typeset with another lane's fonts is the same PDF, byte for byte, though
    /// the fonts are other objects with other bytes.
    #[test]
    fn a_font_lane_gives_the_same_pdf_from_fonts_of_its_own() {
        let main = "#set text(font: (\"Inter\", \"Droid Sans Fallback\"))\n\
                    Станок 16К20Ф3, A↑ = 5.26 µm, 立式加工中心\n\n\
                    #text(font: \"DejaVu Sans Mono\", weight: \"bold\")[X̄i↑ 0.0280]";
        let templates = HashMap::from([("/main.typ".to_string(), main.to_string())]);
        let typesetter = Typesetter::new(templates).unwrap();
        let pdf_on = |lane: usize| {
            on_font_lane(lane, || {
                let world = DocumentWorld::new(&typesetter, "/main.typ", vec![], vec![], None);
                let world = world.unwrap();
                let doc = typst::compile::<typst_layout::PagedDocument>(&world);
                let options = typst_pdf::PdfOptions {
                    ident: typst::foundations::Smart::Custom("lane".into()),
                    ..typst_pdf::PdfOptions::default()
                };
                let fonts: Vec<Font> = (0..typesetter.fonts.len())
                    .filter_map(|i| world.font(i))
                    .collect();
                (
                    typst_pdf::pdf(&doc.output.unwrap(), &options).unwrap(),
                    fonts,
                )
            })
        };
        let (first, fonts_0) = pdf_on(0);
        let (second, fonts_1) = pdf_on(1);
        assert!(first.len() > 1000);
        assert_eq!(first, second);
        for (a, b) in fonts_0.iter().zip(&fonts_1) {
            assert_ne!(a, b, "{}", a.info().family);
            assert_eq!(a.data().len() + 1, b.data().len());
            assert_eq!(a.info(), b.info());
        }
        assert_eq!(
            LANE.get(),
            0,
            "the lane is the thread's again after the work"
        );
    }

    /// Every letter of the names campaign (tests/data/names/) and of GB/T 17421.2's terms
    /// (a report in simplified Chinese) has a glyph in an embedded face: the one the
    /// templates' font list gives it, after Inter.
    #[test]
    fn the_embedded_faces_cover_every_script_of_the_names() {
        let fonts: Vec<Font> = EMBEDDED
            .iter()
            .flat_map(|data| Font::iter(Bytes::new(*data)))
            .collect();
        let family = |c: char| {
            (fonts.iter())
                .find(|f| f.info().coverage.contains(c as u32))
                .map(|f| f.info().family.clone())
        };
        let samples = [
            ("Станок-16К20Ф3 Поворотная ось", "Inter"),
            ("מכונת-כרסום-אנכית ציר", "Noto Sans Hebrew"),
            ("آلة-تفريز-عمودية المحور", "Noto Sans Arabic"),
            ("立式加工中心三号车间精密主轴", "Droid Sans Fallback"),
            (
                "定位精度重复定位精度反向差值系统偏差",
                "Droid Sans Fallback",
            ),
            ("轴线双向单向平均值扩展不确定度合格", "Droid Sans Fallback"),
        ];
        for (text, face) in samples {
            for c in text
                .chars()
                .filter(|c| !c.is_ascii_punctuation() && *c != ' ')
            {
                let found = family(c);
                let expected = if c.is_ascii_alphanumeric() {
                    "Inter"
                } else {
                    face
                };
                assert_eq!(found.as_deref(), Some(expected), "{c:?} in {text}");
            }
        }
    }
}
