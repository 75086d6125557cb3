//! Report charts drawn with `plotters` into [`Scene`]s (shapes and texts as data).
//!
//! Every function here is pure: the same input gives the same scene, nothing touches the
//! file system, and no input makes it panic (a chart that cannot be drawn comes back as a
//! small chart that says so).
//!
//! Sizes are in pixels and the text sizes are fixed, chosen for a chart about 900 px wide
//! shown about 16 cm wide: 900 × 420 for [`bidirectional`], 900 × 600 for [`unidirectional`]
//! (two panels stacked).

use crate::report::chart_kit::scene::Scene;
use crate::report::chart_kit::{
    Area, AxesSpec, Chart, Conventions, DASHED, DESC_PX, DOWN, Failed, GUIDE, INK, LegendItem,
    MUTED, Marker, Px, SOLID, Stroke, UP, X_DESC_H, X_TICK_H, build_axes, draw_line, draw_marker,
    draw_text, extent, fmt_fixed_for_print, message_chart, padded_range, render, round_px,
    sig_decimals, text_style,
};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

pub use crate::report::chart_kit::Style;

/// One approach direction's per-target statistics. All deviation values in the axis's
/// deviation unit (µm or arcsec).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DirectionSeries {
    /// X̄i↑ (or ↓) per target
    pub mean: Vec<f64>,
    /// X̄i + kSi per target (None when n = 1)
    pub upper: Option<Vec<f64>>,
    /// X̄i − kSi per target
    pub lower: Option<Vec<f64>>,
    /// the n individual readings at each target
    pub deviations: Vec<Vec<f64>>,
}

/// A range-type axis parameter to mark on the chart, e.g. A = max(upper) − min(lower).
#[derive(Debug, Clone, PartialEq)]
pub struct Span {
    pub label: String,
    pub upper: f64,
    pub lower: f64,
}

/// Everything the two axis charts show.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AxisChart {
    /// target positions P_i, ascending (mm or deg)
    pub positions: Vec<f64>,
    /// e.g. "Target position Pi / mm"
    pub position_label: String,
    /// e.g. "Positional deviation / µm"
    pub deviation_label: String,
    pub up: DirectionSeries,
    pub down: DirectionSeries,
    /// bidirectional mean X̄i per target
    pub mean: Vec<f64>,
    /// e.g. "X̄ ± 2S" (ISO) or "X̄ ± 3S" (GOST)
    pub band_label: String,
    /// e.g. A, E, M for the bidirectional chart
    pub spans: Vec<Span>,
}

// ---------------------------------------------------------------------------------------------
// Look

pub(in crate::report) const UP_LIGHT: RGBColor = RGBColor(0x5F, 0x7F, 0xB0);
pub(in crate::report) const DOWN_LIGHT: RGBColor = RGBColor(0xBE, 0x62, 0x62);

/// Text size of the span labels, in SVG pixels (the `font-size` written into the SVG).
const SPAN_PX: f64 = 14.0;

/// Dash patterns in pixels: on, off, on, off …
pub(in crate::report) const DASHED_THIN: &[f64] = &[6.0, 4.0];
const DASH_DOT: &[f64] = &[9.0, 3.5, 2.0, 3.5];

/// How these charts measure text (see [`Conventions`]).
pub(in crate::report) const KIT: Conventions = Conventions {
    narrow_superscripts: false,
};

const MEAN_UP: Stroke = Stroke::new(UP, 2, SOLID);
const MEAN_DOWN: Stroke = Stroke::new(DOWN, 2, DASHED);
const LIMIT_UP: Stroke = Stroke::new(UP_LIGHT, 1, SOLID);
const LIMIT_DOWN: Stroke = Stroke::new(DOWN_LIGHT, 1, DASHED_THIN);
const MEAN_BIDIR: Stroke = Stroke::new(INK, 1, DASH_DOT);
const MARK_MEAN_UP: (Marker, RGBColor) = (Marker::Dot(4), UP);
const MARK_MEAN_DOWN: (Marker, RGBColor) = (Marker::Triangle(5), DOWN);
const MARK_READ_UP: (Marker, RGBColor) = (Marker::Dot(2), UP_LIGHT);
const MARK_READ_DOWN: (Marker, RGBColor) = (Marker::TriangleOutline(3), DOWN_LIGHT);

// ---------------------------------------------------------------------------------------------
// Numbers

/// Three significant digits, at most nine decimals.
fn fmt_sig(v: f64) -> String {
    fmt_fixed_for_print(v, sig_decimals(v))
}

/// The x range: the targets with 4 % to spare; a single target gets a window around it.
fn x_range(positions: &[f64]) -> Option<(f64, f64)> {
    padded_range(positions.iter().copied(), 0.04)
}

