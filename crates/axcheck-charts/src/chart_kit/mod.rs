//! What the report's chart modules ([`crate::charts`], [`crate::charts::diagnosis`] and
//! [`crate::charts::compensation`]) share: the look (tones, text sizes, dash patterns), the
//! canvas, text measuring and fitting, number formatting, line, marker and legend drawing,
//! and the axes with grid and ticks.
//!
//! Where the two modules measure text differently, the difference is a field of
//! [`Conventions`] and each module passes its own, so every chart keeps its layout.

pub(crate) mod canvas;
pub mod labels;
pub mod scene;
#[cfg(test)]
pub(crate) mod svg_probe;

use crate::chart_kit::canvas::{Canvas, DashedLine};
use crate::chart_kit::scene::{Colour, Scene};
use crate::units::fmt_fixed;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A chart's size in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    pub width_px: u32,
    pub height_px: u32,
}

// ---------------------------------------------------------------------------------------------
// Look

pub(crate) const UP: RGBColor = RGBColor(0x1F, 0x3A, 0x6E);
pub(crate) const DOWN: RGBColor = RGBColor(0x8E, 0x1B, 0x1B);
pub(crate) const INK: RGBColor = RGBColor(0x1A, 0x1A, 0x1A);
pub(crate) const MUTED: RGBColor = RGBColor(0x55, 0x55, 0x55);
pub(crate) const GRID: RGBColor = RGBColor(0xE2, 0xE2, 0xE2);
pub(crate) const GUIDE: RGBColor = RGBColor(0xC4, 0xC4, 0xC4);
pub(crate) const FRAME: RGBColor = RGBColor(0x9A, 0x9A, 0x9A);
pub(crate) const STRIPE: RGBColor = RGBColor(0xF3, 0xF3, 0xF3);

/// A verdict's colours (light fill, dark edge and text), as the templates' `verdict-style`
/// (style.typ) has them. Every verdict has its own: a chart coloured by verdict follows
/// when one is added.
pub(crate) fn verdict_tone(v: crate::judge::Verdict) -> (RGBColor, RGBColor) {
    use crate::judge::Verdict;
    match v {
        Verdict::Pass => (RGBColor(0xE3, 0xF1, 0xE3), RGBColor(0x2D, 0x6A, 0x2D)),
        Verdict::Fail => (RGBColor(0xF8, 0xDE, 0xDB), RGBColor(0x9B, 0x1C, 0x12)),
        Verdict::Noncompliant => (RGBColor(0xFB, 0xED, 0xD0), RGBColor(0x8A, 0x5A, 0x00)),
        Verdict::Error => (RGBColor(228, 228, 228), RGBColor(40, 40, 40)),
        Verdict::Inconclusive => (RGBColor(0xE6, 0xE9, 0xF5), RGBColor(0x2F, 0x3F, 0x7A)),
        Verdict::NotJudged => (RGBColor(0xE4, 0xEC, 0xF2), RGBColor(0x2C, 0x4A, 0x5E)),
    }
}

/// Text sizes in SVG pixels (the `font-size` written into the SVG).
pub(crate) const TICK_PX: f64 = 14.0;
pub(crate) const DESC_PX: f64 = 15.5;
pub(crate) const LEGEND_PX: f64 = 14.0;

/// Dash patterns in pixels: on, off, on, off …
pub(crate) const SOLID: &[f64] = &[];
pub(crate) const DASHED: &[f64] = &[10.0, 5.0];

#[derive(Clone, Copy)]
pub struct Stroke {
    pub(crate) color: RGBColor,
    pub width: u32,
    pub dash: &'static [f64],
}

