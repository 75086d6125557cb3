//! A chart as data: the shapes and texts plotters drew, recorded by [`crate::chart_kit::canvas`].
//!
//! The drawing goes to Typst as frame items built from these shapes (see
//! the PDF report's drawing (`axcheck::report::typeset::drawing`)), the texts as labels set by the template (see [`crate::chart_kit::labels`]);
//! [`Scene::svg`] writes the whole chart as SVG for templates that show it as an image.
//!
//! Runs of like shapes are kept as one [`SceneShape`] with an outline per element: a chart of
//! 11 targets × 5 runs draws about 250 markers, ticks and segments, and the PDF pays per
//! path (a graphics state and a path object each). Only opaque paint is merged, fills
//! without a stroke and strokes without dashes: there, painting the outlines together
//! gives the same pixels as painting them one after the other, and merging only
//! consecutive elements keeps the drawing order.

use std::fmt::Write;

/// A point in chart pixels (plotters' backend coordinates).
pub type Point = (i32, i32);

/// An opaque colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Colour(pub u8, pub u8, pub u8);

impl Colour {
    pub const WHITE: Colour = Colour(0xFF, 0xFF, 0xFF);

    /// `#RRGGBB`.
    pub fn hex(self) -> String {
        format!("#{:02X}{:02X}{:02X}", self.0, self.1, self.2)
    }
}

/// How a shape is painted: filled, or stroked with a width in pixels and a dash pattern
/// (on, off, on … in pixels; empty for a solid line).
#[derive(Debug, Clone, PartialEq)]
pub enum Paint {
    Fill(Colour),
    Stroke {
        colour: Colour,
        width: u32,
        dash: Vec<f64>,
    },
}

/// One element's outline, in chart pixels.
#[derive(Debug, Clone, PartialEq)]
pub enum Outline {
    /// An open polyline.
    Line(Vec<Point>),
    /// A closed polygon.
    Polygon(Vec<Point>),
    /// A rectangle from its upper left to its lower right corner.
    Rect(Point, Point),
    /// A circle: centre and radius.
    Circle(Point, u32),
}

/// Outlines painted alike.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneShape {
    pub paint: Paint,
    /// 1 for opaque paint.
    pub opacity: f64,
    pub outlines: Vec<Outline>,
}

impl SceneShape {
    /// Whether more outlines painted like this one may join it (see the module docs).
    /// Rectangles stay apart: PDF viewers snap a lone rectangle's edges to whole pixels
    /// (bars and bands print crisp), which they do not do for a path of several.
    fn mergeable(&self) -> bool {
        self.opacity == 1.0
            && !self.outlines.iter().any(|o| matches!(o, Outline::Rect(..)))
            && match &self.paint {
                Paint::Fill(_) => true,
                Paint::Stroke { dash, .. } => dash.is_empty(),
            }
    }
}

/// The drawing of a chart: its canvas size in pixels and its shapes in drawing order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Drawing {
    pub width: u32,
    pub height: u32,
    pub shapes: Vec<SceneShape>,
}

impl Drawing {
    /// Adds an outline, joining it to the last shape when that is painted alike.
    pub fn push(&mut self, paint: Paint, opacity: f64, outline: Outline) {
        if let Some(last) = self.shapes.last_mut()
            && !matches!(outline, Outline::Rect(..))
            && last.mergeable()
            && last.paint == paint
            && last.opacity == opacity
        {
            last.outlines.push(outline);
            return;
        }
        self.shapes.push(SceneShape {
            paint,
            opacity,
            outlines: vec![outline],
        });
    }

    /// Every outline painted with `paint`, in drawing order.
    #[cfg(test)]
    pub(crate) fn outlines_painted(&self, paint: &Paint) -> impl Iterator<Item = &Outline> {
        self.shapes
            .iter()
            .filter(move |s| s.paint == *paint)
            .flat_map(|s| &s.outlines)
    }
}

/// The drawing as bytes (`/charts/NAME.drawing`, read by `chart-drawing`): Typst hands a
/// function's data to the layout as bytes, and a flat form reads back several times
/// faster than JSON. Integers little-endian; see [`Drawing::decode`] for the layout.
impl Drawing {
    pub fn encode(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(64 + 32 * self.shapes.len());
        out.extend_from_slice(MAGIC);
        put_u32(&mut out, self.width);
        put_u32(&mut out, self.height);
        put_len(&mut out, self.shapes.len());
        for shape in &self.shapes {
            match &shape.paint {
                Paint::Fill(c) => out.extend_from_slice(&[0, c.0, c.1, c.2]),
                Paint::Stroke {
                    colour: c,
                    width,
                    dash,
                } => {
                    out.extend_from_slice(&[1, c.0, c.1, c.2]);
                    put_u32(&mut out, *width);
                    put_len(&mut out, dash.len());
                    dash.iter()
                        .for_each(|d| out.extend_from_slice(&d.to_le_bytes()));
                }
            }
            out.extend_from_slice(&shape.opacity.to_le_bytes());
            put_len(&mut out, shape.outlines.len());
            shape.outlines.iter().for_each(|o| put_outline(&mut out, o));
        }
        out
    }