/// The y range: every value and zero, padded by 8 %.
pub(in crate::report) fn y_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = extent(values.into_iter().chain([0.0]))?;
    let span = hi - lo;
    // Zero is inside, so only data that is all (practically) zero has no extent.
    let (lo, hi) = if span < 1e-9 {
        (lo - 1.0, hi + 1.0)
    } else {
        (lo - span * 0.08, hi + span * 0.08)
    };
    (lo.is_finite() && hi.is_finite() && hi > lo).then_some((lo, hi))
}

// ---------------------------------------------------------------------------------------------
// Drawing primitives (in backend pixels, on the root area)

pub(in crate::report) fn to_px(c: (i32, i32)) -> Px {
    (c.0 as f64, c.1 as f64)
}

// ---------------------------------------------------------------------------------------------
// Axis charts

/// Builds one panel's chart with grid, ticks, frame and zero line.
pub(in crate::report) fn build_panel<'a>(
    area: &'a Area,
    frame: &AxesSpec,
    y_label_w: u32,
) -> Result<Chart<'a>, Failed> {
    let chart = build_axes(area, frame, y_label_w)?;

    // The zero line.
    // (`area` draws in its own pixels; the chart reports backend pixels.)
    let (bx, by) = area.get_base_pixel();
    let (xr, _) = chart.plotting_area().get_pixel_range();
    let (l, r) = (xr.start - bx, xr.end - 1 - bx);
    let zero = chart.backend_coord(&(frame.x.0, 0.0)).1 - by;
    area.draw(&PathElement::new(
        vec![(l, zero), (r, zero)],
        MUTED.stroke_width(1),
    ))?;
    Ok(chart)
}

/// What of a direction to draw; drawn in this order so means stay on top.
#[derive(Clone, Copy, PartialEq)]
enum Layer {
    Limits,
    Readings,
    Mean,
}

/// Draws one layer of one direction.
fn draw_direction(
    root: &Area,
    chart: &Chart,
    positions: &[f64],
    series: &DirectionSeries,
    up: bool,
    layer: Layer,
) -> Result<(), Failed> {
    let (mean_stroke, limit_stroke, mean_mark, read_mark) = if up {
        (MEAN_UP, LIMIT_UP, MARK_MEAN_UP, MARK_READ_UP)
    } else {
        (MEAN_DOWN, LIMIT_DOWN, MARK_MEAN_DOWN, MARK_READ_DOWN)
    };
    match layer {
        Layer::Limits => {
            for limit in [&series.upper, &series.lower].into_iter().flatten() {
                draw_line(root, &curve(chart, positions, limit), limit_stroke)?;
            }
        }
        Layer::Readings if has_readings(series) => {
            for (x, readings) in positions.iter().zip(&series.deviations) {
                for v in readings {
                    if x.is_finite() && v.is_finite() {
                        let at = chart.backend_coord(&(*x, *v));
                        draw_marker(root, at, read_mark.0, read_mark.1)?;
                    }
                }
            }
        }
        Layer::Readings => {}
        Layer::Mean => {
            let mean = curve(chart, positions, &series.mean);
            draw_line(root, &mean, mean_stroke)?;
            for p in &mean {
                draw_marker(root, round_px(*p), mean_mark.0, mean_mark.1)?;
            }
        }
    }
    Ok(())
}

/// Pixel points of a per-target curve (non-finite values are skipped).
pub(in crate::report) fn curve(chart: &Chart, positions: &[f64], values: &[f64]) -> Vec<Px> {
    positions
        .iter()
        .zip(values)
        .filter(|(x, v)| x.is_finite() && v.is_finite())
        .map(|(x, v)| to_px(chart.backend_coord(&(*x, *v))))
        .collect()
}

/// Every value a direction draws.
fn direction_values<'a>(
    positions: &'a [f64],
    s: &'a DirectionSeries,
) -> impl Iterator<Item = f64> + 'a {
    let n = positions.len();
    let limits = [&s.upper, &s.lower]
        .into_iter()
        .flatten()
        .flat_map(move |v| v.iter().take(n).copied());
    s.mean
        .iter()
        .take(n)
        .copied()
        .chain(limits)
        .chain(s.deviations.iter().take(n).flatten().copied())
}

fn span_values(spans: &[Span]) -> impl Iterator<Item = f64> + '_ {
    spans
        .iter()
        .filter(|s| s.upper.is_finite() && s.lower.is_finite())
        .flat_map(|s| [s.upper, s.lower])
}

