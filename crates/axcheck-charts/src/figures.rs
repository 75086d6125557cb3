//! The figures as the documents size them: the ISO 230-2 charts of an axis report and
//! `summary.html`, and the trend charts of a history section.

use crate::chart_kit::scene::Scene;
use crate::charts;
use crate::data;
use crate::evaluate::Evaluation;

/// Chart sizes in pixels, shown about 16 cm wide (the chart module's design size).
pub const CHART_WIDTH_PX: u32 = 900;
pub const CHART_HEIGHT_PX: u32 = 420;
pub(crate) const UNIDIRECTIONAL_HEIGHT_PX: u32 = 600;
/// A trend chart, three to a row: about 5.7 cm wide at the charts' scale.
pub const TREND_STYLE: charts::trend::Style = charts::trend::Style {
    width_px: 320,
    height_px: 210,
};

/// The figures of ISO 230-2 Fig. 2a (bidirectional) and Fig. 2b (unidirectional) of an
/// evaluation, as the axis report shows them (`summary.html` draws the same scenes).
pub fn iso_charts(e: &Evaluation) -> [Scene; 2] {
    let (chart, up, down) = data::axis_chart(e);
    let style = |height_px| charts::Style {
        width_px: CHART_WIDTH_PX,
        height_px,
    };
    [
        charts::bidirectional(&chart, &style(CHART_HEIGHT_PX)),
        charts::unidirectional(&chart, &up, &down, &style(UNIDIRECTIONAL_HEIGHT_PX)),
    ]
}
