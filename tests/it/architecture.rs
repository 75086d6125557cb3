//! The shape of the code, checked: the pipeline's stages only look down (no module
//! cycle), functions fit on a screen or two and files stay small, and sources are cited
//! by their titles.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The top-level modules from the bottom up: a module may use only modules of a lower
/// layer (its own layer's modules are independent of each other).
const LAYERS: &[&[&str]] = &[
    &[
        "units",
        "lang",
        "param_key",
        "suggest",
        "files",
        "panics",
        "safe_text",
    ],
    &["measurement", "yaml", "lock", "atomic", "inputs"],
    &["evaluate", "nde", "axis_model"],
    &["uncertainty", "crosscheck", "simulate"],
    &["rules", "judge", "diagnose", "trend"],
    &["geometry"],
    &["compensate", "plan", "one_file"],
    &["verify"],
    &["campaign"],
    &["results"],
    &["table", "words"],
    &["chart_kit"],
    &["charts"],
    &["data"],
    &["figures"],
    &["batch"],
    &["history"],
    &["report"],
    &["export"],
    &["session"],
    &["other_tests"],
];

const MAX_FUNCTION_LINES: usize = 100;
const MAX_FILE_LINES: usize = 800;

/// The source folders of the workspace's crates, the top first (README "Layout").
const CRATES: &[&str] = &[
    "python/src",
    "src",
    "crates/axcheck-charts/src",
    "crates/axcheck-campaign/src",
    "crates/axcheck-core/src",
];

/// What each lower crate must build without (README "Layout"): the core opens no file,
/// parses no YAML and reads no workbook; neither draws a page nor writes Parquet.
const FORBIDDEN: &[(&str, &[&str])] = &[
    (
        "crates/axcheck-core",
        &[
            "typst",
            "polars",
            "calamine",
            "serde_norway",
            "walkdir",
            "zip",
        ],
    ),
    (
        "crates/axcheck-campaign",
        &["typst", "polars", "plotters", "rust_xlsxwriter"],
    ),
    (
        "crates/axcheck-charts",
        &["typst", "polars", "calamine", "rust_xlsxwriter"],
    ),
    // The Python package wraps the pure crates: a wheel without Typst or polars, and
    // nothing of the root package (README "Python").
    ("python", &["typst", "polars"]),
];

