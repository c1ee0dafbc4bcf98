//! The students' copy holds no solution of an exercise handed out: each line of each handed-out solution
//! (`exercises/src/solutions/<name>.rs`, the bodies of its functions) is searched for in every file of the
//! copy and found in none; and the copy has no `.git` to find one in the history.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use teacher::hand_out::{hand_out, workbook_exercises};
use teacher::workbook;

/// A line this short (in characters other than white space) says too little to be an answer
/// (`if k < 0.0 {`, `} else {`); every longer one is searched for.
const SHORTEST_KEY_LINE: usize = 15;

/// The key lines of each exercise's solution: every line of its functions' bodies long enough to say
/// something, its white space collapsed.
fn key_lines() -> BTreeMap<String, Vec<String>> {
    let folder = workbook().join("exercises").join("src").join("solutions");
    let mut keys = BTreeMap::new();
    for name in workbook_exercises(workbook()).expect("the workbook's exercises") {
        let source = std::fs::read_to_string(folder.join(format!("{name}.rs"))).expect("the solution's file");
        let file = syn::parse_file(&source).expect("the solution parses");
        let lines: Vec<&str> = source.lines().collect();
        let mut found = Vec::new();
        for item in &file.items {
            let syn::Item::Fn(function) = item else { continue };
            let (open, close) = (
                function.block.brace_token.span.open().start().line,
                function.block.brace_token.span.close().start().line,
            );
            // The lines between the braces (1-based `open` is the brace's line, whose index is `open - 1`).
            for line in &lines[open..close - 1] {
                let line = collapsed(line);
                if line.chars().filter(|c| !c.is_whitespace()).count() >= SHORTEST_KEY_LINE && !line.starts_with("//") {
                    found.push(line);
                }
            }
        }
        assert!(!found.is_empty(), "{name}'s solution has no key line");
        keys.insert(name, found);
    }
    keys
}

/// `line` with its white space collapsed to single spaces.
fn collapsed(line: &str) -> String {
    line.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Every file under `dir` and its lines, white space collapsed (files that are not text: no lines).
fn files(dir: &Path) -> Vec<(PathBuf, Vec<String>)> {
    let mut found = Vec::new();
    let mut folders = vec![dir.to_path_buf()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("a readable folder").map(|e| e.expect("an entry")) {
            let path = entry.path();
            if path.is_dir() {
                folders.push(path);
            } else {
                let text = std::fs::read_to_string(&path).unwrap_or_default();
                found.push((path, text.lines().map(collapsed).collect()));
            }
        }
    }
    found
}

/// The files of `copy` that hold `key`, by their path in the copy.
fn holding(copy: &[(PathBuf, Vec<String>)], root: &Path, key: &str) -> Vec<String> {
    copy.iter()
        .filter(|(_, lines)| lines.iter().any(|line| line.contains(key)))
        .map(|(path, _)| path.strip_prefix(root).unwrap_or(path).display().to_string())
        .collect()
}

#[test]
fn a_copy_handing_out_every_exercise_holds_none_of_their_solutions_and_no_history() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let copy = dir.path().join("students");
    let all = workbook_exercises(workbook()).expect("the workbook's exercises");
    let done = hand_out(workbook(), &copy, &all).expect("handed out");
    assert!(done.files > 100, "{} files", done.files);
    assert!(!copy.join(".git").exists(), "the copy has a .git");
    assert!(!copy.join("exercises/src/solutions").exists());
    let files = files(&copy);
    let mut found = Vec::new();
    for (name, keys) in key_lines() {
        for key in keys {
            let files = holding(&files, &copy, &key);
            if !files.is_empty() {
                found.push(format!("{name}: {key:?} in {}", files.join(", ")));
            }
        }
    }
    assert!(found.is_empty(), "the copy holds solutions:\n{}", found.join("\n"));
    // The blanks are there, handed out, and the library is built for them.
    let lib = std::fs::read_to_string(copy.join("exercises/src/lib.rs")).expect("the exercises' list");
    assert!(lib.contains("pub const HANDED_OUT: &[&str] = &[\"bilinear\", \"transform_inverse\""), "{lib}");
    // The grader is told the workbook's own versions are gone, so that it advises nothing that needs them.
    assert!(lib.contains("pub const TAKEN_OUT: &[&str] = &[\"bilinear\", \"transform_inverse\""), "{lib}");
    let manifest = std::fs::read_to_string(copy.join("Cargo.toml")).expect("the manifest");
    assert!(manifest.contains("default = [\"exercises\"]"), "{manifest}");
}

