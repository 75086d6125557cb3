//! The templates' `chart-drawing` function: a chart (`/charts/NAME.drawing`: a
//! [`Drawing`] and its [`ChartLabels`] as bytes) laid out as Typst shapes and text, built
//! directly as frame items.
//!
//! Handing Typst the drawing as an SVG image cost a fifth of a report: the SVG decoder
//! parsed the text into a tree, and the PDF writer turned the tree into an image object of
//! its own. Here the shapes go straight into the page, and the labels are set as text in
//! the current font (see [`crate::report::typeset::text_lines`]), placed as the scene's texts were. The
//! function is defined once in the shared library (see [`crate::report::typeset::world`]) and reads the
//! chart through the document's `World`, so Typst's caches see it as data like any file.

use crate::report::typeset::text_lines::{self, Paragraph, ParagraphSettings};
use axcheck_charts::chart_kit::labels::{ChartLabels, Label};
use axcheck_charts::chart_kit::scene::{Colour, Drawing, Outline, Paint};
use typst::diag::{At, SourceResult};
use typst::engine::Engine;
use typst::foundations::{Bytes, Content, NativeElement, Packed, Resolve, StyleChain, Styles};
use typst::introspection::{Locator, SplitLocator};
use typst::layout::{
    Abs, AlignElem, Alignment, Angle, Axes, BlockElem, Frame, FrameItem, GroupItem, Length, Point,
    Ratio, Region, Size, Transform,
};
use typst::loading::{DataSource, Load};
use typst::model::ParElem;
use typst::syntax::Span;
use typst::syntax::Spanned;
use typst::text::{
    BottomEdge, BottomEdgeMetric, FontWeight, TextElem, TextSize, TopEdge, TopEdgeMetric,
};
use typst::visualize::{
    Color, Curve, DashPattern, FixedStroke, Geometry, Paint as TypstPaint, Shape,
};
use typst_library::foundations::{elem, func};

/// A chart drawn by axcheck (its shapes and labels), `width` wide.
#[func]
pub(crate) fn chart_drawing(
    engine: &mut Engine,
    /// The chart: a path (`"/charts/NAME.drawing"`) or its bytes.
    source: Spanned<DataSource>,
    /// How wide to show it; the height follows.
    width: Length,
) -> SourceResult<Content> {
    let loaded = source.load(engine.world)?;
    let elem = ChartDrawingElem::new(loaded.data, width);
    Ok(BlockElem::single_layouter(Packed::new(elem).spanned(source.span), layout).pack())
}

/// What the layout of a chart drawing needs.
#[elem(name = "chart-drawing-data")]
pub(crate) struct ChartDrawingElem {
    /// The drawing as bytes.
    #[required]
    pub drawing: Bytes,
    /// How wide to show it.
    #[required]
    pub width: Length,
}

fn parse(data: &Bytes) -> Result<(Drawing, ChartLabels), &'static str> {
    let (drawing, rest) = Drawing::decode_front(data.as_slice()).ok_or("not a chart drawing")?;
    match ChartLabels::decode(rest) {
        Some(labels) if drawing.width > 0 && drawing.height > 0 => Ok((drawing, labels)),
        _ => Err("not a chart drawing"),
    }
}

/// The drawing in its own pixels (so the PDF writes whole numbers), scaled to `width`, and
/// the labels over it.
fn layout(
    elem: &Packed<ChartDrawingElem>,
    engine: &mut Engine,
    locator: Locator,
    styles: StyleChain,
    _: Region,
) -> SourceResult<Frame> {
    let (drawing, labels) = parse(&elem.drawing).at(elem.span())?;
    let px = |v: u32| Abs::pt(f64::from(v));
    let mut pixels = Frame::hard(Size::new(px(drawing.width), px(drawing.height)));
    for shape in &drawing.shapes {
        let item = dots(shape).unwrap_or_else(|| {
            let mut curve = Curve::new();
            for outline in &shape.outlines {
                trace(&mut curve, outline);
            }
            painted(Geometry::Curve(curve), &shape.paint, shape.opacity)
        });
        pixels.push(Point::zero(), FrameItem::Shape(item, elem.span()));
    }
    let width = elem.width.resolve(styles);
    let scale = Ratio::new(width.to_pt() / f64::from(drawing.width));
    let mut frame = Frame::hard(Size::new(width, px(drawing.height) * scale.get()));
    let mut group = GroupItem::new(pixels);
    group.transform = Transform::scale(scale, scale);
    frame.push(Point::zero(), FrameItem::Group(group));
    let mut placement = Placement {
        k: scale.get(),
        size: frame.size(),
        locator: locator.split(),
        settings: ParagraphSettings::default(),
        span: elem.span(),
    };
    for label in &labels.labels {
        placement.label(engine, styles, label, &mut frame)?;
    }
    Ok(frame)
}

