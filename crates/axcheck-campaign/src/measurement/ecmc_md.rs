//! The ecmc motion system test reports of 2021 (`# ecmc motion system test report`,
//! Markdown, written by the ecmc ISO 230-2 scripts of anderssandstrom/ecmccomgui), the
//! reports ESS wrote before the ecmc ISO 230 app. Two forms hold a positioning test:
//!
//! - 2021-10: `# Forward test sequence` and `# Backward test sequence`, one row per reading
//!   (`i (pos id)| j (cycle)| Tgt_pos(i,j) [mm] | … | x(i,j) (diff ref-tgt), [mm]`, or the
//!   older column order `Cycle (j)| Pos (i)| Tgt Pos [mm] | …`), the deviation x(i,j) read
//!   as written;
//! - 2021-11: `# ISO 230-2 motion test` with `### Data forward direction` and `### Data
//!   backward direction`, one row per target (`i |tgt_pos(i) [mm]|ref_pos(i,1) [mm]|…`), the
//!   deviation ref_pos − tgt_pos. The script that wrote this form (`ecmcISO230_2.py`) stores
//!   the input's forward readings (the approach from below) as its backward data, so its
//!   "forward" table holds the approach from above: axcheck reads each table as the
//!   direction its readings were taken in, and says so.
//!
//! Both print the script's results as `NAME = value [mm]` lines (B, B_avg, R_fwd, R_bwd, R,
//! E_fwd, E_bwd, E, M, A_fwd, A_bwd, A), kept for [`crate::crosscheck`]. Numbers may be
//! written with a leading dot (`.00742`, from `bc`).

use super::ecmc_app::error;
use super::reported::{Family, Reported, ReportedQuantity, ToolResults};
use super::{AxisData, Lines, RawReading, ReadError};
use crate::param_key::ParamKey;
use crate::units::{AxisKind, Direction};
use std::io::BufRead;

/// The report's first line.
pub(crate) const TITLE: &str = "# ecmc motion system test report";

/// The scripts, as the comparison names them.
const TOOL: &str = "ecmc ISO 230-2 scripts (2021)";

/// The results the scripts print, and the quantity each names (by the report's own
/// words: `R_fwd = Forward unidirectional positioning repeatability of an axis`).
const RESULTS: &[(&str, ReportedQuantity)] = &[
    ("B", ReportedQuantity::Parameter(ParamKey::B)),
    ("B_avg", ReportedQuantity::Parameter(ParamKey::BMean)),
    ("R_fwd", ReportedQuantity::Parameter(ParamKey::RUp)),
    ("R_bwd", ReportedQuantity::Parameter(ParamKey::RDown)),
    ("R", ReportedQuantity::Parameter(ParamKey::R)),
    ("E_fwd", ReportedQuantity::Parameter(ParamKey::EUp)),
    ("E_bwd", ReportedQuantity::Parameter(ParamKey::EDown)),
    ("E", ReportedQuantity::Parameter(ParamKey::E)),
    ("M", ReportedQuantity::Parameter(ParamKey::M)),
    ("A_fwd", ReportedQuantity::Parameter(ParamKey::AUp)),
    ("A_bwd", ReportedQuantity::Parameter(ParamKey::ADown)),
    ("A", ReportedQuantity::Parameter(ParamKey::A)),
];

/// Whether `head` starts as such a report.
pub fn looks_like(head: &[u8]) -> bool {
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let first = (head.split(|&b| b == b'\n'))
        .map(<[u8]>::trim_ascii)
        .find(|l| !l.is_empty());
    first == Some(TITLE.as_bytes())
}

/// Which table a row belongs to.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Part {
    /// A 2021-10 sequence table of `direction`.
    Sequence(Direction),
    /// A 2021-11 data table headed `forward` (`true`) or `backward`.
    Wide {
        labelled_forward: bool,
    },
    Other,
}

