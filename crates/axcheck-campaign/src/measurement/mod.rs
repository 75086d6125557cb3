//! Measurement files: the readers of one positioning test of one axis.
//!
//! Readers parse text from any `BufRead` (they never open files themselves; [`read_file`]
//! is the one place that does) and build an [`AxisData`] (the core's readings: the
//! validated, dense grid of deviations X_ij, ISO 230-2 clause 2.5).

pub mod csv;
pub mod ecmc_app;
pub mod ecmc_md;
pub(crate) mod fields;
pub mod info;
pub mod keyvalue;
pub mod layout;
pub mod renishaw;
pub(crate) mod table;
pub mod wide;
pub mod xlsx;

pub use axcheck_core::measurement::*;
pub use ecmc_app::{Source, UnknownSource};
pub use info::FileInfo;
pub use layout::{Layout, ReadTest, Recognised};
pub use table::TableKind;

use std::io::BufRead;
use std::path::Path;

/// Largest workbook read: a positioning test's book is a few hundred kB.
pub(crate) const MAX_BOOK_BYTES: usize = 16 << 20;

/// What to read of a file beyond its layout: the sheet of a workbook, the position source
/// of an ecmc ISO 230 app file.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ReadOptions<'a> {
    /// The sheet of a workbook (the first when `None`; an error for another file).
    pub sheet: Option<&'a str>,
    /// The reference of an ecmc ISO 230 app file (the one it evaluated when `None`; an
    /// error for another file).
    pub source: Option<Source>,
    /// An angular test of a linear axis (pitch, yaw, roll): angles at targets in mm, from
    /// the long or the wide CSV or either in an XLSX sheet. Without it, those units are
    /// refused as an angular test's; with it, µm or degree targets are refused, and so is
    /// every other layout (none records an angular test of a linear axis).
    pub angular: bool,
}

impl<'a> ReadOptions<'a> {
    pub fn sheet(sheet: Option<&'a str>) -> ReadOptions<'a> {
        ReadOptions {
            sheet,
            ..ReadOptions::default()
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
    let quantities = table::Quantities::angular(options.angular);
    if options.angular {
        refuse_for_angular(how, file)?;
    }
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
            return xlsx::read_for(&bytes, file, sheet, quantities);
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
                    reported: reported.map(Box::new),
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
        Layout::WideCsv => wide::read_for(reader, file, quantities)?,
        _ => csv::read_for(reader, file, quantities)?,
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

/// An angular test of a linear axis is read from the tables only (the long and the wide
/// CSV, in a text file or a workbook's sheet), whose column names carry the angle's unit.
/// A Renishaw file records no test type and no angle unit for a linear axis (see
/// [`renishaw`]); the ecmc layouts hold positions. Each is refused, saying why.
fn refuse_for_angular(how: layout::Reader, file: &str) -> Result<(), ReadError> {
    let test = table::ANGULAR_TEST.to_string();
    let kind = match how {
        layout::Reader::Table(_) | layout::Reader::Book => return Ok(()),
        layout::Reader::Renishaw => ReadErrorKind::RenishawTestNotRecorded { test },
        other => ReadErrorKind::LayoutForTest {
            test,
            layout: other.described().into(),
        },
    };
    Err(ReadError::new(Location::file(file), kind))
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
            reported: reported.map(Box::new),
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
            info: info.map(Box::new),
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
pub(crate) fn read_file_within(
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

    fn angular() -> ReadOptions<'static> {
        ReadOptions {
            angular: true,
            ..ReadOptions::default()
        }
    }

    /// An angular test is read from the tables only: another layout is refused naming the
    /// file, the test and what the file is.
    #[test]
    fn an_angular_test_is_refused_from_layouts_without_its_units() {
        let key_value = "UNIT=mm\nTGT_DATA[1]=0\nREF_DATA_FWD[1,1]=0.001\n";
        let e = read_with(key_value.as_bytes(), "x.dat", &angular()).unwrap_err();
        assert_eq!(e.location, Location::file("x.dat"));
        assert_eq!(
            e.to_string(),
            "x.dat: an angular test of a linear axis is read from the long CSV (target_mm, direction, run, deviation_arcsec, deviation_urad or deviation_deg), the wide CSV (target_mm, up_1_arcsec, down_1_arcsec, …) or either in an XLSX sheet; this file is an ecmc key=value file"
        );
        let wide = "target_mm,up_1_arcsec,down_1_arcsec\n0,1,2\n100,3,4\n";
        let read = read_with(wide.as_bytes(), "w.csv", &angular()).unwrap();
        assert_eq!(read.recognised.layout, Layout::WideCsv);
        assert_eq!(
            read.data.deviations(1, crate::units::Direction::Down),
            &[4.0]
        );
    }
}
