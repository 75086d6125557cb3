//! The ecmc ISO 230 app's Markdown report: `# ecmc ISO 230 Bidirectional Positioning
//! Report`, then `## Status` (the app's results), `## Configuration` (targets, cycles,
//! references, samples per point …), `## Notes` (its formulas), `## Raw Measured Points`
//! (one row per point of the reference the app evaluated, with the readback) and, when
//! other references were recorded, `## Appendix: Additional Reference PVs` with a table per
//! reference (`### Ref N: \`PV\``).
//!
//! The raw table is checked against the Configuration: its targets are the listed
//! `Targets`, and it holds `Cycles` × targets × 2 points; a report cut short or whose
//! targets disagree is refused with the line.

use super::reported::{results, status_item};
use super::{
    Point, Source, Transform, cycle, direction_at, error, notes, number, readings, timestamp,
};
use crate::measurement::reported::{Reported, ToolResults};
use crate::measurement::{AxisData, Lines, ReadError};
use crate::units::AxisKind;
use std::io::BufRead;

/// The report's first line.
pub(crate) const TITLE: &str = "# ecmc ISO 230 Bidirectional Positioning Report";

/// Whether `head` starts as the app's report (blank lines and a BOM before it allowed).
pub fn looks_like(head: &[u8]) -> bool {
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    let first = head
        .split(|&b| b == b'\n')
        .map(<[u8]>::trim_ascii)
        .find(|l| !l.is_empty());
    first == Some(TITLE.as_bytes())
}

/// A Markdown table: its header's cells and its rows, each with its line.
#[derive(Debug, Default)]
struct Table {
    header: Vec<String>,
    rows: Vec<(usize, Vec<String>)>,
    /// The line of the header, and of the table's last line.
    header_line: usize,
    last_line: usize,
}

impl Table {
    fn column(&self, names: &[&str]) -> Option<usize> {
        self.header.iter().position(|h| names.contains(&h.as_str()))
    }
}

/// The report as read, before its points are chosen.
#[derive(Debug, Default)]
struct Report {
    status: Vec<Reported>,
    state: Option<String>,
    /// Configuration items: label, value, line.
    config: Vec<(String, String, usize)>,
    formulas: Vec<String>,
    /// The raw table of the evaluated reference.
    main: Option<Table>,
    /// Other references' tables: their number (1-based) and table.
    appendix: Vec<(u8, Table)>,
}

impl Report {
    fn config(&self, label: &str) -> Option<(&str, usize)> {
        let item = self.config.iter().find(|(l, _, _)| l == label);
        item.map(|(_, v, line)| (v.as_str(), *line))
    }
}

/// Reads a report: the points of `source` as a linear axis, the notes, and the app's own
/// results when `source` is the reference they were computed from.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
    source: Source,
) -> Result<(AxisData, Vec<String>, Option<ToolResults>), ReadError> {
    let report = parse(reader, file)?;
    let (table, columns, transform, name) = choose(&report, source, file)?;
    let points = points(table, &columns, transform, file)?;
    check_plan(&report, &points, table, file)?;
    let mut notes = notes(&name, transform, &points);
    if let Some(state) = report.state.as_deref().filter(|s| *s != "Complete") {
        notes.push(format!("the report's state is `{state}`, not `Complete`"));
    }
    let own = source == Source::Selected || columns.evaluated;
    let tool = match own {
        true => {
            let decimals = printed_decimals(table, &columns);
            results(report.status, report.state, report.formulas, decimals)
        }
        false => {
            notes.push(format!(
                "the app's own results are of the reference it evaluated, not of {}: not compared",
                source.describe()
            ));
            None
        }
    };
    let raw = readings(&points, file)?;
    let data = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), file)?;
    Ok((data, notes, tool))
}

