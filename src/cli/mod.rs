//! Command-line front end: parses arguments, calls the library, prints results.

pub mod campaign;
pub mod compensate;
pub mod cross;
pub mod diagnose;
pub mod eval;
pub mod geometry;
pub mod other_tool;
pub mod plan;
pub mod reproduce;
pub mod simulate;
pub mod tables;
pub mod text;
#[cfg(feature = "parquet")]
pub mod trend;
pub mod verify;

/// `--json` output of `diagnose` and `verify`: `value`'s JSON, then the input file's name.
pub fn json_with_file<T: serde::Serialize>(value: &T, file: &str) -> serde_json::Result<String> {
    let with = axcheck::one_file::WithFile { value, file };
    Ok(serde_json::to_string_pretty(&with)? + "\n")
}

/// `--sheet NAME` and `--ecmc-reference N`: what to read of a file.
///
/// The ecmc option is not `--reference`: `compensate` has its own `--reference POS`, the
/// table's reference point, and one name for two options made clap hand the position to
/// this one. `eval` and `diagnose`, which have no reference point, keep `--reference` as an
/// alias ([`REFERENCE_ALIAS`]).
#[derive(clap::Args, Debug, Clone, Default)]
pub struct SheetArg {
    /// The sheet to read when the file is a workbook (XLSX); default: the first.
    #[arg(long, value_name = "NAME")]
    sheet: Option<String>,
    /// The position source of an ecmc ISO 230 app file: reference 1 to 5, or `rbv` (the
    /// motor's readback); default: the reference the app evaluated.
    #[arg(long, value_name = "N|rbv", value_parser = axcheck::measurement::Source::parse)]
    ecmc_reference: Option<axcheck::measurement::Source>,
}

/// The id of `--ecmc-reference`, for commands that add `--reference` as its alias.
pub const ECMC_REFERENCE: &str = "ecmc_reference";

/// `--ecmc-reference`'s older name, kept where no other option has it.
pub const REFERENCE_ALIAS: &str = "reference";

impl SheetArg {
    /// The sheet and the reference, as the readers take them.
    pub fn options(&self) -> axcheck::measurement::ReadOptions<'_> {
        axcheck::measurement::ReadOptions {
            sheet: self.sheet.as_deref(),
            source: self.ecmc_reference,
            ..Default::default()
        }
    }

    /// Whether `--ecmc-reference` was given.
    pub fn names_source(&self) -> bool {
        self.ecmc_reference.is_some()
    }
}

/// `--standard`: a standard's key.
pub fn parse_standard(text: &str) -> Result<axcheck::evaluate::StandardId, String> {
    axcheck::evaluate::StandardId::parse(text).ok_or_else(|| {
        format!(
            "unknown standard `{text}`; expected iso230-2, gbt17421.2, gost27843, vdi3441 or nmtba"
        )
    })
}

/// Prints to stdout, hidden characters from input shown as `\uXXXX` (so a name cannot
/// clear the screen or reverse a line; in `--json` output the escape is JSON's own, the
/// strings unchanged); a closed pipe (`| head`) is not an error.
pub fn print(text: &str) -> anyhow::Result<()> {
    use std::io::Write;
    let text = axcheck::safe_text::visible(text);
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|_| out.flush()) {
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        other => Ok(other?),
    }
}

/// Prints `line` and a line break to stdout, hidden characters shown.
pub fn say(line: &str) {
    println!("{}", axcheck::safe_text::visible(line));
}

/// Prints `line` and a line break to stderr, hidden characters shown.
pub fn tell(line: &str) {
    eprintln!("{}", axcheck::safe_text::visible(line));
}

/// `--jobs` bounded by the machine's threads: more workers than threads only wait for one
/// another and each takes a 64 MB stack (`--jobs 100000` started 15 813 threads and ran 13
/// minutes); 0 stays 0 (one per thread). A capped value is said on stderr.
pub fn capped_jobs(requested: usize) -> usize {
    let threads = std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get);
    if requested <= threads {
        return requested;
    }
    eprintln!(
        "axcheck: note: --jobs {requested} is more than the machine's {threads} threads; using {threads}"
    );
    threads
}

/// `--thermal-origin`: a finite position (mm or deg), negative ones included.
pub fn parse_position(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(p) if p.is_finite() => Ok(p),
        _ => Err(format!(
            "`{text}` is not a position; a position is a number (mm, or deg for a rotary axis), such as 0 or -120"
        )),
    }
}

/// `--pitch` and `--scale-pitch`: a positive, finite length (mm or deg). Negative values
/// reach this parser (`allow_negative_numbers`), so that `--pitch -5` is refused for its
/// sign instead of as an unknown argument.
pub fn parse_pitch(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(p) if p.is_finite() && p > 0.0 => Ok(p),
        Ok(_) => Err(format!(
            "the pitch is {text}; a pitch is a positive length (mm, or deg for a rotary axis), such as 5 or 10"
        )),
        Err(_) => Err(format!(
            "`{text}` is not a number; a pitch is a positive length (mm, or deg for a rotary axis), such as 5 or 10"
        )),
    }
}
