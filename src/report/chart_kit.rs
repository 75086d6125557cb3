//! What the report's chart modules ([`super::charts`] and [`super::diagnosis_charts`]) share:
//! the look (tones, text sizes, dash patterns), the SVG frame, text measuring and fitting,
//! number formatting, line, marker and legend drawing, and the axes with grid and ticks.
//!
//! Where the two modules measure or draw slightly differently, the difference is a field of
//! [`Conventions`] and each module passes its own, so every chart keeps its exact bytes.

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::cell::RefCell;

/// Style shared by all charts. `font_family` is the family name of the sans-serif face the
/// PDF renderer embeds ("Inter"); charts must only ever name this family in SVG text.
#[derive(Debug, Clone, PartialEq)]
pub struct Style {
    pub font_family: String,
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

/// Text sizes in SVG pixels (the `font-size` written into the SVG).
pub(crate) const TICK_PX: f64 = 14.0;
pub(crate) const DESC_PX: f64 = 15.5;
pub(crate) const LEGEND_PX: f64 = 14.0;

/// Dash patterns in pixels: on, off, on, off …
pub(crate) const SOLID: &[f64] = &[];
pub(crate) const DASHED: &[f64] = &[10.0, 5.0];

#[derive(Clone, Copy)]
pub(crate) struct Stroke {
    pub color: RGBColor,
    pub width: u32,
    pub dash: &'static [f64],
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
    pub swatch: Option<RGBColor>,
    pub text: String,
}

/// How a chart module measures text and joins line pixels. The modules differ here and each
/// keeps its own so its charts draw exactly as they did.
#[derive(Clone, Copy)]
pub(crate) struct Conventions {
    /// Superscript digits and minus (as in 10⁻³) measure 0.4 em; otherwise they count as the
    /// 0.7 em of other symbols.
    pub narrow_superscripts: bool,
    /// Each dash of a line drops points that round to the pixel of the point before.
    pub dedup_pixels: bool,
}

// ---------------------------------------------------------------------------------------------
// Errors and the SVG frame

/// A drawing step failed; the chart falls back to a message.
pub(crate) struct Failed;

impl<E: std::error::Error + Send + Sync> From<DrawingAreaErrorKind<E>> for Failed {
    fn from(_: DrawingAreaErrorKind<E>) -> Self {
        Failed
    }
}

pub(crate) type Area<'b> = DrawingArea<SVGBackend<'b>, Shift>;
pub(crate) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

pub(crate) fn dims(style: &Style) -> (u32, u32) {
    (
        style.width_px.clamp(240, 10_000),
        style.height_px.clamp(140, 20_000),
    )
}

thread_local! {
    /// The dashed lines of the chart being drawn on this thread, as finished SVG elements.
    static DASHED_LINES: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

/// Font family of the placeholder text that stands for a dashed line until [`render`]
/// replaces it (charts name no other family than the style's, so it cannot clash).
const DASHED_LINE_PLACEHOLDER: &str = "axcheck-dashed-line";

/// Draws with `paint` on a white SVG of the style's size; a failure gives a message chart.
pub(crate) fn render(style: &Style, paint: impl FnOnce(&Area) -> Result<(), Failed>) -> String {
    let size = dims(style);
    let mut buf = String::new();
    DASHED_LINES.with_borrow_mut(Vec::clear);
    let ok = {
        let root = SVGBackend::with_string(&mut buf, size).into_drawing_area();
        let drawn = root
            .fill(&WHITE)
            .map_err(Failed::from)
            .and_then(|_| paint(&root));
        let presented = root.present().map_err(Failed::from);
        drawn.is_ok() && presented.is_ok()
    };
    let dashed = DASHED_LINES.with_borrow_mut(std::mem::take);
    if ok {
        insert_dashed_lines(&buf, &dashed)
            .unwrap_or_else(|| message_chart(style, "This chart could not be drawn."))
    } else {
        message_chart(style, "This chart could not be drawn.")
    }
}

/// A chart holding only a centred message (for empty or unusable input).
pub(crate) fn message_chart(style: &Style, message: &str) -> String {
    let size = dims(style);
    let mut buf = String::new();
    let ok = {
        let root = SVGBackend::with_string(&mut buf, size).into_drawing_area();
        let drawn = root.fill(&WHITE).is_ok()
            && root
                .draw(&Text::new(
                    message.to_string(),
                    (size.0 as i32 / 2, size.1 as i32 / 2),
                    text_style(style, DESC_PX, false, MUTED, HPos::Center, VPos::Center),
                ))
                .is_ok();
        drawn && root.present().is_ok()
    };
    if ok {
        buf
    } else {
        format!(
            "<svg width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" xmlns=\"http://www.w3.org/2000/svg\">\n</svg>\n",
            size.0, size.1
        )
    }
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

pub(crate) fn font<'a>(style: &'a Style, px: f64, bold: bool) -> FontDesc<'a> {
    let face = if bold {
        FontStyle::Bold
    } else {
        FontStyle::Normal
    };
    FontDesc::new(
        FontFamily::Name(&style.font_family),
        plotters_size(px),
        face,
    )
}

pub(crate) fn text_style<'a>(
    style: &'a Style,
    px: f64,
    bold: bool,
    color: RGBColor,
    h: HPos,
    v: VPos,
) -> TextStyle<'a> {
    font(style, px, bold).color(&color).pos(Pos::new(h, v))
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