/// Splits the report into its sections' items and tables.
fn parse<R: BufRead>(reader: R, file: &str) -> Result<Report, ReadError> {
    let mut lines = Lines::new(reader, file);
    let mut report = Report::default();
    let mut section = String::new();
    let mut table: Option<(Option<u8>, Table)> = None;
    while let Some((number, line)) = lines.next_line()? {
        let text = line.trim();
        if let Some(name) = text.strip_prefix("## ") {
            finish(&mut report, table.take());
            section = name.trim().to_string();
        } else if let Some(rest) = text.strip_prefix("### Ref ") {
            finish(&mut report, table.take());
            let slot = rest.split(':').next().and_then(|n| n.trim().parse().ok());
            table = slot.map(|n| (Some(n), Table::default()));
        } else if text.starts_with('|') && (section == "Raw Measured Points" || table.is_some()) {
            let (_, t) = table.get_or_insert_with(|| (None, Table::default()));
            add_row(t, number, text);
        } else if let Some(item) = text.strip_prefix("- ") {
            list_item(&mut report, &section, item, number);
        }
    }
    finish(&mut report, table);
    Ok(report)
}

/// Files a finished table as the main one or a reference's.
fn finish(report: &mut Report, table: Option<(Option<u8>, Table)>) {
    match table {
        Some((None, t)) if report.main.is_none() => report.main = Some(t),
        Some((Some(n), t)) => report.appendix.push((n, t)),
        _ => {}
    }
}

/// A table line: the header, the `| --- |` rule (skipped) or a row.
fn add_row(table: &mut Table, number: usize, text: &str) {
    let inner = text.trim_start_matches('|').trim_end_matches('|');
    let cells: Vec<String> = inner.split('|').map(|c| c.trim().to_string()).collect();
    table.last_line = number;
    if table.header.is_empty() {
        table.header = cells;
        table.header_line = number;
    } else if !cells
        .iter()
        .all(|c| !c.is_empty() && c.chars().all(|ch| ch == '-' || ch == ':'))
    {
        table.rows.push((number, cells));
    }
}

/// `Label: \`value\`` in the Status or Configuration list, or a line of the Notes.
fn list_item(report: &mut Report, section: &str, item: &str, number: usize) {
    let labelled = item.split_once(": ").map(|(l, v)| {
        let v = v.trim();
        let v = v
            .strip_prefix('`')
            .and_then(|v| v.strip_suffix('`'))
            .unwrap_or(v);
        (l.trim().to_string(), v.to_string())
    });
    match (section, labelled) {
        ("Status", Some((label, value))) if label == "State" => report.state = Some(value),
        ("Status", Some((label, value))) => {
            report.status.extend(status_item(&label, &value, number));
        }
        ("Configuration", Some((label, value))) => report.config.push((label, value, number)),
        ("Notes", _) => report.formulas.push(item.trim().to_string()),
        _ => {}
    }
}

/// Where the chosen source's values are in a table.
struct Columns {
    /// The error as written, or the raw mean to transform.
    error: Option<usize>,
    mean: Option<usize>,
    std: Option<usize>,
    /// Whether the table is the one the app evaluated.
    evaluated: bool,
}

