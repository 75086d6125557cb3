//! The templates' `text-lines` and `text-columns` functions: strings set as the lines of a
//! paragraph in the current text and paragraph style, as Typst sets `lines.join("\n")`,
//! shaped and placed by axcheck when they are plain (see [`crate::report::typeset::shaping`]), else laid
//! out by Typst.
//!
//! The reports' tables are columns of values and the charts' labels short strings; set by
//! Typst's paragraph layout, each in a box placed and aligned by Typst, they were a third
//! of a report's time. The result is the same either way: line `i`'s baseline lies
//! `top + i × (top + bottom + leading)` below the top (the text's edges and the
//! paragraph's leading), each line aligned as the paragraph is, in a frame as wide as the
//! widest line (or the region, when it expands).

use crate::report::typeset::shaping::{Line, Setting};
use typst::comemo::Tracked;
use typst::diag::{At, HintedStrResult, SourceResult};
use typst::engine::Engine;
use typst::foundations::{
    Array, Content, Context, Dict, NativeElement, Packed, Resolve, Str, StyleChain, Styles, Value,
};
use typst::introspection::Locator;
use typst::layout::{
    Abs, AlignElem, Alignment, Axes, BlockElem, Dir, Em, Frame, FrameItem, Length, Point, Region,
    Rel, Size,
};
use typst::syntax::Span;
use typst::text::{FontWeight, Glyph, TextElem, TextItem, TextSize};
use typst::visualize::Paint;
use typst_library::foundations::{elem, func};
use typst_utils::Numeric;

/// Strings as the lines of a paragraph in the current text style (`none` for an empty
/// line): like `lines.join("\n")` set as text, faster. Show rules on text do not apply.
#[func]
pub(crate) fn text_lines(
    span: Span,
    /// The lines.
    lines: Vec<Option<Str>>,
) -> Content {
    let lines = lines.into_iter().map(Option::unwrap_or_default).collect();
    let elem = TextLinesElem::new(lines);
    BlockElem::single_layouter(Packed::new(elem).spanned(span), layout_lines).pack()
}

/// The width of each string set on one line in the current text style, as `measure` gives
/// it, or `none` for a string `text-lines` would leave to Typst (see `text-lines`):
/// cheaper than `measure`, for a template that places columns itself.
#[func(contextual)]
pub(crate) fn text_widths(
    engine: &mut Engine,
    context: Tracked<Context>,
    span: Span,
    /// The strings.
    strings: Vec<Str>,
) -> SourceResult<Array> {
    let styles = context.styles().at(span)?;
    let setting = Setting::of(engine.world, styles);
    Ok(strings
        .iter()
        .map(|s| {
            let line = setting
                .as_ref()
                .and_then(|set| set.lines(&[s.as_str()], span));
            match line.as_deref() {
                Some([line]) => Value::Length(line.width.into()),
                _ => Value::None,
            }
        })
        .collect())
}

/// What the layout of `text-lines` needs.
#[elem(name = "text-lines-data")]
pub(crate) struct TextLinesElem {
    /// The lines.
    #[required]
    pub lines: Vec<Str>,
}

fn layout_lines(
    elem: &Packed<TextLinesElem>,
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    region: Region,
) -> SourceResult<Frame> {
    let lines: Vec<&str> = elem.lines.iter().map(Str::as_str).collect();
    let setting = Setting::of(engine.world, styles);
    let lines = Paragraph {
        lines: &lines,
        region,
        span: elem.span(),
    };
    paragraph(engine, locator, styles, setting.as_ref(), lines)
}

/// Columns of lines side by side, one paragraph each, as in a table: every column a
/// dictionary with `x` (where the column stands, relative to the width), `align` (`left`:
/// its lines start at `x`, `center`: centred on `x`, `right`: end at `x`), `lines` (as for
/// `text-lines`) and, to set it apart, `fill`, `weight` or `size`. As placing a
/// `text-lines` per column at `x`, faster.
/// A column's fields are read when it is laid out (and a wrong one reported there).
#[func]
pub(crate) fn text_columns(
    span: Span,
    /// The columns.
    columns: Vec<Dict>,
) -> Content {
    let elem = TextColumnsElem::new(columns);
    BlockElem::single_layouter(Packed::new(elem).spanned(span), layout_columns).pack()
}

