//! Text from input (names, notes, messages quoting a file) made safe for the output it goes
//! to: what a terminal, a viewer or a spreadsheet would act on instead of showing it is
//! shown as written, so a name cannot clear a screen, reverse a line, become a formula or
//! markup. One notation everywhere: a hidden character as `\u` and four hex digits
//! (`\u001b`, `\u202e`), which inside a JSON string is the JSON escape of that same
//! character.

use std::borrow::Cow;

/// Whether `c` acts on how the text around it is shown instead of being shown itself: C0
/// controls but tab and line feed, DEL, C1 controls (ECMA-48: ESC and OSC sequences, the C1
/// CSI), the bidirectional marks, embeddings, overrides and isolates of Unicode's UAX #9
/// (U+061C, U+200E/F, U+202A–U+202E, U+2066–U+2069), and the line and paragraph
/// separators U+2028/U+2029.
pub(crate) fn is_hidden(c: char) -> bool {
    matches!(c as u32,
        0x00..=0x08 | 0x0B..=0x1F | 0x7F..=0x9F | 0x061C | 0x200E | 0x200F
        | 0x2028 | 0x2029 | 0x202A..=0x202E | 0x2066..=0x2069)
}

/// `text` with each hidden character ([`is_hidden`]) written as `\uXXXX`; borrowed when
/// there is none. Applied to JSON text it changes no value (the escape is JSON's own).
pub fn visible(text: &str) -> Cow<'_, str> {
    if !text.chars().any(is_hidden) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        push_visible(&mut out, c);
    }
    Cow::Owned(out)
}

/// [`visible`] for a text that is one line by nature (a name, a title): line feeds and
/// tabs are shown as escapes too, so a name cannot break a console line or a column.
pub fn one_line(text: &str) -> Cow<'_, str> {
    if !text.chars().any(|c| is_hidden(c) || c == '\n' || c == '\t') {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        match c {
            '\n' | '\t' => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => push_visible(&mut out, c),
        }
    }
    Cow::Owned(out)
}

fn push_visible(out: &mut String, c: char) {
    if is_hidden(c) {
        out.push_str(&format!("\\u{:04x}", c as u32));
    } else {
        out.push(c);
    }
}

/// First characters that make a spreadsheet read a CSV cell as a formula (OWASP, "CSV
/// Injection": `=`, `+`, `-`, `@`, tab, carriage return), with their full-width forms,
/// which spreadsheets in East Asian locales read as the same.
const FORMULA_START: [char; 10] = [
    '=', '+', '-', '@', '\t', '\r', '\u{FF1D}', '\u{FF0B}', '\u{FF0D}', '\u{FF20}',
];

/// A text cell of a CSV file: visible, then neutralised as OWASP recommends (a cell that
/// would start a formula gets a leading `'`), then quoted as RFC 4180 asks (a field with a
/// comma, quote or line break in quotes, quotes doubled). Only for text: numbers are
/// written as numbers, never through this.
pub fn csv_text(text: &str) -> String {
    let shown = visible(text);
    let neutral = match shown.starts_with(FORMULA_START) {
        true => Cow::Owned(format!("'{shown}")),
        false => shown,
    };
    if neutral.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", neutral.replace('"', "\"\""))
    } else {
        neutral.into_owned()
    }
}

/// Text for a Markdown table cell or line (GitHub-flavoured, as in a CI job summary):
/// visible, on one line, no HTML (`<`, `>` and `&` as entities), and no Markdown syntax
/// (`\`, `` ` ``, `*`, `_`, `[`, `]`, `|`, `~`, `#`, `!` escaped with a backslash), so a
/// name shows as written and cannot end a cell, open a link or become a tag.
pub fn markdown_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '\n' | '\t' => out.push(' '),
            '\\' | '`' | '*' | '_' | '[' | ']' | '|' | '~' | '#' | '!' => {
                out.push('\\');
                out.push(c);
            }
            c => push_visible(&mut out, c),
        }
    }
    out
}

/// Text for XML 1.0 content and attributes: visible (so a C0 character, which XML 1.0
/// forbids, never makes the file invalid), markup characters as entities, U+FFFE/U+FFFF
/// (not XML characters either) as `\ufffe`/`\uffff`.
pub fn xml_text(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\u{FFFE}' | '\u{FFFF}' => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => push_visible(&mut out, c),
        }
    }
    out
}

/// `value` as compact JSON whose strings hold their hidden characters as visible text
/// (`\u001b` as six characters): for data that a page or a report shows, where a JSON
/// escape would give the character back.
pub fn shown_json(value: &impl serde::Serialize) -> serde_json::Result<Vec<u8>> {
    let mut out = Vec::new();
    let mut serializer = serde_json::Serializer::with_formatter(&mut out, Shown);
    value.serialize(&mut serializer)?;
    Ok(out)
}

/// serde_json's compact output with hidden characters written as text.
struct Shown;