/// Where the labels go: `k` points per chart pixel, in a frame of `size`; the settings of
/// their looks.
struct Placement<'a> {
    k: f64,
    size: Size,
    locator: SplitLocator<'a>,
    settings: ParagraphSettings,
    span: Span,
}

impl Placement<'_> {
    /// Sets `label` over the drawing as the template's `chart` did with Typst's own
    /// elements: a line's baseline is its top, stacked lines `pitch` apart, each line
    /// aligned on the anchor; a turned label is aligned in its box and turned about its
    /// anchor.
    fn label(
        &mut self,
        engine: &mut Engine,
        base: StyleChain,
        label: &Label,
        frame: &mut Frame,
    ) -> SourceResult<()> {
        let k = self.k;
        let pt = |px: f64| Abs::pt(px * k);
        let local = label_style(label, pt(label.size), pt(label.pitch));
        let setting = self.settings.of(engine, base, &local);
        let styles = base.chain(&local);
        let lines: Vec<&str> = label.text.split('\n').collect();
        let width = self.size.x;
        let locator = self.locator.next(&());
        if label.rotate != 0.0 {
            let region = Region::new(Size::new(pt(label.w), Abs::inf()), Axes::new(true, false));
            let paragraph = Paragraph {
                lines: &lines,
                region,
                span: self.span,
            };
            let text = text_lines::paragraph(engine, locator, styles, setting, paragraph)?;
            let mut turned = Frame::soft(Size::new(pt(label.w), Abs::zero()));
            turned.push_frame(Point::new(pt(label.dx), pt(label.dy)), text);
            let mut group = GroupItem::new(turned);
            group.transform = Transform::rotate(Angle::deg(label.rotate));
            frame.push(
                Point::new(pt(label.x), pt(label.y)),
                FrameItem::Group(group),
            );
            return Ok(());
        }
        let paragraph = Paragraph {
            lines: &lines,
            region: Region::new(self.size, Axes::splat(false)),
            span: self.span,
        };
        let text = text_lines::paragraph(engine, locator, styles, setting, paragraph)?;
        let free = width - text.width();
        let x = match label.align {
            "left" => pt(label.x),
            "center" => free / 2.0 + (pt(label.x) - width / 2.0),
            _ => free + (pt(label.x) - width),
        };
        frame.push_frame(Point::new(x, pt(label.y + label.dy)), text);
        Ok(())
    }
}

/// A label's text style: its size, colour and weight, no kerning (numbers and short words,
/// as in the tables), lines of no height (the first baseline is the top) `pitch` apart,
/// aligned as the label.
fn label_style(label: &Label, size: Abs, pitch: Abs) -> Styles {
    let mut local = Styles::new();
    local.set(TextElem::size, TextSize(size.into()));
    local.set(TextElem::fill, TypstPaint::Solid(hex_colour(&label.fill)));
    let weight = if label.bold {
        FontWeight::BOLD
    } else {
        FontWeight::REGULAR
    };
    local.set(TextElem::weight, weight);
    local.set(TextElem::kerning, false);
    local.set(TextElem::top_edge, TopEdge::Metric(TopEdgeMetric::Baseline));
    local.set(
        TextElem::bottom_edge,
        BottomEdge::Metric(BottomEdgeMetric::Baseline),
    );
    if pitch != Abs::zero() {
        local.set(ParElem::leading, pitch.into());
    }
    let align = match label.align {
        "left" => Alignment::LEFT,
        "center" => Alignment::CENTER,
        _ => Alignment::RIGHT,
    };
    local.set(AlignElem::alignment, align);
    local
}