/// Column widths of the span brackets at the right edge.
fn span_columns(spans: &[Span]) -> Vec<u32> {
    spans
        .iter()
        .filter(|s| s.upper.is_finite() && s.lower.is_finite())
        .map(|s| {
            let label = KIT.text_width(&s.label, SPAN_PX);
            let value = KIT.text_width(&fmt_sig((s.upper - s.lower).abs()), SPAN_PX);
            (label.max(value).ceil() as u32 + 22).clamp(34, 140)
        })
        .collect()
}

/// Right margin that holds the span brackets (a small gap when there are none).
fn span_margin(spans: &[Span], width: u32) -> u32 {
    let cols: u32 = span_columns(spans).iter().sum();
    if cols == 0 {
        18
    } else {
        (cols + 12).min(width * 2 / 5)
    }
}

/// Draws each span as a bracket in its own column right of the plot, with guides to the
/// plot edge, its label and its value.
fn draw_spans(root: &Area, chart: &Chart, spans: &[Span]) -> Result<(), Failed> {
    let (xr, _) = chart.plotting_area().get_pixel_range();
    let plot_right = xr.end - 1;
    let x_any = chart.as_coord_spec().get_x_range().start;
    let finite: Vec<&Span> = spans
        .iter()
        .filter(|s| s.upper.is_finite() && s.lower.is_finite())
        .collect();
    let mut x = plot_right + 14;
    // Squeeze the columns when more spans come than the margin was allowed to hold.
    let columns = span_columns(spans);
    let total: u32 = columns.iter().sum();
    let room = (root.dim_in_pixel().0 as i32 - x).max(1) as f64;
    let squeeze = (room / total.max(1) as f64).min(1.0);
    for (span, col) in finite.iter().zip(columns) {
        let y_hi = chart.backend_coord(&(x_any, span.upper.max(span.lower))).1;
        let y_lo = chart.backend_coord(&(x_any, span.upper.min(span.lower))).1;
        for y in [y_hi, y_lo] {
            root.draw(&PathElement::new(
                vec![(plot_right + 1, y), (x - 7, y)],
                GUIDE.stroke_width(1),
            ))?;
        }
        root.draw(&PathElement::new(
            vec![(x - 6, y_hi), (x, y_hi), (x, y_lo), (x - 6, y_lo)],
            INK.stroke_width(2),
        ))?;
        let mid = (y_hi + y_lo) / 2;
        let tx = x + 5;
        draw_text(
            root,
            &span.label,
            (tx, mid - 1),
            text_style(SPAN_PX, true, INK, HPos::Left, VPos::Bottom),
        )?;
        draw_text(
            root,
            &fmt_sig((span.upper - span.lower).abs()),
            (tx, mid + 1),
            text_style(SPAN_PX, false, INK, HPos::Left, VPos::Top),
        )?;
        x += (col as f64 * squeeze).round() as i32;
    }
    Ok(())
}

fn band_text(chart: &AxisChart) -> &str {
    if chart.band_label.trim().is_empty() {
        "X̄ ± kS"
    } else {
        chart.band_label.trim()
    }
}

fn has_limits(s: &DirectionSeries) -> bool {
    s.upper.as_ref().is_some_and(|v| !v.is_empty())
        || s.lower.as_ref().is_some_and(|v| !v.is_empty())
}

/// Readings are worth showing when some target has more than one (with n = 1 each reading is
/// its mean and hides under the mean's marker).
fn has_readings(s: &DirectionSeries) -> bool {
    s.deviations.iter().any(|r| r.len() > 1)
}

/// The legend entries a direction actually draws.
fn direction_legend(chart: &AxisChart, up: bool) -> Vec<LegendItem> {
    let (series, arrow, mean, limit, mean_mark, read_mark) = if up {
        (
            &chart.up,
            '↑',
            MEAN_UP,
            LIMIT_UP,
            MARK_MEAN_UP,
            MARK_READ_UP,
        )
    } else {
        (
            &chart.down,
            '↓',
            MEAN_DOWN,
            LIMIT_DOWN,
            MARK_MEAN_DOWN,
            MARK_READ_DOWN,
        )
    };
    let mut items = Vec::new();
    if !series.mean.is_empty() {
        items.push(LegendItem {
            stroke: Some(mean),
            marker: Some(mean_mark),
            swatch: None,
            text: format!("mean X̄i{arrow}"),
        });
    }
    if has_limits(series) {
        items.push(LegendItem {
            stroke: Some(limit),
            marker: None,
            swatch: None,
            text: format!("{} {arrow}", band_text(chart)),
        });
    }
    if has_readings(series) {
        items.push(LegendItem {
            stroke: None,
            marker: Some(read_mark),
            swatch: None,
            text: format!("readings {arrow}"),
        });
    }
    items
}

