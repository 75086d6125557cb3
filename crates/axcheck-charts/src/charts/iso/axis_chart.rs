//! What the ISO 230-2 axis charts show ([`bidirectional`](fn@super::bidirectional),
//! 900 × 420 px, and [`unidirectional`](fn@super::unidirectional), 900 × 600 px): an
//! [`AxisChart`] with a [`DirectionSeries`] per approach direction and the [`Span`]s to mark.

/// One approach direction's per-target statistics. All deviation values in the axis's
/// deviation unit (µm or arcsec).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DirectionSeries {
    /// X̄i↑ (or ↓) per target
    pub mean: Vec<f64>,
    /// X̄i + kSi per target (None when n = 1)
    pub upper: Option<Vec<f64>>,
    /// X̄i − kSi per target
    pub lower: Option<Vec<f64>>,
    /// the n individual readings at each target
    pub deviations: Vec<Vec<f64>>,
}

/// A range-type axis parameter to mark on the chart, e.g. A = max(upper) − min(lower).
#[derive(Debug, Clone, PartialEq)]
pub struct Span {
    pub label: String,
    pub upper: f64,
    pub lower: f64,
}

/// Everything the two axis charts show.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AxisChart {
    /// target positions P_i, ascending (mm or deg)
    pub positions: Vec<f64>,
    /// e.g. "Target position Pi / mm"
    pub(crate) position_label: String,
    /// e.g. "Positional deviation / µm"
    pub(crate) deviation_label: String,
    pub up: DirectionSeries,
    pub down: DirectionSeries,
    /// bidirectional mean X̄i per target
    pub mean: Vec<f64>,
    /// e.g. "X̄ ± 2S" (ISO) or "X̄ ± 3S" (GOST)
    pub(crate) band_label: String,
    /// e.g. A, E, M for the bidirectional chart
    pub spans: Vec<Span>,
}
