//! `USER-TEXT::`: what the operator typed about the test (free text, any field may be
//! empty). It names the machine and the conditions (ISO 230-2 clause 7.1) when the
//! campaign does not.

use super::text::{Section, shown};
use super::unused_keys;

/// The USER-TEXT:: fields; `None` when absent or empty.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct UserText {
    /// `Machine`.
    pub machine: Option<String>,
    /// `Serial No` of the machine.
    pub serial: Option<String>,
    /// `Date`, free format as typed.
    pub date: Option<String>,
    /// `By`: who measured.
    pub operator: Option<String>,
    /// `Axis`.
    pub axis: Option<String>,
    /// `Location`.
    pub location: Option<String>,
    /// `TITLE`.
    pub title: Option<String>,
}

/// Reads USER-TEXT:: (a file without it gives empty fields and a note).
pub(super) fn read(section: Option<&Section>, notes: &mut Vec<String>) -> UserText {
    let mut out = UserText::default();
    let Some(section) = section else {
        notes.push("no USER-TEXT:: section: machine, serial number, operator and axis not given by the file".into());
        return out;
    };
    let mut unused = Vec::new();
    for line in &section.lines {
        let Some(kv) = line.key_value() else {
            unused.push(shown(line.text()));
            continue;
        };
        let field = match kv.normal.as_str() {
            "machine" => &mut out.machine,
            "serialno" => &mut out.serial,
            "date" => &mut out.date,
            "by" => &mut out.operator,
            "axis" => &mut out.axis,
            "location" => &mut out.location,
            "title" => &mut out.title,
            _ => {
                unused.push(shown(kv.key));
                continue;
            }
        };
        *field = (!kv.value.is_empty()).then(|| kv.value.to_string());
    }
    unused_keys("USER-TEXT", &unused, notes);
    out
}