/// Like ISO 230-2 Fig. 2a (bidirectional): X̄i↑ and X̄i↓ joined by lines, the X̄ ± kS limit
/// curves of each direction, the bidirectional mean X̄i, the individual readings as small
/// markers, and the spans (A, E, M …) marked as labelled vertical brackets at the right edge.
///
/// ↑ is dark blue, solid, filled circles; ↓ is dark red, dashed, open triangles; the
/// bidirectional mean is a thin black dash-dot line. The legend sits in a band above the plot.
/// Designed for 900 × 420 px.
pub fn bidirectional(chart: &AxisChart, style: &Style) -> Scene {
    let n = chart.positions.len();
    let Some(x) = x_range(&chart.positions) else {
        return message_chart(style, "No target positions to plot.");
    };
    let values = direction_values(&chart.positions, &chart.up)
        .chain(direction_values(&chart.positions, &chart.down))
        .chain(chart.mean.iter().take(n).copied())
        .chain(span_values(&chart.spans));
    let Some(y) = y_range(values) else {
        return message_chart(style, "The deviations are out of range.");
    };
    render(style, |root| {
        let (w, h) = root.dim_in_pixel();
        let mut items = direction_legend(chart, true);
        items.extend(direction_legend(chart, false));
        if !chart.mean.is_empty() {
            items.push(LegendItem {
                stroke: Some(MEAN_BIDIR),
                marker: None,
                swatch: None,
                text: "mean X̄i (bidirectional)".to_string(),
            });
        }
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let right = span_margin(&chart.spans, w);
        let top = legend_h + 8;
        let plot_h = h.saturating_sub(top + X_TICK_H + X_DESC_H + 6);
        let frame = AxesSpec {
            x,
            y,
            top,
            right,
            x_desc: Some(chart.position_label.as_str()).filter(|d| !d.trim().is_empty()),
            own_x_ticks: false,
        };
        let cp = build_panel(root, &frame, KIT.y_tick_width(y, plot_h))?;
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        let (_, yr) = cp.plotting_area().get_pixel_range();
        KIT.draw_y_desc(root, &chart.deviation_label, yr.start, yr.end)?;

        for layer in [Layer::Limits, Layer::Readings] {
            draw_direction(root, &cp, &chart.positions, &chart.up, true, layer)?;
            draw_direction(root, &cp, &chart.positions, &chart.down, false, layer)?;
        }
        draw_line(root, &curve(&cp, &chart.positions, &chart.mean), MEAN_BIDIR)?;
        draw_direction(root, &cp, &chart.positions, &chart.up, true, Layer::Mean)?;
        draw_direction(root, &cp, &chart.positions, &chart.down, false, Layer::Mean)?;
        draw_spans(root, &cp, &chart.spans)?;
        Ok(())
    })
}