impl Stroke {
    /// A line of this colour, width in pixels and dash pattern.
    pub(crate) const fn new(color: RGBColor, width: u32, dash: &'static [f64]) -> Stroke {
        Stroke { color, width, dash }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) enum Marker {
    /// Filled circle of the given radius.
    Dot(u32),
    /// Open (white-filled) triangle with the given half size.
    Triangle(i32),
    /// Outline-only triangle with the given half size (for the many readings).
    TriangleOutline(i32),
    /// Outline-only triangle (pointing up) with the given half size, drawn as one path that
    /// starts mid-base.
    OpenTriangle(i32),
    /// Filled diamond with the given half size.
    Diamond(i32),
}

pub(crate) struct LegendItem {
    pub stroke: Option<Stroke>,
    pub marker: Option<(Marker, RGBColor)>,
    /// a filled box (for bands and regions)
    pub(crate) swatch: Option<RGBColor>,
    pub text: String,
}

/// How a chart module measures text. The modules differ here and each keeps its own so
/// its charts keep their layout.
#[derive(Clone, Copy)]
pub(crate) struct Conventions {
    /// Superscript digits and minus (as in 10⁻³) measure 0.4 em; otherwise they count as the
    /// 0.7 em of other symbols.
    pub(crate) narrow_superscripts: bool,
}

// ---------------------------------------------------------------------------------------------
// Errors and the canvas

/// A drawing step failed; the chart falls back to a message.
pub struct Failed;

impl<E: std::error::Error + Send + Sync> From<DrawingAreaErrorKind<E>> for Failed {
    fn from(_: DrawingAreaErrorKind<E>) -> Self {
        Failed
    }
}

pub(crate) type Area = DrawingArea<Canvas, Shift>;
pub(crate) type Chart<'a> = ChartContext<'a, Canvas, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

pub(crate) fn dims(style: &Style) -> (u32, u32) {
    (
        style.width_px.clamp(240, 10_000),
        style.height_px.clamp(140, 20_000),
    )
}

/// Draws with `paint` on a white canvas of the style's size; a failure gives a message chart.
pub(crate) fn render(style: &Style, paint: impl FnOnce(&Area) -> Result<(), Failed>) -> Scene {
    let (canvas, scene) = Canvas::new(dims(style));
    let root = canvas.into_drawing_area();
    let drawn = root
        .fill(&WHITE)
        .map_err(Failed::from)
        .and_then(|_| paint(&root));
    drop(root);
    match drawn {
        Ok(()) => scene.take(),
        Err(Failed) => message_chart(style, "This chart could not be drawn."),
    }
}

/// A chart holding only a centred message (for empty or unusable input).
pub(crate) fn message_chart(style: &Style, message: &str) -> Scene {
    let size = dims(style);
    let (canvas, scene) = Canvas::new(size);
    let root = canvas.into_drawing_area();
    // Drawing on a canvas in memory cannot fail: a failure would leave the canvas blank.
    let _ = root.fill(&WHITE).and_then(|_| {
        root.draw(&Text::new(
            message.to_string(),
            (size.0 as i32 / 2, size.1 as i32 / 2),
            text_style(DESC_PX, false, MUTED, HPos::Center, VPos::Center),
        ))
    });
    drop(root);
    scene.take()
}

// ---------------------------------------------------------------------------------------------
// Text

/// Plotters writes `font-size = size / 1.24`; find the size that writes exactly `px` (the text
/// sizes above are chosen so that one exists), else the plain product.
pub(crate) fn plotters_size(px: f64) -> f64 {
    let guess = px * 1.24;
    let bits = guess.to_bits();
    (0..16u64)
        .flat_map(|step| [bits.wrapping_add(step), bits.wrapping_sub(step)])
        .map(f64::from_bits)
        .find(|s| s.is_finite() && *s / 1.24 == px)
        .unwrap_or(guess)
}

pub(crate) fn font(px: f64, bold: bool) -> FontDesc<'static> {
    let face = if bold {
        FontStyle::Bold
    } else {
        FontStyle::Normal
    };
    // The family is the template's to choose: the canvas records only size and weight.
    FontDesc::new(FontFamily::SansSerif, plotters_size(px), face)
}

