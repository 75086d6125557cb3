//! ISO 230-2 Fig. 2a, the bidirectional chart of an axis: both approach directions in one
//! plot with the bidirectional mean and the spans. Designed for 900 × 420 px.

use super::axis_chart::AxisChart;
use super::direction::{Layer, direction_legend, direction_values, draw_direction};
use super::look::{KIT, MEAN_BIDIR, build_panel, curve, x_range, y_range};
use super::spans::{draw_spans, span_margin, span_values};
use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    AxesSpec, LegendItem, Style, X_DESC_H, X_TICK_H, draw_line, message_chart, render,
};

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
                text: crate::words::Words::new(crate::words::numbers())
                    .get("chart-mean-bidirectional"),
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

#[cfg(test)]
mod tests {
    use super::super::look::testing::{
        assert_plain_font_sizes, assert_small, degenerate_cases, iso_example, single_run, style,
    };
    use super::*;
    use crate::chart_kit::svg_probe::{assert_well_formed, degenerate_styles, texts};

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn bidirectional(chart: &AxisChart, style: &Style) -> String {
        super::bidirectional(chart, style).element_svg()
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
    fn font_sizes_are_plain_numbers() {
        assert_plain_font_sizes(&bidirectional(&iso_example(), &style()));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            bidirectional(&iso_example(), &style()),
            bidirectional(&iso_example(), &style())
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
        let svg = bidirectional(&single_run(40), &style());
        assert_well_formed(&svg);
        let t = texts(&svg);
        assert!(t.iter().any(|x| x == "mean X̄i↑"));
        assert!(!t.iter().any(|x| x.contains("X̄ ± 3S")), "{t:?}");
        assert!(!t.iter().any(|x| x.starts_with("readings")), "{t:?}");
    }

    #[test]
    fn degenerate_inputs_do_not_panic() {
        let styles = degenerate_styles(style());
        for chart in &degenerate_cases() {
            for st in &styles {
                assert_well_formed(&bidirectional(chart, st));
            }
        }
    }

    #[test]
    fn axis_charts_stay_small() {
        assert_small(&bidirectional(&iso_example(), &style()));
        assert_small(&bidirectional(&single_run(40), &style()));
    }
}
