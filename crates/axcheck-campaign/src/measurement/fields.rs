//! A CSV line's fields: split at the header's separator (`,`, `;` or tab), double quotes
//! undone, each field with its 1-based character column for the errors. The fields are
//! slices of the line: a text is copied only to undo quotes.

use std::borrow::Cow;

/// Splits one line at `sep`, honouring double quotes; returns each field with its
/// 1-based character column.
pub(crate) fn split_fields(line: &str, sep: char) -> Vec<(usize, String)> {
    let mut fields = Vec::new();
    fields_of(line, sep, |column, text| {
        fields.push((column, text.into_owned()))
    });
    fields
}

/// Gives `field` each field of `line` split at `sep` with its 1-based character column:
/// a slice of the line, copied only when it has double quotes to undo.
pub(crate) fn fields_of<'a>(line: &'a str, sep: char, mut field: impl FnMut(usize, Cow<'a, str>)) {
    if !plain_fields(line, sep, |column, text| field(column, Cow::Borrowed(text))) {
        quoted_fields(line, sep, field);
    }
}

/// [`fields_of`] for a line without double quotes and a one-byte separator, each field
/// a slice of the line; `false`, and no field given, for any other line. (A caller that
/// stores the fields builds them from the slices where they go: built from a `Cow` first,
/// each was copied through the stack at a tenth of the gate's reading time.)
pub(crate) fn plain_fields<'a>(
    line: &'a str,
    sep: char,
    mut field: impl FnMut(usize, &'a str),
) -> bool {
    let bytes = line.as_bytes();
    // Quotes to undo, or a separator that is not one byte: the careful path.
    if bytes.contains(&b'"') || !sep.is_ascii() {
        return false;
    }
    let sep = sep as u8;
    let ascii = line.is_ascii();
    let column = |start: usize| match ascii {
        true => start + 1,
        false => line[..start].chars().count() + 1,
    };
    let mut start = 0;
    // An ASCII separator never falls inside a multi-byte character: every cut is a
    // character boundary. (A byte loop: the fields are a few bytes long, too short for
    // a vectorised search to pay for its set-up.)
    for (end, &b) in bytes.iter().enumerate() {
        if b == sep {
            field(column(start), &line[start..end]);
            start = end + 1;
        }
    }
    field(column(start), &line[start..]);
    true
}

/// [`fields_of`] for a line with double quotes: `"a,b"` is one field, `""` a quote.
fn quoted_fields<'a>(line: &'a str, sep: char, mut out: impl FnMut(usize, Cow<'a, str>)) {
    let mut field = String::new();
    let mut start = 1;
    let mut in_quotes = false;
    let mut chars = line.chars().enumerate().peekable();
    while let Some((k, c)) = chars.next() {
        if in_quotes {
            if c == '"' {
                if chars.peek().map(|&(_, c)| c) == Some('"') {
                    field.push('"');
                    chars.next();
                } else {
                    in_quotes = false;
                }
            } else {
                field.push(c);
            }
        } else if c == '"' {
            in_quotes = true;
        } else if c == sep {
            out(start, Cow::Owned(std::mem::take(&mut field)));
            start = k + 2;
        } else {
            field.push(c);
        }
    }
    out(start, Cow::Owned(field));
}

/// The separator of a header line: `;`, else tab, else `,`.
pub(crate) fn detect_separator(header: &str) -> char {
    if header.contains(';') {
        ';'
    } else if header.contains('\t') {
        '\t'
    } else {
        ','
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plain(line: &str, sep: char) -> Option<Vec<(usize, String)>> {
        let mut out = Vec::new();
        plain_fields(line, sep, |c, t| out.push((c, t.to_string()))).then_some(out)
    }

    /// The plain path gives what the careful one gives, columns in characters; a line with
    /// quotes or a separator past ASCII is left to the careful path, with no field given.
    #[test]
    fn plain_lines_split_as_the_careful_path_does() {
        for (line, sep) in [
            ("5,up,1,0.9488", ','),
            ("µ;2,5;x", ';'),
            ("a\t\tb", '\t'),
            ("", ','),
        ] {
            assert_eq!(plain(line, sep), Some(split_fields(line, sep)), "{line:?}");
        }
        assert_eq!(plain("µ;2,5;x", ';').unwrap()[2].0, 7);
        assert_eq!(plain("\"a,b\",c", ','), None);
        assert_eq!(plain("a→b", '→'), None);
        assert_eq!(
            split_fields("\"a,b\",c", ','),
            vec![(1, "a,b".to_string()), (7, "c".to_string())]
        );
    }
}