pub(crate) fn text_style(
    px: f64,
    bold: bool,
    color: RGBColor,
    h: HPos,
    v: VPos,
) -> TextStyle<'static> {
    font(px, bold).color(&color).pos(Pos::new(h, v))
}

impl Conventions {
    /// Rough advance width of `text` in Inter at `px` (slightly generous, for layout only).
    pub(crate) fn text_width(self, text: &str, px: f64) -> f64 {
        let em: f64 = text
            .chars()
            .map(|c| match c {
                '\u{0300}'..='\u{036F}' => 0.0,
                ' ' => 0.28,
                'i' | 'l' | 'j' | 'I' | '.' | ',' | ':' | ';' | '\'' | '|' | '!' => 0.3,
                'f' | 't' | 'r' | '(' | ')' | '/' | '[' | ']' => 0.4,
                'm' | 'w' | 'M' | 'W' | '%' => 0.88,
                '0'..='9' => 0.62,
                'A'..='Z' => 0.7,
                'a'..='z' => 0.57,
                '↑' | '↓' => 0.7,
                '−' | '±' | '+' | '=' | '×' => 0.66,
                '⁰'..='⁹' | '¹' | '²' | '³' | '⁻' if self.narrow_superscripts => 0.4,
                _ => 0.7,
            })
            .sum();
        em * px
    }

    /// Cut `text` to fit `max_w` pixels, ending with an ellipsis when cut.
    pub(crate) fn fit_text(self, text: &str, px: f64, max_w: f64) -> String {
        if self.text_width(text, px) <= max_w {
            return text.to_string();
        }
        let mut out = String::new();
        for c in text.chars() {
            out.push(c);
            if self.text_width(&out, px) + self.text_width("…", px) > max_w {
                out.pop();
                break;
            }
        }
        out.push('…');
        out
    }
}

// ---------------------------------------------------------------------------------------------
// Numbers

/// `v` with `decimals` places as a chart prints it: [`fmt_fixed`] (no "−0") with a true
/// minus sign, words for non-finite values ("n/a", "∞") and e-notation from 10⁹ on.
pub(crate) fn fmt_fixed_for_print(v: f64, decimals: usize) -> String {
    if !v.is_finite() {
        return if v.is_nan() {
            "n/a".to_string()
        } else if v > 0.0 {
            "∞".to_string()
        } else {
            "−∞".to_string()
        };
    }
    if v.abs() >= 1e9 {
        return format!("{v:.2e}").replace('-', "−");
    }
    // In the language of the document being drawn (a decimal comma in Russian).
    let s = crate::words::numbers().number(&fmt_fixed(v, decimals));
    match s.strip_prefix('-') {
        Some(rest) => format!("−{rest}"),
        None => s,
    }
}

/// Decimals that show three significant digits of `v` (at most nine).
pub(crate) fn sig_decimals(v: f64) -> usize {
    if !v.is_finite() || v == 0.0 {
        return 2;
    }
    let mag = v.abs().log10().floor();
    (2.0 - mag).clamp(0.0, 9.0) as usize
}

/// The tick values plotters will label, and the decimals they need.
pub(crate) fn ticks(range: (f64, f64), max_points: usize) -> (Vec<f64>, usize) {
    let points = RangedCoordf64::from(range.0..range.1).key_points(max_points);
    let step = points
        .windows(2)
        .map(|w| (w[1] - w[0]).abs())
        .find(|d| *d > 0.0)
        .unwrap_or((range.1 - range.0).abs() / 4.0);
    let decimals = if step.is_finite() && step > 0.0 {
        (-(step.log10() + 1e-9).floor()).clamp(0.0, 12.0) as usize
    } else {
        2
    };
    (points, decimals)
}

