//! Where each test's own outputs go (its report, its compensation table): one folder per
//! machine, one file per axis test, names safe on every file system.

use crate::campaign::geometry::symbol;
use crate::geometry::TestKind;
use crate::results::CampaignResult;
use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

/// Longest file-name part, in bytes of UTF-8: with `-testK`, `-N` and the extension the
/// name stays under the 255 bytes of ext4 and the 255 UTF-16 units of NTFS.
const NAME_BYTES: usize = 120;

/// A file-name part from user text: letters, marks and digits of every script, `-`, `_` and
/// `.` kept (`Ось X` → `Ось_X`); anything else (`/`, `\`, `:`, `..`, NUL, controls,
/// spaces, direction marks) becomes `_`; no leading dot and no trailing dot (Windows drops
/// it); Windows' reserved device names get a trailing `_`; at most 64 characters and
/// [`NAME_BYTES`] bytes, cut before a letter, never between it and its marks.
pub(crate) fn safe_name(text: &str) -> String {
    use unicode_properties::{GeneralCategoryGroup as G, UnicodeGeneralCategory};
    let mut s = String::new();
    for (n, c) in text.chars().enumerate() {
        let group = c.general_category_group();
        let kept = matches!(group, G::Letter | G::Mark | G::Number) || matches!(c, '-' | '_' | '.');
        let c = if kept { c } else { '_' };
        let full = n >= 64 || s.len() + c.len_utf8() > NAME_BYTES;
        if full && group != G::Mark || s.len() + c.len_utf8() > NAME_BYTES {
            break;
        }
        s.push(c);
    }
    while s.starts_with('.') {
        s.replace_range(0..1, "_");
    }
    while s.ends_with('.') {
        s.pop();
        s.push('_');
    }
    if s.is_empty() {
        s.push('_');
    }
    if reserved_on_windows(&s) {
        s.push('_');
    }
    s
}

/// `CON`, `PRN`, `AUX`, `NUL`, `COM1`…`COM9`, `LPT1`…`LPT9` (also with the superscript
/// digits ¹ ² ³, and `COM0`/`LPT0`), before any extension: Windows opens the device.
fn reserved_on_windows(name: &str) -> bool {
    let stem = name.split('.').next().unwrap_or("").to_uppercase();
    let digit = |d: &str| {
        let mut it = d.chars();
        matches!((it.next(), it.next()), (Some(c), None) if c.is_ascii_digit() || "¹²³".contains(c))
    };
    matches!(stem.as_str(), "CON" | "PRN" | "AUX" | "NUL")
        || ["COM", "LPT"]
            .iter()
            .any(|p| stem.strip_prefix(p).is_some_and(digit))
}

/// A path per test under `folder`, `MACHINE/AXIS.ext` (`AXIS-testK.ext` when an axis has
/// several tests), unique even when names collide after sanitising.
pub(crate) fn test_paths(result: &CampaignResult, folder: &str, ext: &str) -> Vec<PathBuf> {
    test_stems(result, folder)
        .into_iter()
        .map(|stem| PathBuf::from(format!("{}.{ext}", stem.display())))
        .collect()
}

/// [`test_paths`] without the extension (each test's file may take its own).
pub(crate) fn test_stems(result: &CampaignResult, folder: &str) -> Vec<PathBuf> {
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
            // An axis's other laser tests beside its positioning test: `X-EYX`.
            let axis = match t.spec.as_ref().and_then(|s| symbol(&s.raw)) {
                Some(symbol) => safe_name(&format!("{}-{symbol}", t.axis)),
                None if t.test_kind() == TestKind::Squareness => {
                    safe_name(&format!("{}-squareness", t.axis))
                }
                None => safe_name(&t.axis),
            };
            let base = match t.tests > 1 {
                true => format!("{axis}-test{}", t.test),
                false => axis,
            };
            let name = unique(&base, used.entry(dir.clone()).or_default());
            PathBuf::from(folder).join(dir).join(name)
        })
        .collect()
}

fn unique(base: &str, taken: &mut BTreeSet<String>) -> String {
    let mut name = base.to_string();
    let mut k = 2;
    // Case-insensitive file systems (NTFS, APFS) fold every script's case.
    while !taken.insert(name.to_lowercase()) {
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
        assert_eq!(safe_name(".."), "__");
        assert_eq!(safe_name("a\0b"), "a_b");
        assert_eq!(safe_name("slit 1"), "slit_1");
        assert_eq!(safe_name("CON"), "CON_");
        assert_eq!(safe_name("com1.txt"), "com1.txt_");
        assert_eq!(safe_name(""), "_");
        assert_eq!(safe_name("Ось X"), "Ось_X");
        assert_eq!(safe_name("COM¹"), "COM¹_");
        assert_eq!(safe_name("lpt0.pdf"), "lpt0.pdf_");
        assert_eq!(safe_name("X."), "X_");
    }

    #[test]
    fn every_script_keeps_its_letters() {
        assert_eq!(safe_name("Станок-16К20Ф3"), "Станок-16К20Ф3");
        assert_eq!(safe_name("主轴Z轴"), "主轴Z轴");
        assert_eq!(safe_name("ציר Y"), "ציר_Y");
        assert_eq!(safe_name("المحور X"), "المحور_X");
        // Combining marks stay with their letter (X̄, Hindi vowel signs).
        assert_eq!(safe_name("X\u{304}"), "X\u{304}");
        assert_eq!(safe_name("अक्ष"), "अक्ष");
        // Windows' forbidden characters and direction overrides are replaced.
        assert_eq!(safe_name("a<b>c:d\"e|f?g*h\\i/j"), "a_b_c_d_e_f_g_h_i_j");
        assert_eq!(safe_name("\u{202E}X"), "_X");
    }

    #[test]
    fn names_are_bounded_in_characters_and_bytes() {
        assert_eq!(safe_name(&"x".repeat(10_000)).len(), 64);
        // 4-byte letters: at most NAME_BYTES bytes, whole characters.
        let wide = safe_name(&"𠀀".repeat(100));
        assert_eq!(wide, "𠀀".repeat(NAME_BYTES / 4));
        // Deterministic.
        assert_eq!(safe_name("Ось X"), safe_name("Ось X"));
    }
}
