//! The key=value layout of the open-source ISO 230-2 toolchain used at ESS (ecmc):
//!
//! ```text
//! UNIT=mm
//! CYCLES=5
//! POSITIONS=5
//! TGT_DATA[1]=15
//! REF_DATA_FWD[1,1]=15.00474806227268489274
//! REF_DATA_BWD[1,1]=15.00067042688033089959
//! ```
//! `TGT_DATA[i]` is the target P_i, `REF_DATA_FWD[i,j]` / `REF_DATA_BWD[i,j]` the
//! reference system's reading (an actual position P_ij, absolute, in `UNIT`) at target i
//! in cycle j moving forward (↑) or backward (↓). X_ij = P_ij − P_i (clause 2.5). `UNIT`
//! defaults to mm; `CYCLES` and `POSITIONS`, when given, must match the data. Other plain
//! keys (`REF_PV`, `DEC`, …) are metadata and ignored.

use super::error::{Location, ReadError, ReadErrorKind};
use super::{AxisData, Lines, MAX_READINGS, RawReading, parse_number};
use crate::units::{AxisKind, Direction};
use std::collections::BTreeMap;
use std::io::BufRead;

/// True when `line` has the shape `NAME=…` or `NAME[…]=…`.
pub(crate) fn looks_like_key_value(line: &[u8]) -> bool {
    let Some(eq) = line.iter().position(|&b| b == b'=') else {
        return false;
    };
    let key = line[..eq].trim_ascii();
    // `NAME[` counts even without its `]`, so the key=value reader can say what is wrong.
    let name_end = key.iter().position(|&b| b == b'[').unwrap_or(key.len());
    let name = &key[..name_end];
    !name.is_empty()
        && name[0].is_ascii_alphabetic()
        && name.iter().all(|b| b.is_ascii_alphanumeric() || *b == b'_')
}

struct Entry {
    value: f64,
    line: usize,
}

/// Parses the key=value layout.
pub fn parse<R: BufRead>(reader: R, file: &str) -> Result<AxisData, ReadError> {
    read(reader, file).map(|(data, _)| data)
}

/// Most ignored metadata keys named in the notes.
const MAX_IGNORED_SHOWN: usize = 8;

/// Parses the key=value layout; also returns what was assumed or skipped.
pub(crate) fn read<R: BufRead>(
    reader: R,
    file: &str,
) -> Result<(AxisData, Vec<String>), ReadError> {
    let mut lines = Lines::new(reader, file);
    let mut entries = Entries::default();
    let mut count = 0usize;
    while let Some((number, text)) = lines.next_line()? {
        let trimmed = text.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let Some(eq) = text.find('=') else {
            let message = format!("expected KEY=VALUE, found `{trimmed}`");
            return Err(fail(file, number, 1, message));
        };
        count += 1;
        if count > 3 * MAX_READINGS {
            return Err(ReadError::new(
                Location::line(file, number),
                ReadErrorKind::TooManyReadings {
                    limit: MAX_READINGS,
                },
            ));
        }
        let line = KeyValueLine {
            key: text[..eq].trim(),
            value: text[eq + 1..].trim(),
            value_col: text[..eq + 1].chars().count() + 1,
            number,
            file,
        };
        entries.add(&line)?;
    }
    let (kind, factor) = unit(&entries.unit, file)?;
    entries.check(file)?;
    let raw = entries.readings(kind, factor, file)?;
    let mut notes = Vec::new();
    if entries.unit.is_none() {
        notes.push("no UNIT: the readings are taken in mm".to_string());
    }
    notes.push(
        "deviations taken as REF_DATA − TGT_DATA; order of measurement: each cycle forward through the positions, then backward".into(),
    );
    if !entries.ignored.is_empty() {
        let mut shown: Vec<&str> = entries.ignored.iter().map(String::as_str).collect();
        if shown.len() > MAX_IGNORED_SHOWN {
            shown.truncate(MAX_IGNORED_SHOWN);
            shown.push("…");
        }
        notes.push(format!("metadata keys ignored: {}", shown.join(", ")));
    }
    Ok((AxisData::from_raw(kind, raw, Vec::new(), file)?, notes))
}

/// A key=value error at `line`, `column`.
fn fail(file: &str, line: usize, column: usize, message: String) -> ReadError {
    ReadError::new(
        Location::at(file, line, column),
        ReadErrorKind::KeyValue(message),
    )
}

/// One `KEY=VALUE` line, split.
struct KeyValueLine<'a> {
    key: &'a str,
    value: &'a str,
    /// 1-based character column of the value.
    value_col: usize,
    number: usize,
    file: &'a str,
}