/// A range over the finite values with `margin` (a fraction of their span) to spare at
/// either end; a single value gets a window around it.
pub(crate) fn padded_range(
    values: impl IntoIterator<Item = f64>,
    margin: f64,
) -> Option<(f64, f64)> {
    let (lo, hi) = extent(values)?;
    let span = hi - lo;
    let scale = lo.abs().max(hi.abs()).max(1.0);
    let (lo, hi) = if span <= scale * 1e-9 {
        let half = (scale * 0.05).max(1.0);
        (lo - half, hi + half)
    } else {
        (lo - span * margin, hi + span * margin)
    };
    (lo.is_finite() && hi.is_finite() && (hi - lo).is_finite() && hi > lo).then_some((lo, hi))
}

/// Smallest and largest of the finite values, if any.
pub(crate) fn extent(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(None, |acc, v| match acc {
            None => Some((v, v)),
            Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
        })
}

// ---------------------------------------------------------------------------------------------
// Drawing primitives (in backend pixels, on the root area)

pub(crate) type Px = (f64, f64);

pub(crate) fn round_px(p: Px) -> (i32, i32) {
    (p.0.round() as i32, p.1.round() as i32)
}

/// Whether `pattern` draws gaps (an empty or invalid pattern draws a solid line).
fn is_dashed(pattern: &[f64]) -> bool {
    !pattern.is_empty() && pattern.iter().all(|d| d.is_finite() && *d > 0.0)
}

/// Drops points that round to the pixel of the point before (a zero-length segment draws
/// nothing).
fn dedup_pixels(points: Vec<(i32, i32)>) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = Vec::with_capacity(points.len());
    for p in points {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    out
}

/// Draws a polyline through `points` (rounded to pixels) with the stroke's dash pattern.
pub(crate) fn draw_line(root: &Area, points: &[Px], stroke: Stroke) -> Result<(), Failed> {
    let points = dedup_pixels(points.iter().map(|p| round_px(*p)).collect());
    if points.len() < 2 {
        return Ok(());
    }
    if is_dashed(stroke.dash) {
        let RGBColor(r, g, b) = stroke.color;
        root.draw(&DashedLine {
            points,
            colour: Colour(r, g, b),
            width: stroke.width,
            dash: stroke.dash.to_vec(),
        })?;
    } else {
        let shape = ShapeStyle::from(&stroke.color).stroke_width(stroke.width);
        root.draw(&PathElement::new(points, shape))?;
    }
    Ok(())
}

fn triangle(c: (i32, i32), half: i32) -> Vec<(i32, i32)> {
    let h = half;
    vec![
        (c.0, c.1 - h - 1),
        (c.0 + h, c.1 + h - 1),
        (c.0 - h, c.1 + h - 1),
    ]
}

pub(crate) fn draw_marker(
    root: &Area,
    at: (i32, i32),
    marker: Marker,
    color: RGBColor,
) -> Result<(), Failed> {
    match marker {
        Marker::Dot(r) => root.draw(&Circle::new(at, r, color.filled()))?,
        Marker::Triangle(h) => {
            let pts = triangle(at, h);
            root.draw(&Polygon::new(pts.clone(), WHITE.filled()))?;
            let mut closed = pts;
            closed.push(closed[0]);
            root.draw(&PathElement::new(closed, color.stroke_width(2)))?;
        }
        Marker::TriangleOutline(h) => {
            let mut closed = triangle(at, h);
            closed.push(closed[0]);
            root.draw(&PathElement::new(closed, color.stroke_width(1)))?;
        }
        Marker::OpenTriangle(h) => {
            // Start mid-base so the path closes on a straight edge (no notch at a corner).
            let (x, y) = at;
            let path = vec![
                (x, y + h),
                (x + h + 1, y + h),
                (x, y - h - 1),
                (x - h - 1, y + h),
                (x, y + h),
            ];
            root.draw(&PathElement::new(path, color.stroke_width(2)))?;
        }
        Marker::Diamond(h) => {
            let (x, y) = at;
            root.draw(&Polygon::new(
                vec![(x, y - h), (x + h, y), (x, y + h), (x - h, y)],
                color.filled(),
            ))?;
        }
    }
    Ok(())
}

