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
pub fn looks_like_key_value(line: &[u8]) -> bool {
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
    let mut lines = Lines::new(reader, file);
    let fail = |line: usize, column: usize, message: String| {
        ReadError::new(
            Location::at(file, line, column),
            ReadErrorKind::KeyValue(message),
        )
    };
    let mut unit: Option<(String, usize)> = None;
    let mut cycles: Option<(usize, usize)> = None;
    let mut positions: Option<(usize, usize)> = None;
    let mut targets: BTreeMap<usize, Entry> = BTreeMap::new();
    let mut fwd: BTreeMap<(usize, usize), Entry> = BTreeMap::new();
    let mut bwd: BTreeMap<(usize, usize), Entry> = BTreeMap::new();
    let mut count = 0usize;

    while let Some((number, text)) = lines.next_line()? {
        let trimmed = text.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let Some(eq) = text.find('=') else {
            return Err(fail(
                number,
                1,
                format!("expected KEY=VALUE, found `{trimmed}`"),
            ));
        };
        let key = text[..eq].trim();
        let value = text[eq + 1..].trim();
        let value_col = text[..eq + 1].chars().count() + 1;
        count += 1;
        if count > 3 * MAX_READINGS {
            return Err(ReadError::new(
                Location::line(file, number),
                ReadErrorKind::TooManyReadings {
                    limit: MAX_READINGS,
                },
            ));
        }
        let number_value = |what: &str| {
            parse_number(value, false).map_err(|_| {
                fail(
                    number,
                    value_col,
                    format!("{key}: expected a finite number for the {what}, found `{value}`"),
                )
            })
        };
        let count_value = || {
            value
                .parse::<usize>()
                .ok()
                .filter(|&c| c >= 1)
                .ok_or_else(|| {
                    fail(
                        number,
                        value_col,
                        format!("{key}: expected a positive whole number, found `{value}`"),
                    )
                })
        };
        if let Some(open) = key.find('[') {
            let name = &key[..open];
            let inside = key[open + 1..]
                .strip_suffix(']')
                .ok_or_else(|| fail(number, 1, format!("`{key}`: expected a closing `]`")))?;
            let indices: Vec<Option<usize>> = inside
                .split(',')
                .map(|s| s.trim().parse::<usize>().ok().filter(|&k| k >= 1))
                .collect();
            let bad_index = || {
                fail(
                    number,
                    open + 2,
                    format!(
                        "`{key}`: expected 1-based indices, e.g. {name}[3]{}",
                        if name == "TGT_DATA" {
                            ""
                        } else {
                            " or [3,2] (position, cycle)"
                        }
                    ),
                )
            };
            match name {
                "TGT_DATA" => {
                    let [Some(i)] = indices.as_slice() else {
                        return Err(bad_index());
                    };
                    let entry = Entry {
                        value: number_value("target position")?,
                        line: number,
                    };
                    if let Some(prev) = targets.insert(*i, entry) {
                        return Err(fail(
                            number,
                            1,
                            format!("TGT_DATA[{i}] is given twice (first on line {})", prev.line),
                        ));
                    }
                }
                "REF_DATA_FWD" | "REF_DATA_BWD" => {
                    let [Some(i), Some(j)] = indices.as_slice() else {
                        return Err(bad_index());
                    };
                    let entry = Entry {
                        value: number_value("reference reading")?,
                        line: number,
                    };
                    let map = if name == "REF_DATA_FWD" {
                        &mut fwd
                    } else {
                        &mut bwd
                    };
                    if let Some(prev) = map.insert((*i, *j), entry) {
                        return Err(fail(
                            number,
                            1,
                            format!(
                                "{name}[{i},{j}] is given twice (first on line {})",
                                prev.line
                            ),
                        ));
                    }
                }
                _ => {
                    return Err(fail(
                        number,
                        1,
                        format!(
                            "unknown key `{name}[…]`; expected TGT_DATA[i], REF_DATA_FWD[i,j] or REF_DATA_BWD[i,j]"
                        ),
                    ));
                }
            }
        } else {
            match key {
                "UNIT" => unit = Some((value.to_string(), number)),
                "CYCLES" => cycles = Some((count_value()?, number)),
                "POSITIONS" => positions = Some((count_value()?, number)),
                _ => {} // REF_PV, TEST_PV, TGT_SET_PV, DEC, …: metadata
            }
        }
    }

    let (kind, factor) = match &unit {
        None => (AxisKind::Linear, 1000.0),
        Some((u, line)) => match u.to_ascii_lowercase().as_str() {
            "mm" => (AxisKind::Linear, 1000.0),
            "um" | "µm" | "micron" => (AxisKind::Linear, 1.0),
            "m" => (AxisKind::Linear, 1e6),
            "deg" | "degree" | "degrees" | "°" => (AxisKind::Rotary, 3600.0),
            "arcsec" => (AxisKind::Rotary, 1.0),
            other => {
                return Err(fail(
                    *line,
                    6,
                    format!("UNIT: unknown unit `{other}`; expected mm, um, m, deg or arcsec"),
                ));
            }
        },
    };
    if targets.is_empty() {
        return Err(ReadError::new(
            Location::file(file),
            ReadErrorKind::KeyValue(
                "no TGT_DATA[i] lines; expected the target positions TGT_DATA[1], TGT_DATA[2], …"
                    .into(),
            ),
        ));
    }
    if let Some((p, line)) = positions
        && p != targets.len()
    {
        return Err(fail(
            line,
            11,
            format!(
                "POSITIONS={p} but the file has {} TGT_DATA entries",
                targets.len()
            ),
        ));
    }
    for (label, map) in [("REF_DATA_FWD", &fwd), ("REF_DATA_BWD", &bwd)] {
        for (&(i, j), entry) in map {
            if !targets.contains_key(&i) {
                return Err(fail(
                    entry.line,
                    1,
                    format!("{label}[{i},{j}] refers to position {i}, which has no TGT_DATA[{i}]"),
                ));
            }
            if let Some((c, _)) = cycles
                && j > c
            {
                return Err(fail(
                    entry.line,
                    1,
                    format!("{label}[{i},{j}] is cycle {j} but CYCLES={c}"),
                ));
            }
        }
    }
    // FWD means moving through the positions in index order, so the targets must increase
    // with their index (a repeated value would also merge two positions into one).
    let mut previous: Option<(usize, &Entry)> = None;
    for (&i, entry) in &targets {
        if let Some((p, prev)) = previous
            && entry.value.partial_cmp(&prev.value) != Some(std::cmp::Ordering::Greater)
        {
            return Err(fail(
                entry.line,
                1,
                format!(
                    "TGT_DATA[{i}] = {} does not increase from TGT_DATA[{p}] = {} (line {}); targets must increase with their index, because REF_DATA_FWD runs through them in that order",
                    entry.value, prev.value, prev.line
                ),
            ));
        }
        previous = Some((i, entry));
    }

    // Measurement order of the toolchain: cycle j forward over the positions, then backward.
    // Sorted from the entries themselves, so the work grows with the readings, never with
    // the largest index written (REF_DATA_FWD[1,4000000000] is one reading, not 4e9 cycles).
    // Sort key: (cycle, forward first, position ascending forward and descending backward).
    type Ordered<'a> = ((usize, u8, usize), usize, Direction, &'a Entry);
    let mut order: Vec<Ordered> = fwd
        .iter()
        .map(|(&(i, j), e)| ((j, 0, i), i, Direction::Up, e))
        .chain(
            bwd.iter()
                .map(|(&(i, j), e)| ((j, 1, usize::MAX - i), i, Direction::Down, e)),
        )
        .collect();
    order.sort_unstable_by_key(|&(key, ..)| key);
    let mut raw = Vec::with_capacity(order.len());
    for ((j, ..), i, direction, entry) in order {
        let target = targets[&i].value + 0.0;
        let deviation = (entry.value - target) * factor;
        if deviation.abs() > super::MAX_DEVIATION {
            return Err(ReadError::new(
                Location::at(file, entry.line, 1),
                ReadErrorKind::Implausible {
                    column: format!(
                        "REF_DATA_{}[{i},{j}]",
                        if direction == Direction::Up {
                            "FWD"
                        } else {
                            "BWD"
                        }
                    ),
                    value: entry.value.to_string(),
                    limit: format!("{}", super::MAX_DEVIATION),
                    unit: kind.deviation_unit().to_string(),
                },
            ));
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
    AxisData::from_raw(kind, raw, Vec::new(), file)
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
