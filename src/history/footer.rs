//! A history file's footer walked before polars decodes it. polars 0.55 sizes each list
//! of the footer (`FileMetaData`, Thrift compact protocol) from the length the list
//! claims, so a damaged length (found by fuzzing: 20 GB reserved for a 5 kB file) makes
//! it allocate without bound and abort the process; when it skips a list of booleans it
//! loops once per claimed element, so a damaged length can also make it spin for hours.
//! Every element a writer encodes takes at least one byte, so a list can claim no more
//! elements than bytes are left: that is checked here, for every list at any depth.
//!
//! The walk reads the bytes exactly as polars' decoder does (polars-parquet 0.55.2,
//! `handwritten_thrift`): a field it knows is read by its id whatever type the field
//! claims, any other is skipped by the type it claims. Otherwise a damaged type could
//! make the walk and polars part ways, and the check would look at other bytes than
//! those polars sizes its lists from. Encoding: Apache Thrift, "Thrift Compact protocol
//! encoding"; the footer's place: Apache Parquet format, "File format".

/// How polars reads a field it knows.
#[derive(Clone, Copy)]
enum Read {
    /// A varint (`read_i16/i32/i64`, `skip_vlq`).
    Varint,
    /// One byte (`read_i8`).
    Byte,
    /// A length and that many bytes (`read_string`, `skip_binary`).
    Binary,
    /// A length read as 32 bits, and that many bytes (statistics' min and max values).
    Binary32,
    /// A boolean held in the field's header: no bytes.
    Bool,
    /// A list of structures (`read_list`): the vector is sized from the length.
    List(Schema),
    /// A list skipped element by element as varints or binaries.
    SkipVarints,
    SkipBinaries,
    Struct(Schema),
}

/// The fields polars reads of one structure, by id; any other is skipped.
type Schema = &'static [(i16, Read)];

use Read::*;

const EMPTY: Schema = &[];
const FILE_METADATA: Schema = &[
    (1, Varint),
    (2, List(SCHEMA_ELEMENT)),
    (3, Varint),
    (4, List(ROW_GROUP)),
    (5, List(KEY_VALUE)),
    (6, Binary),
    (7, List(COLUMN_ORDER)),
];
const SCHEMA_ELEMENT: Schema = &[
    (1, Varint),
    (2, Varint),
    (3, Varint),
    (4, Binary),
    (5, Varint),
    (6, Varint),
    (7, Varint),
    (8, Varint),
    (9, Varint),
    (10, Struct(LOGICAL_TYPE)),
];
const ROW_GROUP: Schema = &[
    (1, List(COLUMN_CHUNK)),
    (2, Varint),
    (3, Varint),
    (4, List(SORTING_COLUMN)),
    (5, Varint),
    (6, Varint),
    (7, Varint),
];
const COLUMN_CHUNK: Schema = &[
    (1, Binary),
    (2, Varint),
    (3, Struct(COLUMN_METADATA)),
    (4, Varint),
    (5, Varint),
    (6, Varint),
    (7, Varint),
];
const COLUMN_METADATA: Schema = &[
    (1, Varint),
    (2, SkipVarints),
    (3, SkipBinaries),
    (4, Varint),
    (5, Varint),
    (6, Varint),
    (7, Varint),
    (9, Varint),
    (10, Varint),
    (11, Varint),
    (12, Struct(STATISTICS)),
    (14, Varint),
    (15, Varint),
];
const STATISTICS: Schema = &[
    (1, Binary),
    (2, Binary),
    (3, Varint),
    (4, Varint),
    (5, Binary32),
    (6, Binary32),
    (7, Bool),
    (8, Bool),
];
const KEY_VALUE: Schema = &[(1, Binary), (2, Binary)];
const SORTING_COLUMN: Schema = &[(1, Varint), (2, Bool), (3, Bool)];
const COLUMN_ORDER: Schema = &[(1, Struct(EMPTY)), (2, Struct(EMPTY))];
const LOGICAL_TYPE: Schema = &[
    (1, Struct(EMPTY)),
    (2, Struct(EMPTY)),
    (3, Struct(EMPTY)),
    (4, Struct(EMPTY)),
    (5, Struct(DECIMAL)),
    (6, Struct(EMPTY)),
    (7, Struct(TIME)),
    (8, Struct(TIME)),
    (10, Struct(INT)),
    (11, Struct(EMPTY)),
    (12, Struct(EMPTY)),
    (13, Struct(EMPTY)),
    (14, Struct(EMPTY)),
    (15, Struct(EMPTY)),
];
const DECIMAL: Schema = &[(1, Varint), (2, Varint)];
const TIME: Schema = &[(1, Bool), (2, Struct(TIME_UNIT))];
const TIME_UNIT: Schema = &[(1, Struct(EMPTY)), (2, Struct(EMPTY)), (3, Struct(EMPTY))];
const INT: Schema = &[(1, Byte), (2, Bool)];

