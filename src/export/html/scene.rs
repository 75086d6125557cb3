//! The charts of a block of details as data for the page's script, which draws each as
//! inline SVG: the same shapes and texts the PDF report draws (see
//! [`axcheck_charts::chart_kit::scene`]), never markup. The script creates each element and
//! sets each text as text, so a label can hold anything.
//!
//! A chart is mostly numbers (a reading's dot is a centre and a radius), so the scenes of
//! a block are written compactly, and the page rebuilds from them the very paths, paints
//! and texts the scene holds:
//! - the paints, the texts' styles and the texts themselves are tables of the block, in
//!   its JSON (so the texts pass through [`crate::safe_text::shown_json`] like any other);
//!   a shape names its paint and a text its style and string by their index;
//! - the outlines are numbers in four byte streams (LEB128 varints, signed ones
//!   zigzagged): `ops` (each scene's size and shape count; per shape its paint and outline
//!   count; per outline its op), `xs` and `ys` (coordinates, each the difference to the
//!   scene's previous point, so the targets' spacing and a run's spread are small numbers
//!   that repeat) and `texts` (per scene its text count; per text its style, position as
//!   a difference to the previous text's, and string).
//!
//! An outline is coded as new (its kind and all its points) or as one of the last
//! [`FORMS`] distinct forms moved to a new anchor: the second of a run of markers, grid
//! lines or ticks is one op and its anchor. The ops: `k < FORMS` repeats form `k` (then
//! made the first), `FORMS` a new polyline (point count, points), `FORMS + 1` a new
//! polygon (the same), `FORMS + 2` a new rectangle (upper left corner, then width and
//! height in `xs`, `ys`), `FORMS + 3` a new circle (radius, then its centre). The cursor
//! a difference is taken from is the last point coded, `(0, 0)` at each scene's start.

use axcheck_charts::chart_kit::scene::{Align, Outline, Paint, Point, Scene};
use serde::Serialize;

/// The distinct outline forms a scene remembers.
pub(crate) const FORMS: usize = 4;

/// How outlines are painted: `fill` or `stroke` (`#RRGGBB`), the stroke's width and
/// dashes, the opacity when not 1.
#[derive(Debug, Serialize, PartialEq)]
pub(crate) struct PaintData {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fill: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stroke: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width: Option<u32>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub dash: Vec<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub opacity: Option<f64>,
}

/// How a text is set: `start`/`middle`/`end`, the baseline's offset in pixels, size in
/// pixels, colour, bold, clockwise rotation in degrees about the anchor.
#[derive(Debug, Serialize, PartialEq)]
pub(crate) struct TextStyle {
    pub anchor: &'static str,
    pub dy: f64,
    pub size: f64,
    pub colour: String,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub bold: bool,
    #[serde(skip_serializing_if = "is_zero")]
    pub rotate: u16,
}

fn is_zero(x: &u16) -> bool {
    *x == 0
}

/// The tables of a block's scenes, serialized in the block's JSON.
#[derive(Debug, Default, Serialize)]
pub(crate) struct Tables {
    pub paints: Vec<PaintData>,
    pub styles: Vec<TextStyle>,
    pub strings: Vec<String>,
    #[serde(skip)]
    string_index: std::collections::HashMap<String, usize>,
}

/// The byte streams of a block's scenes (see the module docs).
#[derive(Debug, Default)]
pub(crate) struct Streams {
    pub ops: Vec<u8>,
    pub xs: Vec<u8>,
    pub ys: Vec<u8>,
    pub texts: Vec<u8>,
}

/// The scenes of one block, in the order the page reads them.
#[derive(Debug, Default)]
pub(crate) struct SceneBlock {
    pub tables: Tables,
    pub streams: Streams,
}

/// An outline up to where it lies.
#[derive(Debug, Clone, PartialEq)]
enum Form {
    Line(Vec<Point>),
    Polygon(Vec<Point>),
    Rect(i32, i32),
    Circle(u32),
}

