//! What a measurement file was read as: its layout, found from its content (never from
//! its extension alone), and what was assumed or skipped in reading it.
//!
//! [`recognise`] looks at the file's first bytes: a ZIP archive is a workbook
//! ([`super::xlsx`]), a first line `HEADER::` a Renishaw laser file
//! ([`super::renishaw`]); otherwise the first line that is neither blank nor a `#` comment
//! decides: `KEY=VALUE` is the ecmc layout ([`super::keyvalue`]), a header naming the
//! long layout's columns is the long CSV ([`super::csv`]), one naming `up_J_UNIT` /
//! `down_J_UNIT` columns after the target is the wide CSV ([`super::wide`]). A file none
//! of them recognises is refused with what each tried and the line that failed it.
//!
//! A reader that needs the whole file in memory (a workbook, a Renishaw file) plugs in as a [`Reader`] variant: a check on the head in
//! [`recognise`] before the text layouts, a line in [`tried`], and an arm in
//! [`super::read_sheet`] that reads the bytes with [`super::read_all`] and returns its
//! [`Layout`] with its notes.

use super::AxisData;
use super::error::ReadErrorKind;
use super::table::TableKind;
use serde::Serialize;

/// The layouts axcheck reads.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Layout {
    /// One row per reading with unit-carrying column names.
    LongCsv,
    /// One row per target, a column per run and direction.
    WideCsv,
    /// A sheet of an XLSX workbook holding the long or the wide table.
    Xlsx { sheet: String, table: TableKind },
    /// `KEY=VALUE` lines with `TGT_DATA[i]`, `REF_DATA_FWD[i,j]`, `REF_DATA_BWD[i,j]`.
    KeyValue,
    /// A Renishaw laser test of a linear axis.
    RenishawRtl,
    /// A Renishaw laser test of a rotary axis.
    RenishawRta,
    /// The ecmc ISO 230 app's Markdown report.
    EcmcAppReport,
    /// The ecmc ISO 230 app's raw-points CSV.
    EcmcAppCsv,
    /// An ecmc motion system test report of 2021 (Markdown).
    EcmcReport,
}

impl Layout {
    /// A stable key for JSON.
    pub fn key(&self) -> &'static str {
        match self {
            Layout::LongCsv => "long-csv",
            Layout::WideCsv => "wide-csv",
            Layout::Xlsx { .. } => "xlsx",
            Layout::KeyValue => "key-value",
            Layout::RenishawRtl => "renishaw-rtl",
            Layout::RenishawRta => "renishaw-rta",
            Layout::EcmcAppReport => "ecmc-iso230-report",
            Layout::EcmcAppCsv => "ecmc-iso230-csv",
            Layout::EcmcReport => "ecmc-report",
        }
    }

    /// The layout for people: `long CSV`, `XLSX sheet "X axis", wide table`.
    pub fn name(&self) -> String {
        match self {
            Layout::LongCsv => "long CSV".into(),
            Layout::WideCsv => "wide CSV".into(),
            Layout::Xlsx { sheet, table } => format!("XLSX sheet \"{sheet}\", {}", table.name()),
            Layout::KeyValue => "ecmc key=value".into(),
            Layout::RenishawRtl => "Renishaw .rtl (linear)".into(),
            Layout::RenishawRta => "Renishaw .rta (rotary)".into(),
            Layout::EcmcAppReport => "ecmc ISO 230 app report (Markdown)".into(),
            Layout::EcmcAppCsv => "ecmc ISO 230 app raw points (CSV)".into(),
            Layout::EcmcReport => "ecmc motion system test report (Markdown, 2021)".into(),
        }
    }
}

