//! ISO 230-2 Fig. 2b, the unidirectional chart of an axis: ↑ and ↓ in two panels stacked,
//! each with its own spans. Designed for 900 × 600 px.

use super::axis_chart::{AxisChart, Span};
use super::direction::{Layer, direction_legend, direction_values, draw_direction};
use super::look::{KIT, build_panel, x_range, y_range};
use super::spans::{draw_spans, span_margin, span_values};
use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    AxesSpec, DESC_PX, DOWN, Style, UP, X_DESC_H, X_TICK_H, draw_text, message_chart, render,
    text_style,
};
use plotters::style::text_anchor::{HPos, VPos};

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

        // The panels' titles in the language of the document being drawn.
        let words = crate::words::Words::new(crate::words::numbers());
        let (approach_up, approach_down) = (
            words.args("chart-approach", &[("arrow", "↑")]),
            words.args("chart-approach", &[("arrow", "↓")]),
        );
        let panels = [
            (
                &upper_area,
                &chart.up,
                up_spans,
                true,
                approach_up.as_str(),
                None,
            ),
            (
                &lower_area,
                &chart.down,
                down_spans,
                false,
                approach_down.as_str(),
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
    use super::super::look::testing::{
        assert_plain_font_sizes, assert_small, degenerate_cases, iso_example, single_run, span,
        style,
    };
    use super::*;
    use crate::chart_kit::svg_probe::{assert_well_formed, degenerate_styles, texts};

    // The chart as SVG with an element per outline, as plotters wrote it.
    fn unidirectional(chart: &AxisChart, up: &[Span], down: &[Span], style: &Style) -> String {
        super::unidirectional(chart, up, down, style).element_svg()
    }

    /// The chart of `chart` with a few spans in each panel.
    fn with_spans(chart: &AxisChart, style: &Style) -> String {
        let ups = [span("A↑", 0.66, -5.58), span("R↑", 3.0, 0.0)];
        let downs = [span("A↓", 4.01, -1.9)];
        unidirectional(chart, &ups, &downs, style)
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
        assert_plain_font_sizes(&with_spans(&iso_example(), &style()));
    }

    #[test]
    fn same_input_gives_same_bytes() {
        assert_eq!(
            with_spans(&iso_example(), &style()),
            with_spans(&iso_example(), &style())
        );
    }

    #[test]
    fn n1_has_no_limit_curves_and_no_readings_entry() {
        let svg = unidirectional(&single_run(40), &[], &[], &style());
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
                assert_well_formed(&with_spans(chart, st));
                let svg = unidirectional(chart, &chart.spans, &chart.spans, st);
                assert_well_formed(&svg);
            }
        }
    }

    #[test]
    fn axis_charts_stay_small() {
        assert_small(&with_spans(&iso_example(), &style()));
    }
}
