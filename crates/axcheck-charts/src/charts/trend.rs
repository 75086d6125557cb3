//! The small chart of one parameter of one axis over its inspections (`axcheck trend`'s
//! `trends.pdf` and an axis report's history section): the inspections as dots, the
//! Theil–Sen line through them (solid over the inspections, dashed ahead to the
//! horizon), the band of Sen's 95 % slope interval, the limit and the forecast date at
//! which the line reaches it.
//!
//! Same conventions as [`crate::charts`]: pure, never panics (a chart that cannot be
//! drawn comes back as a small chart that says so). Time runs in decimal years
//! (2024.5 is about 1 July 2024); the ticks are whole years.

use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    Area, AxesSpec, Chart, DASHED, FRAME, Failed, GRID, INK, Marker, SOLID, Stroke, TICK_PX, UP,
    X_TICK_H, draw_line, draw_marker, draw_text, message_chart, padded_range, render, round_px,
    text_style,
};
use crate::charts::iso::look::{KIT, build_panel, to_px, y_range};
use plotters::prelude::*;
use plotters::style::RGBColor;
use plotters::style::text_anchor::{HPos, VPos};

pub use crate::chart_kit::Style;

/// What a trend chart shows. Values in the parameter's unit (µm or arcsec).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TrendChart {
    /// e.g. "E / µm"
    pub value_label: String,
    /// The inspections: (decimal year, value).
    pub points: Vec<(f64, f64)>,
    /// The fitted line at the first and the latest inspection.
    pub fitted: Option<[(f64, f64); 2]>,
    /// The line ahead: from the latest inspection to the chart's right end.
    pub ahead: Option<[(f64, f64); 2]>,
    /// The band: (decimal year, low, high), in time order.
    pub band: Vec<(f64, f64, f64)>,
    pub limit: Option<f64>,
    /// When the line reaches the limit, if within the chart.
    pub forecast: Option<f64>,
    /// The time axis: first inspection (less a margin) to the horizon.
    pub years: (f64, f64),
    /// The series is flagged: its line is drawn in the alarm colour.
    pub flagged: bool,
}

const BAND: RGBColor = RGBColor(0xDD, 0xE5, 0xF0);
const ALARM: RGBColor = RGBColor(0x8E, 0x1B, 0x1B);
const LIMIT: Stroke = Stroke::new(ALARM, 2, SOLID);
const NOW: Stroke = Stroke::new(FRAME, 1, DASHED);

/// The series' chart, designed for about 300 × 200 px.
pub fn trend(chart: &TrendChart, style: &Style) -> Scene {
    if chart.points.is_empty() {
        return message_chart(style, "No inspections.");
    }
    let (from, to) = chart.years;
    let Some(x) = padded_range([from, to], 0.0).filter(|_| from.is_finite() && to > from) else {
        return message_chart(style, "No inspection dates.");
    };
    let values = chart.points.iter().map(|p| p.1);
    let band = chart.band.iter().flat_map(|b| [b.1, b.2]);
    let lines = chart.fitted.iter().chain(&chart.ahead).flatten();
    let all = values
        .chain(band)
        .chain(lines.map(|p| p.1))
        .chain(chart.limit);
    let Some(y) = y_range(all) else {
        return message_chart(style, "The values are out of range.");
    };
    let line = Stroke::new(if chart.flagged { ALARM } else { UP }, 2, SOLID);
    let ahead = Stroke::new(line.color, 2, DASHED);
    render(style, |root| {
        let (_, h) = root.dim_in_pixel();
        let frame = AxesSpec {
            x,
            y,
            top: 8,
            right: 12,
            x_desc: None,
            own_x_ticks: true,
        };
        let plot_h = h.saturating_sub(8 + X_TICK_H + 6);
        let cp = build_panel(root, &frame, KIT.y_tick_width(y, plot_h))?;
        let (_, rows) = cp.plotting_area().get_pixel_range();
        KIT.draw_y_desc(root, &chart.value_label, rows.start, rows.end)?;
        draw_band(root, &cp, &chart.band)?;
        draw_year_ticks(root, &cp, x)?;
        let latest = chart.points.iter().map(|p| p.0).fold(f64::NAN, f64::max);
        draw_vertical(root, &cp, latest, NOW)?;
        if let Some(limit) = chart.limit {
            draw_line(root, &[px(&cp, x.0, limit), px(&cp, x.1, limit)], LIMIT)?;
        }
        for (segment, stroke) in [(chart.fitted, line), (chart.ahead, ahead)] {
            if let Some([a, b]) = segment {
                draw_line(root, &[px(&cp, a.0, a.1), px(&cp, b.0, b.1)], stroke)?;
            }
        }
        for p in &chart.points {
            draw_marker(root, round_px(px(&cp, p.0, p.1)), Marker::Dot(4), INK)?;
        }
        if let (Some(at), Some(limit)) = (chart.forecast, chart.limit) {
            draw_vertical(root, &cp, at, Stroke::new(ALARM, 1, DASHED))?;
            draw_marker(
                root,
                round_px(px(&cp, at, limit)),
                Marker::Diamond(6),
                ALARM,
            )?;
        }
        Ok(())
    })
}

/// The backend pixel of (decimal year, value).
fn px(chart: &Chart, x: f64, y: f64) -> (f64, f64) {
    to_px(chart.backend_coord(&(x, y)))
}