/// What the layout of `text-columns` needs.
#[elem(name = "text-columns-data")]
pub(crate) struct TextColumnsElem {
    /// The columns.
    #[required]
    pub columns: Vec<Dict>,
}

/// One column of `text-columns`.
struct Column {
    x: Rel<Length>,
    align: Alignment,
    lines: Vec<Str>,
    style: Styles,
}

impl Column {
    fn of(dict: &Dict) -> HintedStrResult<Column> {
        let field = |key: &str| dict.get(key).ok().cloned();
        let lines: Vec<Option<Str>> = field("lines").unwrap_or(Value::None).cast()?;
        let mut style = Styles::new();
        if let Some(fill) = field("fill") {
            style.set(TextElem::fill, fill.cast::<Paint>()?);
        }
        if let Some(weight) = field("weight") {
            style.set(TextElem::weight, weight.cast::<FontWeight>()?);
        }
        if let Some(size) = field("size") {
            style.set(TextElem::size, TextSize(size.cast::<Length>()?));
        }
        let align = match field("align") {
            Some(align) => align.cast::<Alignment>()?,
            None => Alignment::LEFT,
        };
        style.set(AlignElem::alignment, align);
        Ok(Column {
            x: field("x").map_or(Ok(Rel::zero()), Value::cast)?,
            align,
            lines: lines.into_iter().map(Option::unwrap_or_default).collect(),
            style,
        })
    }
}

fn layout_columns(
    elem: &Packed<TextColumnsElem>,
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    region: Region,
) -> SourceResult<Frame> {
    let span = elem.span();
    let mut locator = locator.split();
    let pod = Region::new(region.size, Axes::splat(false));
    let mut pieces = Vec::new();
    let mut frames = Vec::new();
    let mut right = Abs::zero();
    let mut height = Abs::zero();
    let mut settings = ParagraphSettings::default();
    for dict in &elem.columns {
        let column = Column::of(dict).at(span)?;
        let lines: Vec<&str> = column.lines.iter().map(Str::as_str).collect();
        let setting = settings.of(engine, styles, &column.style);
        let styles = styles.chain(&column.style);
        let x = column.x.resolve(styles).relative_to(region.size.x);
        let align = column.align.fix(Dir::LTR).x;
        let paragraph = Paragraph {
            lines: &lines,
            region: pod,
            span,
        };
        let laid = lay_out(engine, locator.next(&()), styles, setting, paragraph)?;
        let size = laid.size();
        let x = x - align.position(size.x);
        right.set_max(x + size.x);
        height.set_max(size.y);
        match laid {
            Laid::Direct(_, _, column) => pieces.extend(column.into_iter().map(|p| p.moved(x))),
            Laid::Typst(frame) => frames.push((x, frame)),
        }
    }
    let width = if region.size.x.is_finite() {
        region.size.x
    } else {
        right
    };
    let mut frame = Frame::soft(Size::new(width, height));
    for piece in rows(pieces) {
        frame.push(piece.at, FrameItem::Text(piece.item));
    }
    for (x, column) in frames {
        frame.push_frame(Point::with_x(x), column);
    }
    Ok(frame)
}

/// A text item of a paragraph line: where it goes and the baseline of its line (an item
/// of marks lies off the baseline).
struct Piece {
    line: Abs,
    at: Point,
    item: TextItem,
}

impl Piece {
    fn moved(mut self, dx: Abs) -> Piece {
        self.at.x += dx;
        self
    }
}

/// The least gap between two columns that makes them one text run.
const COLUMN_GAP: Abs = Abs::raw(0.5);

