//! Where every key and value of a YAML document is written, by path, so that errors
//! found after parsing still name line and column. Built when first asked: a file read
//! without an error (a 10 000-axis campaign in the CI gate) never needs it, and building it
//! is a second parse of the text.

use rustc_hash::FxHashMap;
use saphyr_parser::{Event, Parser};
use std::sync::{Arc, OnceLock};

/// Line and column (both 1-based) of every key and value of a text, by path
/// (`machines[0].axes[1].kind`), indexed at the first question.
#[derive(Debug, Default, Clone)]
pub struct LocationIndex {
    text: Arc<str>,
    built: OnceLock<Built>,
}

/// The index itself.
#[derive(Debug, Default, Clone)]
struct Built {
    // FxHash: the paths are the program's own, not an attacker's choice of collisions
    // worth defending against, and a 10 000-axis campaign has 100 000 of them.
    keys: FxHashMap<String, (usize, usize)>,
    values: FxHashMap<String, (usize, usize)>,
    /// Where each YAML document of the stream starts.
    documents: Vec<(usize, usize)>,
}

enum Frame {
    Map { path: String, key: Option<String> },
    Seq { path: String, index: usize },
}

fn child(frame: &mut Frame) -> Option<String> {
    match frame {
        Frame::Map { path, key } => key.take().map(|k| join(path, &k)),
        Frame::Seq { path, index } => {
            let p = format!("{path}[{index}]");
            *index += 1;
            Some(p)
        }
    }
}

/// `path.key`, or `key` at the top.
pub fn join(path: &str, key: &str) -> String {
    if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    }
}

impl LocationIndex {
    /// The index of `text`, built when first asked.
    pub fn new(text: &str) -> LocationIndex {
        LocationIndex {
            text: Arc::from(text),
            built: OnceLock::new(),
        }
    }

    fn built(&self) -> &Built {
        self.built.get_or_init(|| Built::new(&self.text))
    }

    /// Where the key at `path` is written.
    pub fn key(&self, path: &str) -> Option<(usize, usize)> {
        self.built().keys.get(path).copied()
    }

    /// Where the value at `path` is written, or failing that its key, or the nearest parent.
    pub fn value(&self, path: &str) -> Option<(usize, usize)> {
        let built = self.built();
        let mut p = path.to_string();
        loop {
            if let Some(at) = built.values.get(&p).or_else(|| built.keys.get(&p)) {
                return Some(*at);
            }
            let cut = p.rfind(['.', '['])?;
            p.truncate(cut);
        }
    }

    /// Where the second YAML document of the stream starts, if there is one.
    pub(crate) fn second_document(&self) -> Option<(usize, usize)> {
        self.built().documents.get(1).copied()
    }

    /// Where the key at `path` is written, or failing that its value or nearest parent.
    pub(crate) fn key_or_value(&self, path: &str) -> Option<(usize, usize)> {
        self.key(path).or_else(|| self.value(path))
    }
}

impl Built {
    /// Indexes `text`; a syntax error leaves the index partial (the YAML parser that reads
    /// the values reports it).
    fn new(text: &str) -> Built {
        let mut index = Built::default();
        // About one key a colon and one value a key or list item: sized once, not doubled.
        let colons = text.bytes().filter(|&b| b == b':').count();
        index.keys.reserve(colons);
        index.values.reserve(colons + colons / 4);
        let mut stack: Vec<Frame> = Vec::new();
        for event in Parser::new_from_str(text) {
            let Ok((event, span)) = event else { break };
            let at = (span.start.line(), span.start.col() + 1);
            match event {
                Event::Scalar(value, ..) => match stack.last_mut() {
                    Some(Frame::Map { path, key }) if key.is_none() => {
                        let k = value.to_string();
                        index.keys.insert(join(path, &k), at);
                        *key = Some(k);
                    }
                    Some(frame) => {
                        if let Some(p) = child(frame) {
                            index.values.insert(p, at);
                        }
                    }
                    None => {}
                },
                Event::Alias(_) => {
                    if let Some(p) = stack.last_mut().and_then(child) {
                        index.values.insert(p, at);
                    }
                }
                Event::MappingStart(..) | Event::SequenceStart(..) => {
                    let path = stack.last_mut().and_then(child).unwrap_or_default();
                    index.values.insert(path.clone(), at);
                    stack.push(if matches!(event, Event::MappingStart(..)) {
                        Frame::Map { path, key: None }
                    } else {
                        Frame::Seq { path, index: 0 }
                    });
                }
                Event::MappingEnd | Event::SequenceEnd => {
                    stack.pop();
                }
                Event::DocumentStart(_) => index.documents.push(at),
                _ => {}
            }
        }
        index
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const DOC: &str = "campaign:\n  name: x\nmachines:\n  - id: M1\n    axes:\n      - name: X\n        kind: linear\n      - {name: Y, kind: rotary}\n";

    #[test]
    fn indexes_keys_and_values() {
        let i = LocationIndex::new(DOC);
        assert_eq!(i.key("campaign.name"), Some((2, 3)));
        assert_eq!(i.value("campaign.name"), Some((2, 9)));
        assert_eq!(i.key("machines[0].axes[0].kind"), Some((7, 9)));
        assert_eq!(i.value("machines[0].axes[1]"), Some((8, 9)));
        assert_eq!(i.key("machines[0].axes[1].kind"), Some((8, 19)));
        assert_eq!(i.value("machines[0].axes[1].missing"), Some((8, 9)));
    }
}
