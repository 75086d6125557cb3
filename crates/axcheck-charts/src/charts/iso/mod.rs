//! Report charts drawn with `plotters` into [`Scene`]s (shapes and texts as data).
//!
//! Every function here is pure: the same input gives the same scene, nothing touches the
//! file system, and no input makes it panic (a chart that cannot be drawn comes back as a
//! small chart that says so).
//!
//! Sizes are in pixels and the text sizes are fixed, chosen for a chart about 900 px wide
//! shown about 16 cm wide: 900 × 420 for [`bidirectional`](fn@bidirectional), 900 × 600
//! for [`unidirectional`](fn@unidirectional) (two panels stacked).
//!
//! One file per chart: `bidirectional.rs` (Fig. 2a) and `unidirectional.rs` (Fig. 2b). What
//! both draw from: `axis_chart.rs` (the data), `direction.rs` (an approach direction's
//! limits, readings, mean and legend entries), `spans.rs` (the span brackets) and `look.rs`
//! (tones, strokes, numbers, the panel), whose look the other report charts borrow.
//!
//! [`Scene`]: crate::chart_kit::scene::Scene

mod axis_chart;
mod bidirectional;
mod direction;
pub mod look;
mod spans;
mod unidirectional;

pub use crate::chart_kit::Style;
pub use axis_chart::{AxisChart, DirectionSeries, Span};
pub use bidirectional::bidirectional;
pub use unidirectional::unidirectional;