pub(crate) fn draw_text(
    root: &Area,
    text: &str,
    at: (i32, i32),
    style: TextStyle<'static>,
) -> Result<(), Failed> {
    if text.is_empty() {
        return Ok(());
    }
    root.draw(&Text::new(text.to_string(), at, style))?;
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Legend (a band above the plot, wrapped into rows)

const LEGEND_SAMPLE_W: i32 = 34;
const LEGEND_ROW_H: i32 = 22;
const LEGEND_GAP: i32 = 22;

impl Conventions {
    fn legend_item_width(self, item: &LegendItem) -> i32 {
        LEGEND_SAMPLE_W + 7 + self.text_width(&item.text, LEGEND_PX).ceil() as i32
    }

    /// Rows of item indices that fit `avail` pixels.
    fn legend_rows(self, items: &[LegendItem], avail: i32) -> Vec<Vec<usize>> {
        let mut rows: Vec<Vec<usize>> = Vec::new();
        let mut used = 0;
        for (i, item) in items.iter().enumerate() {
            let w = self.legend_item_width(item);
            match rows.last_mut() {
                Some(row) if used + LEGEND_GAP + w <= avail => {
                    row.push(i);
                    used += LEGEND_GAP + w;
                }
                _ => {
                    rows.push(vec![i]);
                    used = w;
                }
            }
        }
        rows
    }

    /// Height of the legend band; 0 (no legend) when it would take over a quarter of the chart.
    pub(crate) fn legend_height(self, items: &[LegendItem], avail: i32, chart_h: i32) -> i32 {
        let rows = self.legend_rows(items, avail).len() as i32;
        let h = if rows == 0 {
            0
        } else {
            rows * LEGEND_ROW_H + 10
        };
        if h * 4 > chart_h { 0 } else { h }
    }

    /// Draws the legend rows centred between `left` and `right`, starting at `top`.
    pub(crate) fn draw_legend(
        self,
        root: &Area,
        items: &[LegendItem],
        left: i32,
        right: i32,
        top: i32,
    ) -> Result<(), Failed> {
        let avail = right - left;
        for (r, row) in self.legend_rows(items, avail).iter().enumerate() {
            let widths: Vec<i32> = row
                .iter()
                .map(|&i| self.legend_item_width(&items[i]))
                .collect();
            let total: i32 = widths.iter().sum::<i32>() + LEGEND_GAP * (row.len() as i32 - 1);
            let mut x = left + ((avail - total) / 2).max(0);
            let y = top + 6 + r as i32 * LEGEND_ROW_H + LEGEND_ROW_H / 2;
            for (&i, w) in row.iter().zip(&widths) {
                let item = &items[i];
                if let Some(fill) = item.swatch {
                    let (a, b) = ((x + 2, y - 7), (x + LEGEND_SAMPLE_W - 2, y + 7));
                    root.draw(&Rectangle::new([a, b], fill.filled()))?;
                    root.draw(&Rectangle::new([a, b], GUIDE.stroke_width(1)))?;
                }
                if let Some(stroke) = item.stroke {
                    draw_line(
                        root,
                        &[
                            (x as f64, y as f64),
                            ((x + LEGEND_SAMPLE_W) as f64, y as f64),
                        ],
                        stroke,
                    )?;
                }
                if let Some((marker, color)) = item.marker {
                    draw_marker(root, (x + LEGEND_SAMPLE_W / 2, y), marker, color)?;
                }
                draw_text(
                    root,
                    &item.text,
                    (x + LEGEND_SAMPLE_W + 7, y),
                    text_style(LEGEND_PX, false, INK, HPos::Left, VPos::Center),
                )?;
                x += w + LEGEND_GAP;
            }
        }
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------
// Axes

/// Left margin holding the rotated y description.
pub(crate) const Y_DESC_W: u32 = 26;
/// Height of the x tick label row, and of the row holding the x description below it.
pub(crate) const X_TICK_H: u32 = 26;
pub(crate) const X_DESC_H: u32 = 24;

/// One plot's frame: ranges, margins, the x description and who draws the x ticks.
pub(crate) struct AxesSpec<'s> {
    pub x: (f64, f64),
    pub y: (f64, f64),
    pub top: u32,
    pub right: u32,
    pub(crate) x_desc: Option<&'s str>,
    /// x ticks and vertical grid drawn by the caller (log axis)
    pub(crate) own_x_ticks: bool,
}

/// Row height of a chart of stacked rows (bars, checks): rows are lower the more there are,
/// `steps` gives (up to this many rows, this height), in increasing row counts.
pub(crate) fn row_height(rows: usize, steps: &[(usize, u32)], rest: u32) -> u32 {
    steps
        .iter()
        .find(|(up_to, _)| rows <= *up_to)
        .map_or(rest, |&(_, h)| h)
}

pub(crate) fn y_tick_count(plot_h: u32) -> usize {
    ((plot_h / 30) as usize).clamp(3, 12)
}

pub(crate) fn x_tick_count(plot_w: u32) -> usize {
    ((plot_w / 85) as usize).clamp(3, 12)
}

impl Conventions {
    /// Width of the y tick label column for a y range.
    pub(crate) fn y_tick_width(self, y: (f64, f64), plot_h: u32) -> u32 {
        let (points, decimals) = ticks(y, y_tick_count(plot_h));
        let widest = points
            .iter()
            .map(|v| self.text_width(&fmt_fixed_for_print(*v, decimals), TICK_PX))
            .fold(0.0, f64::max);
        (widest.ceil() as u32 + 14).clamp(30, 160)
    }

    /// The rotated y description, centred on pixel rows `top..bottom`.
    pub(crate) fn draw_y_desc(
        self,
        root: &Area,
        text: &str,
        top: i32,
        bottom: i32,
    ) -> Result<(), Failed> {
        // Centred on the plot, it may reach past it as far as the chart's own edges.
        let centre = (top + bottom) / 2;
        let height = root.dim_in_pixel().1 as i32;
        let len = (2 * centre.min(height - centre) - 8).max(20) as f64;
        let text = self.fit_text(text, DESC_PX, len);
        let st = text_style(DESC_PX, false, INK, HPos::Center, VPos::Top)
            .transform(FontTransform::Rotate270);
        draw_text(root, &text, (4, centre), st)
    }
}

/// Builds the chart with grid, ticks and the frame's four edges.
pub(crate) fn build_axes<'a>(
    area: &'a Area,
    spec: &AxesSpec,
    y_label_w: u32,
) -> Result<Chart<'a>, Failed> {
    let (w, h) = area.dim_in_pixel();
    let x_label_h = X_TICK_H + if spec.x_desc.is_some() { X_DESC_H } else { 0 };
    let plot_w = w.saturating_sub(Y_DESC_W + y_label_w + spec.right).max(10);
    let plot_h = h.saturating_sub(spec.top + x_label_h + 6).max(10);
    let mut chart = ChartBuilder::on(area)
        .margin_top(spec.top)
        .margin_right(spec.right)
        .margin_left(Y_DESC_W)
        .margin_bottom(6)
        .x_label_area_size(x_label_h)
        .y_label_area_size(y_label_w)
        .build_cartesian_2d(spec.x.0..spec.x.1, spec.y.0..spec.y.1)?;

    let nx = if spec.own_x_ticks {
        0
    } else {
        x_tick_count(plot_w)
    };
    let ny = y_tick_count(plot_h);
    let (_, x_dec) = ticks(spec.x, nx.max(1));
    let (_, y_dec) = ticks(spec.y, ny);
    let x_fmt = move |v: &f64| fmt_fixed_for_print(*v, x_dec);
    let y_fmt = move |v: &f64| fmt_fixed_for_print(*v, y_dec);
    let tick_font = font(TICK_PX, false).color(&INK);
    let desc_font = font(DESC_PX, false).color(&INK);
    let mut mesh = chart.configure_mesh();
    mesh.x_labels(nx)
        .y_labels(ny)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .x_label_style(tick_font.clone())
        .y_label_style(tick_font)
        .axis_desc_style(desc_font)
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .axis_style(FRAME.stroke_width(1))
        .set_all_tick_mark_size(4);
    if spec.own_x_ticks {
        mesh.disable_x_mesh();
    }
    if let Some(desc) = spec.x_desc {
        mesh.x_desc(desc);
    }
    mesh.draw()?;
    draw_frame_edges(area, &chart)?;
    Ok(chart)
}