/// The layout a file was read as, and what was assumed or skipped in reading it (e.g.
/// "order of measurement assumed: the standard test cycle").
#[derive(Debug, Clone, PartialEq)]
pub struct Recognised {
    pub layout: Layout,
    pub notes: Vec<String>,
    /// What the file says of its test beyond the readings (Renishaw USER-TEXT and
    /// ENVIRONMENT), when it says anything. Boxed, as `reported`: most files say nothing,
    /// and a 10 000-axis check holds one of these per axis.
    pub info: Option<Box<super::FileInfo>>,
    /// The results the tool that wrote the file printed in it (the ecmc ISO 230 app's
    /// Status list), set beside axcheck's by [`crate::crosscheck`].
    pub reported: Option<Box<super::reported::ToolResults>>,
}

impl Serialize for Recognised {
    /// `{"layout": "xlsx", "name": "XLSX sheet \"X\", wide table", "sheet": "X", "table":
    /// "wide", "notes": [...]}`; `sheet` and `table` only for a workbook.
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        #[derive(Serialize)]
        struct View<'a> {
            layout: &'static str,
            name: String,
            #[serde(skip_serializing_if = "Option::is_none")]
            sheet: Option<&'a str>,
            #[serde(skip_serializing_if = "Option::is_none")]
            table: Option<TableKind>,
            notes: &'a [String],
            #[serde(skip_serializing_if = "Option::is_none")]
            file_info: Option<&'a super::FileInfo>,
        }
        let (sheet, table) = match &self.layout {
            Layout::Xlsx { sheet, table } => (Some(sheet.as_str()), Some(*table)),
            _ => (None, None),
        };
        View {
            layout: self.layout.key(),
            name: self.layout.name(),
            sheet,
            table,
            notes: &self.notes,
            file_info: self.info.as_deref(),
        }
        .serialize(serializer)
    }
}

/// A measurement as read: the test and what it was read as.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadTest {
    pub data: AxisData,
    pub recognised: Recognised,
}

/// How a recognised file is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reader {
    /// A workbook (ZIP or OLE2 container), read whole.
    Book,
    KeyValue,
    /// A CSV table, long or wide.
    Table(TableKind),
    /// A Renishaw `.rtl`/`.rta` file, read whole.
    Renishaw,
    /// The ecmc ISO 230 app's Markdown report.
    EcmcAppReport,
    /// The ecmc ISO 230 app's raw-points CSV.
    EcmcAppCsv,
    /// An ecmc motion system test report of 2021.
    EcmcReport,
}

impl Reader {
    /// What the layout is called in a message.
    pub(crate) fn described(self) -> &'static str {
        match self {
            Reader::Book => "a workbook",
            Reader::KeyValue => "an ecmc key=value file",
            Reader::Table(TableKind::Long) => "a long CSV",
            Reader::Table(TableKind::Wide) => "a wide CSV",
            Reader::Renishaw => "a Renishaw file",
            Reader::EcmcAppReport => "an ecmc ISO 230 app report",
            Reader::EcmcAppCsv => "an ecmc ISO 230 app CSV",
            Reader::EcmcReport => "an ecmc test report",
        }
    }
}

/// The first bytes of a ZIP archive (an XLSX or ODS workbook) and of an OLE2 compound
/// file (an Excel 97–2003 `.xls`).
pub(crate) const ZIP_MAGIC: &[u8] = b"PK\x03\x04";
pub(crate) const OLE_MAGIC: &[u8] = b"\xD0\xCF\x11\xE0\xA1\xB1\x1A\xE1";

