//! The readings of one positioning test of one axis, as every reader builds them: the
//! validated, dense grid of deviations X_ij (ISO 230-2 clause 2.5) with every reading's
//! order, time and temperatures kept for the diagnosis, and the error that names the file,
//! line and field a reading came from. The readers themselves (which parse text) live
//! outside the core.

pub mod cell;
pub mod error;
pub mod number;
pub mod reported;

use cell::Origin;
pub use error::{Location, ReadError, ReadErrorKind};
pub use number::parse_number;

use crate::units::{AxisKind, Direction, fmt_position};
/// Most readings one file may hold. A positioning test has a few hundred to a few
/// thousand (1 000 targets × 2 directions × 50 runs is 100 000); beyond this the file is
/// refused after reading that far, so memory stays bounded whatever its size.
pub const MAX_READINGS: usize = 100_000;

/// Largest plausible |deviation| in µm or arcsec (100 mm, or 27.8°): anything larger is a
/// unit mistake or a corrupt value, not a positioning error.
pub const MAX_DEVIATION: f64 = 1e5;
/// Largest plausible |target position| in mm or degrees (1 km, or 2 778 turns), the bound
/// a plan's targets have too: a target of `1e300` is a corrupt value, and its squares and
/// differences overflow every statistic.
pub(crate) const MAX_TARGET: f64 = 1e6;
/// Most `temp_<name>_c` columns a CSV file may have: with [`MAX_READINGS`] this bounds
/// the temperatures kept (64 × 100 000 × 8 bytes = 51 MB) whatever the file holds.
pub const MAX_TEMPERATURES: usize = 64;
/// Longest line a reader accepts.
pub const MAX_LINE_BYTES: usize = 64 * 1024;

/// One reading as parsed, before validation.
#[derive(Debug, Clone, PartialEq)]
pub struct RawReading {
    /// Target position P_i, mm or deg.
    pub target: f64,
    pub direction: Direction,
    /// Approach index j as written in the file (1-based).
    pub run: u32,
    /// Positional deviation X_ij in µm or arcsec.
    pub deviation: f64,
    /// Seconds from the start of the test, when the file gives them.
    pub time_s: Option<f64>,
    /// Temperatures (°C) in the order of [`AxisData::temperature_names`].
    pub temps_c: Vec<f64>,
    /// 1-based line in the source file (0 when generated).
    pub line: usize,
}

/// One validated reading, in measurement order.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// Index i of the target (0-based) in [`AxisData::targets`].
    pub target: usize,
    pub direction: Direction,
    /// Index j of the run (0-based) in [`AxisData::run_labels`].
    pub run: usize,
    /// X_ij in µm or arcsec.
    pub deviation: f64,
    pub time_s: Option<f64>,
    pub line: usize,
}

/// A validated positioning test: m targets, n runs per direction, both directions at
/// every target.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisData {
    pub kind: AxisKind,
    /// Target positions P_i (clause 2.3), ascending, mm or deg.
    pub targets: Vec<f64>,
    /// Run labels as written in the file, ascending; n = `run_labels.len()`.
    pub run_labels: Vec<u32>,
    /// Every reading in file order (the order of measurement).
    pub readings: Vec<Reading>,
    /// Names of the `temp_<name>_c` columns.
    pub temperature_names: Vec<String>,
    /// Temperatures per reading (same order as `readings`), °C.
    pub temperatures_c: Vec<Vec<f64>>,
    /// Dense deviations: `grid[direction][i * n + j]`.
    grid: [Vec<f64>; 2],
}

/// A target beyond [`MAX_TARGET`] refused at its line, for every reader (they all build
/// their data here).
fn check_target(r: &RawReading, kind: AxisKind, place: &Origin) -> Result<(), ReadError> {
    if r.target.abs() <= MAX_TARGET {
        return Ok(());
    }
    let location = match r.line {
        0 => place.whole(),
        line => place.line(line),
    };
    let kind = ReadErrorKind::ImplausibleTarget {
        // `1e300`, not 301 digits.
        value: match r.target.abs() < 1e15 {
            true => format!("{}", r.target),
            false => format!("{:e}", r.target),
        },
        limit: format!("{MAX_TARGET}"),
        unit: kind.position_unit().to_string(),
    };
    Err(ReadError::new(location, kind))
}

impl AxisData {
    /// Validates raw readings (duplicates, one-direction targets, ragged runs) and builds
    /// the dense grid. `file` names the source in errors.
    pub fn from_raw(
        kind: AxisKind,
        raw: Vec<RawReading>,
        temperature_names: Vec<String>,
        file: &str,
    ) -> Result<AxisData, ReadError> {
        let place = Origin::text(file, false);
        AxisData::from_raw_in(kind, raw, temperature_names, &place)
    }

