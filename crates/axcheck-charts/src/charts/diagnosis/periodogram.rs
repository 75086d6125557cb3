//! The periodogram chart of an axis report's diagnosis section: a Lomb–Scargle periodogram
//! on a logarithmic period axis (its ticks are made here), with the false-alarm level, the
//! detected period and the periods the plan cannot resolve. Designed for 900 × 320 px.

use super::frame::{Frame, draw_clipped};
use super::look::{
    CURVE, KIT, MARKED, NOTE_PX, POWER, SHADE, THRESHOLD, bold_width, build_axes, fill_rect,
    fmt_short, non_empty,
};
use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    Area, AxesSpec, FRAME, Failed, GRID, INK, LegendItem, MUTED, Marker, Px, Style, TICK_PX,
    X_DESC_H, X_TICK_H, Y_DESC_W, draw_line, draw_marker, draw_text, extent, fmt_fixed_for_print,
    message_chart, render, round_px, text_style, ticks, x_tick_count,
};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, VPos};

/// A Lomb–Scargle periodogram along the axis.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Periodogram {
    /// periods in mm or deg, in any order (plotted on a logarithmic axis; periods that are
    /// not positive and finite are skipped)
    pub period: Vec<f64>,
    /// normalised power 0…1, one per period
    pub power: Vec<f64>,
    /// e.g. "Period / mm"
    pub(crate) period_label: String,
    /// power at the false-alarm level (e.g. 0.1 %), drawn as a dashed horizontal line
    pub threshold: Option<f64>,
    /// detected period and its label, e.g. (10.02, "10.0 mm"), marked above the plot
    pub marked: Option<(f64, String)>,
    /// periods shorter than this cannot be resolved by the plan: that region is shaded and
    /// labelled "not resolvable"
    pub(crate) unresolved_below: Option<f64>,
}

// ---------------------------------------------------------------------------------------------
// The period axis: logarithmic, its ticks 1-2-5 per decade or sparser

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
    use super::super::look::testing::{Lcg, assert_plain_font_sizes, assert_small, style};
    use super::*;
    use crate::chart_kit::svg_probe::{
        assert_well_formed, attr_values, degenerate_styles, has_text, text_tag, texts,
    };

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn periodogram(p: &Periodogram, style: &Style) -> String {
        super::periodogram(p, style).element_svg()
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
        assert_eq!(fmt_power(5.0, -3), "0.005");
        assert_eq!(fmt_power(1.0, 6), "10⁶");
        assert_eq!(fmt_power(2.0, -12), "2×10⁻¹²");
    }

    #[test]
    fn font_sizes_are_plain_numbers() {
        assert_plain_font_sizes(&periodogram(&example_periodogram(400), &style(360)));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            periodogram(&example_periodogram(400), &style(360)),
            periodogram(&example_periodogram(400), &style(360))
        );
    }

    #[test]
    fn charts_stay_small() {
        assert_small(&periodogram(&example_periodogram(400), &style(360)));
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let styles = degenerate_styles(style(360));
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
        for st in &styles {
            for p in &periodogram_cases {
                assert_well_formed(&periodogram(p, st));
            }
        }
    }
}
