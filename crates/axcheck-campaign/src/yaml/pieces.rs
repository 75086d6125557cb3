//! A long top-level list parsed in pieces at once. A fleet's campaign is one `machines:`
//! list of thousands of items; parsed whole, it was a fifth of the CI gate's wall time on
//! 10 000 axes, on one core while the others waited.
//!
//! The text is cut only where the cut is certain: the list is a block list whose items
//! each start with `- ` at one indentation, every other line of it is indented deeper,
//! blank or a comment, and the file has no tab, anchor, alias, tag, directive or document
//! marker (nothing that could tie one item to another or change how a line continues).
//! Then each piece is a YAML list of its own, and the list is the pieces' items in order.
//! Anything else, and any piece that does not parse, gives `None`: the caller parses the
//! text whole, and an error is the whole parse's.

use rayon::prelude::*;
use serde_norway::Value;

/// Fewer items than this are parsed whole: cutting would not pay.
const MIN_ITEMS: usize = 256;

/// The document `text` whose top-level key `key` holds a block list, parsed in up to
/// `pieces` pieces at once; `None` when the text is not plainly cut (see the module).
pub(super) fn parse_list_in_pieces(text: &str, key: &str, pieces: usize) -> Option<Value> {
    if pieces < 2 || !plain(text) {
        return None;
    }
    let lines = line_starts(text);
    let list = find_list(text, &lines, key)?;
    if list.items.len() < MIN_ITEMS {
        return None;
    }
    let header = format!(
        "{}{}",
        &text[..list.body_start],
        &text[list.body_end.min(text.len())..]
    );
    let groups = split_evenly(&list.items, list.body_end, pieces);
    let parsed: Vec<Option<Vec<Value>>> = groups
        .par_iter()
        .map(
            |&(start, end, count)| match serde_norway::from_str::<Value>(&text[start..end]) {
                Ok(Value::Sequence(items)) if items.len() == count => Some(items),
                _ => None,
            },
        )
        .collect();
    let mut top = match serde_norway::from_str::<Value>(&header).ok()? {
        Value::Mapping(top) => top,
        _ => return None,
    };
    let slot = top.get_mut(key)?;
    if !slot.is_null() {
        return None;
    }
    let mut items = Vec::with_capacity(list.items.len());
    for group in parsed {
        items.extend(group?);
    }
    *slot = Value::Sequence(items);
    Some(Value::Mapping(top))
}

/// Whether nothing in `text` can tie lines together beyond their indentation.
fn plain(text: &str) -> bool {
    let marks = |b: u8| matches!(b, b'\t' | b'&' | b'*' | b'!' | b'\r');
    if text.bytes().any(marks) {
        return false;
    }
    !text
        .lines()
        .any(|line| line.starts_with('%') || line.starts_with("---") || line.starts_with("..."))
}

/// Byte offset of each line's start, and the text's length last.
fn line_starts(text: &str) -> Vec<usize> {
    let mut starts = vec![0];
    starts.extend(text.match_indices('\n').map(|(k, _)| k + 1));
    if *starts.last().unwrap_or(&0) != text.len() {
        starts.push(text.len());
    }
    starts
}

/// The list under `key:`: where its body starts and ends and where each item starts.
struct List {
    body_start: usize,
    body_end: usize,
    items: Vec<usize>,
}

fn find_list(text: &str, lines: &[usize], key: &str) -> Option<List> {
    let line = |k: usize| &text[lines[k]..lines[k + 1]];
    let heading = format!("{key}:");
    let first = (0..lines.len() - 1).find(|&k| line(k).trim_end() == heading)?;
    let body_start = lines[first + 1];
    let mut items = Vec::new();
    let mut indent = None;
    let mut body_end = text.len();
    for bounds in lines[first + 1..].windows(2) {
        let (start, l) = (bounds[0], &text[bounds[0]..bounds[1]]);
        let content = l.trim_start_matches(' ');
        if content.trim().is_empty() || content.starts_with('#') {
            continue;
        }
        let depth = l.len() - content.len();
        let item = content.starts_with("- ");
        match indent {
            None if item => indent = Some(depth),
            None => return None,
            Some(i) if depth == i && item => {}
            Some(i) if depth > i => continue,
            // The list ends at the next top-level key.
            Some(_) if depth == 0 && !content.starts_with('-') => {
                body_end = start;
                break;
            }
            Some(_) => return None,
        }
        items.push(start);
    }
    Some(List {
        body_start,
        body_end,
        items,
    })
}

