//! Plain-text table helpers for the terminal.

/// Width of `s` on a terminal (Unicode's East Asian Width, UAX #11): combining marks (as in
/// X̄, B̄) take no column, CJK characters two.
pub fn width(s: &str) -> usize {
    unicode_width::UnicodeWidthStr::width(s)
}

/// `s` padded on the left to `w` columns.
pub fn right(s: &str, w: usize) -> String {
    format!("{}{s}", " ".repeat(w.saturating_sub(width(s))))
}

/// `s` padded on the right to `w` columns.
pub fn left(s: &str, w: usize) -> String {
    format!("{s}{}", " ".repeat(w.saturating_sub(width(s))))
}

/// Lines of the tests that need attention printed at most; the rest are counted.
pub const MAX_PROBLEM_LINES: usize = 20;

#[cfg(test)]
mod tests {
    #[test]
    fn combining_marks_take_no_width() {
        assert_eq!(super::width("X̄i↑"), 3);
        assert_eq!(super::right("B̄", 3), "  B̄");
    }

    /// Issue 42: a CJK name takes two columns a character, so the columns after it line up.
    #[test]
    fn wide_characters_take_two_columns() {
        assert_eq!(super::width("长轴 X"), 6);
        assert_eq!(super::left("长轴", 6), "长轴  ");
    }
}