/// `#RRGGBB` as a colour (black if it is not one).
fn hex_colour(hex: &str) -> Color {
    let channel = |i: usize| {
        hex.get(i..i + 2)
            .and_then(|h| u8::from_str_radix(h, 16).ok())
            .unwrap_or(0)
    };
    Color::from_u8(channel(1), channel(3), channel(5), 255)
}

fn point((x, y): (i32, i32)) -> Point {
    Point::new(Abs::pt(f64::from(x)), Abs::pt(f64::from(y)))
}

/// Filled circles of one radius (a series' markers) as the dots of a line of no length with
/// round caps as wide as the circles: a few bytes each in the page instead of four curves.
/// `None` for other shapes and for one circle alone (PDF writers drop a path of no extent).
fn dots(shape: &axcheck_charts::chart_kit::scene::SceneShape) -> Option<Shape> {
    let Paint::Fill(colour) = shape.paint else {
        return None;
    };
    let radius = match shape.outlines.first()? {
        Outline::Circle(_, r) => *r,
        _ => return None,
    };
    let mut curve = Curve::new();
    for outline in &shape.outlines {
        match outline {
            Outline::Circle(centre, r) if *r == radius => {
                curve.move_(point(*centre));
                curve.line(point(*centre));
            }
            _ => return None,
        }
    }
    if shape.outlines.len() < 2 {
        return None;
    }
    let stroke = Paint::Stroke {
        colour,
        width: 2 * radius,
        dash: Vec::new(),
    };
    let mut dots = painted(Geometry::Curve(curve), &stroke, shape.opacity);
    if let Some(s) = dots.stroke.as_mut() {
        s.cap = typst::visualize::LineCap::Round;
    }
    Some(dots)
}

/// Adds an outline to `curve` as a subpath.
fn trace(curve: &mut Curve, outline: &Outline) {
    let mut polyline = |points: &[(i32, i32)]| {
        for (i, p) in points.iter().enumerate() {
            if i == 0 {
                curve.move_(point(*p));
            } else {
                curve.line(point(*p));
            }
        }
    };
    match outline {
        Outline::Line(points) => polyline(points),
        Outline::Polygon(points) => {
            polyline(points);
            curve.close();
        }
        Outline::Rect((x0, y0), (x1, y1)) => {
            polyline(&[(*x0, *y0), (*x1, *y0), (*x1, *y1), (*x0, *y1)]);
            curve.close();
        }
        Outline::Circle(centre, radius) => circle(curve, *centre, *radius),
    }
}

/// A circle as four cubic Bézier arcs, starting at its left, turning as SVG's arcs do.
fn circle(curve: &mut Curve, (cx, cy): (i32, i32), radius: u32) {
    // The control distance that makes a quarter arc of a unit circle.
    const KAPPA: f64 = 0.552_284_749_831;
    let (cx, cy, r) = (f64::from(cx), f64::from(cy), f64::from(radius));
    let k = KAPPA * r;
    let p = |x: f64, y: f64| Point::new(Abs::pt(x), Abs::pt(y));
    curve.move_(p(cx - r, cy));
    curve.cubic(p(cx - r, cy + k), p(cx - k, cy + r), p(cx, cy + r));
    curve.cubic(p(cx + k, cy + r), p(cx + r, cy + k), p(cx + r, cy));
    curve.cubic(p(cx + r, cy - k), p(cx + k, cy - r), p(cx, cy - r));
    curve.cubic(p(cx - k, cy - r), p(cx - r, cy - k), p(cx - r, cy));
    curve.close();
}

fn painted(geometry: Geometry, paint: &Paint, opacity: f64) -> Shape {
    let colour = |Colour(r, g, b): Colour| {
        let alpha = (opacity.clamp(0.0, 1.0) * 255.0).round() as u8;
        TypstPaint::Solid(Color::from_u8(r, g, b, alpha))
    };
    match paint {
        Paint::Fill(c) => geometry.filled(colour(*c)),
        Paint::Stroke {
            colour: c,
            width,
            dash,
        } => {
            let pattern = (!dash.is_empty()).then(|| DashPattern {
                array: dash.iter().map(|d| Abs::pt(*d)).collect(),
                phase: Abs::zero(),
            });
            geometry.stroked(FixedStroke {
                paint: colour(*c),
                thickness: Abs::pt(f64::from(*width)),
                dash: pattern,
                ..FixedStroke::default()
            })
        }
    }
}