/// The `.rs` files under `dir` (relative to the workspace), each with its path in the crate.
fn sources_of(dir: &str) -> Vec<(PathBuf, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join(dir);
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

/// Every crate's files: its source folder, and each file with its path in the crate.
fn sources() -> Vec<(&'static str, PathBuf, String)> {
    CRATES
        .iter()
        .flat_map(|dir| {
            sources_of(dir)
                .into_iter()
                .map(move |(path, text)| (*dir, path, text))
        })
        .collect()
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

/// `code` without its comment lines: a doc comment may point up to where its values come
/// from, which is no use.
fn without_comments(code: &str) -> String {
    code.lines()
        .filter(|line| !line.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The top-level modules that `code` names as `crate::x` or in `crate::{x, y}` (outside
/// comments).
fn uses(code: &str) -> Vec<String> {
    let code = without_comments(code);
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
    for (dir, path, text) in sources() {
        let from = top_module(&path);
        if matches!(from.as_str(), "main" | "lib" | "cli") {
            continue;
        }
        let Some(&here) = layer.get(from.as_str()) else {
            panic!(
                "{dir}/{}: module `{from}` is in no layer of LAYERS",
                path.display()
            );
        };
        for to in uses(code(&text)) {
            if to == from || to.is_empty() {
                continue;
            }
            match layer.get(to.as_str()) {
                Some(&there) if there < here => {}
                _ => wrong.push(format!("{dir}/{} ({from}) uses {to}", path.display())),
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
    for (dir, path, text) in sources() {
        let code = code(&text);
        let lines = code.lines().count();
        if lines > MAX_FILE_LINES {
            long.push(format!("{dir}/{}: {lines} lines of code", path.display()));
        }
        for (line, name, length) in function_lengths(code) {
            if length > MAX_FUNCTION_LINES {
                long.push(format!(
                    "{dir}/{}:{line} fn {name}: {length} lines",
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
    for dir in ["src", "crates", "templates", "tests"] {
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

/// The module path of a source file (`diagnose/effects/drift.rs` → diagnose, effects,
/// drift; a `mod.rs` is its folder; `lib.rs` and `main.rs` the crate).
fn module_of(path: &Path) -> Vec<String> {
    let mut parts: Vec<String> = path
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().unwrap_or_default();
    match last.as_str() {
        "mod.rs" | "lib.rs" | "main.rs" => {}
        file => parts.push(file.trim_end_matches(".rs").to_string()),
    }
    parts
}

/// Every path a use tree names: `a::{b, c::{d, e}}` → a::b, a::c::d, a::c::e.
fn expand_tree(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        return vec![tree.split(" as ").next().unwrap_or("").trim().to_string()];
    };
    let prefix = &tree[..open];
    let close = tree.rfind('}').filter(|&c| c > open).unwrap_or(tree.len());
    let inner = &tree[open + 1..close];
    let (mut parts, mut depth, mut start) = (Vec::new(), 0, 0);
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.trim().is_empty())
        .flat_map(expand_tree)
        .map(|p| format!("{prefix}{p}"))
        .collect()
}

/// The module paths `code` names: its `use` trees (not its re-exports) and its inline
/// `crate::…` and `super::…` paths (outside comments).
fn named_paths(code: &str) -> Vec<String> {
    let code = without_comments(code);
    let mut out = Vec::new();
    let mut lines = code.lines();
    while let Some(line) = lines.next() {
        let line = line.trim_start();
        // A re-export (`pub use child::Thing;`) is the folder's front, not a use of it.
        let Some(tree) = line.strip_prefix("use ") else {
            continue;
        };
        let mut tree = tree.to_string();
        while !tree.contains(';') {
            let Some(more) = lines.next() else { break };
            tree.push_str(more);
        }
        out.extend(expand_tree(tree.trim_end().trim_end_matches(';')));
    }
    // Inline paths, outside the use statements just read and the visibilities
    // (`pub(in crate::report)` names where an item is seen, not what it uses).
    let code: String = without_uses(&code).replace("pub(in crate::", "pub(in ");
    for start in ["crate::", "super::"] {
        for (i, _) in code.match_indices(start) {
            let path: String = code[i..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            out.push(path);
        }
    }
    out
}

/// `code` without its `use` statements (which may span lines).
fn without_uses(code: &str) -> String {
    let mut out = String::new();
    let mut in_use = false;
    for line in code.lines() {
        let trimmed = line.trim_start();
        if trimmed.starts_with("use ") || trimmed.starts_with("pub use ") {
            in_use = true;
        }
        if !in_use {
            out.push_str(line);
            out.push('\n');
        }
        if in_use && line.contains(';') {
            in_use = false;
        }
    }
    out
}

/// The source file a path named in the file of module `here` leads to: the deepest
/// module along it that is a file.
fn file_of(here: &[String], path: &str, files: &BTreeMap<Vec<String>, PathBuf>) -> Option<PathBuf> {
    let mut segments = path.split("::").filter(|s| !s.is_empty());
    let mut module: Vec<String> = match segments.next()? {
        "crate" => Vec::new(),
        "self" => here.to_vec(),
        "super" => here[..here.len().saturating_sub(1)].to_vec(),
        // A path from a child module (`use frame::Frame;`); else another crate's.
        child => {
            let mut module = here.to_vec();
            module.push(child.to_string());
            if !files.contains_key(&module) {
                return None;
            }
            module
        }
    };
    for s in segments {
        if s == "super" {
            module.pop();
        } else {
            module.push(s.to_string());
        }
    }
    (0..=module.len())
        .rev()
        .find_map(|k| files.get(&module[..k]).cloned())
}

/// The circles of the graph of `src/` with files as nodes (each as its files in order).
fn circles(edges: &BTreeMap<PathBuf, Vec<PathBuf>>) -> Vec<Vec<PathBuf>> {
    // Tarjan's strongly connected components; a component of two or more is a circle.
    struct State<'a> {
        edges: &'a BTreeMap<PathBuf, Vec<PathBuf>>,
        index: BTreeMap<&'a Path, (usize, usize)>,
        stack: Vec<&'a Path>,
        found: Vec<Vec<PathBuf>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a Path) {
        let n = s.index.len();
        s.index.insert(v, (n, n));
        s.stack.push(v);
        for w in s.edges.get(v).into_iter().flatten() {
            match s.index.get(w.as_path()).copied() {
                None => {
                    visit(s, w);
                    let low = s.index[w.as_path()].1.min(s.index[v].1);
                    s.index.get_mut(v).unwrap().1 = low;
                }
                Some((wi, _)) if s.stack.contains(&w.as_path()) => {
                    let low = wi.min(s.index[v].1);
                    s.index.get_mut(v).unwrap().1 = low;
                }
                Some(_) => {}
            }
        }
        if s.index[v].0 == s.index[v].1 {
            let at = s.stack.iter().position(|x| *x == v).unwrap();
            let component: Vec<PathBuf> = s.stack.drain(at..).map(Path::to_path_buf).collect();
            if component.len() > 1 {
                s.found.push(component);
            }
        }
    }
    let mut s = State {
        edges,
        index: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for v in edges.keys() {
        if !s.index.contains_key(v.as_path()) {
            visit(&mut s, v);
        }
    }
    s.found
}

/// No circle anywhere in the graph of files of a crate: a file that uses another is never
/// used back, directly or around, also inside a folder (between crates the compiler
/// allows none).
#[test]
fn no_circle_of_files() {
    let mut found = Vec::new();
    for dir in CRATES {
        for c in circles(&file_graph(&sources_of(dir))) {
            let names: Vec<String> = c.iter().map(|p| format!("{dir}/{}", p.display())).collect();
            found.push(names.join(" ↔ "));
        }
    }
    assert!(found.is_empty(), "circles of files:\n{}", found.join("\n"));
}

/// The files of one crate as nodes, an arrow from each to the files it names.
fn file_graph(sources: &[(PathBuf, String)]) -> BTreeMap<PathBuf, Vec<PathBuf>> {
    let files: BTreeMap<Vec<String>, PathBuf> = sources
        .iter()
        .filter(|(path, _)| path != Path::new("main.rs"))
        .map(|(path, _)| (module_of(path), path.clone()))
        .collect();
    let mut edges: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    for (path, text) in sources {
        let here = module_of(path);
        let mut to: Vec<PathBuf> = named_paths(code(text))
            .iter()
            .filter_map(|p| file_of(&here, p, &files))
            .filter(|target| target != path)
            .collect();
        to.sort();
        to.dedup();
        edges.insert(path.clone(), to);
    }
    edges
}

#[test]
fn use_trees_are_expanded() {
    assert_eq!(
        expand_tree("super::{a, b::{c, d as e}}"),
        ["super::a", "super::b::c", "super::b::d"]
    );
    let files: BTreeMap<Vec<String>, PathBuf> = [
        (vec!["x".to_string()], PathBuf::from("x/mod.rs")),
        (
            vec!["x".to_string(), "y".to_string()],
            PathBuf::from("x/y.rs"),
        ),
    ]
    .into_iter()
    .collect();
    let here = vec!["x".to_string(), "z".to_string()];
    assert_eq!(
        file_of(&here, "super::y::Thing", &files),
        Some(PathBuf::from("x/y.rs"))
    );
    assert_eq!(
        file_of(&here, "crate::x::Other", &files),
        Some(PathBuf::from("x/mod.rs"))
    );
    assert_eq!(
        file_of(&["x".to_string()], "y::Thing", &files),
        Some(PathBuf::from("x/y.rs"))
    );
    assert_eq!(file_of(&here, "serde::Serialize", &files), None);
    let edges: BTreeMap<PathBuf, Vec<PathBuf>> = [
        (PathBuf::from("a"), vec![PathBuf::from("b")]),
        (PathBuf::from("b"), vec![PathBuf::from("a")]),
        (PathBuf::from("c"), vec![PathBuf::from("a")]),
    ]
    .into_iter()
    .collect();
    assert_eq!(circles(&edges).len(), 1);
}

/// The lower crates' manifests name none of the dependencies their layer forbids, and
/// name only crates below them in the workspace (the compiler holds the rest: a crate
/// cannot import one it does not depend on).
#[test]
fn lower_crates_depend_on_no_heavy_or_higher_crate() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut wrong = Vec::new();
    for (dir, forbidden) in FORBIDDEN {
        let manifest = std::fs::read_to_string(root.join(dir).join("Cargo.toml")).unwrap();
        let deps: Vec<String> = manifest
            .lines()
            .skip_while(|l| !l.starts_with("[dependencies]"))
            .skip(1)
            .take_while(|l| !l.starts_with("[dev-dependencies]"))
            .filter_map(|l| l.split_once('=').map(|(k, _)| k.trim().replace('-', "_")))
            .filter(|k| !k.starts_with('#') && !k.starts_with('['))
            .collect();
        for dep in &deps {
            if forbidden.iter().any(|f| dep.starts_with(f)) || dep == "axcheck" {
                wrong.push(format!("{dir} depends on {dep}"));
            }
        }
        if *dir == "crates/axcheck-core" && deps.iter().any(|d| d == "axcheck_campaign") {
            wrong.push(format!(
                "{dir} depends on axcheck-campaign, a crate above it"
            ));
        }
    }
    assert!(wrong.is_empty(), "{wrong:#?}");
}
