//! The history's Parquet files: written atomically through polars, one per campaign run,
//! and read back with their schema checked.

use super::record::SharedText;
use super::{HistoryError, Record, SCHEMA_VERSION};
use chrono::{Datelike, NaiveDate};
use polars::prelude::*;
use std::path::{Path, PathBuf};

/// `DIR/year=YYYY/<campaign-slug>_<YYYY-MM-DD>.parquet`: a campaign's name and date give
/// one path, so a rerun replaces its file.
pub fn file_path(dir: &Path, campaign: &str, date: NaiveDate) -> PathBuf {
    dir.join(format!("year={}", date.year()))
        .join(super::file_name(campaign, date))
}

/// Writes one run's rows to its file under `dir` (replacing the run's earlier file) and
/// returns the path; with no rows (no test was evaluated) the history is left as it is
/// and the result is `None`.
pub fn append(dir: &Path, records: &[Record]) -> Result<Option<PathBuf>, HistoryError> {
    let Some(first) = records.first() else {
        return Ok(None);
    };
    if let Some(other) = records
        .iter()
        .find(|r| r.campaign != first.campaign || r.date != first.date)
    {
        return Err(HistoryError::MixedRuns {
            first: format!("{} {}", first.campaign, first.date),
            other: format!("{} {}", other.campaign, other.date),
        });
    }
    let path = file_path(dir, &first.campaign, first.date);
    let root = crate::files::Root::folder(dir, "history folder");
    check_same_campaign(&path, &first.campaign, &root)?;
    let bytes = parquet_bytes(records).map_err(|e| HistoryError::Parquet {
        path: path.clone(),
        message: e.to_string(),
    })?;
    crate::atomic::write(&path, &bytes)
        .and_then(|()| crate::atomic::sync_dir(path.parent().unwrap_or(dir)))
        .map_err(|cause| HistoryError::Io {
            path: path.clone(),
            cause,
        })?;
    Ok(Some(path))
}

/// Refuses to replace the file of another campaign whose name has the same slug.
fn check_same_campaign(
    path: &Path,
    campaign: &str,
    root: &crate::files::Root,
) -> Result<(), HistoryError> {
    // A file that cannot be read (or is damaged: checked as `read_bytes` does) is replaced;
    // one opened outside the history folder is never read.
    let Ok(bytes) = root.read(path) else {
        return Ok(());
    };
    if super::pages::check(&bytes).is_err() {
        return Ok(());
    }
    let found = crate::panics::contained(|| {
        ParquetReader::new(std::io::Cursor::new(&bytes))
            .read_parallel(ParallelStrategy::None)
            .with_columns(Some(vec!["campaign".into()]))
            .with_slice(Some((0, 1)))
            .finish()
    })
    .ok()
    .and_then(Result::ok)
    .and_then(|df| {
        let column = df.column("campaign").ok()?.str().ok()?.clone();
        column.get(0).map(str::to_string)
    });
    match found {
        Some(found) if found != campaign => Err(HistoryError::NameClash {
            path: path.to_path_buf(),
            campaign: campaign.into(),
            found,
        }),
        _ => Ok(()),
    }
}

/// The rows as a Parquet file: typed columns, in [`Record`]'s order.
fn parquet_bytes(records: &[Record]) -> PolarsResult<Vec<u8>> {
    let strings = |f: fn(&Record) -> &str| records.iter().map(f).collect::<Vec<&str>>();
    let columns = vec![
        Column::new(
            "schema_version".into(),
            records
                .iter()
                .map(|r| r.schema_version)
                .collect::<Vec<u32>>(),
        ),
        Column::new("campaign".into(), strings(|r| &r.campaign)),
        Series::new(
            "date".into(),
            records
                .iter()
                .map(|r| r.date.to_epoch_days())
                .collect::<Vec<i32>>(),
        )
        .into_date()
        .into(),
        Column::new("machine".into(), strings(|r| &r.machine)),
        Column::new(
            "serial".into(),
            records
                .iter()
                .map(|r| r.serial.as_deref())
                .collect::<Vec<Option<&str>>>(),
        ),
        Column::new("axis".into(), strings(|r| &r.axis)),
        Column::new(
            "test".into(),
            records.iter().map(|r| r.test).collect::<Vec<u32>>(),
        ),
        Column::new("kind".into(), strings(|r| &r.kind)),
        Column::new("standard".into(), strings(|r| &r.standard)),
        Column::new("verdict".into(), strings(|r| &r.verdict)),
        Column::new("parameter".into(), strings(|r| &r.parameter)),
        Column::new("unit".into(), strings(|r| &r.unit)),
        Column::new(
            "value".into(),
            records.iter().map(|r| r.value).collect::<Vec<f64>>(),
        ),
        Column::new(
            "limit".into(),
            records
                .iter()
                .map(|r| r.limit)
                .collect::<Vec<Option<f64>>>(),
        ),
        Column::new(
            "uncertainty".into(),
            records
                .iter()
                .map(|r| r.uncertainty)
                .collect::<Vec<Option<f64>>>(),
        ),
        Column::new("effects".into(), strings(|r| &r.effects)),
    ];
    let mut df = DataFrame::new(records.len(), columns)?;
    let mut bytes = Vec::new();
    ParquetWriter::new(&mut bytes).finish(&mut df)?;
    Ok(bytes)
}

