//! The templates' `text-lines` function: strings set as the lines of one paragraph in the
//! current text and paragraph style, as Typst sets `lines.join("\n")`, shaped and placed
//! by axcheck when they are plain (see [`super::shaping`]), else laid out by Typst.
//!
//! The reports' tables are columns of values and the charts' labels short strings; set by
//! Typst's paragraph layout they were a third of a report's time. The result is the same
//! frame either way: line `i`'s baseline lies `top + i × (top + bottom + leading)` below
//! the top (the text's edges and the paragraph's leading), each line aligned as the
//! paragraph is, in a frame as wide as the widest line (or the region, when it expands).

use super::shaping::{Line, Setting};
use typst::diag::SourceResult;
use typst::engine::Engine;
use typst::foundations::{Content, NativeElement, Packed, Str, StyleChain};
use typst::introspection::Locator;
use typst::layout::{Abs, BlockElem, Frame, FrameItem, Point, Region, Size};
use typst::syntax::Span;
use typst::text::TextElem;
use typst_library::foundations::{elem, func};
use typst_utils::Numeric;

/// Strings as the lines of a paragraph in the current text style (`none` for an empty
/// line): like `lines.join("\n")` set as text, faster. Show rules on text do not apply.
#[func]
pub fn text_lines(
    span: Span,
    /// The lines.
    lines: Vec<Option<Str>>,
) -> Content {
    let lines = lines.into_iter().map(Option::unwrap_or_default).collect();
    let elem = TextLinesElem::new(lines);
    BlockElem::single_layouter(Packed::new(elem).spanned(span), layout).pack()
}

/// What the layout of `text-lines` needs.
#[elem(name = "text-lines-data")]
pub struct TextLinesElem {
    /// The lines.
    #[required]
    pub lines: Vec<Str>,
}

fn layout(
    elem: &Packed<TextLinesElem>,
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    region: Region,
) -> SourceResult<Frame> {
    let lines: Vec<&str> = elem.lines.iter().map(Str::as_str).collect();
    paragraph(engine, locator, styles, &lines, region, elem.span())
}

/// `lines` as a paragraph in `styles`, laid out in `region`: directly when they are plain
/// and fit, else by Typst.
pub fn paragraph(
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    lines: &[&str],
    region: Region,
    span: Span,
) -> SourceResult<Frame> {
    let direct = Setting::of(engine.world, styles).and_then(|setting| {
        let shaped = setting.lines(lines, span)?;
        place(&setting, shaped, region)
    });
    match direct {
        Some(frame) => Ok(frame),
        None => {
            let text = TextElem::packed(lines.join("\n")).spanned(span);
            typst_layout::layout_frame(engine, &text, locator, styles, region)
        }
    }
}

/// The lines stacked and aligned, `None` when one does not fit the region (Typst would
/// break it).
fn place(setting: &Setting, lines: Vec<Line>, region: Region) -> Option<Frame> {
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
    let mut frame = Frame::soft(Size::new(width, total));
    frame.set_baseline(setting.top);
    let mut top = Abs::zero();
    for line in lines {
        let x = setting.align.position(width - line.width + line.overhang);
        let baseline = top + setting.top;
        for (at, item) in line.items {
            let at = Point::new(x + at.x, baseline + at.y);
            frame.push(at, FrameItem::Text(item));
        }
        top += height + setting.leading;
    }
    Some(frame)
}