/// polars' depth limit when it skips a field it does not know.
const SKIP_DEPTH: u8 = 64;

/// Refuses a footer one of whose lists claims more elements than bytes are left. A file
/// too short to have a footer passes: polars reports that itself.
pub fn check(file: &[u8]) -> Result<(), String> {
    let Some(footer) = footer(file) else {
        return Ok(());
    };
    let mut walk = Walk {
        bytes: footer,
        at: 0,
    };
    match walk.structure(FILE_METADATA) {
        Err(Stop::TooLong(e)) => Err(format!(
            "its footer is damaged at byte {} of {}: {e}",
            walk.at,
            footer.len() - 8
        )),
        // Other damage polars reports itself, without allocating from it.
        Ok(()) | Err(Stop::Unreadable) => Ok(()),
    }
}

/// What polars decodes: the footer and the last 8 bytes (its length, then `PAR1`).
fn footer(file: &[u8]) -> Option<&[u8]> {
    let end = file.len().checked_sub(8)?;
    let length = u32::from_le_bytes(file[end..end + 4].try_into().ok()?) as usize;
    file.get(end.checked_sub(length)?..)
}

/// Why a walk stopped.
enum Stop {
    /// A list longer than the bytes left: what polars must not read.
    TooLong(String),
    /// Damage polars stops at with an error of its own.
    Unreadable,
}

type Walked = Result<(), Stop>;

