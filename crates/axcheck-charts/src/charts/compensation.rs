//! The chart of an axis report's compensation section: the mean positional deviations
//! x̄↑ and x̄↓ as measured (thin) and with the controller's table applied (bold), the
//! readings with the table (the scatter no table removes) and the table's points.
//!
//! Same conventions as [`crate::charts`]: pure, never panics (a chart that cannot be
//! drawn comes back as a small chart that says so), sizes in pixels for a chart about
//! 900 px wide shown about 16 cm wide (900 × 420).

use crate::chart_kit::scene::Scene;
use crate::chart_kit::{
    Area, AxesSpec, Chart, DASHED, DOWN, Failed, INK, LegendItem, Marker, SOLID, Stroke, UP,
    X_DESC_H, X_TICK_H, draw_line, draw_marker, message_chart, padded_range, render, round_px,
};
use crate::charts::iso::look::{
    DASHED_THIN, DOWN_LIGHT, KIT, UP_LIGHT, build_panel, curve, y_range,
};
use plotters::style::RGBColor;

pub use crate::chart_kit::Style;

/// What the compensation chart shows. Deviations in µm or arcsec, positions in mm or deg.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct CompensationChart {
    /// The measured target positions Pi, ascending.
    pub positions: Vec<f64>,
    /// e.g. "Target position Pi / mm"
    pub(crate) position_label: String,
    /// e.g. "Mean positional deviation / µm"
    pub(crate) deviation_label: String,
    /// x̄i↑ and x̄i↓ as measured, per target.
    pub measured_up: Vec<f64>,
    pub(crate) measured_down: Vec<f64>,
    /// x̄i↑ and x̄i↓ with the table applied, per target.
    pub compensated_up: Vec<f64>,
    pub compensated_down: Vec<f64>,
    /// The readings with the table applied, per target, ↑ and ↓.
    pub(crate) readings_up: Vec<Vec<f64>>,
    pub(crate) readings_down: Vec<Vec<f64>>,
    /// The table's points (mm or deg).
    pub table_points: Vec<f64>,
}

const MEASURED_UP: Stroke = Stroke::new(UP_LIGHT, 1, SOLID);
const MEASURED_DOWN: Stroke = Stroke::new(DOWN_LIGHT, 1, DASHED_THIN);
const COMPENSATED_UP: Stroke = Stroke::new(UP, 3, SOLID);
const COMPENSATED_DOWN: Stroke = Stroke::new(DOWN, 3, DASHED);
const MARK_MEASURED_UP: (Marker, RGBColor) = (Marker::Dot(3), UP_LIGHT);
const MARK_MEASURED_DOWN: (Marker, RGBColor) = (Marker::TriangleOutline(4), DOWN_LIGHT);
const MARK_COMPENSATED_UP: (Marker, RGBColor) = (Marker::Dot(5), UP);
const MARK_COMPENSATED_DOWN: (Marker, RGBColor) = (Marker::Triangle(5), DOWN);
const MARK_READING: (Marker, RGBColor) = (Marker::Dot(2), RGBColor(0x8A, 0x8A, 0x8A));
const MARK_TABLE_POINT: (Marker, RGBColor) = (Marker::Diamond(5), INK);

/// A line through a direction's means with a marker at each.
pub(crate) struct Means<'a> {
    pub values: &'a [f64],
    pub stroke: Stroke,
    pub mark: (Marker, RGBColor),
    pub text: &'static str,
}

/// A chart of mean curves along the axis: what the compensation and the verification
/// charts draw, each with its own curves.
pub(crate) struct MeansChart<'a> {
    pub positions: &'a [f64],
    pub(crate) position_label: &'a str,
    pub(crate) deviation_label: &'a str,
    /// Drawn in order (the first under the others).
    pub means: Vec<Means<'a>>,
    /// Readings per target, ↑ and ↓ (empty: none drawn), and their legend text.
    pub readings: [&'a [Vec<f64>]; 2],
    pub(crate) readings_text: &'static str,
    pub table_points: &'a [f64],
}

impl CompensationChart {
    /// The chart's curves: measured first (drawn under the compensated ones).
    fn spec(&self) -> MeansChart<'_> {
        let means = |values, stroke, mark, text| Means {
            values,
            stroke,
            mark,
            text,
        };
        MeansChart {
            positions: &self.positions,
            position_label: &self.position_label,
            deviation_label: &self.deviation_label,
            means: vec![
                means(
                    &self.measured_up,
                    MEASURED_UP,
                    MARK_MEASURED_UP,
                    "x̄i↑ measured",
                ),
                means(
                    &self.measured_down,
                    MEASURED_DOWN,
                    MARK_MEASURED_DOWN,
                    "x̄i↓ measured",
                ),
                means(
                    &self.compensated_up,
                    COMPENSATED_UP,
                    MARK_COMPENSATED_UP,
                    "x̄i↑ with the table",
                ),
                means(
                    &self.compensated_down,
                    COMPENSATED_DOWN,
                    MARK_COMPENSATED_DOWN,
                    "x̄i↓ with the table",
                ),
            ],
            readings: [&self.readings_up, &self.readings_down],
            readings_text: "readings with the table",
            table_points: &self.table_points,
        }
    }
}