/// The report as read: its readings, the results, the largest number of decimals of the
/// readings.
#[derive(Default)]
struct Read {
    raw: Vec<RawReading>,
    results: Vec<Reported>,
    decimals: u32,
    wide: bool,
    /// The column names of the table being read.
    header: Vec<String>,
}

/// Reads a report: its readings as a linear axis in µm, the notes, the scripts' results.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
) -> Result<(AxisData, Vec<String>, Option<ToolResults>), ReadError> {
    let mut lines = Lines::new(reader, file);
    let mut read = Read::default();
    let mut part = Part::Other;
    while let Some((number, line)) = lines.next_line()? {
        let text = line.trim();
        if text.starts_with('#') {
            part = heading(text, part);
            read.header.clear();
        } else if text.contains('|') && part != Part::Other {
            table_line(&mut read, part, text, number, file)?;
        } else if let Some(r) = result_line(text, number)
            && !read.results.iter().any(|x| x.label == r.label)
        {
            // The first of each: later sections (limit switches) reuse no names, but a
            // result printed twice keeps its first value.
            read.results.push(r);
        }
    }
    if read.raw.is_empty() {
        return Err(error(file, 0, "this ecmc report holds no positioning test: no `# Forward test sequence` or `### Data forward direction` table".into()));
    }
    let mut notes = vec![
        "an ecmc motion system test report of 2021; deviations as the report gives them: reference − target, mm".to_string(),
    ];
    if read.wide {
        notes.push("its table headed \"Data forward direction\" holds the approach from above and \"Data backward direction\" the approach from below (ecmcISO230_2.py, which wrote it, swaps the input's directions): read as the approaches they are".into());
    }
    notes.push("no time stamps: the readings are taken in the standard test cycle's order".into());
    let raw = std::mem::take(&mut read.raw);
    let data = AxisData::from_raw(AxisKind::Linear, in_cycle_order(raw), Vec::new(), file)?;
    let tool = (!read.results.is_empty()).then(|| ToolResults {
        tool: TOOL.to_string(),
        family: Family::EcmcScripts,
        state: None,
        values: std::mem::take(&mut read.results),
        formulas: Vec::new(),
        readings_rounding: 0.5 * 10f64.powi(-(read.decimals as i32)) * 1000.0,
    });
    Ok((data, notes, tool))
}

/// The part a heading opens.
fn heading(text: &str, current: Part) -> Part {
    let title = text.trim_start_matches('#').trim().to_ascii_lowercase();
    match title.as_str() {
        "forward test sequence" => Part::Sequence(Direction::Up),
        "backward test sequence" => Part::Sequence(Direction::Down),
        "data forward direction" => Part::Wide {
            labelled_forward: true,
        },
        "data backward direction" => Part::Wide {
            labelled_forward: false,
        },
        // Sub-headings inside the ISO test's input (`## Input data`) keep nothing open.
        _ if text.starts_with("####") => current,
        _ => Part::Other,
    }
}

/// A line of a table: its header (kept), the `---` rule, or a row of readings.
fn table_line(
    read: &mut Read,
    part: Part,
    text: &str,
    number: usize,
    file: &str,
) -> Result<(), ReadError> {
    let cells: Vec<&str> = text
        .trim_end_matches('|')
        .split('|')
        .map(str::trim)
        .collect();
    if read.header.is_empty() {
        read.header = cells.iter().map(|c| c.to_ascii_lowercase()).collect();
        return Ok(());
    }
    if cells
        .iter()
        .all(|c| c.chars().all(|ch| ch == '-' || ch == ' '))
    {
        return Ok(());
    }
    match part {
        Part::Sequence(direction) => sequence_row(read, direction, &cells, number, file),
        Part::Wide { labelled_forward } => {
            read.wide = true;
            // The script swapped the directions: its "forward" table is the approach from above.
            let direction = if labelled_forward {
                Direction::Down
            } else {
                Direction::Up
            };
            wide_row(read, direction, &cells, number, file)
        }
        Part::Other => Ok(()),
    }
}

