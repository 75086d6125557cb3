//! Charts of the "model check and diagnosis" section of an axis report, drawn with `plotters`
//! into [`Scene`]s (shapes and texts as data).
//!
//! Same conventions as the report's other charts: every function is pure (the same input
//! gives the same scene, nothing touches the file system) and no input makes it panic (a
//! chart that cannot be drawn comes back as a small chart that says so).
//!
//! Sizes are in pixels and the text sizes are fixed, chosen for a chart about 900 px wide
//! shown about 16 cm wide: 900 × 360 for [`residuals`] (600 high with [`TimePanels`]),
//! 900 × 320 for [`periodogram`] and 900 × [`model_checks_height`] for [`model_checks`].

mod frame;
mod time;

use crate::report::chart_kit::scene::Scene;
use crate::report::chart_kit::{
    Area, AxesSpec, Chart, Conventions, DASHED, DOWN, FRAME, Failed, GRID, GUIDE, INK, LegendItem,
    MUTED, Marker, Px, SOLID, Stroke, TICK_PX, UP, X_DESC_H, X_TICK_H, Y_DESC_W, draw_line,
    draw_marker, draw_text, extent, fmt_fixed_for_print, message_chart, padded_range, render,
    round_px, sig_decimals, text_style, ticks, x_tick_count,
};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};
use std::collections::HashSet;

pub use crate::report::chart_kit::Style;
use frame::{Frame, draw_clipped};
pub use time::TimePanels;

/// Residuals of the fitted base model (reading minus model), in µm or arcsec.
///
/// `x`, `y` and `up` are read in step; the shortest decides how many readings there are.
/// Readings with a non-finite `x` or `y` are skipped.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Residuals {
    /// time in s, or run order index, or position — per reading
    pub x: Vec<f64>,
    /// residual per reading
    pub y: Vec<f64>,
    /// true for ↑ approach, false for ↓ (distinguished by marker shape, not colour only)
    pub up: Vec<bool>,
    /// e.g. "Time since start / min" or "Reading order" or "Target position Pi / mm"
    pub x_label: String,
    /// e.g. "Residual / µm"
    pub y_label: String,
    /// ±2σ of the base model's scatter, drawn as a light horizontal band around zero
    pub band: Option<f64>,
    /// optional fitted curve of an identified effect (e.g. drift line), drawn over the points
    /// in the given order; a non-finite point breaks the line
    pub fit: Option<Vec<(f64, f64)>>,
    /// When present, the chart is instead these panels of a kept effect in time ([`time`]).
    pub time: Option<TimePanels>,
}

/// A Lomb–Scargle periodogram along the axis.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Periodogram {
    /// periods in mm or deg, in any order (plotted on a logarithmic axis; periods that are
    /// not positive and finite are skipped)
    pub period: Vec<f64>,
    /// normalised power 0…1, one per period
    pub power: Vec<f64>,
    /// e.g. "Period / mm"
    pub period_label: String,
    /// power at the false-alarm level (e.g. 0.1 %), drawn as a dashed horizontal line
    pub threshold: Option<f64>,
    /// detected period and its label, e.g. (10.02, "10.0 mm"), marked above the plot
    pub marked: Option<(f64, String)>,
    /// periods shorter than this cannot be resolved by the plan: that region is shaded and
    /// labelled "not resolvable"
    pub unresolved_below: Option<f64>,
}

// ---------------------------------------------------------------------------------------------
// Look (the tones of the report's other charts)

/// ↓ readings: a lighter tone than ↑ so the two also differ in grey print.
const DOWN_MID: RGBColor = RGBColor(0xB4, 0x4E, 0x4E);
/// Light bands: the ±2σ band, the unresolvable region, the simulated 95 % band.
const BAND: RGBColor = RGBColor(0xE8, 0xE8, 0xE8);
const SHADE: RGBColor = RGBColor(0xE4, 0xE4, 0xE4);
pub(crate) const CHECK_BAND: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
const CURVE: RGBColor = RGBColor(0x1F, 0x3A, 0x6E);
pub(crate) const OUTSIDE: RGBColor = RGBColor(0x6E, 0x14, 0x14);

/// Text size of the notes, in SVG pixels (the `font-size` written into the SVG).
pub(crate) const NOTE_PX: f64 = 12.5;

const FIT: Stroke = Stroke::new(INK, 2, SOLID);
const POWER: Stroke = Stroke::new(CURVE, 2, SOLID);
const THRESHOLD: Stroke = Stroke::new(DOWN, 2, DASHED);
const MARKED: Stroke = Stroke::new(MUTED, 1, SOLID);
const MARK_UP: (Marker, RGBColor) = (Marker::Dot(4), UP);
const MARK_DOWN: (Marker, RGBColor) = (Marker::OpenTriangle(4), DOWN_MID);
pub(crate) const MARK_INSIDE: (Marker, RGBColor) = (Marker::Dot(5), INK);
pub(crate) const MARK_OUTSIDE: (Marker, RGBColor) = (Marker::Diamond(7), OUTSIDE);

/// How these charts measure text (see [`Conventions`]).
pub(crate) const KIT: Conventions = Conventions {
    narrow_superscripts: true,
};

// ---------------------------------------------------------------------------------------------
// Text

/// Bold text runs about 6 % wider.
pub(crate) fn bold_width(text: &str, px: f64) -> f64 {
    KIT.text_width(text, px) * 1.06
}

/// The unit of an axis description "Quantity / unit" (empty when there is none).
fn unit_of(label: &str) -> &str {
    label.rsplit_once(" / ").map_or("", |(_, unit)| unit.trim())
}

// ---------------------------------------------------------------------------------------------
// Numbers

/// Up to three significant digits, trailing zeros dropped ("0.35", "12.3", "1750").
fn fmt_short(v: f64) -> String {
    let s = fmt_fixed_for_print(v, sig_decimals(v));
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// A range symmetric about zero holding every value with 10 % to spare (residuals scatter
/// about zero, so zero sits in the middle); ±1 when everything is (practically) zero.
fn symmetric_range(values: impl IntoIterator<Item = f64>) -> Option<(f64, f64)> {
    let m = values
        .into_iter()
        .filter(|v| v.is_finite())
        .map(f64::abs)
        .fold(0.0, f64::max);
    let m = if m < 1e-9 { 1.0 } else { m * 1.1 };
    (m.is_finite() && (2.0 * m).is_finite()).then_some((-m, m))
}

/// Superscript digits for a power of ten.
fn superscript(e: i32) -> String {
    e.to_string()
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            _ => '⁹',
        })
        .collect()
}

/// The label of the log tick m × 10^e: plain digits for 0.001 … 50000, else powers of ten.
fn fmt_power(m: f64, e: i32) -> String {
    if (-3..=4).contains(&e) {
        fmt_fixed_for_print(m * 10f64.powi(e), (-e).max(0) as usize)
    } else if m == 1.0 {
        format!("10{}", superscript(e))
    } else {
        format!("{}×10{}", fmt_fixed_for_print(m, 0), superscript(e))
    }
}