    /// The drawing [`Drawing::encode`] wrote: `AXD1`, width, height, then per shape its
    /// paint (kind 0 fill or 1 stroke, R, G, B; a stroke's width and dash pattern), its
    /// opacity and its outlines (kind, then points, corners or centre and radius).
    pub fn decode(bytes: &[u8]) -> Option<Drawing> {
        let (drawing, rest) = Drawing::decode_front(bytes)?;
        rest.is_empty().then_some(drawing)
    }

    /// A drawing at the front of `bytes`, and the bytes after it.
    pub fn decode_front(bytes: &[u8]) -> Option<(Drawing, &[u8])> {
        let mut r = Reader(bytes.strip_prefix(MAGIC)?);
        let (width, height) = (r.u32()?, r.u32()?);
        let mut shapes = Vec::with_capacity(r.len()?);
        for _ in 0..shapes.capacity() {
            let [kind, red, green, blue] = r.take::<4>()?;
            let colour = Colour(red, green, blue);
            let paint = match kind {
                0 => Paint::Fill(colour),
                1 => {
                    let width = r.u32()?;
                    let dash = (0..r.len()?).map(|_| r.f64()).collect::<Option<_>>()?;
                    Paint::Stroke {
                        colour,
                        width,
                        dash,
                    }
                }
                _ => return None,
            };
            let opacity = r.f64()?;
            let outlines = (0..r.len()?).map(|_| r.outline()).collect::<Option<_>>()?;
            shapes.push(SceneShape {
                paint,
                opacity,
                outlines,
            });
        }
        let drawing = Drawing {
            width,
            height,
            shapes,
        };
        Some((drawing, r.0))
    }
}

const MAGIC: &[u8] = b"AXD1";

pub(crate) fn put_u32(out: &mut Vec<u8>, v: u32) {
    out.extend_from_slice(&v.to_le_bytes());
}

pub(crate) fn put_len(out: &mut Vec<u8>, n: usize) {
    put_u32(out, u32::try_from(n).unwrap_or(u32::MAX));
}

fn put_point(out: &mut Vec<u8>, (x, y): Point) {
    out.extend_from_slice(&x.to_le_bytes());
    out.extend_from_slice(&y.to_le_bytes());
}

fn put_outline(out: &mut Vec<u8>, outline: &Outline) {
    match outline {
        Outline::Line(points) | Outline::Polygon(points) => {
            out.push(if matches!(outline, Outline::Line(_)) {
                0
            } else {
                1
            });
            put_len(out, points.len());
            points.iter().for_each(|p| put_point(out, *p));
        }
        Outline::Rect(a, b) => {
            out.push(2);
            put_point(out, *a);
            put_point(out, *b);
        }
        Outline::Circle(centre, radius) => {
            out.push(3);
            put_point(out, *centre);
            put_u32(out, *radius);
        }
    }
}

/// Reads [`Drawing::encode`]'s bytes from the front.
pub(crate) struct Reader<'a>(pub(crate) &'a [u8]);

impl<'a> Reader<'a> {
    pub(crate) fn take<const N: usize>(&mut self) -> Option<[u8; N]> {
        let (head, rest) = self.0.split_first_chunk::<N>()?;
        self.0 = rest;
        Some(*head)
    }

    pub(crate) fn u32(&mut self) -> Option<u32> {
        self.take().map(u32::from_le_bytes)
    }

    fn i32(&mut self) -> Option<i32> {
        self.take().map(i32::from_le_bytes)
    }

    pub(crate) fn f64(&mut self) -> Option<f64> {
        self.take().map(f64::from_le_bytes)
    }

    /// A count, refused when the bytes left cannot hold that many items of a byte or more.
    pub(crate) fn len(&mut self) -> Option<usize> {
        let n = usize::try_from(self.u32()?).ok()?;
        (n <= self.0.len()).then_some(n)
    }