/// A number as the scripts write it (`.00742`, `-.01989`, `15.0`).
fn number(text: &str, column: &str, line: usize, file: &str) -> Result<f64, ReadError> {
    super::ecmc_app::number(text, column, file, line)
}

fn decimals(text: &str) -> u32 {
    text.trim()
        .split_once('.')
        .map_or(0, |(_, d)| d.len() as u32)
}

/// A 2021-10 row: position i, cycle j, target, …, x(i,j) (the last column).
fn sequence_row(
    read: &mut Read,
    direction: Direction,
    cells: &[&str],
    line: usize,
    file: &str,
) -> Result<(), ReadError> {
    let find = |starts: &[&str]| {
        read.header
            .iter()
            .position(|h| starts.iter().any(|s| h.starts_with(s)))
    };
    let (Some(cycle), Some(target), Some(x)) = (
        find(&["j (cycle)", "cycle (j)"]),
        find(&["tgt_pos", "tgt pos"]),
        find(&["x(i,j)", "diff ref-tgt"]),
    ) else {
        return Err(error(
            file,
            line,
            format!(
                "the sequence table's header lacks the cycle, the target or x(i,j): `{}`",
                read.header.join(" | ")
            ),
        ));
    };
    let cell = |k: usize| cells.get(k).copied().unwrap_or("");
    let run = super::ecmc_app::cycle(cell(cycle), "j (cycle)", file, line)?;
    let deviation_mm = number(cell(x), "x(i,j)", line, file)?;
    read.decimals = read.decimals.max(decimals(cell(x)));
    read.raw.push(RawReading {
        target: number(cell(target), "Tgt_pos", line, file)?,
        direction,
        run,
        deviation: deviation_mm * 1000.0,
        time_s: None,
        temps_c: Vec::new(),
        line,
    });
    Ok(())
}

/// A 2021-11 row: i, tgt_pos(i), ref_pos(i,1) … ref_pos(i,n).
fn wide_row(
    read: &mut Read,
    direction: Direction,
    cells: &[&str],
    line: usize,
    file: &str,
) -> Result<(), ReadError> {
    let target_text = cells.get(1).copied().unwrap_or("");
    let target = number(target_text, "tgt_pos(i)", line, file)?;
    for (j, text) in cells.iter().enumerate().skip(2) {
        let reference = number(text, &format!("ref_pos(i,{})", j - 1), line, file)?;
        read.decimals = read.decimals.max(decimals(text));
        read.raw.push(RawReading {
            target,
            direction,
            run: (j - 1) as u32,
            deviation: (reference - target) * 1000.0,
            time_s: None,
            temps_c: Vec::new(),
            line,
        });
    }
    Ok(())
}

/// `NAME = value [mm]` for a result the scripts print.
fn result_line(text: &str, line: usize) -> Option<Reported> {
    let (name, rest) = text.split_once(" = ")?;
    let (_, quantity) = RESULTS.iter().find(|(n, _)| *n == name.trim())?;
    let value_text = rest.split('[').next()?.trim();
    let value: f64 = value_text.parse().ok().filter(|x: &f64| x.is_finite())?;
    Some(Reported {
        label: name.trim().to_string(),
        quantity: *quantity,
        text: value_text.to_string(),
        value,
        decimals: decimals(value_text),
        unit: "mm",
        to_um: 1000.0,
        line,
    })
}

/// The readings in the standard test cycle's order (ISO 230-2 Figure 1): per cycle, up over
/// the targets ascending, then down descending; the reports list them by table.
fn in_cycle_order(mut raw: Vec<RawReading>) -> Vec<RawReading> {
    raw.sort_by(|a, b| {
        let key = |r: &RawReading| (r.run, r.direction == Direction::Down);
        key(a).cmp(&key(b)).then_with(|| match a.direction {
            Direction::Up => a.target.total_cmp(&b.target),
            Direction::Down => b.target.total_cmp(&a.target),
        })
    });
    raw
}
