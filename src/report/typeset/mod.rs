//! Typesetting: Typst's world (fonts, templates and the report's data as virtual files),
//! plain text shaped directly when Typst's paragraph layout would give the same lines, and
//! the drawings the charts are placed as.

pub(crate) mod drawing;
pub(crate) mod shaping;
pub(crate) mod text_lines;
pub mod world;
