//! The campaign summary's tolerance usage: each axis's worst parameter as a fraction of
//! its limit, one horizontal bar each (900 × [`ratio_chart_height`] pixels).

use super::iso::look::KIT;
use crate::chart_kit::scene::Scene;
use crate::chart_kit::*;
use crate::judge::Verdict;
use crate::words::Words;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

pub use crate::chart_kit::Style;

/// One bar of the campaign summary chart.
#[derive(Debug, Clone, PartialEq)]
pub struct RatioBar {
    pub label: String,
    pub parameter: String,
    pub ratio: f64,
    /// The test's verdict, which the bar's colour follows.
    pub verdict: Verdict,
}

const BAR_OK: RGBColor = RGBColor(0x9D, 0xAF, 0xC8);
const BAR_OK_EDGE: RGBColor = RGBColor(0x5F, 0x73, 0x8F);
const BAR_OVER: RGBColor = RGBColor(0x6E, 0x14, 0x14);

/// Ratios above this are drawn clipped at it, with an arrow marker.
const RATIO_CLIP: f64 = 3.0;

const RATIO_TOP: u32 = 44;
const RATIO_BOTTOM: u32 = 56;

fn ratio_row_height(bars: usize) -> u32 {
    row_height(bars, &[(20, 24), (40, 20)], 18)
}

/// Height in pixels that fits `bars` rows of [`tolerance_usage`] at 900 px wide.
pub fn ratio_chart_height(bars: usize) -> u32 {
    let bars = bars.clamp(1, 500) as u32;
    (RATIO_TOP + RATIO_BOTTOM + bars * ratio_row_height(bars as usize) + 10).max(170)
}

/// Horizontal bars: each axis's worst parameter as a fraction of its tolerance
/// (ratio = |value| / limit), a vertical reference line at 1.0 labelled "limit", bars over
/// 1.0 (or not passing) in a dark tone with a bold label, so they read in grey print, the
/// parameter name and ratio printed at the bar's end (e.g. "B 2.60"). Ratios above 3 are
/// clipped at the axis end with an arrow marker and keep their true value in the label.
/// Size the height with [`ratio_chart_height`].
pub fn tolerance_usage(bars: &[RatioBar], style: &Style) -> Scene {
    if bars.is_empty() {
        return message_chart(
            style,
            &crate::words::Words::new(crate::words::numbers()).get("chart-usage-empty"),
        );
    }
    let max_ratio = bars
        .iter()
        .map(|b| shown_ratio(b.ratio).min(RATIO_CLIP))
        .fold(0.0, f64::max);
    let x_max = (max_ratio * 1.04).max(1.2);
    let clipped = bars.iter().any(|b| shown_ratio(b.ratio) > RATIO_CLIP);
    render(style, |root| {
        let columns = UsageColumns::of(bars, root.dim_in_pixel().0, clipped);
        let chart = usage_axes(root, bars.len(), x_max, &columns)?;
        let rows = usage_rows(&chart, bars.len());
        // Bars first, then the limit line over them, then the texts on small backgrounds.
        let ends = draw_usage_bars(root, &chart, bars, &rows, x_max)?;
        draw_limit(root, &chart)?;
        draw_usage_texts(root, &chart, bars, &columns, &rows, &ends)?;
        draw_usage_key(root, bars, clipped)
    })
}

/// A ratio as drawn: not below 0, 0 when unknown.
fn shown_ratio(r: f64) -> f64 {
    if r.is_nan() { 0.0 } else { r.max(0.0) }
}

/// The label column's width, the value texts and the right margin that holds them.
struct UsageColumns {
    label_w: u32,
    values: Vec<String>,
    right: u32,
}

impl UsageColumns {
    fn of(bars: &[RatioBar], w: u32, clipped: bool) -> UsageColumns {
        let label_w = bars
            .iter()
            .map(|b| KIT.text_width(&b.label, TICK_PX))
            .fold(0.0, f64::max)
            .ceil()
            .clamp(20.0, w as f64 * 0.3) as u32
            + 14;
        let values: Vec<String> = bars
            .iter()
            .map(|b| {
                let value = fmt_fixed_for_print(b.ratio, 2);
                if b.parameter.trim().is_empty() {
                    value
                } else {
                    format!("{} {}", b.parameter.trim(), value)
                }
            })
            .collect();
        let value_w = values
            .iter()
            .map(|t| KIT.text_width(t, TICK_PX))
            .fold(0.0, f64::max)
            .ceil() as u32;
        let right = (value_w + if clipped { 30 } else { 16 }).min(w / 3);
        UsageColumns {
            label_w,
            values,
            right,
        }
    }
}