/// The band as a filled polygon (upper edge left to right, lower edge back).
fn draw_band(root: &Area, chart: &Chart, band: &[(f64, f64, f64)]) -> Result<(), Failed> {
    let finite = |b: &&(f64, f64, f64)| b.0.is_finite() && b.1.is_finite() && b.2.is_finite();
    let band: Vec<_> = band.iter().filter(finite).collect();
    if band.len() < 2 {
        return Ok(());
    }
    let upper = band.iter().map(|b| chart.backend_coord(&(b.0, b.2)));
    let lower = band.iter().rev().map(|b| chart.backend_coord(&(b.0, b.1)));
    let (bx, by) = root.get_base_pixel();
    let outline: Vec<(i32, i32)> = upper.chain(lower).map(|(x, y)| (x - bx, y - by)).collect();
    root.draw(&Polygon::new(outline, BAND.filled()))?;
    Ok(())
}

/// A vertical line across the plot at decimal year `at` (nothing outside it).
fn draw_vertical(root: &Area, chart: &Chart, at: f64, stroke: Stroke) -> Result<(), Failed> {
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let column = chart.backend_coord(&(at, 0.0)).0;
    if !at.is_finite() || column <= xs.start || column >= xs.end - 1 {
        return Ok(());
    }
    let (top, bottom) = (ys.start as f64, (ys.end - 1) as f64);
    draw_line(
        root,
        &[(column as f64, top), (column as f64, bottom)],
        stroke,
    )
}

/// Whole years along the bottom: every year, or every 2nd, 5th … so labels do not crowd.
fn draw_year_ticks(root: &Area, chart: &Chart, x: (f64, f64)) -> Result<(), Failed> {
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let (bx, by) = root.get_base_pixel();
    let bottom = ys.end - 1 - by;
    let room = ((xs.end - xs.start) as f64 / 46.0).max(1.0);
    let step = [1, 2, 5, 10, 20, 50]
        .into_iter()
        .find(|s| (x.1 - x.0) / *s as f64 <= room)
        .unwrap_or(100);
    let first = (x.0.ceil() as i64).div_euclid(step) * step;
    let mut year = if (first as f64) < x.0 {
        first + step
    } else {
        first
    };
    let font = text_style(TICK_PX, false, INK, HPos::Center, VPos::Top);
    while (year as f64) <= x.1 {
        let column = chart.backend_coord(&(year as f64, 0.0)).0 - bx;
        if column > xs.start - bx && column < xs.end - 1 - bx {
            let grid = vec![(column, ys.start - by + 1), (column, bottom - 1)];
            root.draw(&PathElement::new(grid, GRID.stroke_width(1)))?;
        }
        let tick = vec![(column, bottom), (column, bottom + 4)];
        root.draw(&PathElement::new(tick, FRAME.stroke_width(1)))?;
        draw_text(root, &year.to_string(), (column, bottom + 8), font.clone())?;
        year += step;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn style() -> Style {
        Style {
            width_px: 300,
            height_px: 200,
        }
    }

    fn chart() -> TrendChart {
        TrendChart {
            value_label: "B / µm".into(),
            points: vec![(2022.5, 2.0), (2023.5, 3.1), (2024.5, 4.0), (2025.5, 5.2)],
            fitted: Some([(2022.5, 2.0), (2025.5, 5.1)]),
            ahead: Some([(2025.5, 5.1), (2027.5, 7.1)]),
            band: vec![(2022.5, 1.5, 2.5), (2025.5, 4.8, 5.4), (2027.5, 6.0, 8.0)],
            limit: Some(6.0),
            forecast: Some(2026.4),
            years: (2022.2, 2027.5),
            flagged: true,
        }
    }

    #[test]
    fn it_labels_the_value_and_whole_years() {
        let scene = trend(&chart(), &style());
        let texts: Vec<&str> = scene.texts.iter().map(|t| t.text.as_str()).collect();
        // 5.3 years on a 300 px chart: every second year.
        for label in ["B / µm", "2024", "2026"] {
            assert!(texts.contains(&label), "{label} missing from {texts:?}");
        }
        for label in ["2022", "2023", "2025", "2027"] {
            assert!(!texts.contains(&label), "{label} labelled: {texts:?}");
        }
        let wide = trend(
            &chart(),
            &Style {
                width_px: 900,
                height_px: 300,
            },
        );
        let texts: Vec<&str> = wide.texts.iter().map(|t| t.text.as_str()).collect();
        for label in ["2023", "2024", "2025", "2026", "2027"] {
            assert!(texts.contains(&label), "{label} missing from {texts:?}");
        }
    }

    #[test]
    fn long_histories_get_sparser_year_ticks() {
        let mut long = chart();
        long.years = (1990.0, 2030.0);
        let scene = trend(&long, &style());
        let years: Vec<&str> = scene
            .texts
            .iter()
            .map(|t| t.text.as_str())
            .filter(|t| t.len() == 4 && t.starts_with(['1', '2']))
            .collect();
        assert!(years.len() <= 6, "{years:?}");
        assert!(years.contains(&"2000"), "{years:?}");
    }

    #[test]
    fn empty_or_broken_input_gives_a_message_chart() {
        let empty = trend(&TrendChart::default(), &style());
        assert!(empty.texts.iter().any(|t| t.text == "No inspections."));
        let mut nan = chart();
        nan.years = (f64::NAN, 2020.0);
        let scene = trend(&nan, &style());
        assert!(
            scene
                .texts
                .iter()
                .any(|t| t.text.starts_with("No inspection"))
        );
    }
}