/// `v` with `decimals` places, a true minus sign and no "−0" (huge values in e-notation).
pub(crate) fn fmt_fixed(v: f64, decimals: usize) -> String {
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
    let s = format!("{:.*}", decimals, v);
    let is_zero = s
        .trim_start_matches('-')
        .chars()
        .all(|c| c == '0' || c == '.');
    match s.strip_prefix('-') {
        Some(rest) if is_zero => rest.to_string(),
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

/// One SVG polyline with a dash pattern, in the attribute layout plotters writes.
fn dashed_polyline(points: &[(i32, i32)], stroke: Stroke) -> String {
    let RGBColor(r, g, b) = stroke.color;
    let pattern: Vec<String> = stroke.dash.iter().map(f64::to_string).collect();
    let mut out = format!(
        "<polyline fill=\"none\" opacity=\"1\" stroke=\"#{r:02X}{g:02X}{b:02X}\" stroke-width=\"{}\" stroke-dasharray=\"{}\" points=\"",
        stroke.width,
        pattern.join(" ")
    );
    for (x, y) in points {
        out.push_str(&format!("{x},{y} "));
    }
    out.push_str("\"/>");
    out
}

/// Replaces each dashed-line placeholder in `svg` by its polyline, keeping the drawing
/// order; `None` if a placeholder is malformed or unknown (never expected).
fn insert_dashed_lines(svg: &str, lines: &[String]) -> Option<String> {
    let marker = format!("font-family=\"{DASHED_LINE_PLACEHOLDER}\"");
    let mut out = String::with_capacity(svg.len());
    let mut rest = svg;
    while let Some(at) = rest.find(&marker) {
        let start = rest[..at].rfind("<text")?;
        let close = at + rest[at..].find("</text>")?;
        let open_end = at + rest[at..close].find('>')? + 1;
        let index: usize = rest[open_end..close].trim().parse().ok()?;
        out.push_str(&rest[..start]);
        out.push_str(lines.get(index)?);
        rest = &rest[close + "</text>".len()..];
    }
    out.push_str(rest);
    Some(out)
}

/// Drops points that round to the pixel of the point before (keeps polylines short).
fn dedup_pixels(points: Vec<(i32, i32)>) -> Vec<(i32, i32)> {
    let mut out: Vec<(i32, i32)> = Vec::with_capacity(points.len());
    for p in points {
        if out.last() != Some(&p) {
            out.push(p);
        }
    }
    out
}

impl Conventions {
    pub(crate) fn draw_line(
        self,
        root: &Area,
        points: &[Px],
        stroke: Stroke,
    ) -> Result<(), Failed> {
        if points.len() < 2 {
            return Ok(());
        }
        let points: Vec<(i32, i32)> = points.iter().map(|p| round_px(*p)).collect();
        let points = if self.dedup_pixels {
            dedup_pixels(points)
        } else {
            points
        };
        if points.len() < 2 {
            return Ok(());
        }
        if !is_dashed(stroke.dash) {
            let shape = ShapeStyle::from(&stroke.color).stroke_width(stroke.width);
            root.draw(&PathElement::new(points, shape))?;
            return Ok(());
        }
        // Plotters draws only solid paths; one polyline per dash made hundreds of elements
        // per chart for the PDF to convert. Leave a placeholder that `render` replaces by
        // one polyline with `stroke-dasharray`, in place so the drawing order is kept.
        let (dx, dy) = root.get_base_pixel();
        let absolute: Vec<(i32, i32)> = points.iter().map(|(x, y)| (x + dx, y + dy)).collect();
        let index = DASHED_LINES.with_borrow_mut(|lines| {
            lines.push(dashed_polyline(&absolute, stroke));
            lines.len() - 1
        });
        let placeholder = FontDesc::new(
            FontFamily::Name(DASHED_LINE_PLACEHOLDER),
            1.0,
            FontStyle::Normal,
        );
        root.draw(&Text::new(index.to_string(), (0, 0), placeholder))?;
        Ok(())
    }
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
    style: TextStyle,
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
        style: &Style,
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
                    self.draw_line(
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
                    text_style(style, LEGEND_PX, false, INK, HPos::Left, VPos::Center),
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
    pub x_desc: Option<&'s str>,
    /// x ticks and vertical grid drawn by the caller (log axis)
    pub own_x_ticks: bool,
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
            .map(|v| self.text_width(&fmt_fixed(*v, decimals), TICK_PX))
            .fold(0.0, f64::max);
        (widest.ceil() as u32 + 14).clamp(30, 160)
    }

    /// The rotated y description, centred on pixel rows `top..bottom`.
    pub(crate) fn draw_y_desc(
        self,
        root: &Area,
        style: &Style,
        text: &str,
        top: i32,
        bottom: i32,
    ) -> Result<(), Failed> {
        // Centred on the plot, it may reach past it as far as the chart's own edges.
        let centre = (top + bottom) / 2;
        let height = root.dim_in_pixel().1 as i32;
        let len = (2 * centre.min(height - centre) - 8).max(20) as f64;
        let text = self.fit_text(text, DESC_PX, len);
        let st = text_style(style, DESC_PX, false, INK, HPos::Center, VPos::Top)
            .transform(FontTransform::Rotate270);
        draw_text(root, &text, (4, centre), st)
    }
}

/// Builds the chart with grid, ticks and the frame's four edges.
pub(crate) fn build_axes<'a, 'b>(
    area: &'a Area<'b>,
    style: &Style,
    spec: &AxesSpec,
    y_label_w: u32,
) -> Result<Chart<'a, 'b>, Failed> {
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
    let x_fmt = move |v: &f64| fmt_fixed(*v, x_dec);
    let y_fmt = move |v: &f64| fmt_fixed(*v, y_dec);
    let tick_font = font(style, TICK_PX, false).color(&INK);
    let desc_font = font(style, DESC_PX, false).color(&INK);
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

    fn style() -> Style {
        Style {
            font_family: "Inter".into(),
            width_px: 300,
            height_px: 200,
        }
    }

    const KIT: Conventions = Conventions {
        narrow_superscripts: false,
        dedup_pixels: true,
    };

    #[test]
    fn a_dashed_line_is_one_polyline_with_its_pattern_in_drawing_order() {
        let dashed = Stroke {
            color: DOWN,
            width: 2,
            dash: &[9.0, 3.5, 2.0, 3.5],
        };
        let solid = Stroke {
            color: UP,
            width: 1,
            dash: SOLID,
        };
        let svg = render(&style(), |root| {
            // A sub-area: the dashed line is written in the SVG's own coordinates.
            let (_, right) = root.split_horizontally(100);
            KIT.draw_line(&right, &[(0.0, 10.0), (50.0, 10.4), (120.0, 60.0)], dashed)?;
            draw_marker(root, (5, 5), Marker::Dot(3), UP)?;
            KIT.draw_line(root, &[(0.0, 0.0), (30.0, 0.0)], solid)
        });
        assert!(!svg.contains(DASHED_LINE_PLACEHOLDER), "{svg}");
        let dashed_line = "<polyline fill=\"none\" opacity=\"1\" stroke=\"#8E1B1B\" stroke-width=\"2\" stroke-dasharray=\"9 3.5 2 3.5\" points=\"100,10 150,10 220,60 \"/>";
        let at = svg.find(dashed_line).expect(&svg);
        assert!(
            at < svg.find("<circle").expect("marker"),
            "drawing order kept"
        );
        assert_eq!(svg.matches("stroke-dasharray").count(), 1);
        assert!(svg.contains("points=\"0,0 30,0 \""));
    }

    #[test]
    fn an_unknown_placeholder_is_refused() {
        let svg = "<svg><text x=\"0\" font-family=\"axcheck-dashed-line\">3</text></svg>";
        assert_eq!(insert_dashed_lines(svg, &["<polyline/>".into()]), None);
        let one = insert_dashed_lines(svg.replace('3', "0").as_str(), &["<polyline/>".into()]);
        assert_eq!(one.as_deref(), Some("<svg><polyline/></svg>"));
    }
}
