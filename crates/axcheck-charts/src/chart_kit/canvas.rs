//! The plotters backend of the report charts: it records what plotters draws as a
//! [`Scene`] (shapes and texts as data) instead of writing SVG text, so nothing has to be
//! parsed back. Coordinates are plotters' backend pixels.

use crate::chart_kit::scene::{Align, Baseline, Colour, Outline, Paint, Point, Scene, Text};
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::DrawingBackend;
use plotters::style::text_anchor::{HPos, VPos};
use plotters::style::{FontStyle, FontTransform};
use plotters_backend::{BackendColor, BackendStyle, BackendTextStyle, DrawingErrorKind};
use std::cell::RefCell;
use std::rc::Rc;

/// Drawing never fails on a canvas held in memory.
#[derive(Debug)]
pub enum Never {}

impl std::fmt::Display for Never {
    fn fmt(&self, _: &mut std::fmt::Formatter) -> std::fmt::Result {
        match *self {}
    }
}

impl std::error::Error for Never {}

type Drawn = Result<(), DrawingErrorKind<Never>>;

/// Records a chart of `size` pixels.
pub struct Canvas {
    size: (u32, u32),
    /// Shared with the caller: plotters keeps the backend until its drawing areas are gone.
    scene: Rc<RefCell<Scene>>,
}

impl Canvas {
    /// A blank canvas and the scene it records into.
    pub fn new(size: (u32, u32)) -> (Canvas, Rc<RefCell<Scene>>) {
        let mut scene = Scene::default();
        (scene.drawing.width, scene.drawing.height) = size;
        let scene = Rc::new(RefCell::new(scene));
        let canvas = Canvas {
            size,
            scene: Rc::clone(&scene),
        };
        (canvas, scene)
    }

    fn push(&mut self, colour: BackendColor, paint: impl FnOnce(Colour) -> Paint, o: Outline) {
        // Fully transparent paint draws nothing (and plotters' SVG writer left it out).
        if colour.alpha > 0.0 {
            let (r, g, b) = colour.rgb;
            let paint = paint(Colour(r, g, b));
            self.scene.borrow_mut().drawing.push(paint, colour.alpha, o);
        }
    }

    fn push_shape(&mut self, style: &impl BackendStyle, filled: bool, outline: Outline) {
        let width = style.stroke_width();
        if filled {
            self.push(style.color(), Paint::Fill, outline);
        } else {
            let stroke = |colour| Paint::Stroke {
                colour,
                width,
                dash: Vec::new(),
            };
            self.push(style.color(), stroke, outline);
        }
    }
}

impl DrawingBackend for Canvas {
    type ErrorType = Never;

    fn get_size(&self) -> (u32, u32) {
        self.size
    }

    fn ensure_prepared(&mut self) -> Drawn {
        Ok(())
    }

    fn present(&mut self) -> Drawn {
        Ok(())
    }

    fn draw_pixel(&mut self, at: Point, colour: BackendColor) -> Drawn {
        let rect = Outline::Rect(at, (at.0 + 1, at.1 + 1));
        self.push(colour, Paint::Fill, rect);
        Ok(())
    }

    fn draw_line<S: BackendStyle>(&mut self, from: Point, to: Point, style: &S) -> Drawn {
        self.push_shape(style, false, Outline::Line(vec![from, to]));
        Ok(())
    }

    fn draw_rect<S: BackendStyle>(&mut self, a: Point, b: Point, style: &S, fill: bool) -> Drawn {
        // An empty rectangle draws nothing, not even its stroke (as in SVG).
        if b.0 > a.0 && b.1 > a.1 {
            self.push_shape(style, fill, Outline::Rect(a, b));
        }
        Ok(())
    }

    fn draw_path<S: BackendStyle, I: IntoIterator<Item = Point>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Drawn {
        let points: Vec<Point> = path.into_iter().collect();
        if points.len() >= 2 {
            self.push_shape(style, false, Outline::Line(points));
        }
        Ok(())
    }

    fn draw_circle<S: BackendStyle>(
        &mut self,
        centre: Point,
        radius: u32,
        style: &S,
        fill: bool,
    ) -> Drawn {
        if radius > 0 {
            self.push_shape(style, fill, Outline::Circle(centre, radius));
        }
        Ok(())
    }

    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = Point>>(
        &mut self,
        path: I,
        style: &S,
    ) -> Drawn {
        let points: Vec<Point> = path.into_iter().collect();
        if points.len() >= 3 {
            self.push(style.color(), Paint::Fill, Outline::Polygon(points));
        }
        Ok(())
    }

    fn draw_text<S: BackendTextStyle>(&mut self, text: &str, style: &S, at: Point) -> Drawn {
        let colour = style.color();
        // As an SVG viewer shows text: white space collapsed and trimmed.
        let text = text.split_whitespace().collect::<Vec<_>>().join(" ");
        if colour.alpha == 0.0 || text.is_empty() {
            return Ok(());
        }
        let (r, g, b) = colour.rgb;
        let anchor = style.anchor();
        self.scene.borrow_mut().texts.push(Text {
            at,
            align: match anchor.h_pos {
                HPos::Left => Align::Left,
                HPos::Center => Align::Center,
                HPos::Right => Align::Right,
            },
            baseline: match anchor.v_pos {
                VPos::Top => Baseline::Top,
                VPos::Center => Baseline::Middle,
                VPos::Bottom => Baseline::Bottom,
            },
            // plotters' font size is 1.24 times the size it shows.
            size: style.size() / 1.24,
            colour: Colour(r, g, b),
            bold: matches!(style.style(), FontStyle::Bold),
            rotate: match style.transform() {
                FontTransform::Rotate90 => 90,
                FontTransform::Rotate180 => 180,
                FontTransform::Rotate270 => 270,
                _ => 0,
            },
            text,
        });
        Ok(())
    }
}

/// A polyline with a dash pattern (plotters draws only solid ones), drawn on a [`Canvas`].
pub(crate) struct DashedLine {
    pub points: Vec<Point>,
    pub colour: Colour,
    pub width: u32,
    pub dash: Vec<f64>,
}

impl<'a> PointCollection<'a, Point> for &'a DashedLine {
    type Point = &'a Point;
    type IntoIter = &'a [Point];
    fn point_iter(self) -> &'a [Point] {
        &self.points
    }
}

impl Drawable<Canvas> for DashedLine {
    fn draw<I: Iterator<Item = Point>>(
        &self,
        points: I,
        canvas: &mut Canvas,
        _: (u32, u32),
    ) -> Drawn {
        let paint = Paint::Stroke {
            colour: self.colour,
            width: self.width,
            dash: self.dash.clone(),
        };
        let outline = Outline::Line(points.collect());
        canvas.scene.borrow_mut().drawing.push(paint, 1.0, outline);
        Ok(())
    }
}