/// Chooses the reader from the file's first bytes, or says what each layout found wrong.
pub(crate) fn recognise(head: &[u8]) -> Result<Reader, ReadErrorKind> {
    if head.starts_with(ZIP_MAGIC) || head.starts_with(OLE_MAGIC) {
        return Ok(Reader::Book);
    }
    if let Some(encoding) = crate::files::utf16_kind(head) {
        return Err(ReadErrorKind::Utf16 { encoding });
    }
    if super::renishaw::looks_like(head) {
        return Ok(Reader::Renishaw);
    }
    if super::ecmc_app::markdown::looks_like(head) {
        return Ok(Reader::EcmcAppReport);
    }
    if super::ecmc_md::looks_like(head) {
        return Ok(Reader::EcmcReport);
    }
    let Some((number, line)) = first_content_line(head) else {
        // Blank or comments only: the long CSV reader says the file is empty.
        return Ok(Reader::Table(TableKind::Long));
    };
    if super::keyvalue::looks_like_key_value(line) {
        return Ok(Reader::KeyValue);
    }
    let text = std::str::from_utf8(line).ok();
    let names = text.map(header_names).unwrap_or_default();
    if super::ecmc_app::raw_csv::looks_like(&names) {
        return Ok(Reader::EcmcAppCsv);
    }
    if let Some(kind) = table_kind(&names) {
        return Ok(Reader::Table(kind));
    }
    Err(ReadErrorKind::Unrecognised {
        tried: tried(number, text),
    })
}

/// Each layout tried and why line `number` (`text`, or not UTF-8 when `None`) is not
/// its start.
fn tried(number: usize, text: Option<&str>) -> String {
    let line = match text {
        Some(t) => {
            let mut shown: String = t.trim().chars().take(40).collect();
            if t.trim().chars().count() > 40 {
                shown.push('…');
            }
            format!("line {number} `{}`", shown.escape_debug())
        }
        None => format!("line {number} (not UTF-8 text)"),
    };
    [
        "XLSX workbook: the file does not start as a ZIP archive (PK\\x03\\x04)".to_string(),
        "Renishaw .rtl/.rta: the first line is not `HEADER::`".to_string(),
        "ecmc ISO 230 app report: the first line is not `# ecmc ISO 230 Bidirectional Positioning Report`".to_string(),
        "ecmc test report: the first line is not `# ecmc motion system test report`".to_string(),
        format!("ecmc key=value: {line} is not KEY=VALUE"),
        format!("long CSV: {line} names none of target_mm|target_deg, direction, run, deviation_um …"),
        format!(
            "wide CSV: {line} has neither target_mm|target_deg first nor up_J_UNIT/down_J_UNIT columns"
        ),
        format!(
            "ecmc ISO 230 app raw points: {line} has not the columns cycle, direction, target, selected_reference_slot"
        ),
    ]
    .join("; ")
}

/// The first line of `head` that is neither blank nor a `#` comment, with its 1-based
/// number, without a leading BOM or the line ending.
fn first_content_line(head: &[u8]) -> Option<(usize, &[u8])> {
    let head = head.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(head);
    head.split(|&b| b == b'\n')
        .enumerate()
        .map(|(k, line)| (k + 1, line.trim_ascii()))
        .find(|(_, line)| !line.is_empty() && !line.starts_with(b"#"))
}

/// A CSV header's column names: split at its separator, trimmed, lower case.
fn header_names(line: &str) -> Vec<String> {
    let sep = super::fields::detect_separator(line);
    super::fields::split_fields(line, sep)
        .into_iter()
        .map(|(_, name)| name.trim().to_ascii_lowercase())
        .collect()
}

