//! The shape of the code, checked: the pipeline's stages only look down (no module
//! cycle), functions fit on a screen or two and files stay small, and sources are cited
//! by their titles.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The top-level modules from the bottom up: a module may use only modules of a lower
/// layer (its own layer's modules are independent of each other).
const LAYERS: &[&[&str]] = &[
    &["units", "suggest", "files", "panics"],
    &["measurement", "yaml", "lock", "atomic"],
    &["evaluate", "nde", "axis_model"],
    &["uncertainty", "crosscheck", "simulate"],
    &["rules", "judge", "diagnose", "trend"],
    &["compensate", "plan"],
    &["campaign", "verify"],
    &["batch"],
    &["history"],
    &["report"],
    &["export"],
    &["session"],
];

const MAX_FUNCTION_LINES: usize = 100;
const MAX_FILE_LINES: usize = 800;

fn sources() -> Vec<(PathBuf, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files: Vec<(PathBuf, String)> = walkdir::WalkDir::new(&src)
        .into_iter()
        .filter_map(Result::ok)
        .filter(|e| e.path().extension().is_some_and(|x| x == "rs"))
        .map(|e| {
            let text = std::fs::read_to_string(e.path()).unwrap();
            (e.path().strip_prefix(&src).unwrap().to_path_buf(), text)
        })
        .collect();
    files.sort();
    files
}

/// The code of a file without its unit tests.
fn code(text: &str) -> &str {
    text.find("#[cfg(test)]").map_or(text, |i| &text[..i])
}

fn top_module(path: &Path) -> String {
    let first = path
        .components()
        .next()
        .unwrap()
        .as_os_str()
        .to_string_lossy();
    first.trim_end_matches(".rs").to_string()
}

/// The top-level modules that `code` names as `crate::x` or in `crate::{x, y}` (outside
/// comments: a doc comment may point up to where its values come from).
fn uses(code: &str) -> Vec<String> {
    let code: String = code
        .lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n");
    let mut out = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let group = &group[..group.find('}').unwrap_or(group.len())];
            for part in group.split(',') {
                let name: String = part
                    .trim()
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                out.push(name);
            }
        } else {
            out.push(
                rest.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect(),
            );
        }
    }
    out
}

#[test]
fn stages_only_look_down() {
    let layer: BTreeMap<&str, usize> = LAYERS
        .iter()
        .enumerate()
        .flat_map(|(k, names)| names.iter().map(move |n| (*n, k)))
        .collect();
    let mut wrong = Vec::new();
    for (path, text) in sources() {
        let from = top_module(&path);
        if matches!(from.as_str(), "main" | "lib" | "cli") {
            continue;
        }
        let Some(&here) = layer.get(from.as_str()) else {
            panic!(
                "src/{}: module `{from}` is in no layer of LAYERS",
                path.display()
            );
        };
        for to in uses(code(&text)) {
            if to == from || to.is_empty() {
                continue;
            }
            match layer.get(to.as_str()) {
                Some(&there) if there < here => {}
                _ => wrong.push(format!("src/{} ({from}) uses {to}", path.display())),
            }
        }
    }
    wrong.sort();
    wrong.dedup();
    assert!(
        wrong.is_empty(),
        "uses that do not look down:\n{}",
        wrong.join("\n")
    );
}

/// Lengths of the functions of `code` (from the `fn` line to the brace that closes it at
/// the same indentation).
fn function_lengths(code: &str) -> Vec<(usize, String, usize)> {
    let lines: Vec<&str> = code.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        let indent = line.len() - line.trim_start().len();
        let head = line.trim_start();
        let head = head.strip_prefix("pub(crate) ").unwrap_or(head);
        let head = head.strip_prefix("pub(super) ").unwrap_or(head);
        let head = head.strip_prefix("pub ").unwrap_or(head);
        let head = head.strip_prefix("const ").unwrap_or(head);
        if let Some(rest) = head.strip_prefix("fn ")
            && !line.trim_end().ends_with(';')
        {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let close = format!("{}}}", " ".repeat(indent));
            let end = (i + 1..lines.len())
                .find(|&j| lines[j].starts_with(&close))
                .unwrap_or(lines.len());
            out.push((i + 1, name, end - i));
            i = end;
        }
        i += 1;
    }
    out
}

#[test]
fn functions_and_files_stay_small() {
    let mut long = Vec::new();
    for (path, text) in sources() {
        let code = code(&text);
        let lines = code.lines().count();
        if lines > MAX_FILE_LINES {
            long.push(format!("src/{}: {lines} lines of code", path.display()));
        }
        for (line, name, length) in function_lengths(code) {
            if length > MAX_FUNCTION_LINES {
                long.push(format!(
                    "src/{}:{line} fn {name}: {length} lines",
                    path.display()
                ));
            }
        }
    }
    assert!(long.is_empty(), "too long:\n{}", long.join("\n"));
}

#[test]
fn sources_are_cited_by_title() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<PathBuf> = vec![root.join("README.md")];
    for dir in ["src", "templates", "tests"] {
        files.extend(
            walkdir::WalkDir::new(root.join(dir))
                .into_iter()
                .filter_map(Result::ok)
                .filter(|e| {
                    e.path()
                        .extension()
                        .is_some_and(|x| x == "rs" || x == "typ" || x == "md")
                })
                .map(|e| e.path().to_path_buf()),
        );
    }
    // The pattern is built so that this file does not match itself.
    let pattern = format!("{} 00", "seed");
    let cited: Vec<String> = files
        .iter()
        .filter(|f| {
            std::fs::read_to_string(f)
                .unwrap()
                .to_lowercase()
                .contains(&pattern)
        })
        .map(|f| f.display().to_string())
        .collect();
    assert!(
        cited.is_empty(),
        "cite the documents by title (ISO 230-2, GOST 27843, Hemingray et al. 1971), not by file number: {cited:?}"
    );
}

#[test]
fn the_length_check_sees_functions() {
    let code =
        "fn a() {\n    x;\n}\n\n    pub fn b(\n        y: u8,\n    ) -> u8 {\n        y\n    }\n";
    let lengths = function_lengths(code);
    assert_eq!(
        lengths,
        vec![(1, "a".to_string(), 2), (5, "b".to_string(), 4)]
    );
    assert_eq!(
        uses("use crate::{units, evaluate::X};\ncrate::judge::y"),
        ["units", "evaluate", "judge"]
    );
}