impl Form {
    /// The outline's form and its anchor (first point, upper left corner or centre);
    /// none for an empty polyline or polygon, which is always coded anew.
    fn of(outline: &Outline) -> Option<(Form, Point)> {
        let relative = |points: &[Point]| {
            let (x0, y0) = *points.first()?;
            let rel = points.iter().map(|(x, y)| (x - x0, y - y0)).collect();
            Some((rel, (x0, y0)))
        };
        Some(match outline {
            Outline::Line(points) => relative(points).map(|(r, a)| (Form::Line(r), a))?,
            Outline::Polygon(points) => relative(points).map(|(r, a)| (Form::Polygon(r), a))?,
            Outline::Rect(a, b) => (Form::Rect(b.0 - a.0, b.1 - a.1), *a),
            Outline::Circle(centre, r) => (Form::Circle(*r), *centre),
        })
    }
}

/// LEB128.
pub(crate) fn put_uv(out: &mut Vec<u8>, mut n: u64) {
    while n >= 0x80 {
        out.push((n as u8 & 0x7F) | 0x80);
        n >>= 7;
    }
    out.push(n as u8);
}

/// Zigzag, then LEB128: 0, -1, 1, -2 … as 0, 1, 2, 3 …
pub(crate) fn put_sv(out: &mut Vec<u8>, n: i64) {
    put_uv(out, ((n << 1) ^ (n >> 63)) as u64);
}

/// Writes one scene's points, keeping the cursor.
struct Points<'a> {
    xs: &'a mut Vec<u8>,
    ys: &'a mut Vec<u8>,
    cursor: Point,
}

impl Points<'_> {
    fn put(&mut self, (x, y): Point) {
        put_sv(self.xs, i64::from(x) - i64::from(self.cursor.0));
        put_sv(self.ys, i64::from(y) - i64::from(self.cursor.1));
        self.cursor = (x, y);
    }
}

impl SceneBlock {
    /// Appends `scene` to the block.
    pub fn push(&mut self, scene: &Scene) {
        let s = &mut self.streams;
        put_uv(&mut s.ops, u64::from(scene.drawing.width));
        put_uv(&mut s.ops, u64::from(scene.drawing.height));
        put_uv(&mut s.ops, scene.drawing.shapes.len() as u64);
        let mut forms: Vec<Form> = Vec::with_capacity(FORMS + 1);
        let mut points = Points {
            xs: &mut s.xs,
            ys: &mut s.ys,
            cursor: (0, 0),
        };
        for shape in &scene.drawing.shapes {
            let paint = paint_data(&shape.paint, shape.opacity);
            put_uv(&mut s.ops, index_of(&mut self.tables.paints, paint) as u64);
            put_uv(&mut s.ops, shape.outlines.len() as u64);
            for outline in &shape.outlines {
                put_outline(&mut s.ops, &mut points, &mut forms, outline);
            }
        }
        self.push_texts(scene);
    }

    fn push_texts(&mut self, scene: &Scene) {
        let out = &mut self.streams.texts;
        put_uv(out, scene.texts.len() as u64);
        let mut cursor = (0, 0);
        for t in &scene.texts {
            let style = TextStyle {
                anchor: match t.align {
                    Align::Left => "start",
                    Align::Center => "middle",
                    Align::Right => "end",
                },
                dy: t.dy(),
                size: t.size,
                colour: t.colour.hex(),
                bold: t.bold,
                rotate: t.rotate,
            };
            put_uv(out, index_of(&mut self.tables.styles, style) as u64);
            put_sv(out, i64::from(t.at.0) - i64::from(cursor.0));
            put_sv(out, i64::from(t.at.1) - i64::from(cursor.1));
            cursor = t.at;
            put_uv(out, self.tables.string(&t.text) as u64);
        }
    }
}

impl Tables {
    fn string(&mut self, text: &str) -> usize {
        if let Some(&i) = self.string_index.get(text) {
            return i;
        }
        self.strings.push(text.to_string());
        self.string_index
            .insert(text.to_string(), self.strings.len() - 1);
        self.strings.len() - 1
    }
}

