//! The students' copy of the workbook: the chosen exercises handed out as blanks, and their solutions
//! nowhere in it.
//!
//! The copy holds the files git would track (the workbook's `.gitignore` is followed: no `target/`, no
//! `out/`), without `.git` (no history to `git show` a solution from) and without what only the teacher
//! uses: `exercises/src/solutions/`, the grader's own tests (`exercises/tests/grader.rs`, which need the
//! solutions), `.ci/`, these tools (`teacher/`, whose tests name the solutions' lines) and their page
//! (`docs/class.md`). In it:
//!
//! - the README is the students' ([`crate::student_readme`]): its first command grades the exercises, it
//!   says which files to edit and how to read a verdict, and names none of the teacher's tools; the
//!   teacher's sections of `docs/exercises.md` (handing out, adding an exercise, CI) are taken out;
//! - `exercises/src/lib.rs` hands out the chosen exercises (`HANDED_OUT`), and says that the workbook's own
//!   version of each is not in the copy (`TAKEN_OUT`, which the grader reads to give advice that holds);
//! - the library's own version of each one is taken out ([`crate::blanking`]): its function keeps the line
//!   that routes it to the exercise, and the rest becomes `todo!()`;
//! - the library is built for the exercises by default (the feature `exercises` is on, in the workspace
//!   of the library and `exercises/`), so every example,
//!   every test and the grader draw with the student's functions: written, they make the pictures; blank,
//!   they stop with their `todo!()`.

use crate::{blanking, student_readme};
use std::path::{Path, PathBuf};
use toml_edit::{DocumentMut, value};

/// What was handed out.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HandedOut {
    /// The files copied, relative to the copy's folder.
    pub files: usize,
    /// The library's files a solution was taken out of, with the exercises taken out of each.
    pub blanked: Vec<(PathBuf, Vec<String>)>,
}

/// The folders and files of the workbook that stay with the teacher, relative to its folder.
const TEACHERS_ONLY: [&str; 6] =
    [".git", ".ci", "exercises/src/solutions", "exercises/tests/grader.rs", "teacher", "docs/class.md"];

/// The workbook's exercises, in the order of the slides, as its `exercises/src/lib.rs` (the text `lib`)
/// lists them in `EXERCISES`.
pub fn exercises(lib: &str) -> Vec<String> {
    let Some((_, rest)) = lib.split_once("pub const EXERCISES: &[&str] = &[") else { return Vec::new() };
    let list = rest.split_once("];").map_or("", |(list, _)| list);
    list.split(',').map(|s| s.trim().trim_matches('"').to_string()).filter(|s| !s.is_empty()).collect()
}

/// The workbook's exercises, read from its `exercises/src/lib.rs`.
pub fn workbook_exercises(workbook: &Path) -> Result<Vec<String>, String> {
    let lib = workbook.join("exercises").join("src").join("lib.rs");
    let text = std::fs::read_to_string(&lib).map_err(|e| format!("cannot read {}: {e}", lib.display()))?;
    let list = exercises(&text);
    if list.is_empty() {
        return Err(format!("{} lists no exercises (pub const EXERCISES)", lib.display()));
    }
    Ok(list)
}

/// Writes the students' copy of the workbook at `workbook` into the folder `to` (which must not exist, or be
/// empty), handing out `handed_out` (names of the workbook's exercises). Fails with one line naming the
/// exercise, file or folder at fault; a failure leaves `to` incomplete, never a file outside it changed.
pub fn hand_out(workbook: &Path, to: &Path, handed_out: &[String]) -> Result<HandedOut, String> {
    let all = workbook_exercises(workbook)?;
    if let Some(unknown) = handed_out.iter().find(|name| !all.contains(name)) {
        return Err(format!("{unknown:?} is not one of the workbook's exercises ({})", all.join(", ")));
    }
    if std::fs::read_dir(to).is_ok_and(|mut entries| entries.next().is_some()) {
        return Err(format!("{} is not empty: hand out into a new folder", to.display()));
    }
    let files = copy_tracked(workbook, to)?;
    let lib = to.join("exercises").join("src").join("lib.rs");
    // The exercises handed out, and the same list as those whose workbook's own version the copy has not.
    for list in ["HANDED_OUT", "TAKEN_OUT"] {
        edit(&lib, |text| {
            set_list(text, list, handed_out).ok_or_else(|| format!("it has no line `pub const {list}`"))
        })?;
    }
    let hooks = read(&to.join("exercises").join("src").join("answers.rs"))?;
    let hooks = blanking::hooks(&hooks);
    let mut blanked = Vec::new();
    for file in rust_files(&to.join("src"))? {
        let text = read(&file)?;
        if !text.contains("exercise!(") {
            continue;
        }
        let (new, exercises) = blanking::blank(&text, &hooks, handed_out)
            .map_err(|e| format!("cannot read the Rust of {}: {e}", file.display()))?;
        if !exercises.is_empty() {
            write(&file, &new)?;
            blanked.push((file.strip_prefix(to).unwrap_or(&file).to_path_buf(), exercises));
        }
    }
    edit(&to.join("README.md"), |text| Ok(student_readme::readme(text, handed_out)))?;
    edit(&to.join("docs").join("exercises.md"), |text| {
        Ok(student_readme::without_sections(text, &student_readme::TEACHERS_SECTIONS))
    })?;
    edit(&to.join("Cargo.toml"), |text| {
        let mut doc: DocumentMut = text.parse().map_err(|e| format!("{e}"))?;
        // The examples built for the exercises as the grader builds them: one build of the library serves both.
        doc["features"]["default"] = value(toml_edit::Array::from_iter(["exercises"]));
        if let Some(members) = doc["workspace"]["members"].as_array_mut() {
            members.retain(|member| member.as_str() != Some("teacher"));
        }
        Ok(doc.to_string())
    })?;
    edit(&to.join("exercises").join("Cargo.toml"), |text| {
        let mut doc: DocumentMut = text.parse().map_err(|e| format!("{e}"))?;
        if let Some(tests) = doc.get_mut("test").and_then(|t| t.as_array_of_tables_mut()) {
            tests.retain(|test| test.get("name").and_then(|n| n.as_str()) != Some("grader"));
        }
        Ok(doc.to_string())
    })?;
    Ok(HandedOut { files, blanked })
}

