//! Command-line front end: parses arguments, calls the library, prints results.

pub mod campaign;
pub mod compensate;
pub mod diagnose;
pub mod eval;
pub mod plan;
pub mod simulate;
pub mod tables;
pub mod text;
#[cfg(feature = "parquet")]
pub mod trend;
pub mod verify;

/// `--json` output: `value`'s JSON with the input file's name added last, pretty-printed.
pub fn json_with_file<T: serde::Serialize>(value: &T, file: &str) -> serde_json::Result<String> {
    #[derive(serde::Serialize)]
    struct WithFile<'a, T> {
        #[serde(flatten)]
        value: &'a T,
        file: &'a str,
    }
    Ok(serde_json::to_string_pretty(&WithFile { value, file })? + "\n")
}

/// `--json` output of `eval`: `value`'s JSON, then the input file's name and what it was
/// read as (`recognised`: layout, name, sheet, notes), pretty-printed.
pub fn json_with_read<T: serde::Serialize>(
    value: &T,
    file: &str,
    recognised: &axcheck::measurement::Recognised,
) -> serde_json::Result<String> {
    #[derive(serde::Serialize)]
    struct WithRead<'a, T> {
        #[serde(flatten)]
        value: &'a T,
        file: &'a str,
        recognised: &'a axcheck::measurement::Recognised,
    }
    let with = WithRead {
        value,
        file,
        recognised,
    };
    Ok(serde_json::to_string_pretty(&with)? + "\n")
}

/// `--sheet NAME`: the sheet of a workbook to read.
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SheetArg {
    /// The sheet to read when the file is a workbook (XLSX); default: the first.
    #[arg(long, value_name = "NAME")]
    sheet: Option<String>,
}

impl SheetArg {
    pub fn name(&self) -> Option<&str> {
        self.sheet.as_deref()
    }
}
