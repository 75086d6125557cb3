//! Charts of the "model check and diagnosis" section of an axis report, drawn with `plotters`
//! into [`Scene`]s (shapes and texts as data).
//!
//! Same conventions as the report's other charts: every function is pure (the same input
//! gives the same scene, nothing touches the file system) and no input makes it panic (a
//! chart that cannot be drawn comes back as a small chart that says so).
//!
//! Sizes are in pixels and the text sizes are fixed, chosen for a chart about 900 px wide
//! shown about 16 cm wide: 900 × 360 for [`residuals`](fn@residuals) (600 high with
//! [`TimePanels`]), 900 × 320 for [`periodogram`](fn@periodogram) and
//! 900 × [`model_checks_height`] for [`model_checks`].
//!
//! [`model_checks_height`]: crate::charts::check::model_checks_height
//! [`model_checks`]: crate::charts::check::model_checks
//! [`Scene`]: crate::chart_kit::scene::Scene
//!
//! One file per chart: `residuals.rs` (with `time.rs`, its two panels of an effect kept in
//! time) and `periodogram.rs`; `look.rs` (tones, strokes, markers, text and number helpers)
//! and `frame.rs` (data to pixels, clipping) hold what they and the model checks of
//! [`crate::charts::check`] share.

mod frame;
pub(crate) mod look;
mod periodogram;
mod residuals;
mod time;

pub use crate::chart_kit::Style;
pub use periodogram::{Periodogram, periodogram};
pub use residuals::{ResidualsChart, residuals};
pub use time::TimePanels;