/// The plot with stripes behind every other row (when there are many), the x axis with
/// its grid, and the frame.
fn usage_axes<'a>(
    root: &'a Area,
    n: usize,
    x_max: f64,
    columns: &UsageColumns,
) -> Result<Chart<'a>, Failed> {
    let mut chart = ChartBuilder::on(root)
        .margin_top(RATIO_TOP)
        .margin_right(columns.right)
        .margin_left(8)
        .margin_bottom(6)
        .x_label_area_size(RATIO_BOTTOM - 6)
        .y_label_area_size(columns.label_w)
        .build_cartesian_2d(0.0..x_max, 0.0..n as f64)?;
    let plot_w = root
        .dim_in_pixel()
        .0
        .saturating_sub(columns.label_w + columns.right + 8);
    let nx = x_tick_count(plot_w);
    let (_, x_dec) = ticks((0.0, x_max), nx);
    let x_fmt = move |v: &f64| fmt_fixed_for_print(*v, x_dec);
    let (l, r, _, _) = plot_edges(&chart);
    if n > 6 {
        for &(rt, rb) in usage_rows(&chart, n).iter().skip(1).step_by(2) {
            root.draw(&Rectangle::new([(l, rt), (r, rb)], STRIPE.filled()))?;
        }
    }
    chart
        .configure_mesh()
        .x_labels(nx)
        .y_labels(0)
        .disable_y_mesh()
        .x_label_formatter(&x_fmt)
        .x_label_style(font(TICK_PX, false).color(&INK))
        .y_label_style(font(TICK_PX, false).color(&INK))
        .axis_desc_style(font(DESC_PX, false).color(&INK))
        .x_desc(crate::words::Words::new(crate::words::numbers()).get("chart-usage-axis"))
        .bold_line_style(GRID.stroke_width(1))
        .light_line_style(TRANSPARENT)
        .axis_style(FRAME.stroke_width(1))
        .set_all_tick_mark_size(4)
        .draw()?;
    draw_frame_edges(root, &chart)?;
    Ok(chart)
}

/// The plot's left, right, top and bottom pixel.
fn plot_edges(chart: &Chart) -> (i32, i32, i32, i32) {
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    (xr.start, xr.end - 1, yr.start, yr.end - 1)
}

/// Each row's top and bottom pixel, first bar at the top.
fn usage_rows(chart: &Chart, n: usize) -> Vec<(i32, i32)> {
    (0..n)
        .map(|i| {
            let top = chart.backend_coord(&(0.0, (n - i) as f64)).1;
            let bottom = chart.backend_coord(&(0.0, (n - i - 1) as f64)).1;
            (top, bottom)
        })
        .collect()
}

/// A row's bar height.
fn usage_row_height(chart: &Chart, n: usize) -> f64 {
    let (_, _, t, b) = plot_edges(chart);
    ((b - t) as f64 / n as f64).max(1.0)
}

/// Draws the bars (and arrows where clipped); where each bar's text starts.
fn draw_usage_bars(
    root: &Area,
    chart: &Chart,
    bars: &[RatioBar],
    rows: &[(i32, i32)],
    x_max: f64,
) -> Result<Vec<i32>, Failed> {
    let (l, ..) = plot_edges(chart);
    let row_h = usage_row_height(chart, bars.len());
    let thickness = ((row_h * 0.62).round() as i32).clamp(2, 28);
    let mut ends = Vec::with_capacity(bars.len());
    for (bar, &(rt, rb)) in bars.iter().zip(rows) {
        let mid = (rt + rb) / 2;
        let ratio = shown_ratio(bar.ratio);
        let end_x = chart
            .backend_coord(&(ratio.min(RATIO_CLIP).min(x_max), 0.0))
            .0;
        let bar_box = [
            (l, mid - thickness / 2),
            (end_x, mid - thickness / 2 + thickness),
        ];
        if end_x > l {
            let (fill, edge) = tone(bar).colours();
            root.draw(&Rectangle::new(bar_box, fill.filled()))?;
            if let Some(edge) = edge {
                root.draw(&Rectangle::new(bar_box, edge.stroke_width(1)))?;
            }
        }
        if ratio > RATIO_CLIP {
            // Clipped: an arrow head past the bar's end points on.
            let half = (thickness / 2 + 2).max(4);
            let head = vec![
                (end_x + 1, mid - half),
                (end_x + 1 + half + 2, mid),
                (end_x + 1, mid + half),
            ];
            root.draw(&Polygon::new(head, INK.filled()))?;
            ends.push(end_x + half + 8);
        } else {
            ends.push(end_x + 6);
        }
    }
    Ok(ends)
}