/// Every row of every `*.parquet` file under `dir`, files in path order. Temporary files
/// of a write in progress (`.NAME.axcheck-tmp-PID`) and hidden files are not read; a file
/// that is not a history file of a known schema version is an error naming it.
pub fn read(dir: &Path) -> Result<Vec<Record>, HistoryError> {
    let mut all = Vec::new();
    visit(dir, |rows| all.extend(rows))?;
    Ok(all)
}

/// Gives `visit` the rows of every history file under `dir`, file by file in path order
/// (the files [`read`] reads), one file decoded at a time, so that memory holds one file's
/// rows and whatever `visit` keeps, not the whole history: `trend` on ten yearly
/// inspections of 10 000 axes keeps its series only (0.16 GB at its peak, was 0.56 GB).
pub fn visit(dir: &Path, mut visit: impl FnMut(Vec<Record>)) -> Result<(), HistoryError> {
    if !dir.is_dir() {
        return Err(HistoryError::NoHistory {
            path: dir.to_path_buf(),
        });
    }
    let files = history_files(dir)?;
    // Each file is opened inside the folder's real path, resolved once: a folder on the
    // way swapped for a link after the walk is refused, not read.
    let root = crate::files::Root::folder(dir, "history folder");
    for path in &files {
        visit(read_file(path, &root)?);
    }
    Ok(())
}

/// The `*.parquet` files under `dir`, sorted: the files [`visit`] reads.
pub fn history_files(dir: &Path) -> Result<Vec<PathBuf>, HistoryError> {
    let mut files = Vec::new();
    for entry in walkdir::WalkDir::new(dir) {
        let entry = entry.map_err(|e| HistoryError::Io {
            path: e.path().unwrap_or(dir).to_path_buf(),
            cause: e.into(),
        })?;
        let name = entry.file_name().to_string_lossy();
        if !name.ends_with(".parquet") || name.starts_with('.') {
            continue;
        }
        if !entry.file_type().is_file() {
            // A link or a folder named as an inspection is refused, not skipped: no trend
            // may silently miss an inspection.
            let kind = match entry.file_type() {
                t if t.is_symlink() => "a symbolic link",
                t if t.is_dir() => "a folder",
                _ => "not a regular file",
            };
            return Err(HistoryError::NotAFile {
                path: entry.into_path(),
                kind,
            });
        }
        files.push(entry.into_path());
    }
    files.sort();
    Ok(files)
}

/// What to do with a history file that cannot be read: the others are not read either, so
/// that no trend silently misses an inspection.
const UNREADABLE_ADVICE: &str =
    "restore it from a backup, or move it out of the history folder to read the others";

/// One history file's rows, its schema checked; refused unless the file opened lies
/// inside the folder `root` ([`crate::files::Root::read`]).
pub fn read_file(path: &Path, root: &crate::files::Root) -> Result<Vec<Record>, HistoryError> {
    let bytes = root.read(path).map_err(|e| HistoryError::Io {
        path: path.to_path_buf(),
        cause: e.into(),
    })?;
    read_bytes(&bytes, path)
}

/// The rows of a history file's bytes, as [`read_file`] reads them (`path` names it in the
/// errors; the fuzz target reads bytes).
pub fn read_bytes(bytes: &[u8], path: &Path) -> Result<Vec<Record>, HistoryError> {
    // polars panics on some damaged files: contained, that file is an error. Decoded on
    // this thread (the files are read in parallel already), so that the panic is too.
    // Some damage makes it abort instead: the page headers are checked first.
    let reader =
        ParquetReader::new(std::io::Cursor::new(bytes)).read_parallel(ParallelStrategy::None);
    let df = crate::panics::contained(|| {
        super::pages::check(bytes).map_err(|e| format!("it is damaged ({e})"))?;
        reader.finish().map_err(|e| e.to_string())
    })
    .map_err(|panic| format!("it is damaged (the Parquet reader failed: {panic})"))
    .and_then(|read| read)
    .map_err(|message| HistoryError::Parquet {
        path: path.to_path_buf(),
        message: format!("{message}; {UNREADABLE_ADVICE}"),
    })?;
    Columns { df: &df, path }.records()
}

/// A history file's frame and its path (for the errors).
struct Columns<'a> {
    df: &'a DataFrame,
    path: &'a Path,
}

