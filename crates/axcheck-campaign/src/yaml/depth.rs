//! The nesting of flow collections (`[` and `{`) bounded before the text is parsed.
//! libyaml's scanner, under serde_norway, checks every open flow level at each token, so
//! its time grows with the square of the depth: 200 kB of `[` took 20 s (200 000 levels:
//! 79 s) before its own recursion limit of 128 refused them. This scan is linear and
//! refuses the same depth at once.

use super::Located;

/// The deepest flow nesting read: serde_norway refuses deeper values anyway (its
/// recursion limit), and a campaign or spec nests a few levels.
pub const MAX_DEPTH: usize = 128;

/// Refuses `text` when its flow collections nest deeper than [`MAX_DEPTH`], at the
/// bracket that goes too deep. A lexical scan: quoted scalars and comments are skipped,
/// and a `[` or `{` inside a plain scalar of block context is text, not a collection.
pub fn check(text: &str) -> Result<(), Located> {
    let mut scan = Scan::default();
    for (number, line) in text.split('\n').enumerate() {
        scan.starts_scalar = true;
        if let Some(column) = scan.line(line) {
            let message = format!(
                "the values nest deeper than {MAX_DEPTH} levels of `[` and `{{`; axcheck reads at most {MAX_DEPTH} (a campaign needs a few): close the brackets or write the value as a block"
            );
            return Err(Located::new(Some((number + 1, column)), message));
        }
    }
    Ok(())
}

/// Where the scan is: the open flow levels, an open quoted scalar, and whether the next
/// character may start a scalar (after a line's indentation, `:`, `-`, `,`, `[` or `{`).
#[derive(Default)]
struct Scan {
    depth: usize,
    quote: Option<char>,
    starts_scalar: bool,
}

impl Scan {
    /// Scans one line; the 1-based column (in characters) of a bracket past the limit.
    fn line(&mut self, line: &str) -> Option<usize> {
        let mut previous = ' ';
        let mut chars = line.chars().enumerate().peekable();
        while let Some((k, c)) = chars.next() {
            if let Some(q) = self.quote {
                let doubled =
                    c == '\'' && q == '\'' && chars.peek().is_some_and(|&(_, n)| n == '\'');
                if doubled || (c == '\\' && q == '"') {
                    // `''` in single quotes, `\x` in double quotes: not the closing quote.
                    chars.next();
                } else if c == q {
                    self.quote = None;
                }
                previous = c;
                continue;
            }
            match c {
                '#' if previous.is_whitespace() => break,
                '"' | '\'' if self.starts_scalar => self.quote = Some(c),
                '[' | '{' if self.starts_scalar || self.depth > 0 => {
                    self.depth += 1;
                    if self.depth > MAX_DEPTH {
                        return Some(k + 1);
                    }
                }
                ']' | '}' if self.depth > 0 => self.depth -= 1,
                _ => {}
            }
            self.starts_scalar = match c {
                ' ' | '\t' => self.starts_scalar || matches!(previous, ':' | '-' | '?'),
                '[' | '{' | ',' => self.starts_scalar || self.depth > 0,
                _ => false,
            };
            previous = c;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_flow_levels_only() {
        let deep = |n: usize| format!("a: {}1{}\n", "[".repeat(n), "]".repeat(n));
        assert!(check(&deep(MAX_DEPTH)).is_ok());
        let e = check(&deep(MAX_DEPTH + 1)).unwrap_err();
        assert_eq!(e.at, Some((1, 4 + MAX_DEPTH)));
        // Brackets in quoted and plain scalars and in comments are text.
        let text = format!(
            "a: '{0}'\nb: \"{0}\"\nc: x{0}\nd: 1 # {0}\n",
            "[".repeat(MAX_DEPTH + 1)
        );
        assert!(check(&text).is_ok(), "{:?}", check(&text));
        // Levels add up across lines and close.
        let lines = "a: [\n".repeat(MAX_DEPTH) + &"]\n".repeat(MAX_DEPTH) + "b: [[1]]\n";
        assert!(check(&lines).is_ok());
    }
}