impl KeyValueLine<'_> {
    fn fail(&self, column: usize, message: String) -> ReadError {
        fail(self.file, self.number, column, message)
    }

    /// The value as a finite number; `what` says what it is in the error.
    fn number(&self, what: &str) -> Result<f64, ReadError> {
        let (key, value) = (self.key, self.value);
        parse_number(value, false).map_err(|_| {
            let message =
                format!("{key}: expected a finite number for the {what}, found `{value}`");
            self.fail(self.value_col, message)
        })
    }

    /// The value as a count ≥ 1 (`CYCLES`, `POSITIONS`).
    fn count(&self) -> Result<usize, ReadError> {
        let (key, value) = (self.key, self.value);
        value
            .parse::<usize>()
            .ok()
            .filter(|&c| c >= 1)
            .ok_or_else(|| {
                let message = format!("{key}: expected a positive whole number, found `{value}`");
                self.fail(self.value_col, message)
            })
    }

    /// The entry of an indexed key's value, read from this line.
    fn entry(&self, what: &str) -> Result<Entry, ReadError> {
        Ok(Entry {
            value: self.number(what)?,
            line: self.number,
        })
    }
}

/// Everything the file says, keyed by index, before the checks that need all of it.
#[derive(Default)]
struct Entries {
    /// `UNIT` and its line.
    unit: Option<(String, usize)>,
    /// `CYCLES` and its line.
    cycles: Option<(usize, usize)>,
    /// `POSITIONS` and its line.
    positions: Option<(usize, usize)>,
    /// `TGT_DATA[i]`.
    targets: BTreeMap<usize, Entry>,
    /// `REF_DATA_FWD[i,j]`.
    fwd: BTreeMap<(usize, usize), Entry>,
    /// `REF_DATA_BWD[i,j]`.
    bwd: BTreeMap<(usize, usize), Entry>,
    /// Plain keys other than UNIT, CYCLES and POSITIONS, in order of first appearance.
    ignored: Vec<String>,
}

impl Entries {
    /// Takes in one line: an indexed key (`TGT_DATA[3]`) or a plain one (`UNIT`).
    fn add(&mut self, line: &KeyValueLine) -> Result<(), ReadError> {
        let key = line.key;
        let Some(open) = key.find('[') else {
            match key {
                "UNIT" => self.unit = Some((line.value.to_string(), line.number)),
                "CYCLES" => self.cycles = Some((line.count()?, line.number)),
                "POSITIONS" => self.positions = Some((line.count()?, line.number)),
                // REF_PV, TEST_PV, TGT_SET_PV, DEC, …: metadata. Bounded: the notes name
                // a few, and a file of 300 000 distinct keys must not be scanned quadratically.
                other => {
                    if self.ignored.len() <= MAX_IGNORED_SHOWN
                        && !self.ignored.iter().any(|k| k == other)
                    {
                        self.ignored.push(other.to_string());
                    }
                }
            }
            return Ok(());
        };
        let name = &key[..open];
        let inside = key[open + 1..]
            .strip_suffix(']')
            .ok_or_else(|| line.fail(1, format!("`{key}`: expected a closing `]`")))?;
        let indices: Vec<Option<usize>> = inside
            .split(',')
            .map(|s| s.trim().parse::<usize>().ok().filter(|&k| k >= 1))
            .collect();
        let bad_index = || {
            let example = if name == "TGT_DATA" {
                ""
            } else {
                " or [3,2] (position, cycle)"
            };
            let message = format!("`{key}`: expected 1-based indices, e.g. {name}[3]{example}");
            line.fail(open + 2, message)
        };
        match (name, indices.as_slice()) {
            ("TGT_DATA", [Some(i)]) => self.add_target(*i, line),
            ("REF_DATA_FWD" | "REF_DATA_BWD", [Some(i), Some(j)]) => {
                self.add_reference(name, (*i, *j), line)
            }
            ("TGT_DATA" | "REF_DATA_FWD" | "REF_DATA_BWD", _) => Err(bad_index()),
            _ => Err(line.fail(
                1,
                format!(
                    "unknown key `{name}[…]`; expected TGT_DATA[i], REF_DATA_FWD[i,j] or REF_DATA_BWD[i,j]"
                ),
            )),
        }
    }

    fn add_target(&mut self, i: usize, line: &KeyValueLine) -> Result<(), ReadError> {
        let entry = line.entry("target position")?;
        match self.targets.insert(i, entry) {
            Some(prev) => Err(line.fail(
                1,
                format!("TGT_DATA[{i}] is given twice (first on line {})", prev.line),
            )),
            None => Ok(()),
        }
    }