/// `lib.rs` with its list `name` (`HANDED_OUT`) set to `exercises`; `None` when it has no such line.
fn set_list(lib: &str, name: &str, exercises: &[String]) -> Option<String> {
    let line = format!("pub const {name}: &[&str] = ");
    let start = lib.find(&line)?;
    let end = start + lib[start..].find(";\n")? + 1;
    let list: Vec<String> = exercises.iter().map(|name| format!("{name:?}")).collect();
    Some(format!("{}{line}&[{}];{}", &lib[..start], list.join(", "), &lib[end..]))
}

/// Copies the files git would track in `from` (its `.gitignore` followed, with or without a repository),
/// except [`TEACHERS_ONLY`], into `to`; returns how many.
fn copy_tracked(from: &Path, to: &Path) -> Result<usize, String> {
    let skipped: Vec<PathBuf> = TEACHERS_ONLY.iter().map(|p| from.join(p)).collect();
    let walk = ignore::WalkBuilder::new(from)
        .hidden(false)
        .require_git(false)
        .filter_entry(move |entry| !skipped.iter().any(|p| entry.path() == p))
        .build();
    let mut files = 0;
    for entry in walk {
        let entry = entry.map_err(|e| format!("cannot list the workbook's files: {e}"))?;
        let relative = entry.path().strip_prefix(from).unwrap_or(entry.path());
        let target = to.join(relative);
        if entry.file_type().is_some_and(|t| t.is_dir()) {
            std::fs::create_dir_all(&target).map_err(|e| format!("cannot create {}: {e}", target.display()))?;
        } else if entry.file_type().is_some_and(|t| t.is_file()) {
            std::fs::copy(entry.path(), &target).map_err(|e| format!("cannot copy to {}: {e}", target.display()))?;
            files += 1;
        }
    }
    Ok(files)
}

/// Every `.rs` file under `dir`, sorted.
fn rust_files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files = Vec::new();
    for entry in ignore::WalkBuilder::new(dir).standard_filters(false).build() {
        let entry = entry.map_err(|e| format!("cannot list {}: {e}", dir.display()))?;
        if entry.path().extension().is_some_and(|e| e == "rs") && entry.file_type().is_some_and(|t| t.is_file()) {
            files.push(entry.into_path());
        }
    }
    files.sort();
    Ok(files)
}

fn read(path: &Path) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// Rewrites the file at `path` with `change` of its text; a failure names the file.
fn edit(path: &Path, change: impl FnOnce(&str) -> Result<String, String>) -> Result<(), String> {
    let text = read(path)?;
    let new = change(&text).map_err(|e| format!("cannot edit {}: {e}", path.display()))?;
    write(path, &new)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_hand_out_list_is_the_one_line_replaced() {
        let lib = "/// The switch.\npub const HANDED_OUT: &[&str] = EXERCISES;\n\npub const EXERCISES: &[&str] = &[\n    \"bilinear\",\n    \"refract\",\n];\n";
        assert_eq!(exercises(lib), ["bilinear", "refract"]);
        let handed = set_list(lib, "HANDED_OUT", &["refract".to_string()]).expect("the line is there");
        assert!(handed.contains("pub const HANDED_OUT: &[&str] = &[\"refract\"];\n\npub const EXERCISES"), "{handed}");
        assert_eq!(set_list("no list", "HANDED_OUT", &[]), None);
        assert_eq!(set_list(lib, "TAKEN_OUT", &[]), None);
    }
}
