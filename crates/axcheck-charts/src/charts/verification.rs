//! The chart of a verification: the mean positional deviations x̄↑ and x̄↓ before the table
//! was loaded (thin), as predicted with it (dashed) and as measured again (bold), at the
//! re-measurement's targets. Where the bold curves leave the dashed ones, the table did not
//! act as predicted. Same conventions as the compensation chart (900 × 420 px).

use crate::chart_kit::scene::Scene;
use crate::chart_kit::{DASHED, DOWN, Marker, SOLID, Stroke, UP};
use crate::charts::compensation::{Means, MeansChart, Style, means_chart};
use crate::charts::iso::look::{DASHED_THIN, DOWN_LIGHT, UP_LIGHT};
use plotters::style::RGBColor;

/// What the verification chart shows. Deviations in µm or arcsec, positions in mm or deg.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VerificationChart {
    /// The re-measurement's target positions, ascending.
    pub positions: Vec<f64>,
    pub(crate) position_label: String,
    pub(crate) deviation_label: String,
    /// Per target: the means before, predicted and achieved, ↑ and ↓.
    pub(crate) before_up: Vec<f64>,
    pub(crate) before_down: Vec<f64>,
    pub(crate) predicted_up: Vec<f64>,
    pub(crate) predicted_down: Vec<f64>,
    pub(crate) achieved_up: Vec<f64>,
    pub(crate) achieved_down: Vec<f64>,
}

const PREDICTED: &[f64] = &[3.0, 4.0];
const GREY_UP: RGBColor = RGBColor(0x8A, 0x9B, 0xB8);
const GREY_DOWN: RGBColor = RGBColor(0xC0, 0x8E, 0x8E);

/// The three stages before, predicted and achieved.
pub fn verification(chart: &VerificationChart, style: &Style) -> Scene {
    let means = |values, stroke, mark, text| Means {
        values,
        stroke,
        mark,
        text,
    };
    let spec = MeansChart {
        positions: &chart.positions,
        position_label: &chart.position_label,
        deviation_label: &chart.deviation_label,
        means: vec![
            means(
                &chart.before_up,
                Stroke::new(UP_LIGHT, 1, SOLID),
                (Marker::Dot(3), UP_LIGHT),
                "x̄i↑ before",
            ),
            means(
                &chart.before_down,
                Stroke::new(DOWN_LIGHT, 1, DASHED_THIN),
                (Marker::TriangleOutline(4), DOWN_LIGHT),
                "x̄i↓ before",
            ),
            means(
                &chart.predicted_up,
                Stroke::new(GREY_UP, 2, PREDICTED),
                (Marker::Diamond(4), GREY_UP),
                "x̄i↑ predicted",
            ),
            means(
                &chart.predicted_down,
                Stroke::new(GREY_DOWN, 2, PREDICTED),
                (Marker::Diamond(4), GREY_DOWN),
                "x̄i↓ predicted",
            ),
            means(
                &chart.achieved_up,
                Stroke::new(UP, 3, SOLID),
                (Marker::Dot(5), UP),
                "x̄i↑ achieved",
            ),
            means(
                &chart.achieved_down,
                Stroke::new(DOWN, 3, DASHED),
                (Marker::Triangle(5), DOWN),
                "x̄i↓ achieved",
            ),
        ],
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
    fn it_labels_the_three_stages_of_both_directions() {
        let chart = VerificationChart {
            positions: vec![0.0, 100.0, 200.0],
            position_label: "Target position Pi / mm".into(),
            deviation_label: "Mean positional deviation / µm".into(),
            before_up: vec![1.0, 4.0, 8.0],
            before_down: vec![-1.0, 2.0, 5.0],
            predicted_up: vec![0.0; 3],
            predicted_down: vec![0.0; 3],
            achieved_up: vec![-1.0, -4.0, -8.0],
            achieved_down: vec![1.0, -2.0, -5.0],
        };
        let style = Style {
            width_px: 900,
            height_px: 420,
        };
        let scene = verification(&chart, &style);
        let texts: Vec<&str> = scene.texts.iter().map(|t| t.text.as_str()).collect();
        for label in [
            "Mean positional deviation / µm",
            "x̄i↑ before",
            "x̄i↓ predicted",
            "x̄i↑ achieved",
        ] {
            assert!(texts.contains(&label), "{label} missing from {texts:?}");
        }
        assert!(!texts.contains(&"table point"));
    }
}
