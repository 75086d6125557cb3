//! The inspection history: every run's axis results appended to a dataset of Parquet files
//! (one per campaign run, identified by campaign name and date: a rerun replaces its file),
//! read back as trend series. I/O at the edge; the rows are [`Record`]s.

pub mod record;

pub use record::{Record, SCHEMA_VERSION};
