//! The time chart of a diagnosis that keeps an effect in time (drift, warm-up, thermal
//! growth): two panels over one time axis. Above, the run means (↑ filled dots, ↓ open
//! triangles) with the fitted effect as a solid line and its band (the curve ± 2σ/√k, the
//! spread of a run mean about it) in light grey; below, the residuals after the extended
//! model with its ±2σ band. Designed for 900 × [`HEIGHT_PX`].

use super::frame::{Frame, draw_clipped};
use super::look::{
    BAND, FIT, KIT, MARK_DOWN, MARK_UP, build_axes, fill_rect, fmt_short, non_empty,
    symmetric_range, unit_of,
};
use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    Area, AxesSpec, Failed, GUIDE, INK, LegendItem, MUTED, Marker, Px, Style, TICK_PX, UP,
    draw_marker, draw_text, padded_range, render, round_px, text_style,
};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

/// The two panels of the time chart of a diagnosis that keeps an effect in time.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct TimePanels {
    /// Each run's mean partial residual for the effect per direction: (time, mean, ↑).
    pub means: Vec<(f64, f64, bool)>,
    /// The fitted effect, as its residuals have it: (time, value), in order.
    pub curve: Vec<(f64, f64)>,
    /// Half-width of the band about the curve (where a run mean lies in 95 % of tests).
    pub band: f64,
    /// e.g. "fitted drift"
    pub(crate) curve_label: String,
    /// The residuals after the extended model: (time, residual, ↑).
    pub after: Vec<(f64, f64, bool)>,
    /// ±2σ of the extended model's scatter.
    pub(crate) after_band: Option<f64>,
}

/// Height of the two-panel chart: the upper panel as high as the one-panel residual chart's
/// plot, the lower a little lower.
pub(super) const HEIGHT_PX: u32 = 600;

/// Run means: larger than the readings' markers, so they read as summaries.
const MEAN_UP: (Marker, RGBColor) = (Marker::Dot(6), UP);
const MEAN_DOWN: (Marker, RGBColor) = (Marker::OpenTriangle(7), super::look::DOWN_MID);
/// Height of a panel's title row.
const TITLE_H: u32 = 22;

/// The finite (x, y, up) points.
fn finite(points: &[(f64, f64, bool)]) -> Vec<(f64, f64, bool)> {
    points
        .iter()
        .copied()
        .filter(|(x, y, _)| x.is_finite() && y.is_finite())
        .collect()
}

/// The two-panel time chart of a residual chart's `time` panels `t`, under the residual
/// chart's axis descriptions `x_label` and `y_label` (whose unit it takes), or a message when
/// nothing can be drawn.
pub(super) fn time_chart(x_label: &str, y_label: &str, t: &TimePanels, style: &Style) -> Scene {
    let style = Style {
        height_px: HEIGHT_PX,
        ..*style
    };
    let means = finite(&t.means);
    let after = finite(&t.after);
    let curve: Vec<(f64, f64)> = (t.curve.iter().copied())
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect();
    let band = Some(t.band.abs()).filter(|b| b.is_finite() && *b > 0.0);
    let after_band = t
        .after_band
        .map(f64::abs)
        .filter(|b| b.is_finite() && *b > 0.0);
    let xs = (means.iter().map(|p| p.0))
        .chain(after.iter().map(|p| p.0))
        .chain(curve.iter().map(|p| p.0));
    let Some(x) = padded_range(xs, 0.03) else {
        return crate::chart_kit::message_chart(&style, "No run means to plot.");
    };
    let b = band.unwrap_or(0.0);
    let upper_values =
        (means.iter().map(|p| p.1)).chain(curve.iter().flat_map(|p| [p.1 - b, p.1 + b]));
    let lower_values = (after.iter().map(|p| p.1)).chain(after_band);
    let (Some(y_up), Some(y_low)) = (
        padded_range(upper_values, 0.08),
        symmetric_range(lower_values),
    ) else {
        return crate::chart_kit::message_chart(&style, "No run means to plot.");
    };
    let unit = unit_of(y_label).to_string();
    let items = legend(t, band, after_band, &unit, &means, &after);
    render(&style, |root| {
        let (w, h) = root.dim_in_pixel();
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32).max(0) as u32;
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        let body = h.saturating_sub(legend_h + 8);
        let split = legend_h + 8 + body * 11 / 20;
        let (upper, lower) = root.split_vertically(split);
        let label_w = KIT
            .y_tick_width(y_up, split - legend_h)
            .max(KIT.y_tick_width(y_low, h - split));
        let top_spec = AxesSpec {
            x,
            y: y_up,
            top: legend_h + 8 + TITLE_H,
            right: 18,
            x_desc: None,
            own_x_ticks: false,
        };
        let low_spec = AxesSpec {
            x,
            y: y_low,
            top: TITLE_H + 4,
            right: 18,
            x_desc: non_empty(x_label),
            own_x_ticks: false,
        };
        let (_, top) = build_axes(&upper, &top_spec, label_w)?;
        let (_, low) = build_axes(&lower, &low_spec, label_w)?;
        let y_desc = format!("Run mean / {unit}");
        KIT.draw_y_desc(
            root,
            y_desc.trim_end_matches(" / "),
            top.t as i32,
            top.b as i32,
        )?;
        let low_desc = format!("Residual / {unit}");
        KIT.draw_y_desc(
            root,
            low_desc.trim_end_matches(" / "),
            low.t as i32,
            low.b as i32,
        )?;
        title(
            root,
            &top,
            "Run means of the readings less their systematic deviation, and the fitted effect",
        )?;
        title(root, &low, "Residuals after the extended model")?;
        draw_upper(root, &top, &curve, band, &means)?;
        draw_lower(root, &low, after_band, &after)
    })
}

