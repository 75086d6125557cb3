//! Measurement files: the data of one positioning test of one axis.
//!
//! Readers parse text from any `BufRead` (they never open files themselves; [`read_file`]
//! is the one place that does) and build an [`AxisData`]: the validated, dense grid of
//! deviations X_ij (ISO 230-2 clause 2.5) with every reading's order, time and temperatures
//! kept for the diagnosis.

pub(crate) mod cell;
pub mod csv;
pub mod ecmc_app;
pub mod ecmc_md;
pub mod error;
pub(crate) mod fields;
pub mod info;
pub mod keyvalue;
pub mod layout;
mod number;
pub mod renishaw;
pub mod reported;
pub(crate) mod table;
pub mod wide;
pub mod xlsx;

use cell::Place;
pub use ecmc_app::Source;
pub use error::{Location, ReadError, ReadErrorKind};
pub use info::FileInfo;
pub use layout::{Layout, ReadTest, Recognised};
pub(crate) use number::parse_number;
pub use table::TableKind;

use crate::units::{AxisKind, Direction, fmt_position};
use std::io::BufRead;
use std::path::Path;

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
pub const MAX_TARGET: f64 = 1e6;
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
fn check_target(r: &RawReading, kind: AxisKind, place: &Place) -> Result<(), ReadError> {
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
        let place = Place::text(file, false);
        AxisData::from_raw_in(kind, raw, temperature_names, &place)
    }

    /// [`AxisData::from_raw`] with errors located in `place` (a text file or a sheet).
    pub(crate) fn from_raw_in(
        kind: AxisKind,
        mut raw: Vec<RawReading>,
        temperature_names: Vec<String>,
        place: &Place,
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
        place: &Place,
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
        place: &Place,
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
fn list(values: &[u32]) -> String {
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

/// Largest workbook read: a positioning test's book is a few hundred kB.
pub const MAX_BOOK_BYTES: usize = 16 << 20;

/// What to read of a file beyond its layout: the sheet of a workbook, the position source
/// of an ecmc ISO 230 app file.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ReadOptions<'a> {
    /// The sheet of a workbook (the first when `None`; an error for another file).
    pub sheet: Option<&'a str>,
    /// The reference of an ecmc ISO 230 app file (the one it evaluated when `None`; an
    /// error for another file).
    pub source: Option<Source>,
}

impl<'a> ReadOptions<'a> {
    pub fn sheet(sheet: Option<&'a str>) -> ReadOptions<'a> {
        ReadOptions {
            sheet,
            source: None,
        }
    }
}

/// Reads a measurement in any layout from `reader`, choosing the layout by content; a
/// workbook's first sheet.
pub fn read<R: BufRead>(reader: R, file: &str) -> Result<ReadTest, ReadError> {
    read_with(reader, file, &ReadOptions::default())
}

/// Reads a measurement in any layout from `reader`, choosing the layout by content;
/// `sheet` names the sheet of a workbook (the first when `None`; an error for a file that
/// is not a workbook).
pub fn read_sheet<R: BufRead>(
    reader: R,
    file: &str,
    sheet: Option<&str>,
) -> Result<ReadTest, ReadError> {
    read_with(reader, file, &ReadOptions::sheet(sheet))
}

/// Reads a measurement in any layout from `reader`, choosing the layout by content, with
/// `options`.
pub fn read_with<R: BufRead>(
    mut reader: R,
    file: &str,
    options: &ReadOptions,
) -> Result<ReadTest, ReadError> {
    let sheet = options.sheet;
    let head = reader
        .fill_buf()
        .map_err(|e| ReadError::new(Location::file(file), ReadErrorKind::Io(e.to_string())))?;
    let how = layout::recognise(head).map_err(|kind| ReadError::new(Location::file(file), kind))?;
    let text_layout = match how {
        layout::Reader::Book => {
            refuse_source(
                options.source,
                Layout::Xlsx {
                    sheet: sheet.unwrap_or("").into(),
                    table: TableKind::Long,
                },
                file,
            )?;
            let limit = MAX_BOOK_BYTES;
            let bytes = read_all(
                reader,
                limit,
                file,
                ReadErrorKind::BookTooLarge {
                    limit_mib: limit >> 20,
                },
            )?;
            return xlsx::read(&bytes, file, sheet);
        }
        layout::Reader::Renishaw => {
            refuse_sheet(sheet, Layout::RenishawRtl, file)?;
            refuse_source(options.source, Layout::RenishawRtl, file)?;
            return read_renishaw(reader, file);
        }
        layout::Reader::EcmcAppReport | layout::Reader::EcmcAppCsv => {
            return read_ecmc_app(reader, file, how, options);
        }
        layout::Reader::EcmcReport => {
            refuse_sheet(sheet, Layout::EcmcReport, file)?;
            refuse_source(options.source, Layout::EcmcReport, file)?;
            let (data, notes, reported) = ecmc_md::read(reader, file)?;
            return Ok(ReadTest {
                data,
                recognised: Recognised {
                    layout: Layout::EcmcReport,
                    notes,
                    info: None,
                    reported,
                },
            });
        }
        layout::Reader::KeyValue => Layout::KeyValue,
        layout::Reader::Table(TableKind::Long) => Layout::LongCsv,
        layout::Reader::Table(TableKind::Wide) => Layout::WideCsv,
    };
    refuse_sheet(sheet, text_layout.clone(), file)?;
    refuse_source(options.source, text_layout.clone(), file)?;
    let (data, notes) = match text_layout {
        Layout::KeyValue => keyvalue::read(reader, file)?,
        Layout::WideCsv => wide::read(reader, file)?,
        _ => csv::read(reader, file)?,
    };
    Ok(ReadTest {
        data,
        recognised: Recognised {
            layout: text_layout,
            notes,
            info: None,
            reported: None,
        },
    })
}

/// An ecmc ISO 230 app report or raw-points CSV, with `options.source`'s deviations.
fn read_ecmc_app<R: BufRead>(
    reader: R,
    file: &str,
    how: layout::Reader,
    options: &ReadOptions,
) -> Result<ReadTest, ReadError> {
    let source = options.source.unwrap_or_default();
    let (layout, (data, notes, reported)) = match how {
        layout::Reader::EcmcAppReport => (
            Layout::EcmcAppReport,
            ecmc_app::markdown::read(reader, file, source)?,
        ),
        _ => {
            let (data, notes) = ecmc_app::raw_csv::read(reader, file, source)?;
            (Layout::EcmcAppCsv, (data, notes, None))
        }
    };
    refuse_sheet(options.sheet, layout.clone(), file)?;
    Ok(ReadTest {
        data,
        recognised: Recognised {
            layout,
            notes,
            info: None,
            reported,
        },
    })
}

/// A reference chosen for a file that has no references to choose from is an error.
fn refuse_source(source: Option<Source>, layout: Layout, file: &str) -> Result<(), ReadError> {
    match source {
        None => Ok(()),
        Some(source) => {
            let kind = ReadErrorKind::SourceOfOther {
                chosen: source.describe(),
                layout: layout.name(),
            };
            Err(ReadError::new(Location::file(file), kind))
        }
    }
}

/// A sheet named for a file that is not a workbook is an error, not ignored.
fn refuse_sheet(sheet: Option<&str>, layout: Layout, file: &str) -> Result<(), ReadError> {
    match sheet {
        None => Ok(()),
        Some(sheet) => {
            let kind = ReadErrorKind::SheetOfText {
                sheet: sheet.to_string(),
                layout: layout.name(),
            };
            Err(ReadError::new(Location::file(file), kind))
        }
    }
}

/// A Renishaw `.rtl`/`.rta` file: read whole (it is small), its USER-TEXT and
/// ENVIRONMENT kept as the file's [`FileInfo`].
fn read_renishaw<R: BufRead>(reader: R, file: &str) -> Result<ReadTest, ReadError> {
    let limit = renishaw::MAX_FILE_BYTES;
    let too_large = ReadErrorKind::RenishawTooLarge {
        limit: format!("{limit} bytes"),
    };
    let test = renishaw::parse(&read_all(reader, limit, file, too_large)?, file)?;
    let info = Some(test.info()).filter(|i| !i.is_empty());
    let layout = match test.rotary {
        true => Layout::RenishawRta,
        false => Layout::RenishawRtl,
    };
    Ok(ReadTest {
        data: test.data,
        recognised: Recognised {
            layout,
            notes: test.notes,
            info,
            reported: None,
        },
    })
}

/// The whole of `reader`, refused with `too_large` past `limit` bytes (for the readers
/// that need all of a file in memory).
pub(crate) fn read_all<R: std::io::Read>(
    reader: R,
    limit: usize,
    file: &str,
    too_large: ReadErrorKind,
) -> Result<Vec<u8>, ReadError> {
    use std::io::Read;
    let mut bytes = Vec::new();
    reader
        .take(limit as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| ReadError::new(Location::file(file), ReadErrorKind::Io(e.to_string())))?;
    if bytes.len() > limit {
        return Err(ReadError::new(Location::file(file), too_large));
    }
    Ok(bytes)
}

/// Opens and reads a measurement file (the one place this module touches the file system):
/// a regular file only, refused when it changes while it is read ([`crate::files`]);
/// `sheet` as in [`read_sheet`].
pub fn read_file(path: &Path, sheet: Option<&str>) -> Result<ReadTest, ReadError> {
    read_file_within(path, &ReadOptions::sheet(sheet), None)
}

/// [`read_file`] with `options` (the sheet, the reference of an ecmc ISO 230 app file).
pub fn read_file_with(path: &Path, options: &ReadOptions) -> Result<ReadTest, ReadError> {
    read_file_within(path, options, None)
}

/// [`read_file`] with `options`, refused unless the file opened lies inside the folder
/// `files` ([`crate::files::Root`]; `None`: no folder rule).
pub fn read_file_within(
    path: &Path,
    options: &ReadOptions,
    files: Option<&crate::files::Root>,
) -> Result<ReadTest, ReadError> {
    let name = path.display().to_string();
    let read = |file: &mut std::fs::File| {
        read_with(
            std::io::BufReader::with_capacity(64 * 1024, file),
            &name,
            options,
        )
    };
    match files {
        Some(files) => files.read_with(path, read),
        None => crate::files::read_with(path, None, read),
    }
    .map_err(|e| ReadError::new(Location::file(&name), ReadErrorKind::Io(e.to_string())))?
}

/// Reads lines of at most [`MAX_LINE_BYTES`] as UTF-8 text with their 1-based numbers,
/// stripping a leading BOM and the line ending.
pub(crate) struct Lines<R> {
    reader: R,
    file: String,
    number: usize,
    buf: Vec<u8>,
}

impl<R: BufRead> Lines<R> {
    pub(crate) fn new(reader: R, file: &str) -> Lines<R> {
        Lines {
            reader,
            file: file.to_string(),
            number: 0,
            buf: Vec::with_capacity(256),
        }
    }

    /// The next line, or `None` at the end of the input.
    pub(crate) fn next_line(&mut self) -> Result<Option<(usize, &str)>, ReadError> {
        use std::io::Read;
        self.buf.clear();
        let limit = MAX_LINE_BYTES as u64 + 1;
        let read = (&mut self.reader)
            .take(limit)
            .read_until(b'\n', &mut self.buf)
            .map_err(|e| {
                ReadError::new(
                    Location::line(&self.file, self.number + 1),
                    ReadErrorKind::Io(e.to_string()),
                )
            })?;
        if read == 0 {
            return Ok(None);
        }
        self.number += 1;
        if self.buf.len() > MAX_LINE_BYTES {
            return Err(ReadError::new(
                Location::line(&self.file, self.number),
                ReadErrorKind::LineTooLong {
                    limit: MAX_LINE_BYTES,
                },
            ));
        }
        let mut bytes = self.buf.as_slice();
        if self.number == 1 {
            bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        }
        while let [rest @ .., b'\n' | b'\r'] = bytes {
            bytes = rest;
        }
        let text = std::str::from_utf8(bytes).map_err(|_| {
            ReadError::new(
                Location::line(&self.file, self.number),
                ReadErrorKind::InvalidUtf8,
            )
        })?;
        Ok(Some((self.number, text)))
    }
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