/// Text items of the same look on the same baseline, columns apart, joined into one run
/// across the row, a space between columns as wide as the gap: the PDF writes a text
/// object per item (a graphics state, a font, a position: a hundred bytes and its own
/// cost each), and a table row in one run reads, copied or searched, like the row. Items
/// in a line, apart by less than [`COLUMN_GAP`], stay apart.
fn rows(mut pieces: Vec<Piece>) -> Vec<Piece> {
    pieces.sort_by(|a, b| a.line.cmp(&b.line).then(a.at.x.cmp(&b.at.x)));
    let mut out: Vec<(Piece, Abs)> = Vec::with_capacity(pieces.len());
    for piece in pieces {
        let end = piece.at.x + piece.item.width();
        if let Some((last, last_end)) = out.last_mut()
            && last.line == piece.line
            && last.at.y == piece.at.y
            && piece.at.x - *last_end >= COLUMN_GAP
            && look(&last.item) == look(&piece.item)
            && let Some(space) = piece.item.font.ttf().glyph_index(' ')
        {
            join(&mut last.item, space.0, piece.at.x - *last_end, piece.item);
            *last_end = end;
            continue;
        }
        out.push((piece, end));
    }
    out.into_iter().map(|(piece, _)| piece).collect()
}

/// What must be alike for two items to be one.
fn look(item: &TextItem) -> impl PartialEq + '_ {
    (
        &item.font,
        item.size,
        &item.fill,
        &item.stroke,
        item.lang,
        item.region,
    )
}

/// `next` appended to `run` after a space glyph `gap` wide.
fn join(run: &mut TextItem, space: u16, gap: Abs, next: TextItem) {
    let at = |i: usize| u16::try_from(i).unwrap_or(u16::MAX);
    let start = run.text.len();
    let span = next.glyphs.first().map_or(Span::detached(), |g| g.span.0);
    run.glyphs.push(Glyph {
        id: space,
        x_advance: Em::from_abs(gap, run.size),
        x_offset: Em::zero(),
        y_advance: Em::zero(),
        y_offset: Em::zero(),
        range: at(start)..at(start + 1),
        span: (span, 0),
    });
    run.text.push(' ');
    let shift = at(start + 1);
    run.glyphs.extend(next.glyphs.into_iter().map(|mut g| {
        g.range = g.range.start.saturating_add(shift)..g.range.end.saturating_add(shift);
        g
    }));
    run.text.push_str(&next.text);
}

/// A paragraph to set: its lines, the region it is laid out in and where it comes from.
pub(crate) struct Paragraph<'a> {
    pub lines: &'a [&'a str],
    pub region: Region,
    pub span: Span,
}

/// The settings of one element's paragraphs, made once per style that sets some apart
/// (a column's or a label's): reading a style chain is most of a short paragraph's cost.
#[derive(Default)]
pub(crate) struct ParagraphSettings(Vec<(Styles, Option<Setting>)>);

impl ParagraphSettings {
    /// The setting of `base` (the same for every call) with `local` on top.
    pub fn of(&mut self, engine: &Engine, base: StyleChain, local: &Styles) -> Option<&Setting> {
        let i = match self.0.iter().position(|(style, _)| style == local) {
            Some(i) => i,
            None => {
                let setting = Setting::of(engine.world, base.chain(local));
                self.0.push((local.clone(), setting));
                self.0.len() - 1
            }
        };
        self.0[i].1.as_ref()
    }
}

/// A paragraph in `styles` (whose setting is `setting`): directly when its lines are plain
/// and fit, else by Typst.
pub fn paragraph(
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    setting: Option<&Setting>,
    paragraph: Paragraph,
) -> SourceResult<Frame> {
    Ok(
        match lay_out(engine, locator, styles, setting, paragraph)? {
            Laid::Direct(size, baseline, pieces) => {
                let mut frame = Frame::soft(size);
                frame.set_baseline(baseline);
                for piece in pieces {
                    frame.push(piece.at, FrameItem::Text(piece.item));
                }
                frame
            }
            Laid::Typst(frame) => frame,
        },
    )
}