    /// A string: its length in bytes, then its UTF-8.
    pub(crate) fn str(&mut self) -> Option<&'a str> {
        let n = self.len()?;
        let (text, rest) = self.0.split_at(n);
        self.0 = rest;
        std::str::from_utf8(text).ok()
    }

    fn point(&mut self) -> Option<Point> {
        Some((self.i32()?, self.i32()?))
    }

    fn outline(&mut self) -> Option<Outline> {
        let [kind] = self.take::<1>()?;
        Some(match kind {
            0 | 1 => {
                let points = (0..self.len()?)
                    .map(|_| self.point())
                    .collect::<Option<_>>()?;
                if kind == 0 {
                    Outline::Line(points)
                } else {
                    Outline::Polygon(points)
                }
            }
            2 => Outline::Rect(self.point()?, self.point()?),
            3 => Outline::Circle(self.point()?, self.u32()?),
            _ => return None,
        })
    }
}

/// Where a text lies relative to its anchor point, along the text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Align {
    Left,
    Center,
    Right,
}

/// Where a text lies relative to its anchor point, across the text: the anchor is at the
/// top of the text, its middle, or its bottom.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Baseline {
    Top,
    Middle,
    Bottom,
}

/// One text as plotters placed it.
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    pub at: Point,
    pub align: Align,
    pub baseline: Baseline,
    /// Font size in pixels.
    pub size: f64,
    pub colour: Colour,
    pub bold: bool,
    /// Clockwise rotation in degrees about the anchor: 0, 90, 180 or 270.
    pub rotate: u16,
    pub text: String,
}

impl Text {
    /// The baseline's offset from the anchor, as SVG's `dy` gives it for the font size
    /// (1 em is the font size, 1 ex half of it).
    pub fn dy(&self) -> f64 {
        match self.baseline {
            Baseline::Top => 0.76 * self.size,
            Baseline::Middle => 0.25 * self.size,
            Baseline::Bottom => -0.25 * self.size,
        }
    }
}

/// A chart: its drawing and its texts.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Scene {
    pub drawing: Drawing,
    pub texts: Vec<Text>,
}

impl Scene {
    /// The whole chart as SVG, texts in `family` (for templates that show it as an image).
    pub fn svg(&self, family: &str) -> String {
        let mut out = svg_open(&self.drawing);
        push_shapes(&mut out, &self.drawing.shapes);
        for text in &self.texts {
            push_text(&mut out, text, family);
        }
        out.push_str("</svg>\n");
        out
    }

    /// The texts' contents, in drawing order.
    pub fn strings(&self) -> impl Iterator<Item = &str> {
        self.texts.iter().map(|t| t.text.as_str())
    }

    /// The first text whose content is exactly `content`.
    pub fn text(&self, content: &str) -> Option<&Text> {
        self.texts.iter().find(|t| t.text == content)
    }
}

impl Drawing {
    /// The drawing alone as SVG.
    pub fn svg(&self) -> String {
        let mut out = svg_open(self);
        push_shapes(&mut out, &self.shapes);
        out.push_str("</svg>\n");
        out
    }
}

fn svg_open(drawing: &Drawing) -> String {
    format!(
        "<svg width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" xmlns=\"http://www.w3.org/2000/svg\">\n",
        drawing.width, drawing.height
    )
}

fn push_shapes(out: &mut String, shapes: &[SceneShape]) {
    for shape in shapes {
        out.push_str("<path");
        match &shape.paint {
            Paint::Fill(c) => {
                let _ = write!(out, " fill=\"{}\" stroke=\"none\"", c.hex());
            }
            Paint::Stroke {
                colour,
                width,
                dash,
            } => {
                let _ = write!(
                    out,
                    " fill=\"none\" stroke=\"{}\" stroke-width=\"{width}\"",
                    colour.hex()
                );
                if !dash.is_empty() {
                    let pattern: Vec<String> = dash.iter().map(f64::to_string).collect();
                    let _ = write!(out, " stroke-dasharray=\"{}\"", pattern.join(" "));
                }
            }
        }
        if shape.opacity != 1.0 {
            let _ = write!(out, " opacity=\"{}\"", shape.opacity);
        }
        let _ = writeln!(out, " d=\"{}\"/>", shape.path_data());
    }
}

impl SceneShape {
    /// The outlines as one SVG path's `d`, as [`Scene::svg`] writes them.
    pub fn path_data(&self) -> String {
        let mut out = String::new();
        for (i, outline) in self.outlines.iter().enumerate() {
            if i > 0 {
                out.push(' ');
            }
            push_path_data(&mut out, outline);
        }
        out
    }
}

