//! Command-line front end: parses arguments, calls the library, prints results.

pub mod campaign;
pub mod compensate;
pub mod diagnose;
pub mod eval;
pub mod simulate;
pub mod text;
#[cfg(feature = "parquet")]
pub mod trend;

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
