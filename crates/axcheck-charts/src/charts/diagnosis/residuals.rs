//! The residuals chart of an axis report's diagnosis section: the base model's residuals
//! against time, reading order or position, ↑ and ↓ apart, with the base model's ±2σ band
//! and a fitted effect; for an effect kept in time, the two panels of [`super::time`]
//! instead. Designed for 900 × 360 px (900 × 600 with the time panels).

use super::frame::draw_clipped;
use super::look::{
    BAND, FIT, KIT, MARK_DOWN, MARK_UP, build_axes, fill_rect, fmt_short, non_empty,
    symmetric_range, unit_of,
};
use super::time::{self, TimePanels};
use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    AxesSpec, GUIDE, LegendItem, MUTED, Px, Style, X_DESC_H, X_TICK_H, draw_marker, message_chart,
    padded_range, render, round_px,
};
use plotters::prelude::*;
use std::collections::HashSet;

/// ResidualsChart of the fitted base model (reading minus model), in µm or arcsec.
///
/// `x`, `y` and `up` are read in step; the shortest decides how many readings there are.
/// Readings with a non-finite `x` or `y` are skipped.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ResidualsChart {
    /// time in s, or run order index, or position — per reading
    pub x: Vec<f64>,
    /// residual per reading
    pub y: Vec<f64>,
    /// true for ↑ approach, false for ↓ (distinguished by marker shape, not colour only)
    pub up: Vec<bool>,
    /// e.g. "Time since start / min" or "Reading order" or "Target position Pi / mm"
    pub(crate) x_label: String,
    /// e.g. "Residual / µm"
    pub(crate) y_label: String,
    /// ±2σ of the base model's scatter, drawn as a light horizontal band around zero
    pub band: Option<f64>,
    /// optional fitted curve of an identified effect (e.g. drift line), drawn over the points
    /// in the given order; a non-finite point breaks the line
    pub fit: Option<Vec<(f64, f64)>>,
    /// When present, the chart is instead these panels of a kept effect in time ([`time`]).
    pub time: Option<TimePanels>,
}