impl MeansChart<'_> {
    fn has_readings(&self) -> bool {
        self.readings.iter().copied().flatten().any(|r| r.len() > 1)
    }

    fn legend(&self) -> Vec<LegendItem> {
        let mut items: Vec<LegendItem> = self
            .means
            .iter()
            .filter(|m| !m.values.is_empty())
            .map(|m| LegendItem {
                stroke: Some(m.stroke),
                marker: Some(m.mark),
                swatch: None,
                text: m.text.to_string(),
            })
            .collect();
        if self.has_readings() {
            items.push(LegendItem {
                stroke: None,
                marker: Some(MARK_READING),
                swatch: None,
                text: self.readings_text.to_string(),
            });
        }
        if !self.table_points.is_empty() {
            items.push(LegendItem {
                stroke: None,
                marker: Some(MARK_TABLE_POINT),
                swatch: None,
                text: "table point".to_string(),
            });
        }
        items
    }

    /// Every deviation drawn.
    fn values(&self) -> impl Iterator<Item = f64> + '_ {
        let n = self.positions.len();
        let means = self
            .means
            .iter()
            .flat_map(move |m| m.values.iter().take(n).copied());
        let readings = self.readings.iter().copied().flatten().flatten();
        means.chain(readings.copied())
    }
}

/// The mean deviations before and after compensation, with the readings after it and
/// the table's points marked along the bottom of the plot. Designed for 900 × 420 px.
pub fn compensation(chart: &CompensationChart, style: &Style) -> Scene {
    means_chart(&chart.spec(), style)
}

/// A chart of mean curves, readings and table points.
pub(crate) fn means_chart(chart: &MeansChart, style: &Style) -> Scene {
    let xs = chart.positions.iter().chain(chart.table_points).copied();
    let Some(x) = padded_range(xs, 0.04) else {
        return message_chart(style, "No target positions to plot.");
    };
    let Some(y) = y_range(chart.values()) else {
        return message_chart(style, "The deviations are out of range.");
    };
    render(style, |root| {
        let (w, h) = root.dim_in_pixel();
        let items = chart.legend();
        let legend_h = KIT.legend_height(&items, w as i32 - 20, h as i32) as u32;
        let top = legend_h + 8;
        let plot_h = h.saturating_sub(top + X_TICK_H + X_DESC_H + 6);
        let frame = AxesSpec {
            x,
            y,
            top,
            right: 18,
            x_desc: Some(chart.position_label).filter(|d| !d.trim().is_empty()),
            own_x_ticks: false,
        };
        let cp = build_panel(root, &frame, KIT.y_tick_width(y, plot_h))?;
        if legend_h > 0 {
            KIT.draw_legend(root, &items, 10, w as i32 - 10, 0)?;
        }
        let (_, rows) = cp.plotting_area().get_pixel_range();
        KIT.draw_y_desc(root, chart.deviation_label, rows.start, rows.end)?;
        for readings in chart.readings {
            draw_readings(root, &cp, chart.positions, readings)?;
        }
        for means in &chart.means {
            let points = curve(&cp, chart.positions, means.values);
            draw_line(root, &points, means.stroke)?;
            for p in &points {
                draw_marker(root, round_px(*p), means.mark.0, means.mark.1)?;
            }
        }
        draw_table_points(root, &cp, chart.table_points, rows.end - 8)
    })
}

/// The readings at each target as small grey dots (none with n = 1: each is its mean).
fn draw_readings(
    root: &Area,
    chart: &Chart,
    positions: &[f64],
    readings: &[Vec<f64>],
) -> Result<(), Failed> {
    for (x, values) in positions.iter().zip(readings) {
        if values.len() < 2 {
            continue;
        }
        for v in values.iter().filter(|v| v.is_finite() && x.is_finite()) {
            let at = chart.backend_coord(&(*x, *v));
            draw_marker(root, at, MARK_READING.0, MARK_READING.1)?;
        }
    }
    Ok(())
}

/// The table's points as diamonds on pixel row `row`, near the bottom of the plot.
fn draw_table_points(root: &Area, chart: &Chart, points: &[f64], row: i32) -> Result<(), Failed> {
    let y_any = chart.as_coord_spec().get_y_range().start;
    for p in points.iter().filter(|p| p.is_finite()) {
        let column = chart.backend_coord(&(*p, y_any)).0;
        draw_marker(root, (column, row), MARK_TABLE_POINT.0, MARK_TABLE_POINT.1)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn style() -> Style {
        Style {
            width_px: 900,
            height_px: 420,
        }
    }

    fn chart() -> CompensationChart {
        CompensationChart {
            positions: vec![0.0, 100.0, 200.0],
            position_label: "Target position Pi / mm".into(),
            deviation_label: "Mean positional deviation / µm".into(),
            measured_up: vec![1.0, 4.0, 8.0],
            measured_down: vec![-1.0, 2.0, 5.0],
            compensated_up: vec![0.0, 0.1, 0.0],
            compensated_down: vec![0.0, -0.1, 0.0],
            readings_up: vec![vec![0.2, -0.2]; 3],
            readings_down: vec![vec![0.3, -0.3]; 3],
            table_points: vec![0.0, 50.0, 100.0, 150.0, 200.0],
        }
    }

    #[test]
    fn it_labels_both_axes_and_every_series() {
        let scene = compensation(&chart(), &style());
        let texts: Vec<&str> = scene.texts.iter().map(|t| t.text.as_str()).collect();
        for label in [
            "Target position Pi / mm",
            "Mean positional deviation / µm",
            "x̄i↑ measured",
            "x̄i↓ with the table",
            "readings with the table",
            "table point",
        ] {
            assert!(texts.contains(&label), "{label} missing from {texts:?}");
        }
    }

    #[test]
    fn empty_or_broken_input_gives_a_message_chart() {
        let empty = compensation(&CompensationChart::default(), &style());
        assert!(empty.texts.iter().any(|t| t.text.starts_with("No target")));
        let mut nan = chart();
        for v in nan.measured_up.iter_mut().chain(&mut nan.compensated_up) {
            *v = f64::NAN;
        }
        let scene = compensation(&nan, &style());
        assert!(scene.texts.iter().any(|t| t.text == "x̄i↓ measured"));
    }
}