/// Ticks of a logarithmic axis over `lo..hi` (log10 of the values): (log10 of the tick, label).
/// 1-2-5 per decade, then sparser (1-3, decades, every k-th decade) until at most `max_n` fit;
/// a range too short for two such ticks gets plain linear ticks.
fn log_ticks(lo: f64, hi: f64, max_n: usize) -> Vec<(f64, String)> {
    let max_n = max_n.max(2);
    if !(lo.is_finite() && hi.is_finite() && hi > lo) {
        return Vec::new();
    }
    let eps = (hi - lo) * 1e-9 + 1e-12;
    let inside = |v: f64| v >= lo - eps && v <= hi + eps;
    if hi - lo <= 40.0 {
        let (e0, e1) = (lo.floor() as i32 - 1, hi.ceil() as i32 + 1);
        let sets: [&[f64]; 3] = [&[1.0, 2.0, 5.0], &[1.0, 3.0], &[1.0]];
        for (i, set) in sets.iter().enumerate() {
            let out: Vec<(f64, String)> = (e0..=e1)
                .flat_map(|e| set.iter().map(move |m| (*m, e)))
                .map(|(m, e)| (m.log10() + e as f64, m, e))
                .filter(|(v, _, _)| inside(*v))
                .map(|(v, m, e)| (v, fmt_power(m, e)))
                .collect();
            if out.len() < 2 {
                if i == 0 {
                    return linear_log_ticks(lo, hi, max_n);
                }
                break;
            }
            if out.len() <= max_n {
                return out;
            }
        }
    }
    // Every k-th decade.
    for k in [
        1.0, 2.0, 3.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 250.0, 500.0,
    ] {
        let first = (lo / k).ceil() * k;
        let count = ((hi + eps - first) / k).floor() + 1.0;
        if count < 2.0 {
            break;
        }
        if count <= max_n as f64 {
            return (0..count as usize)
                .map(|i| first + k * i as f64)
                .filter(|v| inside(*v))
                .map(|v| (v, fmt_power(1.0, v.round() as i32)))
                .collect();
        }
    }
    Vec::new()
}

/// Linear ticks for a log axis spanning less than a factor of about 2.5.
fn linear_log_ticks(lo: f64, hi: f64, max_n: usize) -> Vec<(f64, String)> {
    let (a, b) = (10f64.powf(lo), 10f64.powf(hi));
    if !(a.is_finite() && b.is_finite() && b > a && a > 0.0) {
        return Vec::new();
    }
    let (points, decimals) = ticks((a, b), max_n);
    points
        .into_iter()
        .filter(|p| *p > 0.0 && p.is_finite())
        .map(|p| (p.log10(), fmt_fixed_for_print(p, decimals)))
        .collect()
}

// ---------------------------------------------------------------------------------------------
// Drawing primitives (in backend pixels, on the root area)

/// A filled arrow head with its tip at `tip`, pointing left (`dir` < 0) or right.
pub(crate) fn draw_arrow(
    root: &Area,
    tip: (i32, i32),
    dir: i32,
    half: i32,
    color: RGBColor,
) -> Result<(), Failed> {
    let back = tip.0 - dir.signum() * (half + 3);
    root.draw(&Polygon::new(
        vec![tip, (back, tip.1 - half), (back, tip.1 + half)],
        color.filled(),
    ))?;
    Ok(())
}