/// The table a header announces: wide when a column is named `up_…`/`down_…`, or when it
/// starts with the target and has no column of the long layout; long when a column is
/// (or nearly is) one of the long layout's; else none.
pub(crate) fn table_kind(names: &[String]) -> Option<TableKind> {
    let first_is_target = names
        .first()
        .is_some_and(|n| n.starts_with("target_") || n == "target");
    let has_long_column = names
        .iter()
        .any(|n| n != "target" && !n.starts_with("target_") && super::csv::is_long_column(n));
    if names.iter().any(|n| super::wide::is_run_column(n)) || (first_is_target && !has_long_column)
    {
        Some(TableKind::Wide)
    } else if names.iter().any(|n| super::csv::is_long_column(n)) {
        Some(TableKind::Long)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(list: &[&str]) -> Vec<String> {
        list.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn header_kinds() {
        let long = names(&["target_mm", "direction", "run", "deviation_um"]);
        assert_eq!(table_kind(&long), Some(TableKind::Long));
        let wide = names(&["target_mm", "up_1_um", "down_1_um"]);
        assert_eq!(table_kind(&wide), Some(TableKind::Wide));
        // A typo in a run column still reads as wide, so its reader can name the typo.
        let typo = names(&["target_deg", "up1_arcsec", "down_1_arcsec"]);
        assert_eq!(table_kind(&typo), Some(TableKind::Wide));
        let only_target = names(&["target_mm", "up1"]);
        assert_eq!(table_kind(&only_target), Some(TableKind::Wide));
        let long_typo = names(&["target_mm", "direction", "run", "deviaton_um"]);
        assert_eq!(table_kind(&long_typo), Some(TableKind::Long));
        assert_eq!(table_kind(&names(&["name", "age"])), None);
        assert_eq!(table_kind(&[]), None);
    }

    #[test]
    fn recognises_by_content() {
        assert_eq!(recognise(b"# c\nUNIT=mm\n"), Ok(Reader::KeyValue));
        assert_eq!(recognise(b"TGT_DATA[1]=3\n"), Ok(Reader::KeyValue));
        assert_eq!(
            recognise(b"\xEF\xBB\xBFtarget_mm,direction,run,deviation_um\n"),
            Ok(Reader::Table(TableKind::Long))
        );
        assert_eq!(
            recognise(b"\n# wide\ntarget_mm;up_1_um;down_1_um\n"),
            Ok(Reader::Table(TableKind::Wide))
        );
        assert_eq!(recognise(b""), Ok(Reader::Table(TableKind::Long)));
        assert_eq!(recognise(b"PK\x03\x04rest"), Ok(Reader::Book));
    }

    #[test]
    fn unrecognised_lists_what_was_tried() {
        let Err(ReadErrorKind::Unrecognised { tried }) = recognise(b"# x\nhello world\n") else {
            panic!("recognised")
        };
        assert!(tried.starts_with("XLSX workbook: "), "{tried}");
        assert!(tried.contains("ecmc key=value: line 2 `hello world` is not KEY=VALUE"));
        assert!(tried.contains("long CSV: line 2 `hello world` names none of"));
        assert!(tried.contains("wide CSV: line 2 `hello world` has neither"));
        let Err(ReadErrorKind::Unrecognised { tried }) = recognise(b"\xc3\x28junk") else {
            panic!("recognised")
        };
        assert!(tried.contains("line 1 (not UTF-8 text)"), "{tried}");
    }

    #[test]
    fn utf16_is_named() {
        let le: Vec<u8> = "target_mm,direction\n"
            .encode_utf16()
            .flat_map(u16::to_le_bytes)
            .collect();
        let be: Vec<u8> = "target_mm,direction\n"
            .encode_utf16()
            .flat_map(u16::to_be_bytes)
            .collect();
        let with_bom = [&[0xFF, 0xFE][..], &le].concat();
        for (bytes, encoding) in [
            (&le, "UTF-16 little-endian"),
            (&be, "UTF-16 big-endian"),
            (&with_bom, "UTF-16 little-endian"),
        ] {
            assert_eq!(recognise(bytes), Err(ReadErrorKind::Utf16 { encoding }));
        }
    }

    #[test]
    fn names_and_keys() {
        let sheet = Layout::Xlsx {
            sheet: "X axis".into(),
            table: TableKind::Wide,
        };
        assert_eq!(sheet.name(), "XLSX sheet \"X axis\", wide table");
        assert_eq!(sheet.key(), "xlsx");
        let r = Recognised {
            layout: sheet,
            notes: vec!["n".into()],
            info: None,
            reported: None,
        };
        assert_eq!(
            serde_json::to_string(&r).unwrap(),
            r#"{"layout":"xlsx","name":"XLSX sheet \"X axis\", wide table","sheet":"X axis","table":"wide","notes":["n"]}"#
        );
        assert_eq!(Layout::RenishawRta.name(), "Renishaw .rta (rotary)");
    }
}
