//! A history file's page headers checked before polars decodes them: polars 0.55 sizes
//! its buffers from a page's value count, so a damaged count (found by fuzzing: a negative
//! 32-bit count read as 2^61) makes it allocate without bound and abort the process, which
//! no error handling can catch. A data page holds at most the rows of its row group, and
//! so does a dictionary page (one entry per distinct value); no page is larger than
//! [`MAX_PAGE_BYTES`] once decompressed (polars fills a buffer of the claimed size).

use polars_buffer::Buffer;
use polars_parquet::parquet::metadata::ColumnChunkMetadata;
use polars_parquet::parquet::page::CompressedPage;
use polars_parquet::parquet::read::{get_page_iterator, read_metadata};
use polars_parquet_format::thrift::protocol::TCompactInputProtocol;
use polars_parquet_format::{PageHeader, PageType};
use std::io::Cursor;

/// Largest page axcheck reads (the page reader refuses larger ones): history pages are
/// kilobytes, a page of a 10 000-axis run a few megabytes.
const MAX_PAGE_BYTES: usize = 256 << 20;

/// Refuses a file whose footer claims more than it holds ([`super::footer`]), or one of
/// whose pages claims more values than its row group has rows or more bytes than
/// [`MAX_PAGE_BYTES`].
pub fn check(bytes: &[u8]) -> Result<(), String> {
    super::footer::check(bytes)?;
    let metadata = read_metadata(&mut Cursor::new(bytes)).map_err(|e| e.to_string())?;
    let buffer = Buffer::from(bytes.to_vec());
    for (g, group) in metadata.row_groups.iter().enumerate() {
        let rows = group.num_rows();
        for column in group.parquet_columns() {
            check_dictionary(bytes, column, rows).map_err(|e| in_column(column, g, &e))?;
            let cursor = Cursor::new(buffer.clone());
            let pages = get_page_iterator(column, cursor, Vec::new(), MAX_PAGE_BYTES)
                .map_err(|e| e.to_string())?;
            for page in pages {
                // The dictionary page was checked above: data pages only.
                let CompressedPage::Data(page) = page.map_err(|e| e.to_string())? else {
                    continue;
                };
                let values = page.num_values();
                if values > rows {
                    let e = format!("claims {values} values for {rows} rows");
                    return Err(in_column(column, g, &e));
                }
                let size = page.uncompressed_size();
                if size > MAX_PAGE_BYTES {
                    return Err(in_column(column, g, &too_large(size)));
                }
            }
        }
    }
    Ok(())
}

/// The message for a page of `column` in row group `g` (from 0).
fn in_column(column: &ColumnChunkMetadata, g: usize, what: &str) -> String {
    let name = column.descriptor().path_in_schema.join(".");
    format!("a page of column `{name}` in row group {} {what}", g + 1)
}

fn too_large(size: usize) -> String {
    format!("claims {size} bytes once decompressed, over the {MAX_PAGE_BYTES} axcheck reads")
}

/// The column's dictionary page, read where and as polars reads it (`PageReader::read_dict`:
/// the first page of the column chunk, if it is one): at most one entry per row, and no
/// larger than [`MAX_PAGE_BYTES`]. polars reserves room for the claimed count before it
/// decodes a byte. A header that cannot be read is left to polars, which refuses it.
fn check_dictionary(bytes: &[u8], column: &ColumnChunkMetadata, rows: usize) -> Result<(), String> {
    let start = usize::try_from(column.byte_range().start).unwrap_or(usize::MAX);
    let Some(at) = bytes.get(start..) else {
        return Ok(());
    };
    let mut protocol = TCompactInputProtocol::new(at, MAX_PAGE_BYTES);
    let Ok(header) = PageHeader::read_from_in_protocol(&mut protocol) else {
        return Ok(());
    };
    let (PageType::DICTIONARY_PAGE, Some(dictionary)) =
        (header.type_, header.dictionary_page_header)
    else {
        return Ok(());
    };
    let values = i64::from(dictionary.num_values);
    if values > rows as i64 {
        return Err(format!(
            "is a dictionary that claims {values} entries for {rows} rows"
        ));
    }
    let size = i64::from(header.uncompressed_page_size);
    if size > MAX_PAGE_BYTES as i64 {
        return Err(format!("is a dictionary that {}", too_large(size as usize)));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::check;

    /// A history file written without compression, then damaged by hand (the same length:
    /// the bytes the count gained were taken from the page's data): the dictionary of
    /// `campaign` claims 2^30 entries (polars reserved 16 GB for them, and aborted the run
    /// where memory is limited).
    const DICTIONARY_COUNT: &[u8] =
        include_bytes!("../../fuzz/corpus/history/oom-dictionary-count");
    /// The same file whose first data page of `campaign` claims 2^30 bytes once
    /// decompressed.
    const PAGE_SIZE: &[u8] = include_bytes!("../../fuzz/corpus/history/page-size-1GB");

    #[test]
    fn a_dictionary_claiming_more_entries_than_rows_is_refused() {
        assert_eq!(
            check(DICTIONARY_COUNT).unwrap_err(),
            "a page of column `campaign` in row group 1 is a dictionary that claims 1073741824 entries for 201 rows"
        );
    }

    #[test]
    fn a_page_larger_than_axcheck_reads_is_refused() {
        assert_eq!(
            check(PAGE_SIZE).unwrap_err(),
            "a page of column `campaign` in row group 1 claims 1073741824 bytes once decompressed, over the 268435456 axcheck reads"
        );
    }
}