    fn add_reference(
        &mut self,
        name: &str,
        (i, j): (usize, usize),
        line: &KeyValueLine,
    ) -> Result<(), ReadError> {
        let entry = line.entry("reference reading")?;
        let map = if name == "REF_DATA_FWD" {
            &mut self.fwd
        } else {
            &mut self.bwd
        };
        match map.insert((i, j), entry) {
            Some(prev) => Err(line.fail(
                1,
                format!(
                    "{name}[{i},{j}] is given twice (first on line {})",
                    prev.line
                ),
            )),
            None => Ok(()),
        }
    }

    /// The file as a whole: targets given, `POSITIONS` and `CYCLES` matching the data,
    /// every reading at a known target, targets increasing with their index.
    fn check(&self, file: &str) -> Result<(), ReadError> {
        if self.targets.is_empty() {
            return Err(ReadError::new(
                Location::file(file),
                ReadErrorKind::KeyValue(
                    "no TGT_DATA[i] lines; expected the target positions TGT_DATA[1], TGT_DATA[2], …"
                        .into(),
                ),
            ));
        }
        if let Some((p, line)) = self.positions
            && p != self.targets.len()
        {
            let message = format!(
                "POSITIONS={p} but the file has {} TGT_DATA entries",
                self.targets.len()
            );
            return Err(fail(file, line, 11, message));
        }
        self.check_references(file)?;
        self.check_targets_increase(file)
    }

    /// Every reading refers to a target given, in a cycle within `CYCLES`.
    fn check_references(&self, file: &str) -> Result<(), ReadError> {
        for (label, map) in [("REF_DATA_FWD", &self.fwd), ("REF_DATA_BWD", &self.bwd)] {
            for (&(i, j), entry) in map {
                if !self.targets.contains_key(&i) {
                    let message = format!(
                        "{label}[{i},{j}] refers to position {i}, which has no TGT_DATA[{i}]"
                    );
                    return Err(fail(file, entry.line, 1, message));
                }
                if let Some((c, _)) = self.cycles
                    && j > c
                {
                    let message = format!("{label}[{i},{j}] is cycle {j} but CYCLES={c}");
                    return Err(fail(file, entry.line, 1, message));
                }
            }
        }
        Ok(())
    }

    /// FWD means moving through the positions in index order, so the targets must
    /// increase with their index (a repeated value would also merge two positions).
    fn check_targets_increase(&self, file: &str) -> Result<(), ReadError> {
        let mut previous: Option<(usize, &Entry)> = None;
        for (&i, entry) in &self.targets {
            if let Some((p, prev)) = previous
                && entry.value.partial_cmp(&prev.value) != Some(std::cmp::Ordering::Greater)
            {
                let message = format!(
                    "TGT_DATA[{i}] = {} does not increase from TGT_DATA[{p}] = {} (line {}); targets must increase with their index, because REF_DATA_FWD runs through them in that order",
                    entry.value, prev.value, prev.line
                );
                return Err(fail(file, entry.line, 1, message));
            }
            previous = Some((i, entry));
        }
        Ok(())
    }

    /// The readings in the toolchain's measurement order: cycle j forward over the
    /// positions, then backward. Sorted from the entries themselves, so the work grows
    /// with the readings, never with the largest index written (`REF_DATA_FWD[1,4000000000]`
    /// is one reading, not 4e9 cycles).
    fn readings(
        &self,
        kind: AxisKind,
        factor: f64,
        file: &str,
    ) -> Result<Vec<RawReading>, ReadError> {
        // Sort key: (cycle, forward first, position ascending forward and descending backward).
        type Ordered<'a> = ((usize, u8, usize), usize, Direction, &'a Entry);
        let mut order: Vec<Ordered> = self
            .fwd
            .iter()
            .map(|(&(i, j), e)| ((j, 0, i), i, Direction::Up, e))
            .chain(
                self.bwd
                    .iter()
                    .map(|(&(i, j), e)| ((j, 1, usize::MAX - i), i, Direction::Down, e)),
            )
            .collect();
        order.sort_unstable_by_key(|&(key, ..)| key);
        let mut raw = Vec::with_capacity(order.len());
        for ((j, ..), i, direction, entry) in order {
            let target = self.targets[&i].value + 0.0;
            let deviation = (entry.value - target) * factor;
            if deviation.abs() > super::MAX_DEVIATION {
                return Err(implausible(kind, (i, j), direction, entry, file));
            }
            raw.push(RawReading {
                target,
                direction,
                run: u32::try_from(j).unwrap_or(u32::MAX),
                deviation,
                time_s: None,
                temps_c: Vec::new(),
                line: entry.line,
            });
        }
        Ok(raw)
    }
}

