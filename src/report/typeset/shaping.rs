//! Plain lines of text shaped by axcheck, the way Typst's paragraph layout shapes them.
//!
//! A report sets a few thousand short strings (table values, chart labels), and Typst's
//! paragraph layout costs far more per string than shaping it does: collecting, bidi
//! analysis, line breaking and measuring are generic machinery a number in a table
//! column does not need. [`Setting::of`] reads the text style of a style chain and
//! refuses (`None`) whatever it does not reproduce exactly; [`Setting::line`] shapes one
//! line with rustybuzz, the plan, features and font Typst would use, split into runs by
//! script as Typst splits them, and refuses lines with characters the first font lacks,
//! right-to-left or control characters, or surrounding spaces. Whatever is refused is laid
//! out by Typst itself (see [`crate::report::typeset::text_lines`]), so the result is always Typst's.

use std::ops::Range;
use std::sync::Arc;
use typst::World;
use typst::comemo::Tracked;
use typst::foundations::StyleChain;
use typst::layout::{Abs, Dir, Em, FixedAlignment, Point};
use typst::model::{LinkElem, ParElem, ParLine};
use typst::syntax::Span;
use typst::text::{
    BottomEdge, BottomEdgeMetric, FontInstance, Glyph, Lang, Region, TextEdgeBounds, TextElem,
    TextItem, TopEdge, TopEdgeMetric,
};
use typst::visualize::{FixedStroke, Paint};
use typst_library::layout::{AlignElem, HideElem};
use typst_utils::Numeric;
use unicode_bidi::BidiClass;
use unicode_script::{Script, UnicodeScript};

/// The text style of a style chain, when plain lines in it can be shaped here.
pub(crate) struct Setting {
    font: FontInstance,
    size: Abs,
    fill: Paint,
    stroke: Option<FixedStroke>,
    lang: Lang,
    region: Option<Region>,
    language: rustybuzz::Language,
    features: Vec<rustybuzz::Feature>,
    overhang: bool,
    /// The extent of a line above and below its baseline.
    pub top: Abs,
    pub bottom: Abs,
    /// Between two lines.
    pub leading: Abs,
    pub align: FixedAlignment,
}

/// A shaped line: its text items (positions relative to the line's start on its baseline)
/// and its width.
pub struct Line {
    pub items: Vec<(Point, TextItem)>,
    pub width: Abs,
    /// What a punctuation mark at the line's end may hang into the margin (Typst's
    /// `overhang`): added to the room the alignment distributes.
    pub(crate) overhang: Abs,
}

impl Setting {
    /// The setting of `styles`, `None` when it asks for something only Typst's paragraph
    /// layout does (tracking, word spacing, decorations, case, sub- or superscripts,
    /// right-to-left text, justification, indents, line numbers, links, hidden text, a
    /// font family with a coverage, edges from glyph bounds) or names no available font.
    pub fn of(world: Tracked<dyn World + '_>, styles: StyleChain) -> Option<Setting> {
        let plain = styles.resolve(TextElem::tracking).is_zero()
            && styles.resolve(TextElem::spacing) == typst::layout::Rel::one()
            && styles.resolve(TextElem::baseline).is_zero()
            && styles.get_cloned(TextElem::deco).is_empty()
            && styles.get_ref(TextElem::case).is_none()
            && styles.get_ref(TextElem::shift_settings).is_none()
            && styles.get(TextElem::script).is_auto()
            && styles.resolve(TextElem::dir) == Dir::LTR
            && !styles.get(ParElem::justify)
            && styles.get(ParElem::first_line_indent).amount().is_zero()
            && styles.resolve(ParElem::hanging_indent).is_zero()
            && styles.get_ref(ParLine::numbering).is_none()
            && styles.get_ref(LinkElem::current).is_none()
            && !styles.get(HideElem::hidden);
        let top_edge = styles.get(TextElem::top_edge);
        let bottom_edge = styles.get(TextElem::bottom_edge);
        let bounds = matches!(top_edge, TopEdge::Metric(TopEdgeMetric::Bounds))
            || matches!(bottom_edge, BottomEdge::Metric(BottomEdgeMetric::Bounds));
        if !plain || bounds {
            return None;
        }
        let family = typst::text::families(styles).next()?;
        if family.covers().is_some() {
            return None;
        }
        let variant = typst::text::variant(styles);
        let size = styles.resolve(TextElem::size);
        let font = world
            .font(world.book().select(family.as_str(), variant)?)?
            .instantiate(variant, size, &styles.get_cloned(TextElem::variations));
        let (top, bottom) = font.edges(top_edge, bottom_edge, size, TextEdgeBounds::Zero);
        Some(Setting {
            size,
            fill: styles.get_ref(TextElem::fill).clone(),
            stroke: styles
                .resolve(TextElem::stroke)
                .map(|s| s.unwrap_or_default()),
            lang: styles.get(TextElem::lang),
            region: styles.get(TextElem::region),
            language: typst::text::language(styles),
            features: typst::text::features(styles),
            overhang: styles.get(TextElem::overhang),
            top: top.max(Abs::zero()),
            bottom: bottom.max(Abs::zero()),
            leading: styles.resolve(ParElem::leading),
            align: styles.get(AlignElem::alignment).fix(Dir::LTR).x,
            font,
        })
    }