/// A paragraph laid out: its size, first baseline and text items, or Typst's frame.
enum Laid {
    Direct(Size, Abs, Vec<Piece>),
    Typst(Frame),
}

impl Laid {
    fn size(&self) -> Size {
        match self {
            Laid::Direct(size, _, _) => *size,
            Laid::Typst(frame) => frame.size(),
        }
    }
}

fn lay_out(
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    setting: Option<&Setting>,
    paragraph: Paragraph,
) -> SourceResult<Laid> {
    let Paragraph {
        lines,
        region,
        span,
    } = paragraph;
    let direct = setting.and_then(|setting| place(setting, setting.lines(lines, span)?, region));
    Ok(match direct {
        Some(laid) => laid,
        None => {
            let text = TextElem::packed(lines.join("\n")).spanned(span);
            let frame = typst_layout::layout_frame(engine, &text, locator, styles, region)?;
            Laid::Typst(frame)
        }
    })
}

/// The lines stacked and aligned, `None` when a line does not fit the region (Typst would
/// break it).
fn place(setting: &Setting, lines: Vec<Line>, region: Region) -> Option<Laid> {
    if lines.iter().any(|l| l.width > region.size.x) {
        return None;
    }
    let widest = lines.iter().map(|l| l.width).fold(Abs::zero(), Abs::max);
    let width = if region.expand.x && region.size.x.is_finite() {
        region.size.x
    } else {
        region.size.x.min(widest)
    };
    let height = setting.top + setting.bottom;
    let count = lines.len() as f64;
    let total = height * count + setting.leading * (count - 1.0).max(0.0);
    let mut pieces = Vec::new();
    let mut top = Abs::zero();
    for line in lines {
        let x = setting.align.position(width - line.width + line.overhang);
        let baseline = top + setting.top;
        for (at, item) in line.items {
            let at = Point::new(x + at.x, baseline + at.y);
            pieces.push(Piece {
                line: baseline,
                at,
                item,
            });
        }
        top += height + setting.leading;
    }
    Some(Laid::Direct(Size::new(width, total), setting.top, pieces))
}

#[cfg(test)]
mod tests {
    use crate::report::typeset::world::{DocumentWorld, Typesetter};
    use std::collections::HashMap;
    use typst::layout::{Frame, FrameItem, Point};
    use typst_layout::PagedDocument;

    /// A glyph where it is drawn: x and y in millionths of a point, and its id.
    type Placed = (i64, i64, u16);

    /// Every glyph but spaces, where it is drawn.
    fn glyphs(frame: &Frame, at: Point, out: &mut Vec<Placed>) {
        let round = |v: f64| (v * 1e6).round() as i64;
        for (pos, item) in frame.items() {
            let pos = at + *pos;
            match item {
                FrameItem::Group(group) => glyphs(&group.frame, pos, out),
                FrameItem::Text(text) => {
                    let mut x = pos.x;
                    for g in &text.glyphs {
                        let c = &text.text[g.range()];
                        if c != " " {
                            let gx = x + g.x_offset.at(text.size);
                            out.push((round(gx.to_pt()), round(pos.y.to_pt()), g.id));
                        }
                        x += g.x_advance.at(text.size);
                    }
                }
                _ => {}
            }
        }
    }

    /// The glyphs of the first page above `split` pt and below it, moved up by `split`.
    fn halves(main: &str, split: f64) -> (Vec<Placed>, Vec<Placed>) {
        let templates = HashMap::from([
            ("/main.typ".to_string(), main.to_string()),
            (
                "/style.typ".to_string(),
                include_str!("../../../templates/style.typ").to_string(),
            ),
        ]);
        let typesetter = Typesetter::new(templates).unwrap();
        // style.typ reads the report's words from /words.json (`t`, `lang`).
        let data = vec![("/words.json".to_string(), b"{}".to_vec())];
        let world = DocumentWorld::new(&typesetter, "/main.typ", data, vec![], None).unwrap();
        let doc = typst::compile::<PagedDocument>(&world).output.unwrap();
        let mut all = Vec::new();
        glyphs(&doc.pages()[0].frame, Point::zero(), &mut all);
        let cut = (split * 1e6) as i64;
        let (mut top, mut bottom): (Vec<_>, Vec<_>) = all.into_iter().partition(|g| g.1 < cut);
        for g in &mut bottom {
            g.1 -= cut;
        }
        top.sort();
        bottom.sort();
        (top, bottom)
    }

