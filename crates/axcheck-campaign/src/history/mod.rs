//! The inspection history's rows and trends, without its store: every run's axis results
//! as [`Record`]s, regrouped as series and fitted ([`AxisTrends`]). The Parquet store that
//! keeps them (one file per campaign run, identified by campaign name and date: a rerun
//! replaces its file) is the root package's `history`, above this crate.
//!
//! Layout: `DIR/year=YYYY/<campaign-slug>_<YYYY-MM-DD>.parquet` (Hive-style partitions, so
//! DuckDB and polars add a `year` column when asked). Each file is written atomically
//! (`atomic::write`: `.NAME.axcheck-tmp-PID`, then a rename), so a reader sees a
//! complete file or none, and temporary files never match `*.parquet`.

mod axes;
pub mod record;
mod rows;
mod series;

pub use axes::{AxisKey, AxisTrends, axis_key};
pub use record::{Record, SCHEMA_VERSION};
pub use rows::{records, run_date};
pub use series::{SeriesBuilder, series};

use std::path::PathBuf;

/// Why the history cannot be written or read.
#[derive(Debug, thiserror::Error)]
pub enum HistoryError {
    #[error(
        "{file}: campaign.date: a history needs the campaign's date (YYYY-MM-DD, e.g. `date: 2026-11-20`), the run's identity with its name"
    )]
    MissingDate { file: String },
    #[error("{file}: campaign.date: expected a date YYYY-MM-DD, got `{date}`")]
    BadDate { file: String, date: String },
    #[error(
        "{file}: campaign.name: a history needs the campaign's name (the run's identity with its date)"
    )]
    MissingName { file: String },
    #[error(
        "{file}: campaign.name: the campaign's history file name would be {bytes} bytes, more than the {} a file system takes with axcheck's temporary name; shorten campaign.name (nothing was evaluated or written)",
        MAX_FILE_NAME_BYTES
    )]
    NameTooLong { file: String, bytes: usize },
    #[error(
        "{path}: it is {kind}, named as an inspection; a history holds its inspections as regular files (the links are not followed): put the file itself there, or rename or move it out of the history folder"
    )]
    NotAFile { path: PathBuf, kind: &'static str },
    #[error(
        "the rows to append belong to more than one campaign run ({first} and {other}); append one run at a time"
    )]
    MixedRuns { first: String, other: String },
    #[error(
        "{path} holds the history of campaign `{found}`, not `{campaign}`: their names give the same file name on this date; rename one of the campaigns"
    )]
    NameClash {
        path: PathBuf,
        campaign: String,
        found: String,
    },
    #[error("the history folder {path} does not exist")]
    NoHistory { path: PathBuf },
    // `cause`, not `source`: a source is printed again after the message (`{e:#}`), and
    // the message holds it already.
    #[error("{path}: {cause}")]
    Io {
        path: PathBuf,
        cause: std::io::Error,
    },
    #[error("{path}: not a readable Parquet file of the history: {message}")]
    Parquet { path: PathBuf, message: String },
    #[error(
        "{path}: no column `{column}`; this is not an axcheck history file (schema version {SCHEMA_VERSION})"
    )]
    MissingColumn { path: PathBuf, column: &'static str },
    #[error("{path}: column `{column}` has type {found}, expected {expected}")]
    WrongType {
        path: PathBuf,
        column: &'static str,
        found: String,
        expected: &'static str,
    },
    #[error(
        "{path}: schema_version {found} is unknown to this axcheck (it reads version {SCHEMA_VERSION}); use a newer axcheck"
    )]
    UnknownVersion { path: PathBuf, found: String },
    #[error("{path}: row {row}: column `{column}` is empty")]
    MissingValue {
        path: PathBuf,
        row: usize,
        column: &'static str,
    },
}

/// A run's history file name: `<campaign-slug>_<YYYY-MM-DD>.parquet`.
pub fn file_name(campaign: &str, date: chrono::NaiveDate) -> String {
    format!("{}_{date}.parquet", slug(campaign))
}

/// The longest history file name, in bytes: it is written as `.NAME.axcheck-tmp-PID`
/// first (25 bytes more), and file systems take names of 255 bytes (ext4, XFS, Btrfs).
pub(crate) const MAX_FILE_NAME_BYTES: usize = 230;

/// `Plant 2 annual inspection` → `plant-2-annual-inspection`: lower-case letters and digits
/// (any script), everything else a single `-`; `campaign` when nothing is left.
pub fn slug(name: &str) -> String {
    let mut slug = String::new();
    for c in name.chars() {
        if c.is_alphanumeric() {
            slug.extend(c.to_lowercase());
        } else if !slug.is_empty() && !slug.ends_with('-') {
            slug.push('-');
        }
    }
    while slug.ends_with('-') {
        slug.pop();
    }
    if slug.is_empty() {
        "campaign".into()
    } else {
        slug
    }
}

#[cfg(test)]
mod tests {
    use super::slug;

    #[test]
    fn slugs_keep_letters_and_digits() {
        assert_eq!(
            slug("Plant 2 annual inspection"),
            "plant-2-annual-inspection"
        );
        assert_eq!(slug("  --Hall B / 2026--  "), "hall-b-2026");
        assert_eq!(slug("Завод №2"), "завод-2");
        assert_eq!(slug("../.."), "campaign");
    }
}