impl serde_json::ser::Formatter for Shown {
    fn write_string_fragment<W: ?Sized + std::io::Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> std::io::Result<()> {
        // A JSON string holding `\uXXXX` as text: the backslash escaped.
        match fragment.chars().any(is_hidden) {
            false => writer.write_all(fragment.as_bytes()),
            true => writer.write_all(visible(fragment).replace("\\u", "\\\\u").as_bytes()),
        }
    }

    fn write_char_escape<W: ?Sized + std::io::Write>(
        &mut self,
        writer: &mut W,
        escape: serde_json::ser::CharEscape,
    ) -> std::io::Result<()> {
        use serde_json::ser::CharEscape::*;
        let text: Cow<str> = match escape {
            Quote => "\\\"".into(),
            ReverseSolidus => "\\\\".into(),
            Solidus => "\\/".into(),
            LineFeed => "\\n".into(),
            Tab => "\\t".into(),
            Backspace => "\\\\u0008".into(),
            FormFeed => "\\\\u000c".into(),
            CarriageReturn => "\\\\u000d".into(),
            AsciiControl(b) => format!("\\\\u{b:04x}").into(),
        };
        writer.write_all(text.as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_line_shows_line_breaks_and_tabs_too() {
        assert_eq!(
            super::one_line("VMC\n07\tX\u{1b}"),
            "VMC\\u000a07\\u0009X\\u001b"
        );
        assert!(matches!(
            super::one_line("长轴"),
            super::Cow::Borrowed("长轴")
        ));
    }

    #[test]
    fn hidden_characters_are_shown_as_escapes() {
        assert_eq!(visible("a\u{1b}[2Jb"), "a\\u001b[2Jb");
        assert_eq!(visible("\u{1b}]0;title\u{7}"), "\\u001b]0;title\\u0007");
        assert_eq!(
            visible("X\u{202e}Y\u{2066}\u{200f}\u{61c}"),
            "X\\u202eY\\u2066\\u200f\\u061c"
        );
        assert_eq!(visible("\u{9b}2J\u{7f}\r"), "\\u009b2J\\u007f\\u000d");
        assert!(matches!(visible("VMC-07\tY\nµm ×"), Cow::Borrowed(_)));
    }

    #[test]
    fn visible_json_keeps_its_values() {
        let json = serde_json::to_string(&"a\u{1b}\u{202e}\u{85}b").unwrap();
        let shown = visible(&json);
        assert!(!shown.chars().any(is_hidden), "{shown}");
        let back: String = serde_json::from_str(&shown).unwrap();
        assert_eq!(back, "a\u{1b}\u{202e}\u{85}b");
    }

    #[test]
    fn csv_cells_that_would_start_a_formula_are_neutralised() {
        assert_eq!(csv_text("=1+2"), "'=1+2");
        assert_eq!(csv_text("+SUM(A1)"), "'+SUM(A1)");
        assert_eq!(csv_text("-3.2"), "'-3.2");
        assert_eq!(csv_text("@cmd"), "'@cmd");
        assert_eq!(csv_text("\t=1"), "'\t=1");
        assert_eq!(csv_text("\r=1"), "\\u000d=1");
        assert_eq!(csv_text("＝1"), "'＝1");
        assert_eq!(
            csv_text("=HYPERLINK(\"x\",\"y\")"),
            "\"'=HYPERLINK(\"\"x\"\",\"\"y\"\")\""
        );
        assert_eq!(csv_text("VMC-07"), "VMC-07");
        assert_eq!(csv_text("a,b"), "\"a,b\"");
    }

    #[test]
    fn markdown_text_has_no_markup() {
        assert_eq!(
            markdown_text("<img src=x onerror=alert(1)>"),
            "&lt;img src=x onerror=alert(1)&gt;"
        );
        assert_eq!(markdown_text("a|b `c` [d](e)"), "a\\|b \\`c\\` \\[d\\](e)");
        assert_eq!(markdown_text("x\ny\u{1b}"), "x y\\u001b");
    }

    #[test]
    fn xml_text_is_valid_xml_1_0() {
        assert_eq!(
            xml_text("a<b>&\"c'\u{1}"),
            "a&lt;b&gt;&amp;&quot;c&apos;\\u0001"
        );
        assert_eq!(xml_text("\u{ffff}\u{202e}"), "\\uffff\\u202e");
    }

    #[test]
    fn shown_json_holds_the_escapes_as_text() {
        let bytes = shown_json(&("a\u{1b}[2J", "\u{202e}x\r", "tab\there \"q\" \\")).unwrap();
        let back: (String, String, String) = serde_json::from_slice(&bytes).unwrap();
        assert_eq!(back.0, "a\\u001b[2J");
        assert_eq!(back.1, "\\u202ex\\u000d");
        assert_eq!(back.2, "tab\there \"q\" \\");
    }
}