/// The items cut into `pieces` runs of about equal count: (start, end, items) each.
fn split_evenly(items: &[usize], end: usize, pieces: usize) -> Vec<(usize, usize, usize)> {
    let per = items.len().div_ceil(pieces);
    items
        .chunks(per)
        .enumerate()
        .map(|(g, chunk)| {
            let stop = items.get((g + 1) * per).copied().unwrap_or(end);
            (chunk[0], stop, chunk.len())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fleet(n: usize, indent: &str) -> String {
        let mut text = String::from("# fleet\ncampaign: {name: F, date: 2026-11-20}\nmachines:\n");
        for m in 0..n {
            text.push_str(&format!(
                "{indent}- id: M{m:05}\n{indent}  model: \"a: b\"\n{indent}  axes:\n{indent}    - {{name: X, kind: linear, travel: {}, data: data/m{m}/x.csv}}\n{indent}    - name: Y\n{indent}      note: |\n{indent}        two\n{indent}        lines\n\n{indent}# between\n",
                100 + m
            ));
        }
        text
    }

    fn whole(text: &str) -> Value {
        serde_norway::from_str(text).unwrap()
    }

    #[test]
    fn pieces_give_the_whole_parse() {
        for indent in ["", "  "] {
            let text = fleet(300, indent);
            for pieces in [2, 3, 8] {
                let cut = parse_list_in_pieces(&text, "machines", pieces).expect("cut");
                assert_eq!(cut, whole(&text), "indent {indent:?}, {pieces} pieces");
            }
            let after = format!("{text}output: {{pdf: false}}\n");
            let cut = parse_list_in_pieces(&after, "machines", 2).expect("cut");
            assert_eq!(cut, whole(&after));
        }
    }

    /// The campaign `axcheck simulate --fleet` writes (the bench's): cut, and the same.
    #[test]
    fn a_simulated_fleet_is_cut_and_the_same() {
        let text = crate::simulate::fleet::generate(2000, 7).campaign_yaml;
        let cut = parse_list_in_pieces(&text, "machines", 8).expect("cut");
        assert_eq!(cut, whole(&text));
        let Value::Mapping(top) = &cut else {
            panic!("a mapping")
        };
        assert!(
            top["machines"]
                .as_sequence()
                .is_some_and(|m| m.len() >= MIN_ITEMS)
        );
    }

    #[test]
    fn what_could_tie_lines_is_parsed_whole() {
        let text = fleet(300, "  ");
        let cases = [
            text.replacen("model: \"a: b\"", "model: &m x", 1),
            text.replacen("model: \"a: b\"", "model: !!str x", 1),
            text.replacen("  model:", "\tmodel:", 1),
            text.replacen("machines:\n", "machines: # list\n  - {id: A}\n---\n", 1),
            text.replacen("  - id: M00007", " - id: M00007", 1),
            text.replacen("machines:\n", "machines: []\nother:\n", 1),
            fleet(10, "  "),
        ];
        for (k, case) in cases.iter().enumerate() {
            assert!(
                parse_list_in_pieces(case, "machines", 2).is_none(),
                "case {k}"
            );
        }
        assert!(parse_list_in_pieces(&text, "machines", 1).is_none());
    }

    #[test]
    fn a_broken_piece_gives_none() {
        let text = fleet(300, "  ").replacen("model: \"a: b\"", "model: \"a: b", 1);
        assert!(parse_list_in_pieces(&text, "machines", 2).is_none());
        assert!(serde_norway::from_str::<Value>(&text).is_err());
    }
}
