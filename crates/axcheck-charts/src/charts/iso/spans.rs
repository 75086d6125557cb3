//! The spans of an ISO 230-2 axis chart (range-type parameters such as A, E, M) as labelled
//! brackets in columns right of the plot, and the margin they need. For the charts' sizes
//! (900 × 420 and 900 × 600 px).

use super::axis_chart::Span;
use super::look::{KIT, SPAN_PX, fmt_sig};
use crate::chart_kit::{Area, Chart, Failed, GUIDE, INK, draw_text, text_style};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

pub(super) fn span_values(spans: &[Span]) -> impl Iterator<Item = f64> + '_ {
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
pub(super) fn span_margin(spans: &[Span], width: u32) -> u32 {
    let cols: u32 = span_columns(spans).iter().sum();
    if cols == 0 {
        18
    } else {
        (cols + 12).min(width * 2 / 5)
    }
}

/// Draws each span as a bracket in its own column right of the plot, with guides to the
/// plot edge, its label and its value.
pub(super) fn draw_spans(root: &Area, chart: &Chart, spans: &[Span]) -> Result<(), Failed> {
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