#[test]
fn a_copy_handing_out_two_exercises_keeps_the_workbooks_own_version_of_the_others() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let copy = dir.path().join("students");
    let handed = ["refract".to_string(), "fresnel_schlick".to_string()];
    hand_out(workbook(), &copy, &handed).expect("handed out");
    let files = files(&copy);
    let keys = key_lines();
    // A line a solution kept in the copy shares (`let eta = eta1_over_eta2;`) says nothing of the others.
    let kept: Vec<&String> = keys.iter().filter(|(name, _)| !handed.contains(name)).flat_map(|(_, k)| k).collect();
    for name in &handed {
        for key in &keys[name] {
            if kept.iter().any(|k| k.contains(key.as_str())) {
                continue;
            }
            let files = holding(&files, &copy, key);
            assert!(files.is_empty(), "{name}: {key:?} in {}", files.join(", "));
        }
    }
    // The exact Fresnel equations, not handed out, are the workbook's own still.
    let math = std::fs::read_to_string(copy.join("src/lesson/math.rs")).expect("the library's math");
    assert!(math.contains("let rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);"));
    assert!(math.contains("todo!(\"refract\")") && math.contains("todo!(\"fresnel_schlick\")"));
}

#[test]
fn a_hand_out_is_refused_an_unknown_exercise_or_a_folder_in_use() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let e = hand_out(workbook(), &dir.path().join("a"), &["refrac".to_string()]).expect_err("no such exercise");
    assert!(e.starts_with("\"refrac\" is not one of the workbook's exercises (bilinear, "), "{e}");
    std::fs::write(dir.path().join("notes.txt"), "mine").expect("a file");
    let e = hand_out(workbook(), dir.path(), &["refract".to_string()]).expect_err("a folder in use");
    assert!(e.ends_with("is not empty: hand out into a new folder"), "{e}");
    assert_eq!(std::fs::read_to_string(dir.path().join("notes.txt")).expect("kept"), "mine");
}

/// The relative links of a Markdown text (`[text](target)`), without their `#anchor`.
fn relative_links(markdown: &str) -> Vec<String> {
    markdown
        .split("](")
        .skip(1)
        .filter_map(|rest| rest.split_once(')').map(|(target, _)| target.split('#').next().unwrap_or("").to_string()))
        .filter(|target| !target.is_empty() && !target.contains("://"))
        .collect()
}

#[test]
fn the_copys_readme_starts_with_the_grader_and_names_none_of_the_teachers_tools() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let copy = dir.path().join("students");
    let handed = ["refract".to_string(), "fresnel_schlick".to_string()];
    hand_out(workbook(), &copy, &handed).expect("handed out");
    let readme = std::fs::read_to_string(copy.join("README.md")).expect("the copy's README");
    // Its first command is the grader's.
    let first = readme.split("```sh\n").nth(1).and_then(|block| block.lines().next()).expect("a command");
    assert!(first.starts_with("cargo test --release -p exercises "), "{first}");
    // It says what to edit, and how to read each kind of verdict.
    for part in [
        "exercises/src/refract.rs",
        "exercises/src/fresnel_schlick.rs",
        "`passed`",
        "`FAILED`",
        "`not yet written`",
        "also needs",
        "`not handed out`",
    ] {
        assert!(readme.contains(part), "the README does not say {part:?}:\n{readme}");
    }
    assert!(!readme.contains("exercises/src/bilinear.rs"), "an exercise not handed out is named to edit");
    // None of the teacher's commands, folders or pages, here or in the exercises' page.
    let exercises_page = std::fs::read_to_string(copy.join("docs/exercises.md")).expect("the exercises' page");
    for (file, text) in [("README.md", &readme), ("docs/exercises.md", &exercises_page)] {
        for mark in ["-p teacher", "hand-out", "teacher/", "class.md"] {
            let lines: Vec<&str> = text.lines().filter(|line| line.contains(mark)).collect();
            assert!(lines.is_empty(), "{file} names {mark:?}: {lines:?}");
        }
    }
    assert!(!copy.join("docs/class.md").exists(), "the teacher's page is in the copy");
    // Every page it links to is in the copy.
    for link in relative_links(&readme) {
        assert!(copy.join(&link).exists(), "the README links to {link}, which the copy does not hold");
    }
    // The workbook's own README follows, its first command among the rest.
    assert!(readme.contains("cargo run --release --example fresnel"), "{readme}");
}
