//! Every path of the workbook that the README, the docs, the examples and the doc comments cite exists, so
//! that none goes stale when a file moves.

use crate::common::root;
use std::path::{Path, PathBuf};

/// The workbook's top-level folders, whose paths are checked.
const FOLDERS: [&str; 8] = ["src", "tests", "benches", "examples", "docs", "textures", "expected", "exercises"];

/// The text files to read: the README, docs/, examples/, src/, tests/, benches/ and exercises/.
fn files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs" || e == "md") {
                out.push(path);
            }
        }
    }
    let mut out = vec![root().join("README.md")];
    for folder in ["docs", "examples", "src", "tests", "benches", "exercises/src", "exercises/tests"] {
        walk(&root().join(folder), &mut out);
    }
    out
}

/// The workbook paths cited in `text`: a top-level folder, then path characters, up to a file name with an
/// extension or a folder's trailing slash.
fn cited(text: &str) -> Vec<String> {
    let mut paths = Vec::new();
    for (i, _) in text.match_indices('/') {
        let start = text[..i]
            .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
            .map_or(0, |s| s + text[s..].chars().next().map_or(1, char::len_utf8));
        // A cargo feature of a package (`--features exercises/solutions`) is not a path either.
        if !FOLDERS.contains(&&text[start..i])
            || text[..start].ends_with(['/', '.', ':', '-', '<', '{', '$'])
            || text[..start].ends_with("--features ")
        {
            continue;
        }
        let end = text[i..]
            .find(|c: char| !(c.is_ascii_alphanumeric() || matches!(c, '_' | '.' | '/' | '-')))
            .map_or(text.len(), |e| i + e);
        let path = text[start..end].trim_end_matches('.');
        let tail = &text[end..];
        // Patterns and placeholders (`examples/<name>.rs`, `out/{name}`, `examples/hw1.rs`, a student's own
        // `examples/my_floor.png`) are not paths.
        if tail.starts_with(['<', '{', '*'])
            || path.starts_with("examples/hw")
            || path.rsplit('/').next().is_some_and(|name| name.starts_with("my_"))
            || path.ends_with('/') && path.len() == i + 1 - start
        {
            continue;
        }
        paths.push(path.to_string());
    }
    paths
}

#[test]
fn every_path_the_docs_and_comments_cite_exists() {
    let mut missing = Vec::new();
    for file in files() {
        let text = std::fs::read_to_string(&file).unwrap();
        for path in cited(&text) {
            // A file of the exercises crate may cite its paths from the crate's own folder.
            let in_exercises =
                file.starts_with(root().join("exercises")) && root().join("exercises").join(&path).exists();
            if !root().join(&path).exists() && !in_exercises {
                missing.push(format!("{}: {path}", file.strip_prefix(root()).unwrap().display()));
            }
        }
    }
    missing.sort();
    missing.dedup();
    assert!(missing.is_empty(), "{} cited paths do not exist:\n{}", missing.len(), missing.join("\n"));
}
