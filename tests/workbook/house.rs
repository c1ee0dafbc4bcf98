//! The shape of the lesson (`src/lesson`): a layered house. Its files import one another (by their
//! `use crate::lesson::...` lines) only in the slides' recursion (`raytrace` calls a shader, which calls
//! `raytrace`) and the one place that dispatches the course's types: no circle of files that import each
//! other has more than 10 files. And the lesson stays a size a
//! student can read: at most 6,600 lines of code (not blank, not a comment).
//!
//! Print the circle: `cargo test --release --test workbook house -- --nocapture`.

use crate::common::{root, rust_files};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The module path of a file of the lesson: `shader/mod.rs` is `["shader"]`, `shader/layered.rs`
/// `["shader", "layered"]`.
fn module_of(file: &Path) -> Vec<String> {
    let relative = file.strip_prefix(root().join("src/lesson")).unwrap().with_extension("");
    let mut parts: Vec<String> = relative.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    if parts.last().is_some_and(|p| p == "mod") {
        parts.pop();
    }
    parts
}

/// The paths a `use` tree names (`a::{b, c::d}` is `a::b` and `a::c::d`), each as its segments.
fn paths_of(tree: &str) -> Vec<Vec<String>> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or(tree);
        return vec![path.split("::").map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect()];
    };
    let prefix: Vec<String> =
        tree[..open].split("::").map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect();
    let inner = &tree[open + 1..tree.rfind('}').unwrap()];
    let (mut depth, mut start, mut out) = (0, 0, Vec::new());
    let mut branches = Vec::new();
    for (i, c) in inner.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                branches.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    branches.push(&inner[start..]);
    for branch in branches.into_iter().filter(|b| !b.trim().is_empty()) {
        for path in paths_of(branch) {
            out.push(prefix.iter().cloned().chain(path).collect());
        }
    }
    out
}

/// For every file of the lesson, the files of the lesson its `use crate::lesson::...` statements import (a
/// path is the file of its longest prefix that is a module: `crate::lesson::shader::Lambert` is
/// `shader/mod.rs`).
fn imports() -> BTreeMap<PathBuf, BTreeSet<PathBuf>> {
    let files = rust_files(&root().join("src/lesson"));
    let modules: BTreeMap<Vec<String>, PathBuf> = files.iter().map(|f| (module_of(f), f.clone())).collect();
    let mut graph = BTreeMap::new();
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        let mut targets = BTreeSet::new();
        let mut statement: Option<String> = None;
        for line in text.lines() {
            let line = line.trim();
            let line = line.strip_prefix("pub(crate) ").or_else(|| line.strip_prefix("pub ")).unwrap_or(line);
            if statement.is_none() && line.starts_with("use crate::lesson::") {
                statement = Some(String::new());
            }
            let Some(so_far) = statement.as_mut() else { continue };
            so_far.push_str(line);
            if let Some(whole) = so_far.strip_suffix(';') {
                for path in paths_of(whole.trim_start_matches("use crate::lesson::")) {
                    let target = (1..=path.len()).rev().find_map(|k| modules.get(&path[..k]));
                    if let Some(target) = target.filter(|t| *t != file) {
                        targets.insert(target.clone());
                    }
                }
                statement = None;
            }
        }
        graph.insert(file.clone(), targets);
    }
    graph
}

/// The circles of files that import each other (the strongly connected components of the import graph,
/// Tarjan's algorithm), largest first.
fn circles(graph: &BTreeMap<PathBuf, BTreeSet<PathBuf>>) -> Vec<Vec<PathBuf>> {
    struct Search<'a> {
        graph: &'a BTreeMap<PathBuf, BTreeSet<PathBuf>>,
        index: BTreeMap<&'a PathBuf, usize>,
        low: BTreeMap<&'a PathBuf, usize>,
        stack: Vec<&'a PathBuf>,
        circles: Vec<Vec<PathBuf>>,
    }
    impl<'a> Search<'a> {
        fn visit(&mut self, v: &'a PathBuf) {
            let n = self.index.len();
            self.index.insert(v, n);
            self.low.insert(v, n);
            self.stack.push(v);
            for w in &self.graph[v] {
                if !self.index.contains_key(w) {
                    self.visit(w);
                    self.low.insert(v, self.low[v].min(self.low[w]));
                } else if self.stack.contains(&w) {
                    self.low.insert(v, self.low[v].min(self.index[w]));
                }
            }
            if self.low[v] == self.index[v] {
                let at = self.stack.iter().rposition(|w| *w == v).unwrap();
                self.circles.push(self.stack.split_off(at).into_iter().cloned().collect());
            }
        }
    }
    let mut search =
        Search { graph, index: BTreeMap::new(), low: BTreeMap::new(), stack: Vec::new(), circles: Vec::new() };
    for v in graph.keys() {
        if !search.index.contains_key(v) {
            search.visit(v);
        }
    }
    let mut circles = search.circles;
    circles.sort_by_key(|c| std::cmp::Reverse(c.len()));
    circles
}

#[test]
fn no_circle_of_the_lessons_files_has_more_than_10() {
    let graph = imports();
    assert!(graph.values().map(BTreeSet::len).sum::<usize>() > 50, "too few imports found: the parser is broken");
    let largest = circles(&graph).into_iter().next().unwrap();
    let names: Vec<String> =
        largest.iter().map(|f| f.strip_prefix(root().join("src/lesson")).unwrap().display().to_string()).collect();
    println!("the largest circle, {} files: {}", names.len(), names.join(", "));
    assert!(largest.len() <= 10, "{} files of src/lesson import each other: {}", largest.len(), names.join(", "));
}

/// A circle of files that import each other is found: the test above can fail.
#[test]
fn a_circle_of_imports_is_found() {
    let file = |name: &str| PathBuf::from(name);
    let graph = BTreeMap::from([
        (file("a"), BTreeSet::from([file("b")])),
        (file("b"), BTreeSet::from([file("c")])),
        (file("c"), BTreeSet::from([file("a"), file("d")])),
        (file("d"), BTreeSet::new()),
    ]);
    assert_eq!(circles(&graph)[0].len(), 3);
    assert_eq!(paths_of("crate::lesson::{a::B, c::{d, e as f}}").len(), 3);
}

#[test]
fn the_lesson_is_at_most_6600_lines_of_code() {
    let mut lines = 0;
    for file in rust_files(&root().join("src/lesson")) {
        let text = std::fs::read_to_string(&file).unwrap();
        lines += text.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with("//")).count();
    }
    println!("src/lesson: {lines} lines of code");
    assert!(lines <= 6600, "src/lesson has {lines} lines of code, more than 6,600");
}