/// The axis kind and the factor from `UNIT` to µm or arcsec (mm when absent).
fn unit(unit: &Option<(String, usize)>, file: &str) -> Result<(AxisKind, f64), ReadError> {
    let Some((u, line)) = unit else {
        return Ok((AxisKind::Linear, 1000.0));
    };
    match u.to_ascii_lowercase().as_str() {
        "mm" => Ok((AxisKind::Linear, 1000.0)),
        "um" | "µm" | "micron" => Ok((AxisKind::Linear, 1.0)),
        "m" => Ok((AxisKind::Linear, 1e6)),
        "deg" | "degree" | "degrees" | "°" => Ok((AxisKind::Rotary, 3600.0)),
        "arcsec" => Ok((AxisKind::Rotary, 1.0)),
        other => {
            let message =
                format!("UNIT: unknown unit `{other}`; expected mm, um, m, deg or arcsec");
            Err(fail(file, *line, 6, message))
        }
    }
}

/// A reference reading too far from its target to be a positioning error.
fn implausible(
    kind: AxisKind,
    (i, j): (usize, usize),
    direction: Direction,
    entry: &Entry,
    file: &str,
) -> ReadError {
    let label = if direction == Direction::Up {
        "FWD"
    } else {
        "BWD"
    };
    ReadError::new(
        Location::at(file, entry.line, 1),
        ReadErrorKind::Implausible {
            column: format!("REF_DATA_{label}[{i},{j}]"),
            value: entry.value.to_string(),
            limit: format!("{}", super::MAX_DEVIATION),
            unit: kind.deviation_unit().to_string(),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shape_detection() {
        assert!(looks_like_key_value(b"UNIT=mm"));
        assert!(looks_like_key_value(b"REF_DATA_FWD[1,2]=3.5"));
        assert!(!looks_like_key_value(
            b"target_mm,direction,run,deviation_um"
        ));
        assert!(!looks_like_key_value(b"=3"));
        assert!(!looks_like_key_value(b"1=3"));
    }

    #[test]
    fn reads_absolute_readings_as_deviations() {
        let text = "UNIT=mm\nCYCLES=2\nPOSITIONS=2\nTGT_DATA[1]=10\nTGT_DATA[2]=20\n\
            REF_DATA_FWD[1,1]=10.001\nREF_DATA_FWD[2,1]=20.002\nREF_DATA_BWD[2,1]=19.999\nREF_DATA_BWD[1,1]=9.998\n\
            REF_DATA_FWD[1,2]=10.0015\nREF_DATA_FWD[2,2]=20.0025\nREF_DATA_BWD[2,2]=19.9985\nREF_DATA_BWD[1,2]=9.9975\n";
        let d = parse(text.as_bytes(), "k.dat").unwrap();
        assert_eq!(d.targets, vec![10.0, 20.0]);
        assert_eq!(d.runs(), 2);
        let up = d.deviations(0, Direction::Up);
        assert!((up[0] - 1.0).abs() < 1e-6 && (up[1] - 1.5).abs() < 1e-6);
        let down = d.deviations(1, Direction::Down);
        assert!((down[0] + 1.0).abs() < 1e-6 && (down[1] + 1.5).abs() < 1e-6);
        // order: cycle 1 forward ascending, then backward descending
        let order: Vec<(usize, Direction)> = d
            .readings
            .iter()
            .take(4)
            .map(|r| (r.target, r.direction))
            .collect();
        assert_eq!(
            order,
            vec![
                (0, Direction::Up),
                (1, Direction::Up),
                (1, Direction::Down),
                (0, Direction::Down)
            ]
        );
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse("TGT_DATA[1]=x\n".as_bytes(), "k.dat").unwrap_err();
        assert!(e.to_string().starts_with("k.dat:1:13:"), "{e}");
        let e = parse("TGT_DATA[1]=1\nFOO[1]=2\n".as_bytes(), "k.dat").unwrap_err();
        assert!(e.to_string().contains("k.dat:2:1: unknown key"), "{e}");
        let e = parse("UNIT=inch\nTGT_DATA[1]=1\n".as_bytes(), "k.dat").unwrap_err();
        assert!(e.to_string().contains("unknown unit"), "{e}");
    }

    /// A cycle index of 3·10^9 is one reading: the reader must not walk every cycle up to
    /// it (that took minutes), only the entries it has.
    #[test]
    fn huge_cycle_index_is_one_reading() {
        let text = "TGT_DATA[1]=0\nTGT_DATA[2]=1\nREF_DATA_FWD[1,1]=0\nREF_DATA_BWD[1,1]=0\n\
            REF_DATA_FWD[2,1]=1\nREF_DATA_BWD[2,1]=1\nREF_DATA_FWD[1,3000000000]=0\n";
        let e = parse(text.as_bytes(), "k.dat").unwrap_err();
        assert!(
            e.to_string()
                .contains("has runs 1, but the test has runs 1,3000000000"),
            "{e}"
        );
    }
}