    /// `lines` shaped as the lines of one paragraph, `None` when Typst's layout must set
    /// them (see the module docs).
    pub fn lines(&self, lines: &[&str], span: Span) -> Option<Vec<Line>> {
        // The script of the text so far: a paragraph's runs continue across lines.
        let mut script = Script::Unknown;
        lines
            .iter()
            .map(|text| self.line(text, &mut script, span))
            .collect()
    }

    fn line(&self, text: &str, script: &mut Script, span: Span) -> Option<Line> {
        let mut line = Line {
            items: Vec::new(),
            width: Abs::zero(),
            overhang: Abs::zero(),
        };
        if text.is_empty() {
            return Some(line);
        }
        if !plain_line(text) {
            return None;
        }
        let mut last = None;
        for run in script_runs(text, script) {
            let glyphs = shape(
                &self.font,
                &text[run.clone()],
                &self.language,
                &self.features,
            )?;
            if let Some(g) = glyphs.last() {
                last = Some((
                    g.x_advance,
                    text[run.start + g.range.start..].chars().next(),
                ));
            }
            self.push_run(&mut line, &text[run], &glyphs, span);
        }
        // Typst lets a mark at the end of a line of more than one glyph hang out.
        let glyphs: usize = line.items.iter().map(|(_, i)| i.glyphs.len()).sum();
        if self.overhang
            && glyphs > 1
            && let Some((advance, Some(c))) = last
        {
            line.overhang = advance.at(self.size) * overhang(c);
        }
        Some(line)
    }

    /// The text items of one run: a new item wherever the vertical offset changes, as
    /// Typst groups glyphs.
    fn push_run(&self, line: &mut Line, text: &str, glyphs: &[Shaped], span: Span) {
        for group in glyphs.chunk_by(|a, b| a.y_offset == b.y_offset) {
            let start = group.iter().map(|g| g.range.start).min().unwrap_or(0);
            let end = group.iter().map(|g| g.range.end).max().unwrap_or(0);
            let relative = |r: &Range<usize>| {
                let at = |i: usize| u16::try_from(i - start).unwrap_or(u16::MAX);
                at(r.start)..at(r.end)
            };
            let item = TextItem {
                font: self.font.clone(),
                size: self.size,
                fill: self.fill.clone(),
                stroke: self.stroke.clone(),
                lang: self.lang,
                region: self.region,
                text: text[start..end].into(),
                glyphs: group
                    .iter()
                    .map(|g| Glyph {
                        id: g.id,
                        x_advance: g.x_advance,
                        x_offset: g.x_offset,
                        y_advance: Em::zero(),
                        y_offset: Em::zero(),
                        range: relative(&g.range),
                        span: (span, 0),
                    })
                    .collect(),
            };
            let y = -group[0].y_offset.at(self.size);
            let width: Abs = group.iter().map(|g| g.x_advance.at(self.size)).sum();
            line.items.push((Point::new(line.width, y), item));
            line.width += width;
        }
    }
}

/// Whether Typst would set `text` as it is on one line of an left-to-right paragraph: no
/// space at either end (trimmed or kept by rules of its own), no control, bidi or
/// no-break character.
fn plain_line(text: &str) -> bool {
    let ends = |c: Option<char>| c.is_some_and(|c| !c.is_whitespace());
    ends(text.chars().next())
        && ends(text.chars().next_back())
        && text.chars().all(|c| {
            !c.is_control()
                && c != '\u{00A0}'
                && c != '\u{00AD}'
                && !matches!(
                    unicode_bidi::bidi_class(c),
                    BidiClass::R
                        | BidiClass::AL
                        | BidiClass::AN
                        | BidiClass::B
                        | BidiClass::S
                        | BidiClass::LRE
                        | BidiClass::LRO
                        | BidiClass::RLE
                        | BidiClass::RLO
                        | BidiClass::PDF
                        | BidiClass::LRI
                        | BidiClass::RLI
                        | BidiClass::FSI
                        | BidiClass::PDI
                )
        })
}

