//! `RUNS::` (`Run-count`) and `DEVIATIONS::` (`run target deviation` lines): the full
//! run × target matrix, read by the target column, turned into readings in the order they
//! were measured.

use super::targets::Targets;
use super::text::{Line, Section, shown};
use super::{ARCSEC_PER_MRAD, unused_keys};
use crate::measurement::error::{Location, ReadError, ReadErrorKind};
use crate::measurement::{MAX_DEVIATION, MAX_READINGS, RawReading, parse_number};
use crate::units::{AxisKind, Direction};

/// `Run-count` and its line.
#[derive(Debug, Clone, Copy)]
pub(super) struct RunCount {
    /// One-direction passes: 2 × cycles.
    pub count: usize,
    pub line: usize,
}

/// Reads `Run-count`: an even number ≥ 2 (each cycle is a pass out and a pass back), and
/// with the targets at most [`MAX_READINGS`] readings.
pub(super) fn run_count(
    section: &Section,
    targets: usize,
    file: &str,
    notes: &mut Vec<String>,
) -> Result<RunCount, ReadError> {
    let unused: Vec<String> = section
        .lines
        .iter()
        .filter(|l| l.key_value().is_none_or(|kv| kv.normal != "runcount"))
        .map(|l| shown(l.text()))
        .collect();
    unused_keys("RUNS", &unused, notes);
    let Some((line, value)) = section.lines.iter().find_map(|l| {
        l.key_value()
            .filter(|kv| kv.normal == "runcount")
            .map(|kv| (l, kv.value))
    }) else {
        return Err(ReadError::new(
            Location::line(file, section.line),
            ReadErrorKind::RenishawMissingKey {
                section: "RUNS::".into(),
                key: "Run-count".into(),
                expected: "`Run-count:N`, the number of one-direction passes".into(),
            },
        ));
    };
    let at = Location::at(file, line.number, line.column_of(value));
    let count: usize = value.parse().map_err(|_| {
        ReadError::new(
            at.clone(),
            ReadErrorKind::RenishawBadValue {
                key: "Run-count".into(),
                expected: "the number of one-direction passes, a whole number such as 10".into(),
                found: shown(value),
            },
        )
    })?;
    if count < 2 || count % 2 == 1 {
        return Err(ReadError::new(
            at,
            ReadErrorKind::Renishaw(format!(
                "Run-count is {count}: a bidirectional test has an even number of passes (2 per cycle, one out and one back), at least 2"
            )),
        ));
    }
    if count.checked_mul(targets).is_none_or(|r| r > MAX_READINGS) {
        return Err(ReadError::new(
            at,
            ReadErrorKind::TooManyReadings {
                limit: MAX_READINGS,
            },
        ));
    }
    Ok(RunCount {
        count,
        line: line.number,
    })
}

/// One deviation as written.
#[derive(Debug, Clone, Copy)]
struct Cell {
    /// In the file's unit (µm or mrad).
    value: f64,
    line: usize,
    column: usize,
    /// Position of the line within DEVIATIONS::, to tell the listing order.
    order: usize,
}

/// Reads DEVIATIONS:: into readings: every run lists every target once; odd runs move
/// along the target list, even runs back; cycle j holds runs 2j − 1 and 2j.
pub(super) fn read(
    section: &Section,
    targets: &Targets,
    runs: &RunCount,
    kind: AxisKind,
    file: &str,
    notes: &mut Vec<String>,
) -> Result<Vec<RawReading>, ReadError> {
    let m = targets.positions.len();
    let mut cells: Vec<Option<Cell>> = vec![None; runs.count * m];
    let mut caption = false;
    for (order, line) in section.lines.iter().enumerate() {
        if line
            .key_value()
            .is_some_and(|kv| kv.normal == "runtargetdata")
        {
            caption = true;
            continue;
        }
        let (run, target, cell) = triplet(line, order, targets, runs, file)?;
        let slot = &mut cells[(run - 1) * m + (target - 1)];
        if let Some(first) = slot {
            return Err(ReadError::new(
                Location::line(file, line.number),
                ReadErrorKind::RenishawDuplicateReading {
                    run: run as u32,
                    target,
                    position: targets.position(target),
                    first_line: first.line,
                },
            ));
        }
        *slot = Some(cell);
    }
    if !caption {
        notes.push(
            "no `Run Target Data:` line; every line of DEVIATIONS:: read as a reading".into(),
        );
    }
    let cells = complete(cells, section, targets, runs, file)?;
    check_even_runs(&cells, m, targets, file, notes)?;
    note_listing_order(&cells, m, notes);
    readings(&cells, targets, kind, file)
}

