//! An approach direction (↑ or ↓) as both ISO 230-2 axis charts draw it — its X̄ ± kS limit
//! curves, readings and mean line — the values it spans and its legend entries. For the
//! charts' sizes (900 × 420 and 900 × 600 px).

use super::axis_chart::{AxisChart, DirectionSeries};
use super::look::{
    LIMIT_DOWN, LIMIT_UP, MARK_MEAN_DOWN, MARK_MEAN_UP, MARK_READ_DOWN, MARK_READ_UP, MEAN_DOWN,
    MEAN_UP, curve,
};
use crate::chart_kit::{Area, Chart, Failed, LegendItem, draw_line, draw_marker, round_px};

/// What of a direction to draw; drawn in this order so means stay on top.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Layer {
    Limits,
    Readings,
    Mean,
}

/// Draws one layer of one direction.
pub(super) fn draw_direction(
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

/// Every value a direction draws.
pub(super) fn direction_values<'a>(
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
pub(super) fn direction_legend(chart: &AxisChart, up: bool) -> Vec<LegendItem> {
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
            text: crate::words::Words::new(crate::words::numbers())
                .args("chart-mean", &[("arrow", &arrow.to_string())]),
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
            text: crate::words::Words::new(crate::words::numbers())
                .args("chart-readings", &[("arrow", &arrow.to_string())]),
        });
    }
    items
}
