//! A history file's page headers checked before polars decodes them: polars 0.55 sizes
//! its buffers from a page's value count, so a damaged count (found by fuzzing: a negative
//! 32-bit count read as 2^61) makes it allocate without bound and abort the process, which
//! no error handling can catch. A data page holds at most the rows of its row group.

use polars_buffer::Buffer;
use polars_parquet::parquet::page::CompressedPage;
use polars_parquet::parquet::read::{get_page_iterator, read_metadata};
use std::io::Cursor;

/// Largest page axcheck reads (the page reader refuses larger ones): history pages are
/// kilobytes, a page of a 10 000-axis run a few megabytes.
const MAX_PAGE_BYTES: usize = 256 << 20;

/// Refuses a file whose footer claims more than it holds ([`super::footer`]) or whose data
/// pages claim more values than their row group has rows.
pub fn check(bytes: &[u8]) -> Result<(), String> {
    super::footer::check(bytes)?;
    let metadata = read_metadata(&mut Cursor::new(bytes)).map_err(|e| e.to_string())?;
    let buffer = Buffer::from(bytes.to_vec());
    for (g, group) in metadata.row_groups.iter().enumerate() {
        let rows = group.num_rows();
        for column in group.parquet_columns() {
            let cursor = Cursor::new(buffer.clone());
            let pages = get_page_iterator(column, cursor, Vec::new(), MAX_PAGE_BYTES)
                .map_err(|e| e.to_string())?;
            for page in pages {
                // A dictionary page's count is not public in polars 0.55: data pages only.
                let CompressedPage::Data(page) = page.map_err(|e| e.to_string())? else {
                    continue;
                };
                let values = page.num_values();
                if values > rows {
                    let name = &column.descriptor().path_in_schema.join(".");
                    return Err(format!(
                        "a page of column `{name}` in row group {} claims {values} values for {rows} rows",
                        g + 1
                    ));
                }
            }
        }
    }
    Ok(())
}