/// The table, columns, transform and name of `source`.
fn choose<'r>(
    report: &'r Report,
    source: Source,
    file: &str,
) -> Result<(&'r Table, Columns, Transform, String), ReadError> {
    let main = report.main.as_ref().ok_or_else(|| {
        error(
            file,
            0,
            "no `## Raw Measured Points` table: the report holds no points to evaluate".into(),
        )
    })?;
    let selected = report.config("Reference used for report calculations");
    let selected_pv = selected.map_or("", |(pv, _)| pv);
    let transform = transform(report, file)?;
    let reference = |t: &Table, evaluated| Columns {
        error: t.column(&["Raw Ref Err", "Ref Err"]),
        mean: t.column(&["Raw Ref Mean", "Ref Mean"]),
        std: t.column(&["Raw Ref Std", "Ref Std"]),
        evaluated,
    };
    match source {
        Source::Readback => {
            let columns = Columns {
                error: main.column(&["RBV Err"]),
                mean: None,
                std: main.column(&["RBV Std"]),
                evaluated: false,
            };
            Ok((main, columns, Transform::NONE, "the readback (RBV)".into()))
        }
        Source::Selected => Ok((main, reference(main, true), transform, named(selected_pv))),
        Source::Reference(n) => {
            let pv = configured_pv(report, n);
            if pv.is_some_and(|pv| pv == selected_pv) {
                let name = format!("{} (Ref {n})", named(selected_pv));
                return Ok((main, reference(main, true), transform, name));
            }
            let found = report.appendix.iter().find(|(k, _)| *k == n);
            let (_, table) = found.ok_or_else(|| {
                error(file, 0, format!("reference {n} was not recorded in this report (no `### Ref {n}` table); the report has {}", available(report)))
            })?;
            let name = format!("{} (Ref {n})", named(pv.unwrap_or("")));
            Ok((table, reference(table, false), transform, name))
        }
    }
}

/// `reference \`PV\``, as the notes name it.
fn named(pv: &str) -> String {
    match pv {
        "" => "the reference the app evaluated".into(),
        pv => format!("reference `{pv}`"),
    }
}

/// The PV of reference `n` in `Configured reference PVs: \`Ref 1=PV, Ref 2=PV\``.
fn configured_pv(report: &Report, n: u8) -> Option<&str> {
    let (list, _) = report.config("Configured reference PVs")?;
    let prefix = format!("Ref {n}=");
    list.split(", ")
        .find_map(|item| item.strip_prefix(prefix.as_str()))
}

/// The references a report holds, for messages.
fn available(report: &Report) -> String {
    match report.config("Configured reference PVs") {
        Some((list, _)) if !list.is_empty() => list.to_string(),
        _ => "only the reference it evaluated".into(),
    }
}

/// `Reference gain` and `Reference offset` (absent before the app had them: none).
fn transform(report: &Report, file: &str) -> Result<Transform, ReadError> {
    let value = |label: &str, default: f64| match report.config(label) {
        None => Ok(default),
        Some((text, line)) => number(text, label, file, line),
    };
    Ok(Transform {
        gain: value("Reference gain", 1.0)?,
        offset: value("Reference offset", 0.0)?,
    })
}

/// The table's rows as points.
fn points(
    table: &Table,
    columns: &Columns,
    transform: Transform,
    file: &str,
) -> Result<Vec<Point>, ReadError> {
    let need = |names: &[&str], what: &str| {
        table.column(names).ok_or_else(|| {
            let header = table.header.join(" | ");
            error(
                file,
                table.header_line,
                format!("the table has no `{what}` column (header: {header})"),
            )
        })
    };
    let cycle_col = need(&["Cycle"], "Cycle")?;
    let dir = need(&["Direction"], "Direction")?;
    let target = need(&["Target"], "Target")?;
    let time = table.column(&["Timestamp"]);
    let value = match (transform.is_none(), columns.error, columns.mean) {
        (true, Some(e), _) => Value::Error(e),
        (_, _, Some(m)) => Value::Mean(m),
        _ => {
            return Err(error(
                file,
                table.header_line,
                "the table has neither the error nor the mean of the reference chosen".into(),
            ));
        }
    };
    let mut out = Vec::with_capacity(table.rows.len());
    for (line, cells) in &table.rows {
        let cell = |k: usize, what: &str| {
            cells.get(k).map(String::as_str).ok_or_else(|| {
                error(
                    file,
                    *line,
                    format!(
                        "the row has {} cells, the header {}: no `{what}`",
                        cells.len(),
                        table.header.len()
                    ),
                )
            })
        };
        let number = |k: usize, what: &str| number(cell(k, what)?, what, file, *line);
        let cycle_n = cycle(cell(cycle_col, "Cycle")?, "Cycle", file, *line)?;
        let direction = direction_at(cell(dir, "Direction")?, "Direction", file, *line)?;
        let target_value = number(target, "Target")?;
        let error_value = match value {
            Value::Error(k) => number(k, &table.header[k])?,
            Value::Mean(k) => transform.error(number(k, &table.header[k])?, target_value),
        };
        out.push(Point {
            cycle: cycle_n,
            direction,
            target: target_value,
            error: error_value,
            std: columns.std.and_then(|k| number(k, "Std").ok()),
            time: time.and_then(|k| cells.get(k)).and_then(|t| timestamp(t)),
            line: *line,
        });
    }
    Ok(out)
}