/// How a bar is drawn: within or over its tolerance, or in its verdict's colour when the
/// verdict says neither (inconclusive: neither conformance nor nonconformance is proven).
#[derive(Clone, Copy, PartialEq)]
enum Tone {
    Within,
    Over,
    Verdict(Verdict),
}

impl Tone {
    /// Fill and edge.
    fn colours(self) -> (RGBColor, Option<RGBColor>) {
        match self {
            Tone::Within => (BAR_OK, Some(BAR_OK_EDGE)),
            Tone::Over => (BAR_OVER, None),
            Tone::Verdict(v) => {
                let (fill, edge) = verdict_tone(v);
                (fill, Some(edge))
            }
        }
    }

    /// The bar's value label: bold in a dark tone unless within tolerance.
    fn label(self) -> (bool, RGBColor) {
        match self {
            Tone::Within => (false, INK),
            Tone::Over => (true, BAR_OVER),
            Tone::Verdict(v) => (true, verdict_tone(v).1),
        }
    }

    /// The key's text, in the language of the document being drawn.
    fn key(self) -> String {
        let words = Words::new(crate::words::numbers());
        match self {
            Tone::Within => words.get("chart-usage-within"),
            Tone::Over => words.get("chart-usage-over"),
            Tone::Verdict(v) => v.name().to_string(),
        }
    }
}

/// A bar's tone: a passed, failed, noncompliant or error test by its ratio (over 1.0 or
/// failed: dark), any other verdict in its own colour.
fn tone(bar: &RatioBar) -> Tone {
    match bar.verdict {
        Verdict::Pass | Verdict::Fail | Verdict::Noncompliant | Verdict::Error => {
            if bar.verdict == Verdict::Fail || bar.ratio > 1.0 {
                Tone::Over
            } else {
                Tone::Within
            }
        }
        other => Tone::Verdict(other),
    }
}

/// The limit line at 1.0, labelled above the plot.
fn draw_limit(root: &Area, chart: &Chart) -> Result<(), Failed> {
    let (_, _, t, b) = plot_edges(chart);
    let limit_x = chart.backend_coord(&(1.0, 0.0)).0;
    root.draw(&PathElement::new(
        vec![(limit_x, t - 4), (limit_x, b)],
        INK.stroke_width(2),
    ))?;
    let style = text_style(TICK_PX, true, INK, HPos::Center, VPos::Bottom);
    let limit = Words::new(crate::words::numbers()).get("chart-usage-limit");
    draw_text(root, &limit, (limit_x, t - 6), style)
}

fn row_text_style(bold: bool, color: RGBColor, h: HPos) -> TextStyle<'static> {
    text_style(TICK_PX, bold, color, h, VPos::Center)
}

/// Each row's label left of the plot and its value at the bar's end, on a small
/// background of the row's tone.
fn draw_usage_texts(
    root: &Area,
    chart: &Chart,
    bars: &[RatioBar],
    columns: &UsageColumns,
    rows: &[(i32, i32)],
    ends: &[i32],
) -> Result<(), Failed> {
    let (l, r, ..) = plot_edges(chart);
    let n = bars.len();
    let row_h = usage_row_height(chart, n);
    let text_h = (TICK_PX as i32 + 2).min(row_h as i32).max(4);
    let rows = bars.iter().zip(&columns.values).zip(rows.iter().zip(ends));
    for (i, ((bar, value), (&(rt, rb), &text_x))) in rows.enumerate() {
        let mid = (rt + rb) / 2;
        let label = KIT.fit_text(&bar.label, TICK_PX, columns.label_w as f64 - 12.0);
        let plain = row_text_style(false, INK, HPos::Right);
        draw_text(root, &label, (l - 8, mid), plain)?;
        let tw = KIT.text_width(value, TICK_PX).ceil() as i32;
        // The background stops at the plot's frame; past it the margin is white anyway.
        let bg_right = (text_x + tw + 2).min(r - 1);
        if bg_right > text_x {
            let background = if n > 6 && i % 2 == 1 { STRIPE } else { WHITE };
            let top = mid - text_h / 2;
            let corners = [(text_x - 2, top), (bg_right, top + text_h)];
            root.draw(&Rectangle::new(corners, background.filled()))?;
        }
        let (bold, color) = tone(bar).label();
        draw_text(
            root,
            value,
            (text_x, mid),
            row_text_style(bold, color, HPos::Left),
        )?;
    }
    Ok(())
}