pub(crate) fn fill_rect(
    root: &Area,
    a: (i32, i32),
    b: (i32, i32),
    color: RGBColor,
) -> Result<(), Failed> {
    if a.0 != b.0 && a.1 != b.1 {
        root.draw(&Rectangle::new([a, b], color.filled()))?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Axes

/// Builds the chart with grid, ticks and frame (no zero line: callers draw bands first).
fn build_axes<'a>(
    area: &'a Area,
    spec: &AxesSpec,
    y_label_w: u32,
) -> Result<(Chart<'a>, Frame), Failed> {
    let chart = crate::report::chart_kit::build_axes(area, spec, y_label_w)?;
    let frame = Frame::of(&chart, spec.x, spec.y);
    Ok((chart, frame))
}

fn non_empty(text: &str) -> Option<&str> {
    Some(text.trim()).filter(|t| !t.is_empty())
}

// ---------------------------------------------------------------------------------------------
// Residuals

/// Residual scatter plot (against time/order or against position): ↑ readings as filled dark
/// blue circles, ↓ readings as open lighter red triangles (shape and tone differ, so they read
/// in grey print), the ±2σ band of the base model as a light grey band about zero, the fitted
/// effect as a solid black line over the points, and the zero line. The y axis is symmetric
/// about zero. The legend sits in a band above the plot. Designed for 900 × 360 px.
pub fn residuals(r: &Residuals, style: &Style) -> Scene {
    if let Some(t) = r.time.as_ref() {
        return time::time_chart(r, t, style);
    }
    let n = r.x.len().min(r.y.len()).min(r.up.len());
    let points: Vec<(f64, f64, bool)> = (0..n)
        .map(|i| (r.x[i], r.y[i], r.up[i]))
        .filter(|(x, y, _)| x.is_finite() && y.is_finite())
        .collect();
    if points.is_empty() {
        return message_chart(style, "No residuals to plot.");
    }
    let Some(x) = padded_range(points.iter().map(|p| p.0), 0.03) else {
        return message_chart(style, "The residuals are out of range.");
    };
    let band = r.band.map(f64::abs).filter(|b| b.is_finite() && *b > 0.0);
    let fit: &[(f64, f64)] = r.fit.as_deref().unwrap_or(&[]);
    let fit_in_view = fit
        .iter()
        .filter(|(fx, _)| *fx >= x.0 && *fx <= x.1)
        .map(|p| p.1);
    let values = points.iter().map(|p| p.1).chain(band).chain(fit_in_view);
    let Some(y) = symmetric_range(values) else {
        return message_chart(style, "The residuals are out of range.");
    };
    let has_fit = fit
        .windows(2)
        .any(|w| w.iter().all(|p| p.0.is_finite() && p.1.is_finite()));

    render(style, |root| {
        let (w, h) = root.dim_in_pixel();
        let items = residual_legend(&points, band, has_fit, &r.y_label);
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let top = legend_h + 8;
        let spec = AxesSpec {
            x,
            y,
            top,
            right: 18,
            x_desc: non_empty(&r.x_label),
            own_x_ticks: false,
        };
        let plot_h = h.saturating_sub(top + X_TICK_H + X_DESC_H + 6);
        let (_, frame) = build_axes(root, &spec, KIT.y_tick_width(y, plot_h))?;
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        KIT.draw_y_desc(root, r.y_label.trim(), frame.t as i32, frame.b as i32)?;

        let (l, rt) = (frame.l.round() as i32 + 1, frame.r.round() as i32 - 1);
        if let Some(b) = band {
            let top_y = frame.px(x.0, b).1.round() as i32;
            let bottom_y = frame.px(x.0, -b).1.round() as i32;
            fill_rect(root, (l, top_y), (rt, bottom_y), BAND)?;
            for yy in [top_y, bottom_y] {
                root.draw(&PathElement::new(
                    vec![(l, yy), (rt, yy)],
                    GUIDE.stroke_width(1),
                ))?;
            }
        }
        let zero = frame.px(x.0, 0.0).1.round() as i32;
        root.draw(&PathElement::new(
            vec![(l, zero), (rt, zero)],
            MUTED.stroke_width(1),
        ))?;

        // ↑ first, then ↓: open triangles drawn over the dots leave both visible.
        let mut drawn: HashSet<(bool, i32, i32)> = HashSet::new();
        for up in [true, false] {
            let (marker, color) = if up { MARK_UP } else { MARK_DOWN };
            for p in points.iter().filter(|p| p.2 == up) {
                let at = round_px(frame.px(p.0, p.1));
                if drawn.insert((up, at.0, at.1)) {
                    draw_marker(root, at, marker, color)?;
                }
            }
        }
        let fit_px: Vec<Px> = fit.iter().map(|p| frame.px(p.0, p.1)).collect();
        draw_clipped(root, &fit_px, &frame, FIT)?;
        Ok(())
    })
}

/// The residual chart's legend: the directions present, the base model's band, the fit.
fn residual_legend(
    points: &[(f64, f64, bool)],
    band: Option<f64>,
    has_fit: bool,
    y_label: &str,
) -> Vec<LegendItem> {
    let mut items = Vec::new();
    for (up, mark, text) in [
        (true, MARK_UP, "residual ↑"),
        (false, MARK_DOWN, "residual ↓"),
    ] {
        if points.iter().any(|p| p.2 == up) {
            items.push(LegendItem {
                stroke: None,
                marker: Some(mark),
                swatch: None,
                text: text.to_string(),
            });
        }
    }
    if let Some(b) = band {
        let unit = unit_of(y_label);
        let value = fmt_short(b);
        let text = if unit.is_empty() {
            format!("base model ±2σ (±{value})")
        } else {
            format!("base model ±2σ (±{value} {unit})")
        };
        items.push(LegendItem {
            stroke: None,
            marker: None,
            swatch: Some(BAND),
            text,
        });
    }
    if has_fit {
        items.push(LegendItem {
            stroke: Some(FIT),
            marker: None,
            swatch: None,
            text: "fitted effect".to_string(),
        });
    }
    items
}

// ---------------------------------------------------------------------------------------------
// Periodogram

const MARK_ROW_H: u32 = 24;
const PERIOD_RIGHT: u32 = 22;

/// The points of a curve sorted by x, thinned to at most four per pixel column (first, lowest,
/// highest, last), so a long periodogram stays small without losing its peaks.
fn thin_columns(points: &[Px]) -> Vec<Px> {
    let mut out = Vec::with_capacity(points.len().min(4096));
    let mut i = 0;
    while i < points.len() {
        let col = points[i].0.round();
        let mut j = i + 1;
        while j < points.len() && points[j].0.round() == col {
            j += 1;
        }
        let group = &points[i..j];
        if group.len() <= 4 {
            out.extend_from_slice(group);
        } else {
            let by_y = |a: &&Px, b: &&Px| a.1.total_cmp(&b.1);
            let lo = group.iter().enumerate().min_by(|a, b| by_y(&a.1, &b.1));
            let hi = group.iter().enumerate().max_by(|a, b| by_y(&a.1, &b.1));
            let mut keep = vec![0, group.len() - 1];
            keep.extend(lo.map(|(k, _)| k));
            keep.extend(hi.map(|(k, _)| k));
            keep.sort_unstable();
            keep.dedup();
            out.extend(keep.into_iter().map(|k| group[k]));
        }
        i = j;
    }
    out
}

/// The frame's left, right, top and bottom pixel.
fn frame_edges(frame: &Frame) -> (i32, i32, i32, i32) {
    (
        frame.l.round() as i32,
        frame.r.round() as i32,
        frame.t.round() as i32,
        frame.b.round() as i32,
    )
}

/// The log axis' ticks: grid, tick marks and labels.
fn draw_log_ticks(root: &Area, frame: &Frame) -> Result<(), Failed> {
    let (l, r, t, b) = frame_edges(frame);
    let w = root.dim_in_pixel().0 as i32;
    let nx = x_tick_count((r - l).max(1) as u32);
    let tick_font = |h| text_style(TICK_PX, false, INK, h, VPos::Top);
    for (v, label) in log_ticks(frame.x.0, frame.x.1, nx) {
        let px = frame.px(v, 0.0).0.round() as i32;
        if px < l - 1 || px > r + 1 {
            continue;
        }
        if px > l + 1 && px < r - 1 {
            root.draw(&PathElement::new(
                vec![(px, t + 1), (px, b - 1)],
                GRID.stroke_width(1),
            ))?;
        }
        root.draw(&PathElement::new(
            vec![(px, b), (px, b + 4)],
            FRAME.stroke_width(1),
        ))?;
        // Labels at the plot's ends stay inside the chart.
        let half = (KIT.text_width(&label, TICK_PX) / 2.0).ceil() as i32;
        let lx = px.clamp(2 + half, (w - 2 - half).max(2 + half));
        draw_text(root, &label, (lx, b + 9), tick_font(HPos::Center))?;
    }
    Ok(())
}

/// Where the unresolvable region's note goes.
#[derive(Clone, Copy, PartialEq)]
enum NotePlace {
    /// Across the region, at its top.
    Inside,
    /// Turned upright in a narrow region.
    Upright,
    /// In the legend (the region is a sliver).
    Legend,
}

/// The periods below `u` (log10) that the plan cannot resolve: shaded, with their note.
fn draw_unresolved(
    root: &Area,
    frame: &Frame,
    u: f64,
    note: &str,
    place: NotePlace,
) -> Result<(), Failed> {
    let (l, r, t, b) = frame_edges(frame);
    let xb = frame.px(u.min(frame.x.1), 0.0).0.round() as i32;
    if xb <= l + 1 {
        return Ok(());
    }
    fill_rect(root, (l + 1, t + 1), (xb.min(r - 1), b - 1), SHADE)?;
    if xb < r {
        root.draw(&PathElement::new(
            vec![(xb, t + 1), (xb, b - 1)],
            MUTED.stroke_width(1),
        ))?;
    }
    let cx = (l + xb.min(r)) / 2;
    match place {
        NotePlace::Inside => {
            let style = text_style(NOTE_PX, false, MUTED, HPos::Center, VPos::Top);
            draw_text(root, note, (cx, t + 7), style)
        }
        NotePlace::Upright => {
            let style = text_style(NOTE_PX, false, MUTED, HPos::Right, VPos::Center)
                .transform(FontTransform::Rotate270);
            draw_text(root, note, (cx, t + 7), style)
        }
        NotePlace::Legend => Ok(()),
    }
}

/// The detected period `m` (log10): a line through the plot, a pointer and its label above.
fn draw_marked(root: &Area, frame: &Frame, m: f64, label: &str) -> Result<(), Failed> {
    let (_, _, t, b) = frame_edges(frame);
    let w = root.dim_in_pixel().0 as i32;
    let xm = frame.px(m, 0.0).0.round() as i32;
    draw_line(
        root,
        &[(xm as f64, (t + 1) as f64), (xm as f64, (b - 1) as f64)],
        MARKED,
    )?;
    root.draw(&Polygon::new(
        vec![(xm, t - 1), (xm - 5, t - 8), (xm + 5, t - 8)],
        INK.filled(),
    ))?;
    let tw = bold_width(label, TICK_PX).ceil() as i32;
    let lx = xm.clamp(4 + tw / 2, (w - 4 - tw / 2).max(4 + tw / 2));
    let style = text_style(TICK_PX, true, INK, HPos::Center, VPos::Bottom);
    draw_text(root, label, (lx, t - 10), style)
}

/// What the periodogram draws, in chart units (log10 of the period on x).
struct PeriodogramView {
    points: Vec<(f64, f64)>,
    marked: Option<(f64, String)>,
    x: (f64, f64),
    y: (f64, f64),
    threshold: Option<f64>,
    unresolved: Option<f64>,
}

impl PeriodogramView {
    /// The view of `p`, or what to say instead of a chart.
    fn of(p: &Periodogram) -> Result<PeriodogramView, &'static str> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        let mut points: Vec<(f64, f64)> = p
            .period
            .iter()
            .zip(&p.power)
            .filter(|(t, w)| positive(**t) && w.is_finite())
            .map(|(t, w)| (t.log10(), *w))
            .collect();
        if points.is_empty() {
            return Err("No periodogram to plot.");
        }
        // By period, then power: the same pairs in any order draw the same chart.
        points.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        let marked = p
            .marked
            .as_ref()
            .filter(|(t, _)| positive(*t))
            .map(|(t, label)| {
                let label = non_empty(label).map_or_else(|| fmt_short(*t), str::to_string);
                (t.log10(), label)
            });
        let Some((lo, hi)) = extent(points.iter().map(|q| q.0).chain(marked.iter().map(|m| m.0)))
        else {
            return Err("No periodogram to plot.");
        };
        let x = if hi - lo < 1e-9 {
            (lo - 0.3, hi + 0.3)
        } else {
            (lo, hi)
        };
        let threshold = p.threshold.filter(|t| t.is_finite() && *t >= 0.0);
        let y_top = points
            .iter()
            .map(|q| q.1)
            .chain(threshold)
            .fold(1.0, f64::max);
        let y = (0.0, y_top);
        if !y_top.is_finite() {
            return Err("The powers are out of range.");
        }
        let unresolved = p
            .unresolved_below
            .filter(|u| positive(*u))
            .map(f64::log10)
            .filter(|u| *u > x.0);
        Ok(PeriodogramView {
            points,
            marked,
            x,
            y,
            threshold,
            unresolved,
        })
    }
}

