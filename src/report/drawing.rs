//! The templates' `chart-drawing` function: a chart's drawing (`/charts/NAME.drawing`, a
//! [`Drawing`] as bytes) laid out as Typst shapes, built directly as frame items.
//!
//! Handing Typst the drawing as an SVG image cost a fifth of a report: the SVG decoder
//! parsed the text into a tree, and the PDF writer turned the tree into an image object of
//! its own. Here the shapes go straight into the page. The function is defined once in the
//! shared library (see [`super::world`]) and reads the drawing through the document's
//! `World`, so Typst's caches see it as data like any file.

use super::scene::{Colour, Drawing, Outline, Paint};
use typst::diag::{At, SourceResult};
use typst::engine::Engine;
use typst::foundations::{Bytes, Content, NativeElement, Packed, Resolve, StyleChain};
use typst::introspection::Locator;
use typst::layout::{
    Abs, BlockElem, Frame, FrameItem, GroupItem, Length, Point, Ratio, Region, Size, Transform,
};
use typst::loading::{DataSource, Load};
use typst::syntax::Spanned;
use typst::visualize::{
    Color, Curve, DashPattern, FixedStroke, Geometry, Paint as TypstPaint, Shape,
};
use typst_library::foundations::{elem, func};

/// The drawing of a chart (its shapes; the labels are the template's), `width` wide.
#[func]
pub fn chart_drawing(
    engine: &mut Engine,
    /// The drawing: a path (`"/charts/NAME.drawing"`) or its bytes.
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
pub struct ChartDrawingElem {
    /// The drawing as bytes.
    #[required]
    pub drawing: Bytes,
    /// How wide to show it.
    #[required]
    pub width: Length,
}

fn parse(data: &Bytes) -> Result<Drawing, &'static str> {
    match Drawing::decode(data.as_slice()) {
        Some(d) if d.width > 0 && d.height > 0 => Ok(d),
        _ => Err("not a chart drawing"),
    }
}

/// The drawing in its own pixels (so the PDF writes whole numbers), scaled to `width`.
fn layout(
    elem: &Packed<ChartDrawingElem>,
    _: &mut Engine,
    _: Locator,
    styles: StyleChain,
    _: Region,
) -> SourceResult<Frame> {
    let drawing = parse(&elem.drawing).at(elem.span())?;
    let px = |v: u32| Abs::pt(f64::from(v));
    let mut pixels = Frame::hard(Size::new(px(drawing.width), px(drawing.height)));
    for shape in &drawing.shapes {
        let mut curve = Curve::new();
        for outline in &shape.outlines {
            trace(&mut curve, outline);
        }
        let item = painted(Geometry::Curve(curve), &shape.paint, shape.opacity);
        pixels.push(Point::zero(), FrameItem::Shape(item, elem.span()));
    }
    let width = elem.width.resolve(styles);
    let scale = Ratio::new(width.to_pt() / f64::from(drawing.width));
    let mut frame = Frame::hard(Size::new(width, px(drawing.height) * scale.get()));
    let mut group = GroupItem::new(pixels);
    group.transform = Transform::scale(scale, scale);
    frame.push(Point::zero(), FrameItem::Group(group));
    Ok(frame)
}

fn point((x, y): (i32, i32)) -> Point {
    Point::new(Abs::pt(f64::from(x)), Abs::pt(f64::from(y)))
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