    /// [`AxisData::from_raw`] with errors located in `place` (a text file or a sheet).
    pub fn from_raw_in(
        kind: AxisKind,
        mut raw: Vec<RawReading>,
        temperature_names: Vec<String>,
        place: &Origin,
    ) -> Result<AxisData, ReadError> {
        if raw.is_empty() {
            return Err(ReadError::new(place.whole(), ReadErrorKind::NoReadings));
        }
        // −0 and 0 are one target (a file may write the zero target as `-0.000` in one
        // direction): the targets are ordered and found by their bits.
        for r in &mut raw {
            r.target += 0.0;
            check_target(r, kind, place)?;
        }
        let targets = distinct_sorted(raw.iter().map(|r| r.target), f64::total_cmp);
        let run_labels = distinct_sorted(raw.iter().map(|r| r.run), u32::cmp);
        let cells = Cells::index(&raw, &targets, &run_labels, kind, place)?;
        cells.check_complete(&raw, &targets, &run_labels, kind, place)?;

        // Every (target, direction) has its n distinct runs: the grid has one cell per reading.
        let (m, n) = (targets.len(), run_labels.len());
        let mut grid = [vec![f64::NAN; m * n], vec![f64::NAN; m * n]];
        let mut readings = Vec::with_capacity(raw.len());
        let mut temperatures_c = Vec::with_capacity(raw.len());
        for (r, (i, j)) in raw.into_iter().zip(cells.indices) {
            grid[r.direction.index()][i * n + j] = r.deviation;
            readings.push(Reading {
                target: i,
                direction: r.direction,
                run: j,
                deviation: r.deviation,
                time_s: r.time_s,
                line: r.line,
            });
            temperatures_c.push(r.temps_c);
        }

        Ok(AxisData {
            kind,
            targets,
            run_labels,
            readings,
            temperature_names,
            temperatures_c,
            grid,
        })
    }

    /// n: approaches per direction at every target.
    pub fn runs(&self) -> usize {
        self.run_labels.len()
    }

    /// m: number of target positions.
    pub fn target_count(&self) -> usize {
        self.targets.len()
    }

    /// X_ij for target i, all runs j, in one direction (µm or arcsec).
    pub fn deviations(&self, target: usize, direction: Direction) -> &[f64] {
        let n = self.runs();
        &self.grid[direction.index()][target * n..(target + 1) * n]
    }

    /// X_ij of one reading.
    pub fn deviation(&self, target: usize, direction: Direction, run: usize) -> f64 {
        self.grid[direction.index()][target * self.runs() + run]
    }

    /// Measurement travel: first and last target (clause 2.2).
    pub fn measurement_travel(&self) -> (f64, f64) {
        (self.targets[0], self.targets[self.targets.len() - 1])
    }

    /// True when every reading carries a time stamp.
    pub fn has_times(&self) -> bool {
        self.readings.iter().all(|r| r.time_s.is_some())
    }

    /// A copy with every deviation replaced by `f(reading, deviation)`; used to remove a
    /// diagnosed effect or to apply an NDE correction.
    pub fn map_deviations(&self, mut f: impl FnMut(&Reading) -> f64) -> AxisData {
        let mut out = self.clone();
        let n = self.runs();
        for r in &mut out.readings {
            let value = f(r);
            r.deviation = value;
            out.grid[r.direction.index()][r.target * n + r.run] = value;
        }
        out
    }
}

/// The first reading, in file order, whose cell (target, direction, run) an earlier
/// reading already filled, with that earlier one: (first, again). The cells are looked up
/// in a table when the grid is small (every test that can be evaluated: 2·m·n cells for
/// 2·m·n readings), else found as neighbours after a sort (a ragged file's grid can be far
/// larger than its readings). `(m, n)`: the numbers of targets and of runs.
fn first_repeat(
    raw: &[RawReading],
    indices: &[(usize, usize)],
    (m, n): (usize, usize),
) -> Option<(usize, usize)> {
    let cell = |k: usize| {
        let row = (indices[k].0 * 2 + raw[k].direction.index()) as u64;
        row * n as u64 + indices[k].1 as u64
    };
    let grid = (2 * m).checked_mul(n).filter(|&size| size <= 4 * raw.len());
    if let Some(size) = grid {
        let mut first = vec![u32::MAX; size];
        for k in 0..raw.len() {
            let slot = &mut first[cell(k) as usize];
            if *slot != u32::MAX {
                return Some((*slot as usize, k));
            }
            *slot = k as u32;
        }
        return None;
    }
    let mut cells: Vec<(u64, u32)> = (0..raw.len()).map(|k| (cell(k), k as u32)).collect();
    cells.sort_unstable();
    (cells.windows(2))
        .filter(|w| w[0].0 == w[1].0)
        .min_by_key(|w| w[1].1)
        .map(|w| (w[0].1 as usize, w[1].1 as usize))
}

