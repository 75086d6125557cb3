//! `TARGET DATA::`: `Target-count`, the positions after `Targets :` (wrapped, usually 5 a
//! line) up to `Flags:`, and the order of the list, which gives the direction of odd runs.

use super::text::{Line, Section, shown};
use super::unused_keys;
use crate::measurement::error::{Location, ReadError, ReadErrorKind};
use crate::measurement::{MAX_READINGS, fmt_target, parse_number};
use crate::units::AxisKind;

/// The target list as read.
#[derive(Debug, Clone)]
pub(super) struct Targets {
    /// P_1 … P_m in list order (mm or degrees): the 1-based target index of DEVIATIONS.
    pub positions: Vec<f64>,
    /// The line each position is on.
    pub lines: Vec<usize>,
    /// True when the list rises (odd runs move up, ↑); a single target counts as rising.
    pub ascending: bool,
    /// Positions per line when every full line holds the same number.
    pub(crate) per_line: Option<usize>,
    /// `Filetype` (e.g. `ISO`).
    pub(crate) test_type: Option<String>,
    /// `Flags` as written.
    pub flags: Option<String>,
    pub kind: AxisKind,
}

impl Targets {
    /// Target `index` (1-based) with its position, for messages: `7 (250 mm)`.
    pub fn position(&self, index: usize) -> String {
        self.positions
            .get(index.wrapping_sub(1))
            .map_or_else(String::new, |&p| fmt_target(self.kind, p))
    }
}

/// Where a line falls relative to the `Targets :` block.
#[derive(PartialEq)]
enum Block {
    Before,
    Inside,
    After,
}

/// Reads TARGET DATA:: and checks the list: as many positions as `Target-count`, every one
/// a number, rising or falling strictly.
pub(super) fn read(
    section: &Section,
    kind: AxisKind,
    file: &str,
    notes: &mut Vec<String>,
) -> Result<Targets, ReadError> {
    let mut out = Targets {
        positions: Vec::new(),
        lines: Vec::new(),
        ascending: true,
        per_line: None,
        test_type: None,
        flags: None,
        kind,
    };
    let mut count: Option<(usize, usize)> = None;
    let mut targets_line = None;
    let mut per_line = Vec::new();
    let mut unused = Vec::new();
    let mut block = Block::Before;
    for line in &section.lines {
        let key_value = line
            .key_value()
            .filter(|kv| parse_number(kv.key, false).is_err());
        if block == Block::Inside && key_value.is_none() {
            let before = out.positions.len();
            positions(line, line.raw, &mut out, file)?;
            per_line.push(out.positions.len() - before);
            continue;
        }
        let Some(kv) = key_value else {
            return Err(not_key_value(line, kind, file));
        };
        if block == Block::Inside {
            block = Block::After;
        }
        match kv.normal.as_str() {
            "targetcount" => count = Some((target_count(line, kv.value, file)?, line.number)),
            "filetype" => out.test_type = Some(kv.value.to_string()),
            "flags" => out.flags = Some(kv.value.to_string()),
            "targets" if targets_line.is_none() => {
                targets_line = Some(line.number);
                block = Block::Inside;
                // The values start on the next line; a file that starts them here is read too.
                if !kv.value.is_empty() {
                    let before = out.positions.len();
                    positions(line, kv.value, &mut out, file)?;
                    per_line.push(out.positions.len() - before);
                }
            }
            _ => unused.push(shown(kv.key)),
        }
    }
    let Some((said, count_line)) = count else {
        return Err(missing_key(
            "Target-count",
            "`Target-count: N`, the number of targets",
            file,
        ));
    };
    if targets_line.is_none() {
        return Err(missing_key(
            "Targets",
            "`Targets :` followed by the target positions",
            file,
        ));
    }
    if said != out.positions.len() {
        return Err(ReadError::new(
            Location::line(file, count_line),
            ReadErrorKind::RenishawTargetCount {
                said,
                found: out.positions.len(),
            },
        ));
    }
    if out.flags.is_none() {
        notes
            .push("no `Flags:` line after the targets; the targets end at the next section".into());
    }
    unused_keys("TARGET DATA", &unused, notes);
    out.per_line = same_per_line(&per_line);
    out.ascending = check_order(&out, file)?;
    Ok(out)
}