/// Residual scatter plot (against time/order or against position): ↑ readings as filled dark
/// blue circles, ↓ readings as open lighter red triangles (shape and tone differ, so they read
/// in grey print), the ±2σ band of the base model as a light grey band about zero, the fitted
/// effect as a solid black line over the points, and the zero line. The y axis is symmetric
/// about zero. The legend sits in a band above the plot. Designed for 900 × 360 px.
pub fn residuals(r: &ResidualsChart, style: &Style) -> Scene {
    if let Some(t) = r.time.as_ref() {
        return time::time_chart(&r.x_label, &r.y_label, t, style);
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
    let words = crate::words::Words::new(crate::words::numbers());
    let mut items = Vec::new();
    for (up, mark, key) in [
        (true, MARK_UP, "diag-residual-up"),
        (false, MARK_DOWN, "diag-residual-down"),
    ] {
        let text = words.get(key);
        if points.iter().any(|p| p.2 == up) {
            items.push(LegendItem {
                stroke: None,
                marker: Some(mark),
                swatch: None,
                text,
            });
        }
    }
    if let Some(b) = band {
        let unit = unit_of(y_label);
        let value = fmt_short(b);
        let value = match unit.is_empty() {
            true => value,
            false => format!("{value} {unit}"),
        };
        let text = words.args("diag-band", &[("value", &value)]);
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

#[cfg(test)]
mod tests {
    use super::super::look::testing::{
        Lcg, assert_plain_font_sizes, assert_small, circles_in, style,
    };
    use super::*;
    use crate::chart_kit::svg_probe::{
        assert_well_formed, attr_values, degenerate_styles, has_text, texts,
    };

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn residuals(r: &ResidualsChart, style: &Style) -> String {
        super::residuals(r, style).element_svg()
    }

    /// An ISO 230-2 test: 11 targets × 2 directions × `runs` runs over 8 min a run, residuals
    /// N(0, 0.4 µm) plus a drift of 2 µm over 40 min.
    fn iso_residuals(runs: usize) -> ResidualsChart {
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
        ResidualsChart {
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

    /// Polylines drawn in `color` (markers and lines).
    fn polylines_in(svg: &str, color: &str) -> usize {
        svg.split("<polyline")
            .skip(1)
            .filter(|p| p.contains(&format!("stroke=\"{color}\"")))
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
        let only_up = ResidualsChart {
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
        let r = ResidualsChart {
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
            let r = ResidualsChart {
                band,
                fit: Some(vec![(1.0, 1.0)]),
                ..iso_residuals(1)
            };
            let svg = residuals(&r, &style(360));
            assert!(!texts(&svg).iter().any(|t| t.contains('σ')), "{band:?}");
            assert!(!has_text(&svg, "fitted effect"));
        }
        let r = ResidualsChart {
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
        let r = ResidualsChart {
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
        let none = ResidualsChart {
            up: Vec::new(),
            ..r
        };
        let svg = residuals(&none, &style(360));
        assert_well_formed(&svg);
        assert!(has_text(&svg, "No residuals to plot."));
    }

    #[test]
    fn fit_is_clipped_to_the_plot_and_broken_at_gaps() {
        let r = ResidualsChart {
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
    fn font_sizes_are_plain_numbers() {
        assert_plain_font_sizes(&residuals(&iso_residuals(5), &style(360)));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            residuals(&iso_residuals(5), &style(360)),
            residuals(&iso_residuals(5), &style(360))
        );
    }

    #[test]
    fn charts_stay_small() {
        // 400 readings (11 targets × 2 directions × 18 runs would be 396).
        let r = iso_residuals(19);
        assert!(r.x.len() >= 400);
        let svg = residuals(&r, &style(360));
        assert!(svg.len() < 60_000, "{} bytes", svg.len());
        assert_small(&residuals(&iso_residuals(5), &style(360)));
    }

    #[test]
    fn unicode_and_markup_survive_escaped() {
        let r = ResidualsChart {
            x_label: "Target position Pi / °".to_string(),
            y_label: "Residual / ″ <arcsec> & \"x\"".to_string(),
            ..iso_residuals(2)
        };
        let svg = residuals(&r, &style(360));
        assert_well_formed(&svg);
        assert!(svg.contains("Target position Pi / °"));
        assert!(svg.contains("&lt;arcsec&gt; &amp; &quot;x&quot;"));
        assert!(!svg.contains("<arcsec>"));
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let styles = degenerate_styles(style(360));
        let base = iso_residuals(1);
        let res = |x: Vec<f64>, y: Vec<f64>| ResidualsChart {
            up: (0..x.len()).map(|i| i % 2 == 0).collect(),
            x,
            y,
            ..base.clone()
        };
        let residual_cases = vec![
            ResidualsChart::default(),
            res(vec![1.0], vec![0.3]),
            res(vec![2.0; 5], vec![0.7; 5]),
            res(vec![0.0, 1.0], vec![0.0, 0.0]),
            res(vec![0.0, 1e-12, 2e-12], vec![1e-300, -1e-300, 0.0]),
            res(vec![-1e300, 1e300], vec![1e300, -1e300]),
            res(vec![0.0, 1.0], vec![f64::MAX, 0.0]),
            res(vec![f64::NAN, f64::INFINITY], vec![1.0, 2.0]),
            ResidualsChart {
                fit: Some(vec![(f64::NAN, f64::NAN); 3]),
                band: Some(1e300),
                x_label: String::new(),
                y_label: "   ".to_string(),
                ..base.clone()
            },
            ResidualsChart {
                fit: Some(Vec::new()),
                ..base.clone()
            },
            ResidualsChart {
                time: Some(TimePanels {
                    means: vec![(f64::INFINITY, 1e300, true), (0.0, -1e300, false)],
                    curve: vec![(f64::NAN, 0.0), (0.0, f64::MAX)],
                    band: f64::NAN,
                    after_band: Some(-1.0),
                    ..TimePanels::default()
                }),
                ..base.clone()
            },
            ResidualsChart {
                time: Some(TimePanels::default()),
                ..base.clone()
            },
        ];
        for st in &styles {
            for r in &residual_cases {
                assert_well_formed(&residuals(r, st));
            }
        }
    }
}