struct Walk<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Walk<'_> {
    fn left(&self) -> usize {
        self.bytes.len() - self.at
    }

    fn byte(&mut self) -> Result<u8, Stop> {
        let b = *self.bytes.get(self.at).ok_or(Stop::Unreadable)?;
        self.at += 1;
        Ok(b)
    }

    fn skip(&mut self, n: u64) -> Walked {
        match usize::try_from(n) {
            Ok(n) if n <= self.left() => {
                self.at += n;
                Ok(())
            }
            _ => Err(Stop::Unreadable),
        }
    }

    /// A ULEB128 varint, any length, its bits past 64 dropped (as polars reads it).
    fn varint(&mut self) -> Result<u64, Stop> {
        let mut value = 0u64;
        let mut shift = 0u32;
        loop {
            let b = self.byte()?;
            value |= u64::from(b & 0x7f).wrapping_shl(shift);
            if b & 0x80 == 0 {
                return Ok(value);
            }
            shift = shift.wrapping_add(7);
        }
    }

    fn zigzag(&mut self) -> Result<i64, Stop> {
        let v = self.varint()?;
        Ok((v >> 1) as i64 ^ -((v & 1) as i64))
    }

    /// A list header: its length as polars takes it (32 bits) and its element type,
    /// refused when the length is more than the bytes left.
    fn list_header(&mut self) -> Result<(usize, u8), Stop> {
        let header = self.byte()?;
        let element = header & 0x0f;
        let size = match header >> 4 {
            15 => self.varint()? as i32,
            n => i32::from(n),
        };
        let empty_untyped = element == 0 && header >> 4 == 0; // how fastparquet writes []
        if !(empty_untyped || (1..=12).contains(&element)) {
            return Err(Stop::Unreadable);
        }
        let size = usize::try_from(size).unwrap_or(0);
        if size > self.left() {
            return Err(Stop::TooLong(format!(
                "a list claims {size} elements, {} bytes are left",
                self.left()
            )));
        }
        Ok((size, element))
    }

    /// A structure's fields, those of `schema` read as polars reads them.
    fn structure(&mut self, schema: Schema) -> Walked {
        let mut last_id = 0i16;
        while let Some((kind, id)) = self.field_header(last_id)? {
            match schema.iter().find(|(known, _)| *known == id) {
                Some((_, read)) => self.known(*read)?,
                None => self.skip_value(kind, SKIP_DEPTH)?,
            }
            last_id = id;
        }
        Ok(())
    }

    /// A field's type and id (`None` at the end of the structure), as polars reads them:
    /// the id as a delta from the last one, or in full after a zero delta.
    fn field_header(&mut self, last_id: i16) -> Result<Option<(u8, i16)>, Stop> {
        let header = self.byte()?;
        let kind = header & 0x0f;
        if kind == 0 {
            return Ok(None);
        }
        if kind > 12 {
            return Err(Stop::Unreadable);
        }
        let id = match header >> 4 {
            0 => self.zigzag()? as i16,
            delta => last_id
                .checked_add(i16::from(delta))
                .ok_or(Stop::Unreadable)?,
        };
        Ok(Some((kind, id)))
    }

    fn known(&mut self, read: Read) -> Walked {
        match read {
            Varint => self.varint().map(drop),
            Byte => self.byte().map(drop),
            Binary => {
                let n = self.varint()?;
                self.skip(n)
            }
            Binary32 => {
                let n = self.varint()? as u32;
                self.skip(u64::from(n))
            }
            Bool => Ok(()),
            List(schema) => {
                let (size, _) = self.list_header()?;
                (0..size).try_for_each(|_| self.structure(schema))
            }
            SkipVarints | SkipBinaries => {
                let (size, _) = self.list_header()?;
                let each = if matches!(read, SkipVarints) {
                    Varint
                } else {
                    Binary
                };
                (0..size).try_for_each(|_| self.known(each))
            }
            Struct(schema) => self.structure(schema),
        }
    }

    /// A value of a field polars does not know, skipped by its claimed type.
    fn skip_value(&mut self, kind: u8, depth: u8) -> Walked {
        if depth == 0 {
            return Err(Stop::Unreadable);
        }
        match kind {
            1 | 2 => Ok(()), // a boolean: no bytes, also as a list element
            3 => self.byte().map(drop),
            4..=6 => self.varint().map(drop),
            7 => self.skip(8),
            8 => self.known(Binary),
            9 => {
                let (size, element) = self.list_header()?;
                (0..size).try_for_each(|_| self.skip_value(element, depth - 1))
            }
            12 => self.skip_struct(depth - 1),
            _ => Err(Stop::Unreadable), // sets and maps: polars does not skip them
        }
    }

    fn skip_struct(&mut self, depth: u8) -> Walked {
        let mut last_id = 0i16;
        while let Some((kind, id)) = self.field_header(last_id)? {
            self.skip_value(kind, depth)?;
            last_id = id;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file of `footer` followed by its length and `PAR1`.
    fn file(footer: &[u8]) -> Vec<u8> {
        let mut bytes = b"PAR1".to_vec();
        bytes.extend_from_slice(footer);
        bytes.extend_from_slice(&(footer.len() as u32).to_le_bytes());
        bytes.extend_from_slice(b"PAR1");
        bytes
    }

    #[test]
    fn a_footer_polars_writes_passes() {
        let df = polars::df!("x" => [1.0f64, 2.0], "name" => ["a", "b"]).unwrap();
        let mut bytes = Vec::new();
        polars::prelude::ParquetWriter::new(&mut bytes)
            .finish(&mut df.clone())
            .unwrap();
        assert_eq!(check(&bytes), Ok(()));
    }

    #[test]
    fn a_list_longer_than_the_footer_is_refused() {
        // Field 2 (schema): a list (9) of structures (12) claiming 2^24 elements.
        let footer = [0x29, 0xfc, 0x80, 0x80, 0x80, 0x08, 0x00];
        let e = check(&file(&footer)).unwrap_err();
        assert!(
            e.contains("at byte 6 of 7: a list claims 16777216 elements, 9 bytes are left"),
            "{e}"
        );
        // Two empty structures with the bytes for them pass; an empty list with no type.
        assert_eq!(check(&file(&[0x29, 0x2c, 0x00, 0x00, 0x00])), Ok(()));
        assert_eq!(check(&file(&[0x59, 0x00, 0x00])), Ok(()));
    }

    #[test]
    fn a_known_field_is_read_as_polars_reads_it_whatever_type_it_claims() {
        // Field 4 (row groups) claiming to be a double: polars reads a list there.
        let footer = [0x47, 0xfc, 0x80, 0x80, 0x80, 0x08, 0, 0, 0];
        let e = check(&file(&footer)).unwrap_err();
        assert!(e.contains("a list claims 16777216 elements"), "{e}");
        // Field 20, unknown: a list of booleans (1) polars would skip 2^24 times.
        let footer = [0x09, 0x28, 0xf1, 0x80, 0x80, 0x80, 0x08, 0x00];
        let e = check(&file(&footer)).unwrap_err();
        assert!(e.contains("a list claims 16777216 elements"), "{e}");
    }

    #[test]
    fn other_damage_is_left_to_polars() {
        // A binary longer than the footer: polars stops at it with an error.
        assert_eq!(check(&file(&[0x68, 0xac, 0x02, 0x00])), Ok(()));
        // 100 nested unknown structures: polars stops at its depth limit.
        assert_eq!(check(&file(&[0xfc; 100])), Ok(()));
        // A file shorter than a footer.
        assert_eq!(check(b"PAR1"), Ok(()));
    }
}
