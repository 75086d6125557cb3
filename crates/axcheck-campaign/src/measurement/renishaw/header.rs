//! `HEADER::` (file type, owner, version) and whether the test is linear or rotary.

use super::text::{Section, shown};
use super::unused_keys;
use std::path::Path;

/// HEADER:: and the TARGET DATA:: fields that describe the file rather than the test.
/// Their values are free text; what they mean is known only from one writer.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Header {
    /// `File type`: `rtl` or `rta` in the files described.
    pub file_type: Option<String>,
    /// `Owner`, e.g. the software module that wrote the file.
    pub(crate) owner: Option<String>,
    /// `Version no` of that software.
    pub version: Option<String>,
    /// `Filetype` of TARGET DATA::, e.g. `ISO`.
    pub(crate) test_type: Option<String>,
    /// `Flags` after the targets, as written (meaning not documented).
    pub flags: Option<String>,
}

/// Reads HEADER:: (present: the file starts with it).
pub(super) fn read(section: Option<&Section>, notes: &mut Vec<String>) -> Header {
    let mut header = Header::default();
    let mut unused = Vec::new();
    for line in section.map_or(&[][..], |s| &s.lines) {
        let Some(kv) = line.key_value() else {
            unused.push(shown(line.text()));
            continue;
        };
        let value = (!kv.value.is_empty()).then(|| kv.value.to_string());
        match kv.normal.as_str() {
            "filetype" => header.file_type = value,
            "owner" => header.owner = value,
            "versionno" => header.version = value,
            _ => unused.push(shown(kv.key)),
        }
    }
    unused_keys("HEADER", &unused, notes);
    header
}

/// Linear or rotary: the file's extension, which is what the laser software and every
/// reader goes by; HEADER's `File type` when the name has neither (it is written by one
/// known writer only). A disagreement is noted; without either the test is read as linear.
pub(super) fn rotary(file: &str, file_type: Option<&str>, notes: &mut Vec<String>) -> bool {
    let by_type = |t: &str| -> Option<bool> {
        match t.trim().to_ascii_lowercase().as_str() {
            "rtl" | ".rtl" => Some(false),
            "rta" | ".rta" => Some(true),
            _ => None,
        }
    };
    let by_name = Path::new(file)
        .extension()
        .and_then(|e| e.to_str())
        .and_then(by_type);
    let in_header = file_type.and_then(by_type);
    match (by_name, in_header) {
        (Some(name), Some(header)) if name != header => {
            notes.push(format!(
                "the file is named .{} but HEADER says `File type : {}`; read as {} from the name",
                if name { "rta" } else { "rtl" },
                shown(file_type.unwrap_or_default()),
                if name { "rotary" } else { "linear" },
            ));
            name
        }
        (Some(name), _) => name,
        (None, Some(header)) => header,
        (None, None) => {
            notes.push(
                "neither the file name (.rtl/.rta) nor HEADER's `File type` says linear or rotary; read as linear (.rtl)"
                    .into(),
            );
            false
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn name_then_header_decides_rotary() {
        let mut notes = Vec::new();
        assert!(rotary("a/B.RTA", None, &mut notes));
        assert!(!rotary("b.rtl", Some("rtl"), &mut notes));
        assert!(rotary("stdin", Some(" rta "), &mut notes));
        assert!(notes.is_empty());
        assert!(!rotary("b.rtl", Some("rta"), &mut notes));
        assert_eq!(
            notes[0],
            "the file is named .rtl but HEADER says `File type : rta`; read as linear from the name"
        );
        assert!(!rotary("b.txt", Some("xyz"), &mut notes));
        assert!(notes[1].starts_with("neither the file name"));
    }
}