/// The distinct values, ascending. (Unstable: values the order calls equal are equal,
/// and a stable sort's scratch buffer cost the gate 2 % of its time.)
fn distinct_sorted<T: Copy + PartialEq>(
    values: impl Iterator<Item = T>,
    order: impl Fn(&T, &T) -> std::cmp::Ordering,
) -> Vec<T> {
    let mut out: Vec<T> = values.collect();
    out.sort_unstable_by(order);
    out.dedup();
    out
}

/// Where each raw reading falls in the grid, and how many readings each target has per
/// direction.
struct Cells {
    /// (target index i, run index j) of every raw reading, in order.
    indices: Vec<(usize, usize)>,
    /// Readings per target, by direction.
    counts: Vec<[usize; 2]>,
}

impl Cells {
    /// Indexes the readings and refuses a duplicate (same target, direction and run),
    /// naming the line of the first. The dense grid is built only once every target has n
    /// runs in both directions (2·m·n = readings): m distinct targets times n distinct runs
    /// could otherwise ask for m·n ≈ 10^10 cells from a 2 MB file.
    fn index(
        raw: &[RawReading],
        targets: &[f64],
        run_labels: &[u32],
        kind: AxisKind,
        place: &Origin,
    ) -> Result<Cells, ReadError> {
        let target_index = |t: f64| {
            targets
                .binary_search_by(|p| p.total_cmp(&t))
                .expect("target collected above")
        };
        let run_index = |r: u32| run_labels.binary_search(&r).expect("run collected above");
        let mut counts = vec![[0usize; 2]; targets.len()];
        let mut indices = Vec::with_capacity(raw.len());
        for r in raw {
            let (i, j) = (target_index(r.target), run_index(r.run));
            counts[i][r.direction.index()] += 1;
            indices.push((i, j));
        }
        if let Some((first, again)) = first_repeat(raw, &indices, (targets.len(), run_labels.len()))
        {
            let r = &raw[again];
            return Err(ReadError::new(
                place.line(r.line),
                ReadErrorKind::DuplicateReading {
                    target: fmt_target(kind, r.target),
                    direction: r.direction.name().into(),
                    run: r.run,
                    first_line: raw[first].line,
                },
            ));
        }
        Ok(Cells { indices, counts })
    }

    /// Every target has n runs in both directions: else the first target that has not is
    /// an error (readings in one direction only, or ragged runs).
    fn check_complete(
        &self,
        raw: &[RawReading],
        targets: &[f64],
        run_labels: &[u32],
        kind: AxisKind,
        place: &Origin,
    ) -> Result<(), ReadError> {
        let n = run_labels.len();
        for (i, &target) in targets.iter().enumerate() {
            let [up, down] = self.counts[i];
            if up == n && down == n {
                continue;
            }
            let at_target = || {
                raw.iter()
                    .zip(&self.indices)
                    .filter(move |(_, (t, _))| *t == i)
                    .map(|(r, _)| r)
            };
            let first_line = at_target().next().map_or(0, |r| r.line);
            let location = place.line(first_line);
            if up == 0 || down == 0 {
                let present = if up == 0 { "down" } else { "up" };
                return Err(ReadError::new(
                    location,
                    ReadErrorKind::OneDirection {
                        target: fmt_target(kind, target),
                        present: present.into(),
                    },
                ));
            }
            let d = if up != n {
                Direction::Up
            } else {
                Direction::Down
            };
            let mut labels: Vec<u32> = at_target()
                .filter(|r| r.direction == d)
                .map(|r| r.run)
                .collect();
            labels.sort_unstable();
            return Err(ReadError::new(
                location,
                ReadErrorKind::RaggedRuns {
                    target: fmt_target(kind, target),
                    direction: d.name().into(),
                    has: list(&labels),
                    expected: list(run_labels),
                },
            ));
        }
        Ok(())
    }
}

/// Run labels for messages: `1,2,4`; long lists as ranges (`1-65`), and at most 12 items
/// with the count, so a file of 100 000 runs does not make a 600 kB message.
pub fn list(values: &[u32]) -> String {
    const MAX_ITEMS: usize = 12;
    if values.len() <= MAX_ITEMS {
        return values
            .iter()
            .map(u32::to_string)
            .collect::<Vec<_>>()
            .join(",");
    }
    let mut items: Vec<String> = Vec::new();
    let mut k = 0;
    while k < values.len() {
        let start = values[k];
        let mut end = start;
        while k + 1 < values.len() && values[k + 1] == end.saturating_add(1) {
            k += 1;
            end = values[k];
        }
        items.push(match end - start {
            0 => start.to_string(),
            1 => format!("{start},{end}"),
            _ => format!("{start}-{end}"),
        });
        k += 1;
    }
    if items.len() > MAX_ITEMS {
        items.truncate(MAX_ITEMS);
        items.push(format!("… ({} runs)", values.len()));
    }
    items.join(",")
}