/// A panel's title, above its plot at the left.
fn title(root: &Area, frame: &Frame, text: &str) -> Result<(), Failed> {
    let st = text_style(TICK_PX, true, INK, HPos::Left, VPos::Bottom);
    draw_text(root, text, (frame.l as i32, frame.t as i32 - 5), st)
}

/// The legend: run means, the fitted effect and its band, the residuals after and theirs.
fn legend(
    t: &TimePanels,
    band: Option<f64>,
    after_band: Option<f64>,
    unit: &str,
    means: &[(f64, f64, bool)],
    after: &[(f64, f64, bool)],
) -> Vec<LegendItem> {
    let with_unit = |v: f64| {
        if unit.is_empty() {
            fmt_short(v)
        } else {
            format!("{} {unit}", fmt_short(v))
        }
    };
    let mut items = Vec::new();
    let marker = |m, text: &str| LegendItem {
        stroke: None,
        marker: Some(m),
        swatch: None,
        text: text.to_string(),
    };
    if means.iter().any(|p| p.2) {
        items.push(marker(MEAN_UP, "run mean ↑"));
    }
    if means.iter().any(|p| !p.2) {
        items.push(marker(MEAN_DOWN, "run mean ↓"));
    }
    if t.curve.len() >= 2 {
        items.push(LegendItem {
            stroke: Some(FIT),
            marker: None,
            swatch: None,
            text: t.curve_label.clone(),
        });
    }
    if let Some(b) = band {
        items.push(LegendItem {
            stroke: None,
            marker: None,
            swatch: Some(BAND),
            text: format!("±2σ/√k of a run mean (±{})", with_unit(b)),
        });
    }
    if after.iter().any(|p| p.2) {
        items.push(marker(MARK_UP, "residual after ↑"));
    }
    if after.iter().any(|p| !p.2) {
        items.push(marker(MARK_DOWN, "residual after ↓"));
    }
    if let Some(b) = after_band {
        items.push(LegendItem {
            stroke: None,
            marker: None,
            swatch: Some(BAND),
            text: format!("extended model ±2σ (±{})", with_unit(b)),
        });
    }
    items
}

/// The band about the curve, the curve, then the run means over them.
fn draw_upper(
    root: &Area,
    frame: &Frame,
    curve: &[(f64, f64)],
    band: Option<f64>,
    means: &[(f64, f64, bool)],
) -> Result<(), Failed> {
    if let Some(b) = band.filter(|_| curve.len() >= 2) {
        let upper = curve.iter().map(|p| frame.px(p.0, p.1 + b));
        let lower = curve.iter().rev().map(|p| frame.px(p.0, p.1 - b));
        let polygon: Vec<(i32, i32)> = upper.chain(lower).map(|p| clamp(p, frame)).collect();
        root.draw(&Polygon::new(polygon, BAND.filled()))?;
    }
    let points: Vec<Px> = curve.iter().map(|p| frame.px(p.0, p.1)).collect();
    draw_clipped(root, &points, frame, FIT)?;
    for (up, (marker, color)) in [(true, MEAN_UP), (false, MEAN_DOWN)] {
        for p in means.iter().filter(|p| p.2 == up) {
            draw_marker(root, round_px(frame.px(p.0, p.1)), marker, color)?;
        }
    }
    Ok(())
}