/// The frame's top and right edges (the axes draw the left and bottom ones).
pub(crate) fn draw_frame_edges(area: &Area, chart: &Chart) -> Result<(), Failed> {
    let (bx, by) = area.get_base_pixel();
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let (l, r, t, b) = (
        xr.start - bx,
        xr.end - 1 - bx,
        yr.start - by,
        yr.end - 1 - by,
    );
    area.draw(&PathElement::new(
        vec![(l, t), (r, t), (r, b)],
        FRAME.stroke_width(1),
    ))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::chart_kit::scene::{Outline, Paint};

    fn style() -> Style {
        Style {
            width_px: 300,
            height_px: 200,
        }
    }

    #[test]
    fn a_dashed_line_is_one_path_with_its_pattern_in_drawing_order() {
        let dashed = Stroke {
            color: DOWN,
            width: 2,
            dash: &[9.0, 3.5, 2.0, 3.5],
        };
        let solid = Stroke::new(UP, 1, SOLID);
        let scene = render(&style(), |root| {
            // A sub-area: the dashed line is recorded in the canvas' own coordinates.
            let (_, right) = root.split_horizontally(100);
            draw_line(&right, &[(0.0, 10.0), (50.0, 10.4), (120.0, 60.0)], dashed)?;
            draw_marker(root, (5, 5), Marker::Dot(3), UP)?;
            draw_line(root, &[(0.0, 0.0), (30.0, 0.0), (30.2, 0.0)], solid)
        });
        let shapes = &scene.drawing.shapes;
        assert_eq!(shapes.len(), 4, "{shapes:?}");
        assert_eq!(shapes[0].paint, Paint::Fill(Colour::WHITE));
        assert_eq!(
            shapes[1].paint,
            Paint::Stroke {
                colour: Colour(0x8E, 0x1B, 0x1B),
                width: 2,
                dash: vec![9.0, 3.5, 2.0, 3.5]
            }
        );
        assert_eq!(
            shapes[1].outlines,
            [Outline::Line(vec![(100, 10), (150, 10), (220, 60)])]
        );
        assert!(matches!(
            shapes[2].outlines[..],
            [Outline::Circle((5, 5), 3)]
        ));
        // The point rounding to the pixel before is dropped.
        assert_eq!(shapes[3].outlines, [Outline::Line(vec![(0, 0), (30, 0)])]);
    }

    #[test]
    fn numbers_for_print_use_a_true_minus_and_words() {
        assert_eq!(fmt_fixed_for_print(-1.5, 2), "−1.50");
        assert_eq!(fmt_fixed_for_print(-0.001, 2), "0.00");
        assert_eq!(fmt_fixed_for_print(f64::NAN, 2), "n/a");
        assert_eq!(fmt_fixed_for_print(f64::NEG_INFINITY, 2), "−∞");
        assert_eq!(fmt_fixed_for_print(-2.5e300, 0), "−2.50e300");
    }
}
