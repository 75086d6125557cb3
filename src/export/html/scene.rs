//! A chart's scene as data for the page's script, which draws it as inline SVG: the same
//! shapes and texts the PDF report draws (see [`axcheck_charts::chart_kit::scene`]), never markup. The
//! script creates each element and sets each text as text, so a label can hold anything.

use axcheck_charts::chart_kit::scene::{Align, Paint, Scene};
use serde::Serialize;

/// A chart: its size in pixels, its shapes in drawing order, its texts.
#[derive(Debug, Serialize)]
pub(crate) struct SceneData {
    pub width: u32,
    pub height: u32,
    pub shapes: Vec<ShapeData>,
    pub texts: Vec<TextData>,
}

/// Outlines painted alike: `fill` or `stroke` (`#RRGGBB`), the stroke's width and dashes,
/// the opacity when not 1, and the outlines as one SVG path.
#[derive(Debug, Serialize)]
pub(crate) struct ShapeData {
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
    pub d: String,
}

/// One text: anchor point, `start`/`middle`/`end`, the baseline's offset in pixels, size
/// in pixels, colour, bold, clockwise rotation in degrees about the anchor.
#[derive(Debug, Serialize)]
pub(crate) struct TextData {
    pub x: i32,
    pub y: i32,
    pub anchor: &'static str,
    pub dy: f64,
    pub size: f64,
    pub colour: String,
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub bold: bool,
    #[serde(skip_serializing_if = "is_zero")]
    pub rotate: u16,
    pub text: String,
}

fn is_zero(x: &u16) -> bool {
    *x == 0
}

impl SceneData {
    pub fn of(scene: &Scene) -> SceneData {
        let shapes = (scene.drawing.shapes.iter())
            .map(|shape| {
                let (fill, stroke, width, dash) = match &shape.paint {
                    Paint::Fill(c) => (Some(c.hex()), None, None, Vec::new()),
                    Paint::Stroke {
                        colour,
                        width,
                        dash,
                    } => (None, Some(colour.hex()), Some(*width), dash.clone()),
                };
                ShapeData {
                    fill,
                    stroke,
                    width,
                    dash,
                    opacity: (shape.opacity != 1.0).then_some(shape.opacity),
                    d: shape.path_data(),
                }
            })
            .collect();
        let texts = (scene.texts.iter())
            .map(|t| TextData {
                x: t.at.0,
                y: t.at.1,
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
                text: t.text.clone(),
            })
            .collect();
        SceneData {
            width: scene.drawing.width,
            height: scene.drawing.height,
            shapes,
            texts,
        }
    }
}