/// The ±2σ band of the extended model, the zero line and the residuals after it.
fn draw_lower(
    root: &Area,
    frame: &Frame,
    band: Option<f64>,
    after: &[(f64, f64, bool)],
) -> Result<(), Failed> {
    let (l, r) = (frame.l.round() as i32 + 1, frame.r.round() as i32 - 1);
    if let Some(b) = band {
        let top = frame.px(frame.x.0, b).1.round() as i32;
        let bottom = frame.px(frame.x.0, -b).1.round() as i32;
        fill_rect(root, (l, top), (r, bottom), BAND)?;
        for y in [top, bottom] {
            root.draw(&PathElement::new(
                vec![(l, y), (r, y)],
                GUIDE.stroke_width(1),
            ))?;
        }
    }
    let zero = frame.px(frame.x.0, 0.0).1.round() as i32;
    root.draw(&PathElement::new(
        vec![(l, zero), (r, zero)],
        MUTED.stroke_width(1),
    ))?;
    for up in [true, false] {
        let (marker, color) = if up { MARK_UP } else { MARK_DOWN };
        for p in after.iter().filter(|p| p.2 == up) {
            draw_marker(root, round_px(frame.px(p.0, p.1)), marker, color)?;
        }
    }
    Ok(())
}

/// A pixel held inside the frame (the band's polygon is cut at the plot's edges).
fn clamp(p: Px, f: &Frame) -> (i32, i32) {
    round_px((p.0.clamp(f.l, f.r), p.1.clamp(f.t, f.b)))
}

#[cfg(test)]
mod tests {
    use super::super::residuals::ResidualsChart;
    use super::*;
    use crate::chart_kit::svg_probe::{assert_well_formed, texts};

    fn panels() -> (ResidualsChart, TimePanels) {
        let r = ResidualsChart {
            x_label: "Time since the start of the test / min".into(),
            y_label: "Residual of the base model / µm".into(),
            ..ResidualsChart::default()
        };
        // Five runs of a drift of 1 µm per 10 min about its mean, ↑ and ↓ 4 min apart.
        let mut means = Vec::new();
        for run in 0..5 {
            for (dir, up) in [(0.0, true), (4.0, false)] {
                let x = run as f64 * 8.0 + dir + 2.0;
                means.push((x, (x - 20.0) / 10.0 + if up { 0.1 } else { -0.1 }, up));
            }
        }
        let t = TimePanels {
            means,
            curve: vec![(0.0, -2.0), (40.0, 2.0)],
            band: 0.3,
            curve_label: "fitted drift".into(),
            after: vec![(1.0, 0.2, true), (5.0, -0.3, false), (39.0, 0.1, true)],
            after_band: Some(0.8),
        };
        (r, t)
    }

    /// The legend names every series with the bands' half-widths; the chart is the
    /// two-panel height; both panel titles are drawn.
    #[test]
    fn two_panels_with_their_legend() {
        let (r, t) = panels();
        let style = Style {
            width_px: 900,
            height_px: 340,
        };
        let svg = time_chart(&r.x_label, &r.y_label, &t, &style).element_svg();
        assert_well_formed(&svg);
        assert!(
            svg.contains(&format!("height=\"{HEIGHT_PX}\"")),
            "{svg:.300}"
        );
        let texts = texts(&svg);
        for want in [
            "run mean ↑",
            "run mean ↓",
            "fitted drift",
            "±2σ/√k of a run mean (±0.3 µm)",
            "extended model ±2σ (±0.8 µm)",
            "Residuals after the extended model",
        ] {
            assert!(texts.iter().any(|s| s == want), "{want}: {texts:?}");
        }
    }

    /// Nothing finite: a message, not a panic.
    #[test]
    fn nothing_to_draw_is_a_message() {
        let (r, mut t) = panels();
        t.means = vec![(f64::NAN, 1.0, true)];
        t.after.clear();
        t.curve.clear();
        let style = Style {
            width_px: 900,
            height_px: 340,
        };
        let svg = time_chart(&r.x_label, &r.y_label, &t, &style).element_svg();
        assert!(texts(&svg).iter().any(|s| s == "No run means to plot."));
    }
}
