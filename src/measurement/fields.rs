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
    let bytes = line.as_bytes();
    // Quotes to undo, or a separator that is not one byte: the careful path.
    if bytes.contains(&b'"') || !sep.is_ascii() {
        return quoted_fields(line, sep, field);
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
            field(column(start), Cow::Borrowed(&line[start..end]));
            start = end + 1;
        }
    }
    field(column(start), Cow::Borrowed(&line[start..]));
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