/// The index of `item` in `table`, added at its end when new (a block has a few dozen).
fn index_of<T: PartialEq>(table: &mut Vec<T>, item: T) -> usize {
    table.iter().position(|x| *x == item).unwrap_or_else(|| {
        table.push(item);
        table.len() - 1
    })
}

fn paint_data(paint: &Paint, opacity: f64) -> PaintData {
    let opacity = (opacity != 1.0).then_some(opacity);
    match paint {
        Paint::Fill(c) => PaintData {
            fill: Some(c.hex()),
            stroke: None,
            width: None,
            dash: Vec::new(),
            opacity,
        },
        Paint::Stroke {
            colour,
            width,
            dash,
        } => PaintData {
            fill: None,
            stroke: Some(colour.hex()),
            width: Some(*width),
            dash: dash.clone(),
            opacity,
        },
    }
}

/// One outline: a remembered form at a new anchor, or new (see the module docs).
fn put_outline(ops: &mut Vec<u8>, points: &mut Points, forms: &mut Vec<Form>, o: &Outline) {
    let form = Form::of(o);
    if let Some((form, anchor)) = &form {
        if let Some(k) = forms.iter().position(|f| f == form) {
            put_uv(ops, k as u64);
            let f = forms.remove(k);
            forms.insert(0, f);
            points.put(*anchor);
            return;
        }
        forms.insert(0, form.clone());
        forms.truncate(FORMS);
    }
    let base = FORMS as u64;
    match o {
        Outline::Line(p) | Outline::Polygon(p) => {
            let polygon = matches!(o, Outline::Polygon(_));
            put_uv(ops, base + u64::from(polygon));
            put_uv(ops, p.len() as u64);
            p.iter().for_each(|&p| points.put(p));
        }
        Outline::Rect(a, b) => {
            put_uv(ops, base + 2);
            points.put(*a);
            put_sv(points.xs, i64::from(b.0) - i64::from(a.0));
            put_sv(points.ys, i64::from(b.1) - i64::from(a.1));
        }
        Outline::Circle(centre, r) => {
            put_uv(ops, base + 3);
            put_uv(ops, u64::from(*r));
            points.put(*centre);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn varints_are_leb128_and_zigzag() {
        let mut out = Vec::new();
        for n in [0, 1, 127, 128, 300, u64::from(u32::MAX)] {
            put_uv(&mut out, n);
        }
        assert_eq!(
            out,
            [0, 1, 127, 0x80, 1, 0xAC, 2, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F]
        );
        let mut out = Vec::new();
        for n in [0, -1, 1, -2, 63, -64, 64] {
            put_sv(&mut out, n);
        }
        assert_eq!(out, [0, 1, 2, 3, 126, 127, 0x80, 1]);
    }

    #[test]
    fn repeated_forms_are_one_op_and_an_anchor() {
        use axcheck_charts::chart_kit::scene::{Colour, Drawing};
        let ink = Paint::Fill(Colour(1, 2, 3));
        let mut drawing = Drawing {
            width: 900,
            height: 420,
            shapes: Vec::new(),
        };
        for (x, y) in [(10, 20), (10, 25), (40, 22)] {
            drawing.push(ink.clone(), 1.0, Outline::Circle((x, y), 2));
        }
        let scene = Scene {
            drawing,
            texts: Vec::new(),
        };
        let mut block = SceneBlock::default();
        block.push(&scene);
        let s = &block.streams;
        // Size, one shape of paint 0 with three outlines: a new circle (r = 2), then the
        // same form twice.
        let new_circle = FORMS as u8 + 3;
        assert_eq!(s.ops, [0x84, 7, 0xA4, 3, 1, 0, 3, new_circle, 2, 0, 0]);
        assert_eq!(s.xs, [20, 0, 60]);
        assert_eq!(s.ys, [40, 10, 5]);
        assert_eq!(s.texts, [0]);
        assert_eq!(block.tables.paints.len(), 1);
    }
}