/// One `run target deviation` line: three fields, run and target in range.
fn triplet(
    line: &Line,
    order: usize,
    targets: &Targets,
    runs: &RunCount,
    file: &str,
) -> Result<(usize, usize, Cell), ReadError> {
    let fields: Vec<&str> = line.raw.split_whitespace().take(4).collect();
    let [run_text, target_text, value_text] = fields[..] else {
        return Err(ReadError::new(
            Location::line(file, line.number),
            ReadErrorKind::Renishaw(format!(
                "expected a deviation line `run target deviation` such as `1  3  -0.250`, found `{}`",
                shown(line.text())
            )),
        ));
    };
    let at = |text: &str| Location::at(file, line.number, line.column_of(text));
    let index = |text: &str| text.parse::<usize>().ok().filter(|&k| k >= 1);
    let run = index(run_text).ok_or_else(|| {
        let message = format!(
            "expected a run number 1, 2, … in the first column, found `{}`",
            shown(run_text)
        );
        ReadError::new(at(run_text), ReadErrorKind::Renishaw(message))
    })?;
    if run > runs.count {
        return Err(ReadError::new(
            at(run_text),
            ReadErrorKind::RenishawRunCount {
                said: runs.count,
                found: format!(
                    "this line is of run {run} (Run-count is on line {})",
                    runs.line
                ),
            },
        ));
    }
    let m = targets.positions.len();
    let target = index(target_text).filter(|&t| t <= m).ok_or_else(|| {
        let message = format!(
            "run {run}: expected a target number 1 … {m} (Target-count) in the second column, found `{}`",
            shown(target_text)
        );
        ReadError::new(at(target_text), ReadErrorKind::Renishaw(message))
    })?;
    let value = parse_number(value_text, false).map_err(|_| {
        let message = format!(
            "run {run} target {target} ({}): the deviation `{}` is not a number; expected e.g. `-0.250`",
            targets.position(target),
            shown(value_text)
        );
        ReadError::new(at(value_text), ReadErrorKind::Renishaw(message))
    })?;
    let cell = Cell {
        value,
        line: line.number,
        column: line.column_of(value_text),
        order,
    };
    Ok((run, target, cell))
}

/// The matrix with every cell filled: a run that is absent altogether means Run-count
/// disagrees with the deviations; a run with a gap misses a reading.
fn complete(
    cells: Vec<Option<Cell>>,
    section: &Section,
    targets: &Targets,
    runs: &RunCount,
    file: &str,
) -> Result<Vec<Cell>, ReadError> {
    let m = targets.positions.len();
    let present: Vec<u32> = (0..runs.count)
        .filter(|r| cells[r * m..(r + 1) * m].iter().any(Option::is_some))
        .map(|r| r as u32 + 1)
        .collect();
    if present.len() < runs.count {
        let readings = cells.iter().filter(|c| c.is_some()).count();
        let found = if present.is_empty() {
            "DEVIATIONS:: holds no readings".to_string()
        } else {
            format!(
                "DEVIATIONS:: holds runs {} only ({readings} readings; expected {} × {m} = {})",
                crate::measurement::list(&present),
                runs.count,
                runs.count * m
            )
        };
        return Err(ReadError::new(
            Location::line(file, runs.line),
            ReadErrorKind::RenishawRunCount {
                said: runs.count,
                found,
            },
        ));
    }
    let mut out = Vec::with_capacity(cells.len());
    for (k, cell) in cells.into_iter().enumerate() {
        let Some(cell) = cell else {
            let (run, target) = (k / m + 1, k % m + 1);
            let last = section.lines.last().map_or(section.line, |l| l.number);
            return Err(ReadError::new(
                Location::line(file, last),
                ReadErrorKind::RenishawMissingReading {
                    run: run as u32,
                    target,
                    position: targets.position(target),
                },
            ));
        };
        out.push(cell);
    }
    Ok(out)
}