/// Key on its own row above the "limit" label: what the tones mean (a verdict's own only
/// when a bar has it).
fn draw_usage_key(root: &Area, bars: &[RatioBar], clipped: bool) -> Result<(), Failed> {
    let key_y = 14;
    let mut kx = 10;
    let mut tones = vec![Tone::Within, Tone::Over];
    for t in bars.iter().map(tone) {
        if !tones.contains(&t) {
            tones.push(t);
        }
    }
    for t in tones {
        let ((fill, edge), text) = (t.colours(), t.key());
        let swatch = [(kx, key_y - 6), (kx + 22, key_y + 6)];
        root.draw(&Rectangle::new(swatch, fill.filled()))?;
        if let Some(edge) = edge {
            root.draw(&Rectangle::new(swatch, edge.stroke_width(1)))?;
        }
        let style = row_text_style(false, INK, HPos::Left);
        draw_text(root, &text, (kx + 28, key_y), style)?;
        kx += 28 + KIT.text_width(&text, TICK_PX).ceil() as i32 + 22;
    }
    if clipped {
        let note = Words::new(crate::words::numbers()).args(
            "chart-usage-clipped",
            &[("ratio", &fmt_fixed_for_print(RATIO_CLIP, 0))],
        );
        let style = row_text_style(false, MUTED, HPos::Left);
        draw_text(root, &note, (kx, key_y), style)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::iso::look::testing::{assert_plain_font_sizes, assert_small, style};
    use super::*;
    use crate::chart_kit::svg_probe::{assert_well_formed, degenerate_styles, text_tag, texts};

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn tolerance_usage(bars: &[RatioBar], style: &Style) -> String {
        super::tolerance_usage(bars, style).element_svg()
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
                    verdict: if ratio <= 1.0 {
                        Verdict::Pass
                    } else {
                        Verdict::Fail
                    },
                }
            })
            .collect()
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
    fn an_inconclusive_axis_is_drawn_in_the_inconclusive_colour() {
        let mut bars = bars(3);
        bars[0].ratio = 1.01;
        bars[0].verdict = Verdict::Inconclusive;
        let svg = tolerance_usage(&bars, &style());
        // The key's swatch and the bar, in the verdict's light fill; no dark bar but the
        // key's; the label in the verdict's dark tone.
        assert_eq!(
            svg.matches("fill=\"#E6E9F5\" stroke=\"none\"").count(),
            2,
            "{svg}"
        );
        assert_eq!(svg.matches("fill=\"#6E1414\" stroke=\"none\"").count(), 1);
        let label = text_tag(&svg, &format!("{} 1.01", bars[0].parameter)).unwrap();
        assert!(label.contains("#2F3F7A"), "{label}");
        assert!(texts(&svg).iter().any(|x| x == "inconclusive"));
    }

    #[test]
    fn tolerance_usage_without_failures_has_no_dark_bar() {
        let bars: Vec<RatioBar> = bars(5)
            .into_iter()
            .map(|mut b| {
                b.ratio = b.ratio.min(0.9);
                b.verdict = Verdict::Pass;
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
                verdict: Verdict::Fail,
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
    fn font_sizes_are_plain_numbers() {
        assert_plain_font_sizes(&tolerance_usage(&bars(20), &style()));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            tolerance_usage(&bars(20), &style()),
            tolerance_usage(&bars(20), &style())
        );
        assert_eq!(
            tolerance_usage(&bars(60), &style()),
            tolerance_usage(&bars(60), &style())
        );
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        for st in &degenerate_styles(style()) {
            assert_well_formed(&tolerance_usage(&bars(20), st));
        }
    }

    #[test]
    fn axis_charts_stay_small() {
        assert_small(&tolerance_usage(&bars(20), &style()));
    }
}