/// The most digits after the point among the table's values of the chosen source.
fn printed_decimals(table: &Table, columns: &Columns) -> u32 {
    let used = [columns.error, columns.mean, table.column(&["Target"])];
    let decimals = |text: &str| text.split_once('.').map_or(0, |(_, d)| d.len() as u32);
    (table.rows.iter())
        .flat_map(|(_, cells)| used.iter().flatten().filter_map(|&k| cells.get(k)))
        .map(|c| decimals(c))
        .max()
        .unwrap_or(0)
}

#[derive(Clone, Copy)]
enum Value {
    Error(usize),
    Mean(usize),
}

/// The points are the Configuration's plan: its targets, `Cycles` × targets × 2 points.
fn check_plan(
    report: &Report,
    points: &[Point],
    table: &Table,
    file: &str,
) -> Result<(), ReadError> {
    if let Some((list, line)) = report.config("Targets") {
        let planned = parse_list(list).map_err(|bad| {
            error(
                file,
                line,
                format!("`Targets`: expected numbers separated by commas, found `{bad}`"),
            )
        })?;
        check_targets(&planned, line, points, file)?;
        if let Some((cycles, cycles_line)) = report.config("Cycles") {
            let cycles: usize = cycles.trim().parse().map_err(|_| {
                error(
                    file,
                    cycles_line,
                    format!("`Cycles`: expected a whole number, found `{cycles}`"),
                )
            })?;
            let expected = cycles * planned.len() * 2;
            if points.len() < expected {
                return Err(error(
                    file,
                    table.last_line,
                    format!(
                        "the Raw Measured Points table ends here after {} of {expected} points ({cycles} cycles × {} targets × 2 directions, lines {cycles_line} and {line}): the report is cut short",
                        points.len(),
                        planned.len()
                    ),
                ));
            }
            if points.len() > expected {
                return Err(error(
                    file,
                    table.last_line,
                    format!(
                        "the Raw Measured Points table holds {} points, but the Configuration plans {expected} ({cycles} cycles × {} targets × 2 directions, lines {cycles_line} and {line})",
                        points.len(),
                        planned.len()
                    ),
                ));
            }
        }
    }
    Ok(())
}

fn parse_list(list: &str) -> Result<Vec<f64>, String> {
    list.split(',')
        .map(|t| {
            t.trim()
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| t.trim().to_string())
        })
        .collect()
}

/// Every point's target is planned, and every planned target is measured.
fn check_targets(
    planned: &[f64],
    line: usize,
    points: &[Point],
    file: &str,
) -> Result<(), ReadError> {
    let same = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0);
    if let Some(p) = points
        .iter()
        .find(|p| !planned.iter().any(|&t| same(t, p.target)))
    {
        return Err(error(
            file,
            p.line,
            format!(
                "target {} is not among the Configuration's `Targets` (line {line}): the table and the configuration disagree",
                p.target
            ),
        ));
    }
    if let Some(t) = planned
        .iter()
        .find(|&&t| !points.iter().any(|p| same(t, p.target)))
    {
        return Err(error(
            file,
            line,
            format!(
                "the Configuration's `Targets` list {t}, which the Raw Measured Points table never measures: the table and the configuration disagree"
            ),
        ));
    }
    Ok(())
}
