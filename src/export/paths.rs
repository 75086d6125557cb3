//! Where each test's own outputs go (its report, its compensation table): one folder per
//! machine, one file per axis test, names safe on every file system.

use crate::batch::CampaignResult;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

/// A file-name part from user text: ASCII letters, digits, `-`, `_` and `.` kept, anything
/// else (`/`, `..`, NUL, spaces, non-ASCII) becomes `_`; no leading dot; Windows' reserved
/// device names get a trailing `_`; at most 64 characters.
pub fn safe_name(text: &str) -> String {
    let mut s: String = text
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.') {
                c
            } else {
                '_'
            }
        })
        .take(64)
        .collect();
    while s.starts_with('.') {
        s.replace_range(0..1, "_");
    }
    if s.is_empty() {
        s.push('_');
    }
    let stem = s.split('.').next().unwrap_or("").to_ascii_uppercase();
    let reserved = matches!(stem.as_str(), "CON" | "PRN" | "AUX" | "NUL")
        || ((stem.starts_with("COM") || stem.starts_with("LPT"))
            && stem.len() == 4
            && stem.as_bytes()[3].is_ascii_digit());
    if reserved {
        s.push('_');
    }
    s
}

/// A path per test under `folder`, `MACHINE/AXIS.ext` (`AXIS-testK.ext` when an axis has
/// several tests), unique even when names collide after sanitising.
pub fn test_paths(result: &CampaignResult, folder: &str, ext: &str) -> Vec<PathBuf> {
    test_stems(result, folder)
        .into_iter()
        .map(|stem| PathBuf::from(format!("{}.{ext}", stem.display())))
        .collect()
}

/// [`test_paths`] without the extension (each test's file may take its own).
pub fn test_stems(result: &CampaignResult, folder: &str) -> Vec<PathBuf> {
    let mut used: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let mut machine_dirs: BTreeMap<String, String> = BTreeMap::new();
    let mut taken_dirs: BTreeSet<String> = BTreeSet::new();
    result
        .tests
        .iter()
        .map(|t| {
            let dir = machine_dirs
                .entry(t.machine.id.clone())
                .or_insert_with(|| unique(&safe_name(&t.machine.id), &mut taken_dirs))
                .clone();
            let base = if t.tests > 1 {
                format!("{}-test{}", safe_name(&t.axis), t.test)
            } else {
                safe_name(&t.axis)
            };
            let name = unique(&base, used.entry(dir.clone()).or_default());
            PathBuf::from(folder).join(dir).join(name)
        })
        .collect()
}

fn unique(base: &str, taken: &mut BTreeSet<String>) -> String {
    let mut name = base.to_string();
    let mut k = 2;
    while !taken.insert(name.to_ascii_lowercase()) {
        name = format!("{base}-{k}");
        k += 1;
    }
    name
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_safe() {
        assert_eq!(safe_name("VMC-07"), "VMC-07");
        assert_eq!(safe_name("../etc/passwd"), "_._etc_passwd");
        assert_eq!(safe_name(".."), "_.");
        assert_eq!(safe_name("a\0b"), "a_b");
        assert_eq!(safe_name("slit 1"), "slit_1");
        assert_eq!(safe_name("CON"), "CON_");
        assert_eq!(safe_name("com1.txt"), "com1.txt_");
        assert_eq!(safe_name(""), "_");
        assert_eq!(safe_name("Ось X"), "____X");
    }
}