    /// The same glyphs at the same places, to a millionth of a point (sums of advances
    /// taken in another order round differently).
    fn same_places(a: &[Placed], b: &[Placed]) {
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert!(
                (x.0 - y.0).abs() <= 1 && x.1 == y.1 && x.2 == y.2,
                "{x:?} {y:?}"
            );
        }
    }

    const SETUP: &str = r#"
        #set page(width: 400pt, height: 600pt, margin: 0pt)
        #set text(font: "Inter", size: 9pt, kerning: false, top-edge: 6pt, bottom-edge: 0pt)
        #set par(leading: 4pt)
        #let lines = ("12.5", "−3.25", "X̄i↑, X̄i↓", "j = 1", "", "Ось X", "2σi", "1.")
    "#;

    #[test]
    fn text_lines_set_lines_where_typst_sets_them() {
        let main = format!(
            r#"{SETUP}
            #place(top + left, text-lines(lines))
            #place(top + right, dx: -20pt, align(right, text-lines(lines)))
            #place(top + left, dx: 100pt, box(width: 80pt, align(center, text-lines(lines))))
            #place(top + left, dy: 300pt, lines.join("\n"))
            #place(top + right, dx: -20pt, dy: 300pt, align(right, lines.join("\n")))
            #place(top + left, dx: 100pt, dy: 300pt, box(width: 80pt, align(center, lines.join("\n"))))
            "#
        );
        let (direct, typst) = halves(&main, 300.0);
        assert!(direct.len() > 60, "{}", direct.len());
        same_places(&direct, &typst);
    }

    /// Names in scripts Inter lacks: set by Typst from the reports' fallback faces (the
    /// direct path refuses them), Latin lines still directly, each as Typst sets it, and
    /// none a `.notdef` box (glyph 0), as CJK names were.
    #[test]
    fn letters_inter_lacks_come_from_the_fallback_faces() {
        let main = r#"
            #import "/style.typ": sans
            #set page(width: 400pt, height: 600pt, margin: 0pt)
            #set text(font: sans, size: 9pt)
            #let lines = ("主轴Z轴", "12.5", "ציר Y", "المحور X", "Ось X", "三号车间")
            #place(top + left, text-lines(lines))
            #place(top + left, dy: 300pt, lines.join("\n"))
        "#;
        let (direct, typst) = halves(main, 300.0);
        // Every letter and digit, the Arabic ones joined but not ligated.
        assert_eq!(direct.len(), 27);
        same_places(&direct, &typst);
        assert!(direct.iter().all(|g| g.2 != 0), "{direct:?}");
    }

    #[test]
    fn text_columns_set_columns_where_typst_sets_them() {
        let main = format!(
            r#"{SETUP}
            #place(top + left, text-columns((
              (x: 0pt, lines: lines),
              (x: 150pt, align: right, weight: "bold", lines: lines.rev()),
              (x: 250pt, align: center, size: 7pt, fill: red, lines: lines),
            )))
            #place(top + left, dy: 300pt, lines.join("\n"))
            #place(top + right, dx: 150pt - 400pt, dy: 300pt, align(right, text(weight: "bold", lines.rev().join("\n"))))
            #place(top + left, dx: 150pt, dy: 300pt, box(width: 200pt, align(center, text(size: 7pt, fill: red, lines.join("\n")))))
            "#
        );
        let (direct, typst) = halves(&main, 300.0);
        assert!(direct.len() > 80, "{}", direct.len());
        same_places(&direct, &typst);
    }
}