impl Columns<'_> {
    fn column(
        &self,
        name: &'static str,
        expected: DataType,
        label: &'static str,
    ) -> Result<&Column, HistoryError> {
        let column = self
            .df
            .column(name)
            .map_err(|_| HistoryError::MissingColumn {
                path: self.path.to_path_buf(),
                column: name,
            })?;
        if column.dtype() != &expected {
            return Err(HistoryError::WrongType {
                path: self.path.to_path_buf(),
                column: name,
                found: column.dtype().to_string(),
                expected: label,
            });
        }
        Ok(column)
    }

    fn polars(&self, e: PolarsError) -> HistoryError {
        HistoryError::Parquet {
            path: self.path.to_path_buf(),
            message: e.to_string(),
        }
    }

    /// A text column, each distinct value held once (see [`SharedText`]).
    fn strings(&self, name: &'static str) -> Result<Vec<Option<SharedText>>, HistoryError> {
        let column = self.column(name, DataType::String, "text (string)")?;
        let ca = column.str().map_err(|e| self.polars(e))?;
        let mut seen: std::collections::HashMap<&str, SharedText> = Default::default();
        let texts = ca
            .iter()
            .map(|value| value.map(|s| seen.entry(s).or_insert_with(|| s.into()).clone()));
        Ok(texts.collect())
    }

    fn u32s(&self, name: &'static str) -> Result<Vec<Option<u32>>, HistoryError> {
        let column = self.column(name, DataType::UInt32, "u32")?;
        Ok(column.u32().map_err(|e| self.polars(e))?.iter().collect())
    }

    fn f64s(&self, name: &'static str) -> Result<Vec<Option<f64>>, HistoryError> {
        let column = self.column(name, DataType::Float64, "f64")?;
        Ok(column.f64().map_err(|e| self.polars(e))?.iter().collect())
    }

    fn dates(&self, name: &'static str) -> Result<Vec<Option<NaiveDate>>, HistoryError> {
        let column = self.column(name, DataType::Date, "date")?;
        let days = column.date().map_err(|e| self.polars(e))?.physical();
        Ok(days
            .iter()
            .map(|d| d.and_then(NaiveDate::from_epoch_days))
            .collect())
    }

    /// `value` of `column` in `row`, which must not be empty.
    fn required<T>(
        &self,
        value: Option<T>,
        row: usize,
        column: &'static str,
    ) -> Result<T, HistoryError> {
        value.ok_or_else(|| HistoryError::MissingValue {
            path: self.path.to_path_buf(),
            row: row + 1,
            column,
        })
    }

    fn check_version(&self) -> Result<(), HistoryError> {
        let versions =
            self.df
                .column("schema_version")
                .map_err(|_| HistoryError::MissingColumn {
                    path: self.path.to_path_buf(),
                    column: "schema_version",
                })?;
        let unknown = versions
            .as_materialized_series()
            .iter()
            .find(|v| v.extract::<u32>() != Some(SCHEMA_VERSION));
        match unknown {
            Some(found) => Err(HistoryError::UnknownVersion {
                path: self.path.to_path_buf(),
                found: found.to_string(),
            }),
            None => Ok(()),
        }
    }

    fn records(&self) -> Result<Vec<Record>, HistoryError> {
        self.check_version()?;
        let mut campaign = self.strings("campaign")?;
        let mut date = self.dates("date")?;
        let mut machine = self.strings("machine")?;
        let mut serial = self.strings("serial")?;
        let mut axis = self.strings("axis")?;
        let mut test = self.u32s("test")?;
        let mut kind = self.strings("kind")?;
        let mut standard = self.strings("standard")?;
        let mut verdict = self.strings("verdict")?;
        let mut parameter = self.strings("parameter")?;
        let mut unit = self.strings("unit")?;
        let mut value = self.f64s("value")?;
        let mut limit = self.f64s("limit")?;
        let mut uncertainty = self.f64s("uncertainty")?;
        let mut effects = self.strings("effects")?;
        let mut records = Vec::with_capacity(self.df.height());
        for row in 0..self.df.height() {
            let need = |v: Option<_>, column| self.required(v, row, column);
            records.push(Record {
                schema_version: SCHEMA_VERSION,
                campaign: need(take(&mut campaign, row), "campaign")?,
                date: self.required(take(&mut date, row), row, "date")?,
                machine: need(take(&mut machine, row), "machine")?,
                serial: take(&mut serial, row),
                axis: need(take(&mut axis, row), "axis")?,
                test: self.required(take(&mut test, row), row, "test")?,
                kind: need(take(&mut kind, row), "kind")?,
                standard: need(take(&mut standard, row), "standard")?,
                verdict: need(take(&mut verdict, row), "verdict")?,
                parameter: need(take(&mut parameter, row), "parameter")?,
                unit: need(take(&mut unit, row), "unit")?,
                value: self.required(take(&mut value, row), row, "value")?,
                limit: take(&mut limit, row),
                uncertainty: take(&mut uncertainty, row),
                effects: take(&mut effects, row).unwrap_or_default(),
            });
        }
        Ok(records)
    }
}

/// The value of `row` in a column's values, moved out.
fn take<T>(values: &mut [Option<T>], row: usize) -> Option<T> {
    values.get_mut(row).and_then(Option::take)
}