/// Byte ranges of `text` with one script each, as Typst's paragraph layout splits a
/// left-to-right text before shaping: common and inherited characters join their
/// neighbours. `previous` is the script of the text before (the lines above), and after.
fn script_runs(text: &str, previous: &mut Script) -> Vec<Range<usize>> {
    let generic = |s: Script| matches!(s, Script::Unknown | Script::Common | Script::Inherited);
    let mut runs = Vec::new();
    let mut start = 0;
    for (i, c) in text.char_indices() {
        let script = c.script();
        if !(generic(script) || generic(*previous) || script == *previous) {
            if start < i {
                runs.push(start..i);
            }
            start = i;
            *previous = script;
        } else if generic(*previous) {
            *previous = script;
        }
    }
    runs.push(start..text.len());
    runs
}

/// A glyph as the shaper placed it; `range` is the bytes of its cluster in the run.
#[derive(Clone)]
struct Shaped {
    id: u16,
    x_advance: Em,
    x_offset: Em,
    y_offset: Em,
    range: Range<usize>,
}

/// The glyphs of a run, `None` when the font lacks one of its characters (Typst would
/// take them from another font). Remembered: the same values and labels recur across a
/// campaign's reports (Typst's caches are cleared between batches of reports, these with
/// them).
#[comemo::memoize]
fn shape(
    font: &FontInstance,
    text: &str,
    language: &rustybuzz::Language,
    features: &[rustybuzz::Feature],
) -> Option<Arc<Vec<Shaped>>> {
    let mut buffer = rustybuzz::UnicodeBuffer::new();
    buffer.push_str(text);
    buffer.set_language(language.clone());
    buffer.set_direction(rustybuzz::Direction::LeftToRight);
    buffer.guess_segment_properties();
    buffer.set_flags(rustybuzz::BufferFlags::REMOVE_DEFAULT_IGNORABLES);
    let plan = shape_plan(font, buffer.script(), language, features);
    let shaped = rustybuzz::shape_with_plan(font.rusty(), &plan, buffer);
    let infos = shaped.glyph_infos();
    let positions = shaped.glyph_positions();
    let mut glyphs = Vec::with_capacity(infos.len());
    for (i, (info, pos)) in infos.iter().zip(positions).enumerate() {
        if info.glyph_id == 0 {
            return None;
        }
        let start = info.cluster as usize;
        // A cluster's glyphs all cover the whole cluster, as Typst assigns them.
        let end = infos[i + 1..]
            .iter()
            .find(|next| next.cluster != info.cluster)
            .map_or(text.len(), |next| next.cluster as usize);
        glyphs.push(Shaped {
            id: u16::try_from(info.glyph_id).ok()?,
            x_advance: font.to_em(pos.x_advance),
            x_offset: font.to_em(pos.x_offset),
            y_offset: font.to_em(pos.y_offset),
            range: start..end,
        });
    }
    Some(Arc::new(glyphs))
}

/// The shape plan Typst would make for these.
#[comemo::memoize]
fn shape_plan(
    font: &FontInstance,
    script: rustybuzz::Script,
    language: &rustybuzz::Language,
    features: &[rustybuzz::Feature],
) -> Arc<rustybuzz::ShapePlan> {
    Arc::new(rustybuzz::ShapePlan::new(
        font.rusty(),
        rustybuzz::Direction::LeftToRight,
        Some(script),
        Some(language),
        features,
    ))
}

/// How much a character at the end of a line hangs into the margin (Typst's table).
fn overhang(c: char) -> f64 {
    match c {
        '–' | '—' => 0.2,
        '-' | '\u{ad}' => 0.55,
        '.' | ',' => 0.8,
        ':' | ';' => 0.3,
        '\u{60C}' | '\u{6D4}' => 0.4,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn runs_split_where_typst_splits_them() {
        let runs = |t: &str, script: &mut Script| -> Vec<String> {
            let runs = script_runs(t, script);
            runs.into_iter().map(|r| t[r].to_string()).collect()
        };
        let mut script = Script::Unknown;
        assert_eq!(runs("12.5 µm", &mut script), ["12.5 µm"]);
        assert_eq!(runs("2σi", &mut script), ["2", "σ", "i"]);
        assert_eq!(runs("X̄i↑, X̄i↓", &mut script), ["X̄i↑, X̄i↓"]);
        assert_eq!(runs("Ось X", &mut script), ["Ось ", "X"]);
        let mut script = Script::Unknown;
        assert_eq!(runs("2σi", &mut script), ["2σ", "i"]);
    }

    #[test]
    fn only_plain_lines_are_set_here() {
        assert!(plain_line("−12.34"));
        assert!(plain_line("j = 1"));
        assert!(!plain_line(""));
        assert!(!plain_line(" 1"));
        assert!(!plain_line("1 "));
        assert!(!plain_line("a\tb"));
        assert!(!plain_line("שלום"));
        assert!(!plain_line("1\u{00A0}mm"));
    }
}
