//! Plain-text table helpers for the terminal.

/// Width of `s` on a terminal: combining marks (as in X̄, B̄) take no column.
pub fn width(s: &str) -> usize {
    s.chars()
        .filter(|c| !matches!(*c as u32, 0x0300..=0x036F))
        .count()
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
}
