//! A test's history as its report and `summary.html` show it: the history section and one
//! trend chart per parameter, drawn as scenes (`axcheck-charts`) from the trends fitted
//! over the inspection history.

use super::AxisTrends;
use crate::results::AxisTest;
use axcheck_charts::chart_kit::scene::Scene;
use axcheck_charts::figures::TREND_STYLE;

/// A test's history over the inspections: the report's section and its charts.
pub struct History {
    pub section: axcheck_charts::data::trends::HistorySection,
    pub charts: Vec<HistoryChart>,
}

/// One parameter's history chart.
pub struct HistoryChart {
    /// The chart's file name in the report.
    pub name: String,
    /// The parameter charted, as the chart labels it.
    pub label: String,
    pub scene: Scene,
}

/// A test's history (when the run keeps one and the test has a series in it).
pub fn history_of(test: &AxisTest, trends: Option<&AxisTrends>) -> Option<History> {
    let trends = trends?;
    let m = &test.machine;
    let pairs = trends.axis(&m.id, m.serial.as_deref(), &test.axis);
    let (section, charts) =
        axcheck_charts::data::trends::history_section(pairs, trends.options.horizon_years)?;
    let charts = (charts.into_iter())
        .map(|(name, chart)| HistoryChart {
            label: chart.value_label.clone(),
            scene: axcheck_charts::charts::trend::trend(&chart, &TREND_STYLE),
            name,
        })
        .collect();
    Some(History { section, charts })
}