/// Like ISO 230-2 Fig. 2b (unidirectional): ↑ and ↓ in two panels stacked (↑ on top), each
/// with its mean line, its X̄ ± kS curves and its readings; spans given per panel via
/// `up_spans` / `down_spans` (e.g. A↑, E↑, R↑ …). Both panels share the x and y scales.
/// Designed for 900 × 600 px.
pub fn unidirectional(
    chart: &AxisChart,
    up_spans: &[Span],
    down_spans: &[Span],
    style: &Style,
) -> Scene {
    let Some(x) = x_range(&chart.positions) else {
        return message_chart(style, "No target positions to plot.");
    };
    let values = direction_values(&chart.positions, &chart.up)
        .chain(direction_values(&chart.positions, &chart.down))
        .chain(span_values(up_spans))
        .chain(span_values(down_spans));
    let Some(y) = y_range(values) else {
        return message_chart(style, "The deviations are out of range.");
    };
    render(style, |root| {
        let (w, h) = root.dim_in_pixel();
        let mut items = direction_legend(chart, true);
        items.extend(direction_legend(chart, false));
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let right = span_margin(up_spans, w).max(span_margin(down_spans, w));
        let body_h = h.saturating_sub(legend_h);
        let top_h = (body_h.saturating_sub(X_DESC_H)) / 2;
        let (_, body) = root.split_vertically(legend_h);
        let (upper_area, lower_area) = body.split_vertically(top_h);
        let heading = 24;
        let plot_h = top_h.saturating_sub(heading + X_TICK_H + 6);
        let y_label_w = KIT.y_tick_width(y, plot_h);

        let panels = [
            (&upper_area, &chart.up, up_spans, true, "Approach ↑", None),
            (
                &lower_area,
                &chart.down,
                down_spans,
                false,
                "Approach ↓",
                Some(chart.position_label.as_str()).filter(|d| !d.trim().is_empty()),
            ),
        ];
        let mut plot_rows = (i32::MAX, i32::MIN);
        for (area, series, spans, up, title, x_desc) in panels {
            let frame = AxesSpec {
                x,
                y,
                top: heading,
                right,
                x_desc,
                own_x_ticks: false,
            };
            let cp = build_panel(area, &frame, y_label_w)?;
            let (xr, yr) = cp.plotting_area().get_pixel_range();
            plot_rows = (plot_rows.0.min(yr.start), plot_rows.1.max(yr.end));
            let color = if up { UP } else { DOWN };
            draw_text(
                root,
                title,
                (xr.start, yr.start - 5),
                text_style(DESC_PX, true, color, HPos::Left, VPos::Bottom),
            )?;
            for layer in [Layer::Limits, Layer::Readings, Layer::Mean] {
                draw_direction(root, &cp, &chart.positions, series, up, layer)?;
            }
            draw_spans(root, &cp, spans)?;
        }
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        KIT.draw_y_desc(root, &chart.deviation_label, plot_rows.0, plot_rows.1)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::super::usage::{RatioBar, ratio_chart_height};
    use super::*;
    use crate::report::chart_kit::svg_probe::{
        assert_well_formed, attr_values, degenerate_styles, text_tag, texts,
    };
    use crate::report::chart_kit::ticks;

    // The charts as SVG with an element per outline, as plotters wrote them.
    fn bidirectional(chart: &AxisChart, style: &Style) -> String {
        super::bidirectional(chart, style).element_svg()
    }

    fn unidirectional(chart: &AxisChart, up: &[Span], down: &[Span], style: &Style) -> String {
        super::unidirectional(chart, up, down, style).element_svg()
    }

    fn tolerance_usage(bars: &[RatioBar], style: &Style) -> String {
        super::super::usage::tolerance_usage(bars, style).element_svg()
    }

    fn style() -> Style {
        Style {
            width_px: 900,
            height_px: 420,
        }
    }

    /// The ISO 230-2 Table 2 example: 11 targets, n = 5, k = 2.
    fn iso_example() -> AxisChart {
        let positions = vec![
            6.711, 175.077, 340.251, 509.912, 674.140, 843.192, 1009.475, 1175.001, 1342.648,
            1510.000, 1750.920,
        ];
        let up = [
            -1.60, -0.70, -0.34, -0.94, -2.16, -3.34, -4.14, -4.28, -4.10, -3.72, -3.96,
        ];
        let down = [
            2.26, 3.42, 3.42, 2.78, 1.44, 0.24, -0.60, -0.62, -0.20, -0.30, -0.48,
        ];
        let s_up = [
            0.35, 0.42, 0.50, 0.30, 0.62, 0.55, 0.70, 0.65, 0.50, 0.45, 0.75,
        ];
        let s_down = [
            0.60, 0.45, 0.30, 0.52, 0.40, 0.66, 0.38, 0.71, 0.55, 0.48, 0.35,
        ];
        let offsets = [-1.2, -0.4, 0.3, 0.5, 0.8];
        let series = |m: &[f64], s: &[f64]| DirectionSeries {
            mean: m.to_vec(),
            upper: Some(m.iter().zip(s).map(|(a, b)| a + 2.0 * b).collect()),
            lower: Some(m.iter().zip(s).map(|(a, b)| a - 2.0 * b).collect()),
            deviations: m
                .iter()
                .zip(s)
                .map(|(a, b)| offsets.iter().map(|o| a + o * b).collect())
                .collect(),
        };
        AxisChart {
            mean: up.iter().zip(&down).map(|(a, b)| (a + b) / 2.0).collect(),
            positions,
            position_label: "Target position Pi / mm".to_string(),
            deviation_label: "Positional deviation / µm".to_string(),
            up: series(&up, &s_up),
            down: series(&down, &s_down),
            band_label: "X̄ ± 2S".to_string(),
            spans: vec![
                span("A", 4.01, -5.58),
                span("E", 3.42, -4.28),
                span("M", 1.54, -2.45),
            ],
        }
    }

    fn span(label: &str, upper: f64, lower: f64) -> Span {
        Span {
            label: label.to_string(),
            upper,
            lower,
        }
    }

    /// An axis measured once per target (n = 1): no limit curves.
    fn single_run(targets: usize) -> AxisChart {
        let positions: Vec<f64> = (0..targets).map(|i| 20.0 + 100.0 * i as f64).collect();
        let up: Vec<f64> = (0..targets).map(|i| (i as f64 * 0.4).sin() * 3.0).collect();
        let down: Vec<f64> = up.iter().map(|v| v + 2.0).collect();
        let series = |m: &[f64]| DirectionSeries {
            mean: m.to_vec(),
            upper: None,
            lower: None,
            deviations: m.iter().map(|v| vec![*v]).collect(),
        };
        AxisChart {
            mean: up.iter().zip(&down).map(|(a, b)| (a + b) / 2.0).collect(),
            positions,
            position_label: "Target position Pi / mm".to_string(),
            deviation_label: "Positional deviation / µm".to_string(),
            up: series(&up),
            down: series(&down),
            band_label: "X̄ ± 3S".to_string(),
            spans: Vec::new(),
        }
    }

    fn bars(n: usize) -> Vec<RatioBar> {
        (0..n)
            .map(|i| {
                let ratio = match i % 20 {
                    3 => 2.6,
                    7 => 1.15,
                    12 => 5.4,
                    _ => 0.1 + ((i * 37) % 90) as f64 / 100.0,
                };
                RatioBar {
                    label: format!("Machine {} / {}", i / 5, ["X", "Y", "Z", "B", "C"][i % 5]),
                    parameter: ["A", "B", "E", "M"][i % 4].to_string(),
                    ratio,
                    pass: ratio <= 1.0,
                }
            })
            .collect()
    }

    fn all_charts(chart: &AxisChart, style: &Style) -> Vec<String> {
        let ups = [span("A↑", 0.66, -5.58), span("R↑", 3.0, 0.0)];
        let downs = [span("A↓", 4.01, -1.9)];
        vec![
            bidirectional(chart, style),
            unidirectional(chart, &ups, &downs, style),
            tolerance_usage(&bars(20), style),
        ]
    }

    #[test]
    fn bidirectional_shows_labels_legend_and_spans() {
        let svg = bidirectional(&iso_example(), &style());
        assert_well_formed(&svg);
        let t = texts(&svg);
        for want in [
            "Target position Pi / mm",
            "Positional deviation / µm",
            "mean X̄i↑",
            "mean X̄i↓",
            "X̄ ± 2S ↑",
            "X̄ ± 2S ↓",
            "readings ↑",
            "readings ↓",
            "mean X̄i (bidirectional)",
            "A",
            "9.59",
            "E",
            "7.70",
            "M",
            "3.99",
        ] {
            assert!(
                t.iter().any(|x| x == want),
                "missing text {want:?} in {t:?}"
            );
        }
        // Tick labels use a true minus sign.
        assert!(t.iter().any(|x| x.starts_with('−')), "{t:?}");
        // ↑ and ↓ differ in marker shape: filled circles and white-filled triangles.
        assert!(svg.contains("<circle"));
        assert!(svg.contains("<polygon opacity=\"1\" fill=\"#FFFFFF\""));
    }

    #[test]
    fn unidirectional_shows_both_panels_and_their_spans() {
        let chart = iso_example();
        let ups = [span("A↑", 0.66, -5.58), span("E↑", -0.34, -4.28)];
        let downs = [span("A↓", 4.01, -1.9), span("R↓", 2.84, 0.0)];
        let svg = unidirectional(&chart, &ups, &downs, &style());
        assert_well_formed(&svg);
        let t = texts(&svg);
        for want in [
            "Approach ↑",
            "Approach ↓",
            "A↑",
            "E↑",
            "A↓",
            "R↓",
            "6.24",
            "Target position Pi / mm",
            "Positional deviation / µm",
            "mean X̄i↑",
            "mean X̄i↓",
        ] {
            assert!(
                t.iter().any(|x| x == want),
                "missing text {want:?} in {t:?}"
            );
        }
        // The bidirectional mean belongs to Fig. 2a only.
        assert!(!t.iter().any(|x| x.contains("bidirectional")));
        // One x description (bottom panel) and one y description (shared).
        assert_eq!(
            t.iter().filter(|x| *x == "Target position Pi / mm").count(),
            1
        );
        assert_eq!(
            t.iter()
                .filter(|x| *x == "Positional deviation / µm")
                .count(),
            1
        );
    }

    #[test]
    fn font_sizes_are_plain_numbers() {
        for svg in all_charts(&iso_example(), &style()) {
            for size in attr_values(&svg, "font-size") {
                let decimals = size.split('.').nth(1).map_or(0, str::len);
                assert!(decimals <= 2, "font-size {size}");
            }
        }
    }

    #[test]
    fn same_input_gives_same_bytes() {
        let a = all_charts(&iso_example(), &style());
        let b = all_charts(&iso_example(), &style());
        assert_eq!(a, b);
        assert_eq!(
            tolerance_usage(&bars(60), &style()),
            tolerance_usage(&bars(60), &style())
        );
    }

    #[test]
    fn unicode_and_markup_survive_escaped() {
        let mut chart = iso_example();
        chart.position_label = "Target position Pi / °".to_string();
        chart.deviation_label = "Angle / ″ <arcsec> & \"x\"".to_string();
        let svg = bidirectional(&chart, &style());
        assert_well_formed(&svg);
        assert!(svg.contains("Target position Pi / °"));
        assert!(svg.contains("&lt;arcsec&gt; &amp; &quot;x&quot;"));
        assert!(!svg.contains("<arcsec>"));
        assert!(svg.contains("X̄ ± 2S ↑"));
    }

    #[test]
    fn n1_has_no_limit_curves_and_no_readings_entry() {
        let chart = single_run(40);
        for svg in [
            bidirectional(&chart, &style()),
            unidirectional(&chart, &[], &[], &style()),
        ] {
            assert_well_formed(&svg);
            let t = texts(&svg);
            assert!(t.iter().any(|x| x == "mean X̄i↑"));
            assert!(!t.iter().any(|x| x.contains("X̄ ± 3S")), "{t:?}");
            assert!(!t.iter().any(|x| x.starts_with("readings")), "{t:?}");
        }
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let flat = |v: f64| DirectionSeries {
            mean: vec![v; 3],
            upper: Some(vec![v; 3]),
            lower: Some(vec![v; 3]),
            deviations: vec![vec![v; 2]; 3],
        };
        let mut cases = vec![
            AxisChart::default(),
            single_run(1),
            single_run(2),
            AxisChart {
                positions: vec![5.0; 3],
                up: flat(0.0),
                down: flat(0.0),
                mean: vec![0.0; 3],
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![0.0, 1.0, 2.0],
                up: flat(7.25),
                down: flat(7.25),
                spans: vec![span("A", 7.25, 7.25)],
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![0.0, 1e-12, 2e-12],
                up: flat(1e-300),
                down: flat(-1e-300),
                ..AxisChart::default()
            },
            AxisChart {
                positions: vec![1.0, 2.0, 3.0],
                up: flat(1e-6),
                down: flat(1.000001e-6),
                ..AxisChart::default()
            },
        ];
        // Ragged and hostile data: lengths that disagree, non-finite values, huge values.
        let mut ragged = iso_example();
        ragged.up.mean.truncate(4);
        ragged.down.upper = Some(vec![1.0]);
        ragged.down.deviations.push(vec![f64::NAN, f64::INFINITY]);
        ragged.mean = vec![f64::NAN, 2.0, f64::NEG_INFINITY];
        ragged.spans.push(span("Z", f64::INFINITY, 0.0));
        ragged.spans.push(span("W", -1.0, 2.0));
        cases.push(ragged);
        let mut huge = iso_example();
        huge.up.mean[0] = 1e300;
        huge.down.mean[0] = -1e300;
        cases.push(huge);
        let mut far = iso_example();
        far.positions = vec![-1e300, 1e300];
        cases.push(far);
        let mut many_spans = iso_example();
        many_spans.spans = (0..25)
            .map(|i| span(&format!("Span number {i}"), i as f64, -(i as f64)))
            .collect();
        cases.push(many_spans);

        let styles = degenerate_styles(style());
        for chart in &cases {
            for st in &styles {
                for svg in all_charts(chart, st) {
                    assert_well_formed(&svg);
                }
                let svg = unidirectional(chart, &chart.spans, &chart.spans, st);
                assert_well_formed(&svg);
            }
        }
    }

    #[test]
    fn y_range_covers_everything_with_padding() {
        let (lo, hi) = y_range([-5.58, 4.36, 1.0]).expect("range");
        let span = 4.36 + 5.58;
        assert!((lo - (-5.58 - 0.08 * span)).abs() < 1e-9);
        assert!((hi - (4.36 + 0.08 * span)).abs() < 1e-9);
        // Zero is always inside.
        let (lo, hi) = y_range([3.0, 4.0]).expect("range");
        assert!(lo < 0.0 && hi > 4.0);
        // All equal (zero) still gives a usable range.
        let (lo, hi) = y_range([0.0, 0.0]).expect("range");
        assert!(lo < 0.0 && hi > 0.0);
        // Non-finite values are ignored.
        let (lo, hi) = y_range([f64::NAN, f64::INFINITY, 2.0]).expect("range");
        assert!(lo < 0.0 && hi > 2.0 && hi < 3.0);
        // A single target gets a window around it.
        let (lo, hi) = x_range(&[6.711]).expect("range");
        assert!(lo < 6.711 && hi > 6.711);
        assert!(x_range(&[]).is_none());
    }

    #[test]
    fn numbers_are_formatted_for_print() {
        assert_eq!(fmt_fixed_for_print(-1.5, 2), "−1.50");
        assert_eq!(fmt_fixed_for_print(-0.001, 2), "0.00");
        assert_eq!(fmt_fixed_for_print(1750.0, 0), "1750");
        assert_eq!(fmt_fixed_for_print(f64::INFINITY, 2), "∞");
        assert_eq!(fmt_fixed_for_print(-2.5e300, 0), "−2.50e300");
        assert_eq!(fmt_sig(9.59), "9.59");
        assert_eq!(fmt_sig(12.34), "12.3");
        assert_eq!(fmt_sig(0.0123), "0.0123");
        assert_eq!(fmt_sig(1234.0), "1234");
        assert_eq!(ticks((-6.0, 5.0), 8).1, 0);
        assert_eq!(ticks((-0.6, 0.5), 8).1, 1);
        assert_eq!(ticks((0.0, 3.12), 12).1, 1);
    }

    #[test]
    fn tolerance_usage_marks_bars_over_the_limit() {
        let bars = bars(20);
        let style = Style {
            height_px: ratio_chart_height(bars.len()),
            ..style()
        };
        let svg = tolerance_usage(&bars, &style);
        assert_well_formed(&svg);
        let t = texts(&svg);
        for want in [
            "limit",
            "within tolerance",
            "over tolerance",
            "Worst parameter / tolerance",
        ] {
            assert!(t.iter().any(|x| x == want), "missing {want:?}");
        }
        // Over the limit: bold, dark label ...
        let over = text_tag(&svg, "M 2.60").expect("label of the bar at 2.60");
        assert!(over.contains("font-weight=\"bold\"") && over.contains("#6E1414"));
        let ok = text_tag(&svg, "A 0.47").or_else(|| text_tag(&svg, "B 0.47"));
        let ok = ok.expect("label of a bar within tolerance");
        assert!(!ok.contains("font-weight"));
        // ... a dark bar (key swatch plus three bars) ...
        let dark = svg.matches("fill=\"#6E1414\" stroke=\"none\"").count();
        assert_eq!(dark, 1 + 3);
        // ... and the clipped one keeps its value and gets the arrow and the note.
        assert!(t.iter().any(|x| x == "A 5.40"), "{t:?}");
        assert!(t.iter().any(|x| x.contains("clipped")));
        // Every bar has its axis label.
        for b in &bars {
            assert!(t.contains(&b.label), "missing {}", b.label);
        }
    }

    #[test]
    fn tolerance_usage_without_failures_has_no_dark_bar() {
        let bars: Vec<RatioBar> = bars(5)
            .into_iter()
            .map(|mut b| {
                b.ratio = b.ratio.min(0.9);
                b.pass = true;
                b
            })
            .collect();
        let svg = tolerance_usage(&bars, &style());
        assert_eq!(svg.matches("fill=\"#6E1414\" stroke=\"none\"").count(), 1);
        assert!(!svg.contains("clipped"));
        assert!(texts(&svg).iter().any(|x| x == "limit"));
    }

    #[test]
    fn tolerance_usage_handles_1_to_60_bars_and_odd_ratios() {
        for n in [1, 2, 20, 40, 60] {
            let style = Style {
                height_px: ratio_chart_height(n),
                ..style()
            };
            let svg = tolerance_usage(&bars(n), &style);
            assert_well_formed(&svg);
            assert!(svg.len() < 80_000, "{n} bars: {} bytes", svg.len());
        }
        assert!(ratio_chart_height(60) > ratio_chart_height(20));
        assert!(ratio_chart_height(1) >= 170);
        let odd = [f64::NAN, f64::INFINITY, -2.0, 0.0, 1e300]
            .into_iter()
            .map(|ratio| RatioBar {
                label: String::new(),
                parameter: String::new(),
                ratio,
                pass: false,
            })
            .collect::<Vec<_>>();
        assert_well_formed(&tolerance_usage(&odd, &style()));
        // Too little height for 60 rows still draws.
        assert_well_formed(&tolerance_usage(&bars(60), &style()));
        let empty = tolerance_usage(&[], &style());
        assert_well_formed(&empty);
        assert!(texts(&empty).iter().any(|x| x.contains("No axes")));
    }

    #[test]
    fn axis_charts_stay_small() {
        for svg in all_charts(&iso_example(), &style())
            .into_iter()
            .chain([bidirectional(&single_run(40), &style())])
        {
            let elements = svg.matches('<').count();
            assert!(svg.len() < 80_000, "{} bytes", svg.len());
            assert!(elements < 1_000, "{elements} elements");
        }
    }
}