/// A Lomb–Scargle periodogram: normalised power against period on a logarithmic period axis
/// (1-2-5 ticks), the false-alarm level as a dashed dark red line, the detected period as a
/// thin vertical line with its label above the plot, and the periods the plan cannot resolve
/// shaded light grey and labelled "not resolvable" (inside the region, turned upright when it
/// is narrow, in the legend when it is a sliver). The y axis runs from 0 to 1 (further if a
/// power or the threshold exceeds 1; negative powers are clipped at 0); a single period is
/// drawn as a dot. The legend sits in a band above the plot.
/// Designed for 900 × 320 px.
pub fn periodogram(p: &Periodogram, style: &Style) -> Scene {
    let view = match PeriodogramView::of(p) {
        Ok(view) => view,
        Err(message) => return message_chart(style, message),
    };
    let PeriodogramView {
        points,
        marked,
        x,
        y,
        threshold,
        unresolved,
    } = view;

    render(style, |root| {
        let (w, h) = root.dim_in_pixel();
        let mark_row = if marked.is_some() { MARK_ROW_H } else { 0 };
        let note = "not resolvable";
        let note_w = KIT.text_width(note, NOTE_PX);
        let mut items = vec![LegendItem {
            stroke: Some(POWER),
            marker: None,
            swatch: None,
            text: "Lomb–Scargle periodogram".to_string(),
        }];
        if let Some(t) = threshold {
            items.push(LegendItem {
                stroke: Some(THRESHOLD),
                marker: None,
                swatch: None,
                text: format!("false-alarm level ({})", fmt_short(t)),
            });
        }
        let legend_h0 = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let plot_h0 = h.saturating_sub(legend_h0 + mark_row + 8 + X_TICK_H + X_DESC_H + 6);
        let y_label_w = KIT.y_tick_width(y, plot_h0);

        // Where the unresolvable region's label goes: inside it when it fits, else the legend.
        let region_w = unresolved.map_or(0.0, |u| {
            let plot_w = w.saturating_sub(Y_DESC_W + y_label_w + PERIOD_RIGHT) as f64;
            ((u.min(x.1) - x.0) / (x.1 - x.0)).clamp(0.0, 1.0) * plot_w
        });
        let horizontal = region_w >= note_w + 12.0;
        let rotated = !horizontal && region_w >= 18.0 && plot_h0 as f64 >= note_w + 16.0;
        if unresolved.is_some() && region_w >= 1.0 && !horizontal && !rotated {
            items.push(LegendItem {
                stroke: None,
                marker: None,
                swatch: Some(SHADE),
                text: note.to_string(),
            });
        }
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let top = legend_h + mark_row + 8;
        let spec = AxesSpec {
            x,
            y,
            top,
            right: PERIOD_RIGHT,
            x_desc: non_empty(&p.period_label),
            own_x_ticks: true,
        };
        let (_, frame) = build_axes(root, &spec, y_label_w)?;
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        KIT.draw_y_desc(root, "Normalised power", frame.t as i32, frame.b as i32)?;
        draw_log_ticks(root, &frame)?;
        if let Some(u) = unresolved {
            let place = if horizontal {
                NotePlace::Inside
            } else if rotated {
                NotePlace::Upright
            } else {
                NotePlace::Legend
            };
            draw_unresolved(root, &frame, u, note, place)?;
        }
        if let Some((m, label)) = &marked {
            draw_marked(root, &frame, *m, label)?;
        }

        if let Some(th) = threshold {
            let yy = frame.px(x.0, th).1;
            draw_line(root, &[(frame.l + 1.0, yy), (frame.r - 1.0, yy)], THRESHOLD)?;
        }
        let curve: Vec<Px> = points.iter().map(|q| frame.px(q.0, q.1)).collect();
        if let [only] = curve[..] {
            // A single period has no line: mark it.
            if only.1 >= frame.t - 0.5 && only.1 <= frame.b + 0.5 {
                draw_marker(root, round_px(only), Marker::Dot(4), CURVE)?;
            }
        }
        draw_clipped(root, &thin_columns(&curve), &frame, POWER)?;
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::frame::clip_polyline;
    use super::*;
    use crate::report::chart_kit::svg_probe::{
        assert_well_formed, attr_values, degenerate_styles, has_text, text_tag, texts,
    };
    use crate::report::charts::check::{
        CheckBar, check_position, model_checks_height, row_decimals,
    };

    // The charts as SVG with an element per outline, as plotters wrote them.
    fn residuals(r: &Residuals, style: &Style) -> String {
        super::residuals(r, style).element_svg()
    }

    fn periodogram(p: &Periodogram, style: &Style) -> String {
        super::periodogram(p, style).element_svg()
    }

    fn model_checks(bars: &[CheckBar], style: &Style) -> String {
        crate::report::charts::check::model_checks(bars, style).element_svg()
    }

    fn style(height_px: u32) -> Style {
        Style {
            width_px: 900,
            height_px,
        }
    }

    /// A small deterministic generator (no dev-dependencies needed).
    struct Lcg(u64);

    impl Lcg {
        fn uniform(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }

        fn normal(&mut self) -> f64 {
            let (u, v) = (self.uniform(), self.uniform());
            (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
        }
    }

    /// An ISO 230-2 test: 11 targets × 2 directions × `runs` runs over 8 min a run, residuals
    /// N(0, 0.4 µm) plus a drift of 2 µm over 40 min.
    fn iso_residuals(runs: usize) -> Residuals {
        let mut rng = Lcg(7);
        let (mut x, mut y, mut up) = (Vec::new(), Vec::new(), Vec::new());
        for run in 0..runs {
            for dir in 0..2 {
                for i in 0..11 {
                    let t = run as f64 * 8.0 + dir as f64 * 4.0 + i as f64 * 4.0 / 11.0;
                    x.push(t);
                    y.push(0.4 * rng.normal() + 2.0 * t / 40.0 - 1.0);
                    up.push(dir == 0);
                }
            }
        }
        Residuals {
            x,
            y,
            up,
            x_label: "Time since start / min".to_string(),
            y_label: "Residual / µm".to_string(),
            band: Some(0.86),
            fit: Some(vec![(0.0, -1.0), (40.0, 1.0)]),
            time: None,
        }
    }

    /// Periods 2…500 mm (descending, as computed from ascending frequencies), a peak at 10 mm.
    fn example_periodogram(n: usize) -> Periodogram {
        let mut rng = Lcg(11);
        let period: Vec<f64> = (0..n)
            .map(|i| 2.0 * 250f64.powf(i as f64 / (n - 1) as f64))
            .rev()
            .collect();
        let power = period
            .iter()
            .map(|p| {
                let f = 1.0 / p;
                let peak = 0.78 / (1.0 + ((f - 0.1) / 0.0035).powi(2));
                (peak + 0.1 * rng.uniform()).min(1.0)
            })
            .collect();
        Periodogram {
            period,
            power,
            period_label: "Period / mm".to_string(),
            threshold: Some(0.35),
            marked: Some((10.02, "10.0 mm".to_string())),
            unresolved_below: Some(8.0),
        }
    }

    fn check(label: &str, measured: f64, low: f64, high: f64, outside: bool) -> CheckBar {
        CheckBar {
            label: label.to_string(),
            measured,
            low,
            high,
            outside,
        }
    }

    fn example_checks() -> Vec<CheckBar> {
        vec![
            check("R (max Ri)", 2.31, 1.42, 2.95, false),
            check("run-mean spread", 1.21, 0.31, 0.96, true),
            check("lag-1 autocorrelation", 0.12, -0.27, 0.25, false),
            check("max periodogram power", 0.29, 0.18, 0.41, false),
        ]
    }

    fn all_charts(st: &Style) -> Vec<String> {
        let checks = example_checks();
        vec![
            residuals(&iso_residuals(5), st),
            periodogram(&example_periodogram(400), st),
            model_checks(&checks, st),
        ]
    }

    /// Polylines drawn in `color` (markers and lines).
    fn polylines_in(svg: &str, color: &str) -> usize {
        svg.split("<polyline")
            .skip(1)
            .filter(|p| p.contains(&format!("stroke=\"{color}\"")))
            .count()
    }

    fn circles_in(svg: &str, color: &str) -> usize {
        svg.split("<circle")
            .skip(1)
            .filter(|p| p.contains(&format!("fill=\"{color}\"")))
            .count()
    }

    #[test]
    fn residuals_show_labels_legend_band_and_fit() {
        let svg = residuals(&iso_residuals(5), &style(360));
        assert_well_formed(&svg);
        for want in [
            "Time since start / min",
            "Residual / µm",
            "residual ↑",
            "residual ↓",
            "base model ±2σ (±0.86 µm)",
            "fitted effect",
        ] {
            assert!(
                has_text(&svg, want),
                "missing {want:?} in {:?}",
                texts(&svg)
            );
        }
        // Tick labels use a true minus sign.
        assert!(texts(&svg).iter().any(|t| t.starts_with('−')));
        assert!(!texts(&svg).iter().any(|t| t.starts_with('-')));
        // The band: a light grey rectangle.
        assert!(svg.contains("fill=\"#E8E8E8\" stroke=\"none\""));
        // The fit: a solid black line 2 px wide (one polyline, plus its legend sample).
        let fit = svg
            .split("<polyline")
            .filter(|p| p.contains("stroke=\"#1A1A1A\" stroke-width=\"2\""))
            .count();
        assert_eq!(fit, 2);
    }

    #[test]
    fn residual_directions_differ_in_marker_shape() {
        let r = iso_residuals(5);
        let svg = residuals(&r, &style(360));
        // ↑: filled circles; ↓: open triangles (outline polylines, no fill). Each has its legend
        // sample; coincident markers may be drawn once.
        let ups = circles_in(&svg, "#1F3A6E");
        let downs = polylines_in(&svg, "#B44E4E");
        assert!((45..=56).contains(&ups), "{ups} ↑ markers");
        assert!((45..=56).contains(&downs), "{downs} ↓ markers");
        assert!(!svg.contains("fill=\"#B44E4E\""));
        // Only ↑ readings: no ↓ legend entry and no triangles.
        let only_up = Residuals {
            up: vec![true; r.x.len()],
            ..r.clone()
        };
        let svg = residuals(&only_up, &style(360));
        assert!(has_text(&svg, "residual ↑") && !has_text(&svg, "residual ↓"));
        assert_eq!(polylines_in(&svg, "#B44E4E"), 0);
    }

    #[test]
    fn residual_axis_is_symmetric_and_holds_band_and_fit() {
        let (lo, hi) = symmetric_range([0.3, -1.5, 1.0]).expect("range");
        assert!((lo + hi).abs() < 1e-12 && hi > 1.5 && hi < 1.8);
        assert_eq!(symmetric_range([0.0, 0.0]), Some((-1.0, 1.0)));
        assert_eq!(symmetric_range([]), Some((-1.0, 1.0)));
        assert_eq!(symmetric_range([f64::MAX]), None);
        // A band wider than the scatter widens the axis.
        let mut r = iso_residuals(1);
        r.band = Some(10.0);
        let svg = residuals(&r, &style(360));
        assert!(
            has_text(&svg, "10") || has_text(&svg, "10.0"),
            "{:?}",
            texts(&svg)
        );
    }

    #[test]
    fn residuals_without_band_or_fit_have_no_such_entries() {
        let r = Residuals {
            band: None,
            fit: None,
            ..iso_residuals(2)
        };
        let svg = residuals(&r, &style(360));
        assert_well_formed(&svg);
        assert!(!texts(&svg).iter().any(|t| t.contains('σ')));
        assert!(!has_text(&svg, "fitted effect"));
        assert!(!svg.contains("fill=\"#E8E8E8\""));
        // A band of zero, a negative or non-finite band, and a fit of one point count as none.
        for band in [Some(0.0), Some(f64::NAN), Some(f64::INFINITY)] {
            let r = Residuals {
                band,
                fit: Some(vec![(1.0, 1.0)]),
                ..iso_residuals(1)
            };
            let svg = residuals(&r, &style(360));
            assert!(!texts(&svg).iter().any(|t| t.contains('σ')), "{band:?}");
            assert!(!has_text(&svg, "fitted effect"));
        }
        let r = Residuals {
            band: Some(-0.5),
            ..iso_residuals(1)
        };
        assert!(has_text(
            &residuals(&r, &style(360)),
            "base model ±2σ (±0.5 µm)"
        ));
    }

    #[test]
    fn residuals_truncate_mismatched_lengths_and_skip_non_finite() {
        let r = Residuals {
            x: vec![0.0, 1.0, 2.0, 3.0, 4.0],
            y: vec![0.5, f64::NAN, -0.5],
            up: vec![true, true, false, true],
            x_label: "Reading order".to_string(),
            y_label: "Residual / µm".to_string(),
            band: None,
            fit: None,
            time: None,
        };
        let svg = residuals(&r, &style(360));
        assert_well_formed(&svg);
        // Readings 0 (↑) and 2 (↓); the legend adds one of each.
        assert_eq!(circles_in(&svg, "#1F3A6E"), 2);
        assert_eq!(polylines_in(&svg, "#B44E4E"), 2);
        // Nothing usable: a message.
        let none = Residuals {
            up: Vec::new(),
            ..r
        };
        let svg = residuals(&none, &style(360));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "No residuals to plot."));
    }

    #[test]
    fn fit_is_clipped_to_the_plot_and_broken_at_gaps() {
        let r = Residuals {
            fit: Some(vec![
                (-100.0, -50.0),
                (20.0, 0.0),
                (f64::NAN, 0.0),
                (30.0, 0.5),
                (1e300, 1e300),
            ]),
            ..iso_residuals(5)
        };
        let svg = residuals(&r, &style(360));
        assert_well_formed(&svg);
        let fit_lines: Vec<&str> = svg
            .split("<polyline")
            .skip(1)
            .filter(|p| p.contains("stroke=\"#1A1A1A\" stroke-width=\"2\""))
            .collect();
        // Legend sample, the piece up to the gap and the piece after it.
        assert_eq!(fit_lines.len(), 3);
        for line in fit_lines {
            for v in attr_values(&format!(" {line}"), "points") {
                for pair in v.split_whitespace() {
                    let (x, y) = pair.split_once(',').expect("x,y");
                    let (x, y): (i32, i32) = (x.parse().expect("x"), y.parse().expect("y"));
                    assert!((0..=900).contains(&x) && (0..=360).contains(&y), "{pair}");
                }
            }
        }
    }

    #[test]
    fn periodogram_labels_threshold_period_and_unresolved_region() {
        let svg = periodogram(&example_periodogram(400), &style(320));
        assert_well_formed(&svg);
        for want in [
            "Period / mm",
            "Normalised power",
            "Lomb–Scargle periodogram",
            "false-alarm level (0.35)",
            "10.0 mm",
            "not resolvable",
            "2",
            "5",
            "10",
            "20",
            "50",
            "100",
            "200",
            "500",
        ] {
            assert!(
                has_text(&svg, want),
                "missing {want:?} in {:?}",
                texts(&svg)
            );
        }
        // The detected period's label is bold.
        let mark = text_tag(&svg, "10.0 mm").expect("marked label");
        assert!(mark.contains("font-weight=\"bold\""));
        // The threshold is dashed: one dark red polyline with a dash pattern, and the legend
        // sample's.
        let threshold = svg
            .split("<polyline")
            .filter(|p| p.contains("stroke=\"#8E1B1B\""))
            .filter(|p| p.contains("stroke-dasharray=\"10 5\""))
            .count();
        assert_eq!(threshold, 2);
        // The unresolvable region is shaded.
        assert!(svg.contains("fill=\"#E4E4E4\" stroke=\"none\""));
    }

    #[test]
    fn periodogram_without_options_has_only_the_curve() {
        let p = Periodogram {
            threshold: None,
            marked: None,
            unresolved_below: None,
            ..example_periodogram(100)
        };
        let svg = periodogram(&p, &style(320));
        assert_well_formed(&svg);
        assert!(!texts(&svg).iter().any(|t| t.contains("false-alarm")));
        assert!(!has_text(&svg, "not resolvable"));
        assert!(!svg.contains("#8E1B1B") && !svg.contains("#E4E4E4"));
        // A region below the shortest period is not drawn either.
        let p = Periodogram {
            unresolved_below: Some(1.0),
            ..p
        };
        assert!(!has_text(&periodogram(&p, &style(320)), "not resolvable"));
    }

    #[test]
    fn periodogram_region_label_moves_to_the_legend_when_narrow() {
        // A sliver of a region: labelled in the legend with a swatch.
        let p = Periodogram {
            unresolved_below: Some(2.02),
            ..example_periodogram(200)
        };
        let svg = periodogram(&p, &style(320));
        let tag = text_tag(&svg, "not resolvable").expect("label");
        assert!(!tag.contains("rotate"));
        // A narrow region: the label is turned to run up the region.
        let p = Periodogram {
            unresolved_below: Some(2.4),
            ..example_periodogram(200)
        };
        let svg = periodogram(&p, &style(320));
        let tag = text_tag(&svg, "not resolvable").expect("label");
        assert!(tag.contains("rotate(270"));
        // Everything unresolvable: the whole plot is shaded and labelled.
        let p = Periodogram {
            unresolved_below: Some(1e6),
            ..example_periodogram(200)
        };
        assert!(has_text(&periodogram(&p, &style(320)), "not resolvable"));
    }

    #[test]
    fn periodogram_does_not_depend_on_the_order_and_skips_bad_periods() {
        let mut p = example_periodogram(300);
        // Equal periods with different powers, too.
        p.period.extend([50.0, 50.0]);
        p.power.extend([0.1, 0.6]);
        let mut pairs: Vec<(f64, f64)> = p.period.iter().copied().zip(p.power.clone()).collect();
        pairs.reverse();
        pairs.extend([
            (0.0, 0.9),
            (-5.0, 0.9),
            (f64::NAN, 0.9),
            (f64::INFINITY, 0.9),
            (3.0, f64::NAN),
        ]);
        let shuffled = Periodogram {
            period: pairs.iter().map(|q| q.0).collect(),
            power: pairs.iter().map(|q| q.1).collect(),
            ..p.clone()
        };
        assert_eq!(
            periodogram(&p, &style(320)),
            periodogram(&shuffled, &style(320))
        );
        // Extra powers without a period are ignored.
        let mut longer = p.clone();
        longer.power.extend([0.99; 10]);
        assert_eq!(
            periodogram(&p, &style(320)),
            periodogram(&longer, &style(320))
        );
    }

    #[test]
    fn periodogram_marked_label_falls_back_to_the_period() {
        let p = Periodogram {
            marked: Some((12.5, "  ".to_string())),
            ..example_periodogram(100)
        };
        assert!(has_text(&periodogram(&p, &style(320)), "12.5"));
        // A marked period outside the data widens the axis.
        let p = Periodogram {
            marked: Some((1000.0, "1000 mm".to_string())),
            ..example_periodogram(100)
        };
        let svg = periodogram(&p, &style(320));
        assert!(has_text(&svg, "1000 mm") && has_text(&svg, "1000"));
    }

    #[test]
    fn log_ticks_are_1_2_5_and_bounded() {
        let labels = |lo: f64, hi: f64, n: usize| -> Vec<String> {
            log_ticks(lo.log10(), hi.log10(), n)
                .into_iter()
                .map(|t| t.1)
                .collect()
        };
        assert_eq!(
            labels(2.0, 500.0, 9),
            ["2", "5", "10", "20", "50", "100", "200", "500"]
        );
        assert_eq!(labels(2.0, 500.0, 5), ["3", "10", "30", "100", "300"]);
        assert_eq!(
            labels(0.01, 0.5, 9),
            ["0.01", "0.02", "0.05", "0.1", "0.2", "0.5"]
        );
        assert_eq!(labels(1e-7, 1e-5, 9)[0], "10⁻⁷");
        assert_eq!(labels(2e5, 5e5, 9)[0], "2×10⁵");
        // A short range gets linear ticks.
        assert_eq!(labels(8.0, 12.0, 5), ["8", "9", "10", "11", "12"]);
        assert_eq!(labels(8.0, 12.0, 9)[..3], ["8.0", "8.5", "9.0"]);
        // Huge ranges: every k-th decade, never more than asked for.
        let huge = log_ticks(-300.0, 300.0, 9);
        assert!((2..=9).contains(&huge.len()), "{huge:?}");
        assert!(
            huge.iter().all(|t| t.1.starts_with("10") || t.1 == "1"),
            "{huge:?}"
        );
        for (lo, hi) in [(0.0, 1e-15), (5.0, 5.0), (f64::NAN, 1.0), (1.0, 0.0)] {
            assert!(log_ticks(lo, hi, 9).len() <= 9);
        }
    }

    #[test]
    fn long_periodograms_stay_small_but_keep_their_peak() {
        let mut p = example_periodogram(20_000);
        let peak = p
            .power
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(i, _)| i)
            .expect("peak");
        p.power[peak] = 1.0;
        let svg = periodogram(&p, &style(320));
        assert_well_formed(&svg);
        assert!(svg.len() < 60_000, "{} bytes", svg.len());
        // The thinned curve still reaches the top of the plot (power 1.0).
        let frame_top = svg
            .split("<polyline")
            .filter(|l| l.contains("stroke=\"#1F3A6E\" stroke-width=\"2\""))
            .flat_map(|l| {
                attr_values(l, "points")
                    .into_iter()
                    .map(str::to_string)
                    .collect::<Vec<_>>()
            })
            .flat_map(|pts| {
                pts.split_whitespace()
                    .filter_map(|q| q.split_once(',').and_then(|(_, y)| y.parse::<i32>().ok()))
                    .collect::<Vec<_>>()
            })
            .min()
            .expect("curve");
        assert!(frame_top < 90, "top of the curve at {frame_top}");
    }

    #[test]
    fn model_checks_mark_outside_rows() {
        let st = style(model_checks_height(4));
        let svg = model_checks(&example_checks(), &st);
        assert_well_formed(&svg);
        for want in [
            "R (max Ri)",
            "run-mean spread",
            "lag-1 autocorrelation",
            "max periodogram power",
            "measured",
            "simulated 95 % band",
            "simulated 95 % band (base model)",
            "measured, check outside",
            "2.31",
            "1.42 … 2.95",
            "1.21",
            "0.31 … 0.96",
            "−0.27 … 0.25",
        ] {
            assert!(
                has_text(&svg, want),
                "missing {want:?} in {:?}",
                texts(&svg)
            );
        }
        // Outside: bold dark red label and value; inside: plain.
        for outside in ["run-mean spread", "1.21"] {
            let tag = text_tag(&svg, outside).expect("outside row");
            assert!(
                tag.contains("font-weight=\"bold\"") && tag.contains("#6E1414"),
                "{tag}"
            );
        }
        for inside in ["R (max Ri)", "2.31"] {
            let tag = text_tag(&svg, inside).expect("inside row");
            assert!(!tag.contains("font-weight"), "{tag}");
        }
        // One diamond in the row, one in the key; inside values as black dots (3 + key).
        assert_eq!(
            svg.matches("<polygon opacity=\"1\" fill=\"#6E1414\"")
                .count(),
            2
        );
        assert_eq!(circles_in(&svg, "#1A1A1A"), 4);
        // No value is off the scale: no arrow, no key for it.
        assert!(!has_text(&svg, "beyond the scale"));
    }

    #[test]
    fn model_checks_without_outside_rows_have_no_outside_key() {
        let checks: Vec<CheckBar> = example_checks()
            .into_iter()
            .map(|c| CheckBar {
                outside: false,
                ..c
            })
            .collect();
        let svg = model_checks(&checks, &style(model_checks_height(4)));
        assert!(!has_text(&svg, "measured, check outside"));
        assert!(!svg.contains("#6E1414"));
    }

    #[test]
    fn far_values_are_clipped_with_an_arrow() {
        let checks = [
            check("far above", 50.0, 0.0, 1.0, true),
            check("far below", -50.0, 0.0, 1.0, true),
            check("inside", 0.5, 0.0, 1.0, false),
        ];
        let svg = model_checks(&checks, &style(model_checks_height(3)));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "beyond the scale"));
        assert!(
            has_text(&svg, "50") && has_text(&svg, "−50"),
            "{:?}",
            texts(&svg)
        );
        // Two arrows in the rows (dark red, the checks are outside), one black in the key.
        assert_eq!(
            svg.matches("<polygon opacity=\"1\" fill=\"#6E1414\"")
                .count(),
            2 + 1
        );
        assert_eq!(check_position(&checks[0]), Some(1.0 / 3.0 + 50.0 / 3.0));
    }

    #[test]
    fn check_positions_map_the_band_to_the_middle_third() {
        let at = |m: f64, lo: f64, hi: f64| check_position(&check("", m, lo, hi, false));
        let near = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() < 1e-12);
        assert!(near(at(1.0, 1.0, 3.0), 1.0 / 3.0));
        assert!(near(at(3.0, 1.0, 3.0), 2.0 / 3.0));
        assert!(near(at(2.0, 3.0, 1.0), 0.5)); // low and high swapped
        assert!(near(at(-1.0, 1.0, 3.0), 0.0));
        assert!(near(at(5.0, 1.0, 3.0), 1.0));
        // Degenerate bands: on it, or off the scale on the right side.
        assert_eq!(at(2.0, 2.0, 2.0), Some(0.5));
        assert_eq!(at(2.5, 2.0, 2.0), Some(f64::INFINITY));
        assert_eq!(at(1.5, 2.0, 2.0), Some(f64::NEG_INFINITY));
        assert_eq!(at(f64::NAN, 0.0, 1.0), None);
        assert_eq!(at(0.5, f64::NAN, 1.0), None);
        assert!(near(at(0.0, -f64::MAX, f64::MAX), 0.5));
        assert!(at(f64::MAX, -1.0, 1.0).is_some_and(|u| u > 1.0));
    }

    #[test]
    fn model_checks_height_fits_the_rows() {
        assert!(model_checks_height(0) >= 150);
        assert!(model_checks_height(4) < model_checks_height(5));
        assert!(model_checks_height(40) > model_checks_height(12));
        assert!(model_checks_height(usize::MAX) <= 20_000);
        let many: Vec<CheckBar> = (0..40)
            .map(|i| check(&format!("statistic {i}"), i as f64, 0.0, 20.0, i > 30))
            .collect();
        let svg = model_checks(&many, &style(model_checks_height(40)));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "statistic 39"));
    }

    #[test]
    fn font_sizes_are_plain_numbers() {
        for svg in all_charts(&style(360)) {
            for size in attr_values(&svg, "font-size") {
                let decimals = size.split('.').nth(1).map_or(0, str::len);
                assert!(decimals <= 2, "font-size {size}");
            }
        }
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(all_charts(&style(360)), all_charts(&style(360)));
    }

    #[test]
    fn charts_stay_small() {
        // 400 readings (11 targets × 2 directions × 18 runs would be 396).
        let r = iso_residuals(19);
        assert!(r.x.len() >= 400);
        let svg = residuals(&r, &style(360));
        assert!(svg.len() < 60_000, "{} bytes", svg.len());
        for svg in all_charts(&style(360)) {
            assert!(svg.len() < 60_000, "{} bytes", svg.len());
            assert!(svg.matches('<').count() < 1_500);
        }
    }

    #[test]
    fn unicode_and_markup_survive_escaped() {
        let r = Residuals {
            x_label: "Target position Pi / °".to_string(),
            y_label: "Residual / ″ <arcsec> & \"x\"".to_string(),
            ..iso_residuals(2)
        };
        let svg = residuals(&r, &style(360));
        assert_well_formed(&svg);
        assert!(svg.contains("Target position Pi / °"));
        assert!(svg.contains("&lt;arcsec&gt; &amp; &quot;x&quot;"));
        assert!(!svg.contains("<arcsec>"));
        let checks = [check("<b>&", 1.0, 0.0, 2.0, true)];
        let svg = model_checks(&checks, &style(model_checks_height(1)));
        assert!(svg.contains("&lt;b&gt;&amp;") && !svg.contains("<b>"));
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let styles = degenerate_styles(style(360));
        let base = iso_residuals(1);
        let res = |x: Vec<f64>, y: Vec<f64>| Residuals {
            up: (0..x.len()).map(|i| i % 2 == 0).collect(),
            x,
            y,
            ..base.clone()
        };
        let residual_cases = vec![
            Residuals::default(),
            res(vec![1.0], vec![0.3]),
            res(vec![2.0; 5], vec![0.7; 5]),
            res(vec![0.0, 1.0], vec![0.0, 0.0]),
            res(vec![0.0, 1e-12, 2e-12], vec![1e-300, -1e-300, 0.0]),
            res(vec![-1e300, 1e300], vec![1e300, -1e300]),
            res(vec![0.0, 1.0], vec![f64::MAX, 0.0]),
            res(vec![f64::NAN, f64::INFINITY], vec![1.0, 2.0]),
            Residuals {
                fit: Some(vec![(f64::NAN, f64::NAN); 3]),
                band: Some(1e300),
                x_label: String::new(),
                y_label: "   ".to_string(),
                ..base.clone()
            },
            Residuals {
                fit: Some(Vec::new()),
                ..base.clone()
            },
            Residuals {
                time: Some(TimePanels {
                    means: vec![(f64::INFINITY, 1e300, true), (0.0, -1e300, false)],
                    curve: vec![(f64::NAN, 0.0), (0.0, f64::MAX)],
                    band: f64::NAN,
                    after_band: Some(-1.0),
                    ..TimePanels::default()
                }),
                ..base.clone()
            },
            Residuals {
                time: Some(TimePanels::default()),
                ..base.clone()
            },
        ];
        let per = |period: Vec<f64>, power: Vec<f64>| Periodogram {
            period,
            power,
            ..example_periodogram(10)
        };
        let periodogram_cases = vec![
            Periodogram::default(),
            per(vec![10.0], vec![0.5]),
            per(vec![10.0; 4], vec![0.5; 4]),
            per(vec![-1.0, 0.0, f64::NAN], vec![0.5; 3]),
            per(vec![1e-300, 1e300], vec![0.2, 0.3]),
            per(vec![1.0, 1.0 + 1e-15], vec![0.2, 0.3]),
            per(vec![f64::MIN_POSITIVE, f64::MAX], vec![2.0, -1.0]),
            per(vec![1.0, 2.0], vec![1e300, f64::MAX]),
            Periodogram {
                threshold: Some(f64::NAN),
                marked: Some((-3.0, "x".to_string())),
                unresolved_below: Some(f64::INFINITY),
                ..example_periodogram(10)
            },
            Periodogram {
                threshold: Some(5.0),
                marked: Some((f64::MAX, String::new())),
                unresolved_below: Some(-1.0),
                ..example_periodogram(10)
            },
        ];
        let check_cases: Vec<Vec<CheckBar>> = vec![
            Vec::new(),
            vec![check("", 0.0, 0.0, 0.0, false)],
            vec![check("nan", f64::NAN, f64::NAN, f64::NAN, true)],
            vec![check("inf", f64::INFINITY, f64::NEG_INFINITY, 1.0, true)],
            vec![check("huge", 1e300, -1e300, 1e300, false)],
            vec![check("tiny", 1e-300, 0.0, 2e-300, false)],
            vec![check(
                &"a very long statistic name ".repeat(20),
                1.0,
                0.0,
                2.0,
                true,
            )],
            (0..300)
                .map(|i| check("row", i as f64, 0.0, 1.0, i % 3 == 0))
                .collect(),
        ];
        for st in &styles {
            for r in &residual_cases {
                assert_well_formed(&residuals(r, st));
            }
            for p in &periodogram_cases {
                assert_well_formed(&periodogram(p, st));
            }
            for c in &check_cases {
                assert_well_formed(&model_checks(c, st));
            }
        }
    }

    #[test]
    fn clipping_keeps_what_is_inside() {
        let f = Frame {
            x: (0.0, 1.0),
            y: (0.0, 1.0),
            l: 0.0,
            r: 100.0,
            t: 0.0,
            b: 50.0,
        };
        let pieces = clip_polyline(&[(-50.0, 25.0), (50.0, 25.0), (150.0, 25.0)], &f);
        assert_eq!(pieces, vec![vec![(0.0, 25.0), (50.0, 25.0), (100.0, 25.0)]]);
        // Out, in, out again: two pieces.
        let pieces = clip_polyline(
            &[(10.0, 10.0), (10.0, 90.0), (20.0, 90.0), (20.0, 10.0)],
            &f,
        );
        assert_eq!(pieces.len(), 2);
        assert!(clip_polyline(&[(200.0, 0.0), (300.0, 0.0)], &f).is_empty());
        assert!(clip_polyline(&[(1.0, 1.0), (f64::NAN, 2.0), (3.0, 3.0)], &f).is_empty());
        assert!(clip_polyline(&[], &f).is_empty());
    }

    #[test]
    fn thinning_keeps_extremes_per_column() {
        let pts: Vec<Px> = (0..100)
            .map(|i| (10.0 + i as f64 * 0.001, (i % 7) as f64))
            .collect();
        let thin = thin_columns(&pts);
        assert!(thin.len() <= 4);
        assert_eq!(thin.first(), pts.first());
        assert_eq!(thin.last(), pts.last());
        assert!(thin.iter().any(|p| p.1 == 0.0) && thin.iter().any(|p| p.1 == 6.0));
    }

    #[test]
    fn numbers_are_formatted_for_print() {
        assert_eq!(fmt_fixed_for_print(-1.5, 2), "−1.50");
        assert_eq!(fmt_fixed_for_print(-0.001, 2), "0.00");
        assert_eq!(fmt_fixed_for_print(f64::NEG_INFINITY, 2), "−∞");
        assert_eq!(fmt_short(0.35), "0.35");
        assert_eq!(fmt_short(10.02), "10");
        assert_eq!(fmt_short(12.5), "12.5");
        assert_eq!(fmt_short(-0.0004567), "−0.000457");
        assert_eq!(fmt_power(5.0, -3), "0.005");
        assert_eq!(fmt_power(1.0, 6), "10⁶");
        assert_eq!(fmt_power(2.0, -12), "2×10⁻¹²");
        assert_eq!(unit_of("Residual / µm"), "µm");
        assert_eq!(unit_of("Reading order"), "");
        let d = |lo, hi, m| row_decimals(&check("", m, lo, hi, false));
        assert_eq!(d(1.42, 2.95, 2.31), 2);
        assert_eq!(d(0.31, 0.96, 1.21), 2);
        assert_eq!(d(0.0, 1.0, 0.5), 1);
        assert_eq!(d(1000.0, 1000.5, 1000.2), 1);
        assert_eq!(d(1000.0, 1000.5, 1000.25), 2);
    }
}
