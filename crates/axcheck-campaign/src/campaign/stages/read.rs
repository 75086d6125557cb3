//! The reading of a test's file as the campaign states it: the file beneath the campaign's
//! folder, with the axis's reading options (sheet, ecmc reference, columns).

use crate::campaign::AxisSpec;
use crate::files::Root;
use crate::measurement::{self, ReadError, ReadTest};
use std::path::Path;

/// The test file at `path` (resolved beneath `files`) as `axis` says to read it.
pub fn read(axis: &AxisSpec, path: &Path, files: &Root) -> Result<ReadTest, ReadError> {
    let options = measurement::ReadOptions {
        // An angular test's readings are angles at positions in mm.
        angular: axis.raw.test == crate::geometry::TestKind::Angular,
        ..axis.data.read_options()
    };
    let mut read = measurement::read_file_within(path, &options, Some(files))?;
    crate::one_file::note_test(&mut read, axis.raw.test);
    Ok(read)
}