fn push_path_data(out: &mut String, outline: &Outline) {
    let points = |out: &mut String, points: &[Point]| {
        for (i, (x, y)) in points.iter().enumerate() {
            let _ = write!(out, "{}{x},{y}", if i == 0 { "M" } else { " L" });
        }
    };
    match outline {
        Outline::Line(p) => points(out, p),
        Outline::Polygon(p) => {
            points(out, p);
            out.push_str(" Z");
        }
        Outline::Rect((x0, y0), (x1, y1)) => {
            let _ = write!(out, "M{x0},{y0} H{x1} V{y1} H{x0} Z");
        }
        Outline::Circle((x, y), r) => {
            let _ = write!(
                out,
                "M{},{y} a{r},{r} 0 1,0 {},0 a{r},{r} 0 1,0 -{},0 Z",
                x - *r as i32,
                2 * r,
                2 * r
            );
        }
    }
}

fn push_text(out: &mut String, text: &Text, family: &str) {
    let (x, y) = text.at;
    let anchor = match text.align {
        Align::Left => "start",
        Align::Center => "middle",
        Align::Right => "end",
    };
    let dy = match text.baseline {
        Baseline::Top => "0.76em",
        Baseline::Middle => "0.5ex",
        Baseline::Bottom => "-0.5ex",
    };
    let _ = write!(
        out,
        "<text x=\"{x}\" y=\"{y}\" dy=\"{dy}\" text-anchor=\"{anchor}\" font-family=\"{}\" font-size=\"{}\" fill=\"{}\"",
        escape(family),
        text.size,
        text.colour.hex()
    );
    if text.bold {
        out.push_str(" font-weight=\"bold\"");
    }
    if text.rotate != 0 {
        let _ = write!(out, " transform=\"rotate({}, {x}, {y})\"", text.rotate);
    }
    let _ = writeln!(out, ">{}</text>", escape(&text.text));
}

/// `text` with the characters that are markup in XML written as entities.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c => out.push(c),
        }
    }
    out
}

/// For the charts' tests: the scene with an SVG element per outline, as plotters wrote it.
#[cfg(test)]
impl Scene {
    pub(crate) fn element_svg(&self) -> String {
        let mut out = svg_open(&self.drawing);
        for shape in &self.drawing.shapes {
            for outline in &shape.outlines {
                push_element(&mut out, shape, outline);
            }
        }
        for text in &self.texts {
            push_text(&mut out, text, "Inter");
        }
        out.push_str("</svg>\n");
        out
    }
}