/// A target position with its unit, for messages: `353.834 mm`, `90 deg`.
pub fn fmt_target(kind: AxisKind, position: f64) -> String {
    format!("{} {}", fmt_position(position), kind.position_unit())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reading without time stamps or temperatures.
    fn reading(
        target: f64,
        direction: Direction,
        run: u32,
        deviation: f64,
        line: usize,
    ) -> RawReading {
        RawReading {
            target,
            direction,
            run,
            deviation,
            time_s: None,
            temps_c: Vec::new(),
            line,
        }
    }

    /// Found by CI's fuzzing (the ecmc app's report): a target written `-00.00000` in one
    /// reading and `0.00000` in another is one target, not a panic.
    #[test]
    fn minus_zero_is_the_zero_target() {
        let raw: Vec<RawReading> = [(-0.0, Direction::Up), (0.0, Direction::Down)]
            .iter()
            .flat_map(|&(zero, direction)| {
                [zero, 100.0].map(|target| reading(target, direction, 1, 0.001, 0))
            })
            .collect();
        let data = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "t.csv").unwrap();
        assert_eq!(data.targets.len(), 2);
        assert_eq!(data.targets[0].to_bits(), 0.0f64.to_bits());
    }

    /// The first repeated cell, in file order, with the reading that filled it first: the
    /// same from the table (a full grid) and from the sort (a grid far larger than the
    /// readings).
    #[test]
    fn the_first_repeat_in_file_order() {
        let (up, down) = (Direction::Up, Direction::Down);
        let full = [
            (0, up, 1),
            (1, up, 1),
            (0, down, 1),
            (1, up, 1),
            (0, up, 1),
            (1, up, 1),
        ];
        let ragged = [
            (0, up, 1),
            (9, up, 90),
            (9, down, 90),
            (9, up, 90),
            (0, up, 1),
        ];
        for (readings, n, expected) in [(&full[..], 1, (1, 3)), (&ragged[..], 90, (1, 3))] {
            let raw: Vec<RawReading> = (readings.iter())
                .map(|&(i, d, r)| reading(i as f64, d, r, 0.0, 0))
                .collect();
            let indices: Vec<(usize, usize)> = (readings.iter())
                .map(|&(i, _, r)| (i, r as usize - 1))
                .collect();
            let m = 1 + indices.iter().map(|&(i, _)| i).max().unwrap_or(0);
            let grid = (m, n);
            assert_eq!(
                first_repeat(&raw, &indices, grid),
                Some(expected),
                "n = {n}"
            );
            assert_eq!(
                first_repeat(&raw[..3], &indices[..3], grid),
                None,
                "n = {n}"
            );
        }
    }

    #[test]
    fn long_run_lists_are_abbreviated() {
        assert_eq!(list(&[1, 2, 4]), "1,2,4");
        let all: Vec<u32> = (1..=100_000).collect();
        assert_eq!(list(&all), "1-100000");
        let odd: Vec<u32> = (0..1000).map(|k| 2 * k + 1).collect();
        assert_eq!(list(&odd), "1,3,5,7,9,11,13,15,17,19,21,23,… (1000 runs)");
        let mixed: Vec<u32> = (1..=20).chain([30, 31, 40]).collect();
        assert_eq!(list(&mixed), "1-20,30,31,40");
    }

    /// Every reading at its own target and its own run: m = n = 50 000, so a dense grid
    /// built before validation would ask for 2 · 2.5·10^9 cells and abort the process.
    #[test]
    fn distinct_targets_and_runs_are_refused_without_a_huge_grid() {
        let raw: Vec<RawReading> = (0..50_000u32)
            .flat_map(|k| {
                [Direction::Up, Direction::Down].map(|direction| {
                    reading(f64::from(k), direction, k + 1, 0.5, 2 * k as usize + 2)
                })
            })
            .collect();
        let e = AxisData::from_raw(AxisKind::Linear, raw, Vec::new(), "d.csv").unwrap_err();
        assert_eq!(
            e.to_string(),
            "d.csv:2: ragged runs: target 0 mm direction up has runs 1, but the test has runs 1-50000; every target needs the same runs in both directions"
        );
    }
}