/// `Target-count`: a whole number of targets, at least one.
fn target_count(line: &Line, value: &str, file: &str) -> Result<usize, ReadError> {
    let bad = || {
        ReadError::new(
            Location::at(file, line.number, line.column_of(value)),
            ReadErrorKind::RenishawBadValue {
                key: "Target-count".into(),
                expected: "the number of targets, a whole number ≥ 1".into(),
                found: shown(value),
            },
        )
    };
    let count: usize = value.parse().map_err(|_| bad())?;
    if count == 0 {
        return Err(bad());
    }
    if count > MAX_READINGS / 2 {
        return Err(too_many(line.number, file));
    }
    Ok(count)
}

/// The positions in `text`, a part of `line` in the `Targets :` block.
fn positions(line: &Line, text: &str, out: &mut Targets, file: &str) -> Result<(), ReadError> {
    for token in text.split_whitespace() {
        let value = parse_number(token, false).map_err(|_| {
            ReadError::new(
                Location::at(file, line.number, line.column_of(token)),
                ReadErrorKind::RenishawBadValue {
                    key: "Targets".into(),
                    expected: format!(
                        "target positions in {} such as `550.000000`",
                        out.kind.position_unit()
                    ),
                    found: shown(token),
                },
            )
        })?;
        if out.positions.len() >= MAX_READINGS / 2 {
            return Err(too_many(line.number, file));
        }
        out.positions.push(value + 0.0); // normalise -0.0
        out.lines.push(line.number);
    }
    Ok(())
}

/// k when every line but the last holds k positions and the last at most k.
fn same_per_line(counts: &[usize]) -> Option<usize> {
    let counts: Vec<usize> = counts.iter().copied().filter(|&c| c > 0).collect();
    let (&last, full) = counts.split_last()?;
    let k = full.first().copied().unwrap_or(last);
    (full.iter().all(|&c| c == k) && last <= k).then_some(k)
}

/// The list must rise or fall strictly: a pass visits the targets in list order, and the
/// order tells which direction the odd runs move in. Returns true for a rising list.
fn check_order(targets: &Targets, file: &str) -> Result<bool, ReadError> {
    let p = &targets.positions;
    let ascending = p.len() < 2 || p[1] > p[0];
    for k in 1..p.len() {
        let (before, here) = (p[k - 1], p[k]);
        let message = if before == here {
            format!(
                "targets {k} and {} are both {}; every target of the list must differ",
                k + 1,
                fmt_target(targets.kind, here)
            )
        } else if (here > before) != ascending {
            format!(
                "target {} ({}) comes after target {k} ({}) in a {} list; the targets must {} along the whole list",
                k + 1,
                fmt_target(targets.kind, here),
                fmt_target(targets.kind, before),
                if ascending { "rising" } else { "falling" },
                if ascending { "rise" } else { "fall" },
            )
        } else {
            continue;
        };
        return Err(ReadError::new(
            Location::line(file, targets.lines[k]),
            ReadErrorKind::Renishaw(message),
        ));
    }
    Ok(ascending)
}

fn not_key_value(line: &Line, kind: AxisKind, file: &str) -> ReadError {
    ReadError::new(
        Location::line(file, line.number),
        ReadErrorKind::Renishaw(format!(
            "TARGET DATA:: line `{}` is not `Key: value`; expected `Target-count: N`, then `Targets :` and the positions in {}, then `Flags:`",
            shown(line.text()),
            kind.position_unit()
        )),
    )
}

fn missing_key(key: &str, expected: &str, file: &str) -> ReadError {
    ReadError::new(
        Location::file(file),
        ReadErrorKind::RenishawMissingKey {
            section: "TARGET DATA::".into(),
            key: key.into(),
            expected: expected.into(),
        },
    )
}

fn too_many(line: usize, file: &str) -> ReadError {
    ReadError::new(
        Location::line(file, line),
        ReadErrorKind::TooManyReadings {
            limit: MAX_READINGS,
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn per_line() {
        assert_eq!(same_per_line(&[5, 5, 1]), Some(5));
        assert_eq!(same_per_line(&[3]), Some(3));
        assert_eq!(same_per_line(&[5, 4, 5]), None);
        assert_eq!(same_per_line(&[]), None);
    }
}