#[cfg(test)]
fn push_element(out: &mut String, shape: &SceneShape, outline: &Outline) {
    let (fill, stroke, width, dash) = match &shape.paint {
        Paint::Fill(c) => (c.hex(), "none".to_string(), 1, String::new()),
        Paint::Stroke {
            colour,
            width,
            dash,
        } => {
            let pattern: Vec<String> = dash.iter().map(f64::to_string).collect();
            let dash = if dash.is_empty() {
                String::new()
            } else {
                format!(" stroke-dasharray=\"{}\"", pattern.join(" "))
            };
            ("none".to_string(), colour.hex(), *width, dash)
        }
    };
    let points = |p: &[Point]| {
        p.iter()
            .map(|(x, y)| format!("{x},{y} "))
            .collect::<String>()
    };
    let o = shape.opacity;
    let _ = match outline {
        Outline::Line(p) => writeln!(
            out,
            "<polyline fill=\"none\" opacity=\"{o}\" stroke=\"{stroke}\" stroke-width=\"{width}\"{dash} points=\"{}\"/>",
            points(p)
        ),
        Outline::Polygon(p) => writeln!(
            out,
            "<polygon opacity=\"{o}\" fill=\"{fill}\" points=\"{}\"/>",
            points(p)
        ),
        Outline::Rect((x0, y0), (x1, y1)) => writeln!(
            out,
            "<rect x=\"{x0}\" y=\"{y0}\" width=\"{}\" height=\"{}\" opacity=\"{o}\" fill=\"{fill}\" stroke=\"{stroke}\"/>",
            x1 - x0,
            y1 - y0
        ),
        Outline::Circle((x, y), r) => writeln!(
            out,
            "<circle cx=\"{x}\" cy=\"{y}\" r=\"{r}\" opacity=\"{o}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{width}\"/>"
        ),
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    const INK: Colour = Colour(0x1A, 0x1A, 0x1A);

    fn stroke(width: u32) -> Paint {
        Paint::Stroke {
            colour: INK,
            width,
            dash: Vec::new(),
        }
    }

    #[test]
    fn runs_of_like_paint_become_one_shape_in_drawing_order() {
        let mut d = Drawing::default();
        d.push(stroke(1), 1.0, Outline::Line(vec![(0, 0), (4, 0)]));
        d.push(stroke(1), 1.0, Outline::Rect((1, 1), (3, 3)));
        d.push(Paint::Fill(INK), 1.0, Outline::Circle((5, 5), 2));
        d.push(
            Paint::Fill(INK),
            1.0,
            Outline::Polygon(vec![(1, 1), (3, 1), (2, 3)]),
        );
        d.push(stroke(2), 1.0, Outline::Line(vec![(0, 0), (4, 0)]));
        d.push(Paint::Fill(INK), 1.0, Outline::Circle((9, 9), 2));
        d.push(stroke(2), 1.0, Outline::Rect((1, 1), (3, 3)));
        let counts: Vec<usize> = d.shapes.iter().map(|s| s.outlines.len()).collect();
        assert_eq!(counts, [1, 1, 2, 1, 1, 1]);
        assert_eq!(d.outlines_painted(&Paint::Fill(INK)).count(), 3);
        let svg = d.svg();
        assert!(svg.contains(
            "<path fill=\"#1A1A1A\" stroke=\"none\" d=\"M3,5 a2,2 0 1,0 4,0 a2,2 0 1,0 -4,0 Z M1,1 L3,1 L2,3 Z\"/>"
        ), "{svg}");
        assert!(svg.contains("d=\"M1,1 H3 V3 H1 Z\""), "{svg}");
    }

    #[test]
    fn a_drawing_reads_back_from_its_bytes() {
        let mut d = Drawing {
            width: 900,
            height: 420,
            shapes: Vec::new(),
        };
        d.push(stroke(1), 1.0, Outline::Line(vec![(0, -3), (4, 0)]));
        d.push(stroke(1), 1.0, Outline::Rect((1, 1), (3, 3)));
        d.push(Paint::Fill(INK), 0.5, Outline::Circle((5, 5), 2));
        d.push(
            Paint::Fill(INK),
            1.0,
            Outline::Polygon(vec![(1, 1), (3, 1), (2, 3)]),
        );
        let dashed = Paint::Stroke {
            colour: INK,
            width: 2,
            dash: vec![9.0, 3.5],
        };
        d.push(dashed, 1.0, Outline::Line(vec![(0, 0), (4, 0)]));
        let bytes = d.encode();
        assert_eq!(Drawing::decode(&bytes), Some(d));
        for cut in [0, 4, 12, bytes.len() - 1] {
            assert_eq!(Drawing::decode(&bytes[..cut]), None);
        }
        let mut longer = bytes.clone();
        longer.push(0);
        assert_eq!(Drawing::decode(&longer), None);
        // A count larger than the bytes left is refused before anything is allocated.
        let mut huge = bytes[..12].to_vec();
        huge.extend_from_slice(&u32::MAX.to_le_bytes());
        assert_eq!(Drawing::decode(&huge), None);
    }

    #[test]
    fn dashed_and_translucent_paint_is_kept_apart() {
        let dashed = Paint::Stroke {
            colour: INK,
            width: 1,
            dash: vec![4.0, 2.0],
        };
        let mut d = Drawing::default();
        for _ in 0..2 {
            d.push(dashed.clone(), 1.0, Outline::Line(vec![(0, 0), (4, 0)]));
        }
        for _ in 0..2 {
            d.push(Paint::Fill(INK), 0.5, Outline::Circle((5, 5), 2));
        }
        assert_eq!(d.shapes.len(), 4);
        let svg = d.svg();
        assert_eq!(svg.matches("stroke-dasharray=\"4 2\"").count(), 2);
        assert_eq!(svg.matches("opacity=\"0.5\"").count(), 2);
    }

    #[test]
    fn the_svg_escapes_texts() {
        let scene = Scene {
            drawing: Drawing {
                width: 10,
                height: 10,
                shapes: Vec::new(),
            },
            texts: vec![Text {
                at: (4, 213),
                align: Align::Center,
                baseline: Baseline::Top,
                size: 15.5,
                colour: INK,
                bold: true,
                rotate: 270,
                text: "a < b & \"c\"".into(),
            }],
        };
        let svg = scene.svg("Inter");
        assert!(svg.contains(
            "<text x=\"4\" y=\"213\" dy=\"0.76em\" text-anchor=\"middle\" font-family=\"Inter\" \
             font-size=\"15.5\" fill=\"#1A1A1A\" font-weight=\"bold\" transform=\"rotate(270, 4, 213)\">\
             a &lt; b &amp; &quot;c&quot;</text>"
        ), "{svg}");
        assert_eq!(scene.texts[0].dy(), 0.76 * 15.5);
    }
}