/// Every return pass all zeros is a one-direction test as one writer stores it (the
/// return passes filled with 0): refused, as ISO 230-2 needs both directions. A single
/// all-zero return pass is noted.
fn check_even_runs(
    cells: &[Cell],
    m: usize,
    targets: &Targets,
    file: &str,
    notes: &mut Vec<String>,
) -> Result<(), ReadError> {
    let zero_runs: Vec<u32> = (1..=cells.len() / m)
        .filter(|r| r % 2 == 0 && cells[(r - 1) * m..r * m].iter().all(|c| c.value == 0.0))
        .map(|r| r as u32)
        .collect();
    let even_runs = cells.len() / m / 2;
    if zero_runs.is_empty() {
        return Ok(());
    }
    if zero_runs.len() == even_runs && m > 1 {
        let flags = targets
            .flags
            .as_deref()
            .map_or(String::new(), |f| format!(" (Flags: {})", shown(f)));
        return Err(ReadError::new(
            Location::line(file, first_line(cells, zero_runs[0] as usize, m)),
            ReadErrorKind::Renishaw(format!(
                "every return run ({}) reads 0 at every target{flags}: this looks like a one-direction test; every target must be approached from both directions (ISO 230-2 clause 2.2, 4.3)",
                crate::measurement::list(&zero_runs)
            )),
        ));
    }
    notes.push(format!(
        "run(s) {} read exactly 0 at every target; check that they were measured",
        crate::measurement::list(&zero_runs)
    ));
    Ok(())
}

/// The first line of run `run` in the file.
fn first_line(cells: &[Cell], run: usize, m: usize) -> usize {
    cells[(run - 1) * m..run * m]
        .iter()
        .map(|c| c.line)
        .min()
        .unwrap_or(0)
}

/// Notes runs not listed in the order they were measured (odd runs from target 1 up,
/// even runs from the last target down); they are read by the target column anyway.
fn note_listing_order(cells: &[Cell], m: usize, notes: &mut Vec<String>) {
    let other: Vec<u32> = (1..=cells.len() / m)
        .filter(|&r| {
            let run = &cells[(r - 1) * m..r * m];
            let forward = run.windows(2).all(|w| w[0].order < w[1].order);
            let backward = run.windows(2).all(|w| w[0].order > w[1].order);
            if r % 2 == 1 { !forward } else { !backward }
        })
        .map(|r| r as u32)
        .collect();
    if !other.is_empty() {
        notes.push(format!(
            "run(s) {} not listed in the order of the pass (odd runs from target 1, even runs from the last target down); read by their target column",
            crate::measurement::list(&other)
        ));
    }
}

/// The readings in the order they were measured: run by run, each pass in its direction.
fn readings(
    cells: &[Cell],
    targets: &Targets,
    kind: AxisKind,
    file: &str,
) -> Result<Vec<RawReading>, ReadError> {
    let m = targets.positions.len();
    let factor = match kind {
        AxisKind::Linear => 1.0,
        AxisKind::Rotary => ARCSEC_PER_MRAD,
    };
    let (first, second) = if targets.ascending {
        (Direction::Up, Direction::Down)
    } else {
        (Direction::Down, Direction::Up)
    };
    let mut out = Vec::with_capacity(cells.len());
    for r in 1..=cells.len() / m {
        let outward = r % 2 == 1;
        let order: Box<dyn Iterator<Item = usize>> = if outward {
            Box::new(0..m)
        } else {
            Box::new((0..m).rev())
        };
        for i in order {
            let cell = cells[(r - 1) * m + i];
            let deviation = cell.value * factor;
            if deviation.abs() > MAX_DEVIATION {
                return Err(implausible(&cell, r, i + 1, targets, kind, file));
            }
            out.push(RawReading {
                target: targets.positions[i],
                direction: if outward { first } else { second },
                run: r.div_ceil(2) as u32,
                deviation,
                time_s: None,
                temps_c: Vec::new(),
                line: cell.line,
            });
        }
    }
    Ok(out)
}

fn implausible(
    cell: &Cell,
    run: usize,
    target: usize,
    targets: &Targets,
    kind: AxisKind,
    file: &str,
) -> ReadError {
    let unit = match kind {
        AxisKind::Linear => "µm",
        AxisKind::Rotary => "mrad",
    };
    let limit = match kind {
        AxisKind::Linear => MAX_DEVIATION,
        AxisKind::Rotary => MAX_DEVIATION / ARCSEC_PER_MRAD,
    };
    ReadError::new(
        Location::at(file, cell.line, cell.column),
        ReadErrorKind::Renishaw(format!(
            "run {run} target {target} ({}): a deviation of {} {unit} is not plausible (more than {limit:.0} {unit}); the file may be corrupt",
            targets.position(target),
            cell.value
        )),
    )
}
