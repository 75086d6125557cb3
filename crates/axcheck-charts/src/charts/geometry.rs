//! The chart of a straightness or angular test's report: each direction's mean
//! deviations along the axis (x̄↑ bold, x̄↓ dashed) and, for a straightness, the mean of
//! both, all about the reference straight line (drawn as the zero line); an angular test
//! is drawn as measured, with no line removed. Same conventions as the compensation
//! chart (900 × 420 px), whose drawing it shares.

use crate::chart_kit::scene::Scene;
use crate::chart_kit::{DASHED, DOWN, INK, Marker, SOLID, Stroke, UP};
use crate::charts::compensation::{Means, MeansChart, Style, means_chart};

/// What the chart shows. Deviations in µm (straightness) or arcsec, positions in mm.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct GeometryChart {
    pub positions: Vec<f64>,
    pub(crate) position_label: String,
    pub(crate) deviation_label: String,
    pub up: Vec<f64>,
    pub down: Vec<f64>,
    /// The bidirectional mean (a straightness: what the reference line is fitted to).
    pub mean: Option<Vec<f64>>,
    /// The legend's words for the three curves.
    pub(crate) texts: [&'static str; 3],
}

/// The test's curves.
pub fn geometry(chart: &GeometryChart, style: &Style) -> Scene {
    let mut means = vec![
        Means {
            values: &chart.up,
            stroke: Stroke::new(UP, 2, SOLID),
            mark: (Marker::Dot(4), UP),
            text: chart.texts[0],
        },
        Means {
            values: &chart.down,
            stroke: Stroke::new(DOWN, 2, DASHED),
            mark: (Marker::Triangle(4), DOWN),
            text: chart.texts[1],
        },
    ];
    if let Some(mean) = &chart.mean {
        means.push(Means {
            values: mean,
            stroke: Stroke::new(INK, 3, SOLID),
            mark: (Marker::Diamond(4), INK),
            text: chart.texts[2],
        });
    }
    let spec = MeansChart {
        positions: &chart.positions,
        position_label: &chart.position_label,
        deviation_label: &chart.deviation_label,
        means,
        readings: [&[], &[]],
        readings_text: "",
        table_points: &[],
    };
    means_chart(&spec, style)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_straightness_shows_both_directions_and_their_mean() {
        let chart = GeometryChart {
            positions: vec![0.0, 500.0, 1000.0],
            position_label: "Position / mm".into(),
            deviation_label: "Deviation about the line / µm".into(),
            up: vec![-2.0, 4.0, -2.0],
            down: vec![-1.0, 3.0, -1.0],
            mean: Some(vec![-1.5, 3.5, -1.5]),
            texts: ["x̄i↑", "x̄i↓", "mean of x̄i↑ and x̄i↓"],
        };
        let style = Style {
            width_px: 900,
            height_px: 420,
        };
        let scene = geometry(&chart, &style);
        let texts: Vec<&str> = scene.texts.iter().map(|t| t.text.as_str()).collect();
        for label in [
            "Deviation about the line / µm",
            "x̄i↑",
            "mean of x̄i↑ and x̄i↓",
        ] {
            assert!(texts.contains(&label), "{label} missing from {texts:?}");
        }
    }
}
