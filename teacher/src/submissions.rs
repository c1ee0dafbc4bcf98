//! A class's submissions, as a folder holds them: one student per file or per folder.
//!
//! - `alice.rs`: Alice's example, a copy of one of the workbook's `examples/` with her changes.
//! - `bob/`: Bob's folder. His examples are the `.rs` files with a `fn main` in it or in its `examples/`;
//!   his exercises are the files named after one of the workbook's exercises (`refract.rs`) without a
//!   `fn main`, in it, its `src/` or its `exercises/src/` (a copy of his `exercises/` folder or of his whole
//!   workbook will do). Anything else in it (his textures, his scene files) is left where it is: his examples
//!   run in his folder.
//!
//! Files and folders whose names start with a dot are not submissions.

use std::path::{Path, PathBuf};

/// One student's submission.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Student {
    /// The student's name: the file's stem, or the folder's name.
    pub name: String,
    /// The folder the student's examples run in: theirs, or `None` for a single file (which runs in the
    /// workbook's folder, where the example it was copied from ran).
    pub folder: Option<PathBuf>,
    /// The student's examples, in the order of their file names.
    pub examples: Vec<PathBuf>,
    /// The student's exercises: the exercise's name and the file.
    pub exercises: Vec<(String, PathBuf)>,
}

/// The students of the folder `dir`, in the order of their names; `exercises` are the names of the
/// workbook's exercises. Fails with one line naming the folder when it cannot be read.
pub fn find(dir: &Path, exercises: &[&str]) -> Result<Vec<Student>, String> {
    let mut students = Vec::new();
    for path in listed(dir)? {
        let name = path.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        if path.is_dir() {
            students.push(from_folder(&path, name, exercises)?);
        } else if path.extension().is_some_and(|e| e == "rs") {
            students.push(Student { name, folder: None, examples: vec![path], exercises: Vec::new() });
        }
    }
    students.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(students)
}

/// The student whose folder is `dir`.
fn from_folder(dir: &Path, name: String, exercises: &[&str]) -> Result<Student, String> {
    let rust_files = |sub: &str| -> Result<Vec<PathBuf>, String> {
        let folder = dir.join(sub);
        if !folder.is_dir() {
            return Ok(Vec::new());
        }
        Ok(listed(&folder)?.into_iter().filter(|p| p.is_file() && p.extension().is_some_and(|e| e == "rs")).collect())
    };
    let mut student = Student { name, folder: Some(dir.to_path_buf()), examples: Vec::new(), exercises: Vec::new() };
    for sub in ["", "examples"] {
        for file in rust_files(sub)? {
            if has_main(&file) {
                student.examples.push(file);
            }
        }
    }
    for sub in ["", "src", "exercises/src"] {
        for file in rust_files(sub)? {
            let stem = file.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
            if exercises.contains(&stem.as_str()) && !has_main(&file) {
                student.exercises.retain(|(name, _)| *name != stem);
                student.exercises.push((stem, file));
            }
        }
    }
    Ok(student)
}

/// Whether the Rust file at `path` has a `main` (an example does, an exercise does not).
fn has_main(path: &Path) -> bool {
    std::fs::read_to_string(path).is_ok_and(|text| text.contains("fn main("))
}

/// The entries of the folder `dir` not starting with a dot, sorted.
fn listed(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let entries = std::fs::read_dir(dir).map_err(|e| format!("cannot read the folder {}: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = entries
        .filter_map(|entry| entry.ok().map(|e| e.path()))
        .filter(|p| !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.')))
        .collect();
    paths.sort();
    Ok(paths)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_a_student_and_a_folder_holds_examples_and_exercises() {
        let dir = tempfile::tempdir().expect("a temporary folder");
        let write = |path: &str, text: &str| {
            let path = dir.path().join(path);
            std::fs::create_dir_all(path.parent().expect("a parent")).expect("a folder");
            std::fs::write(path, text).expect("a file");
        };
        write("carol.rs", "fn main() {}");
        write("alice/hw.rs", "fn main() {}");
        write("alice/refract.rs", "pub fn refract() {}");
        write("alice/exercises/src/faceforward.rs", "pub fn faceforward() {}");
        write("alice/notes.rs", "// not an example");
        write("bob/examples/refract.rs", "fn main() {}");
        write(".hidden.rs", "fn main() {}");
        let students = find(dir.path(), &["refract", "faceforward"]).expect("readable");
        let names: Vec<&str> = students.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["alice", "bob", "carol"]);
        assert_eq!(students[0].examples, [dir.path().join("alice/hw.rs")]);
        let exercises: Vec<&str> = students[0].exercises.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(exercises, ["refract", "faceforward"]);
        // A copied example named like an exercise is an example: it has a main.
        assert_eq!(students[1].examples, [dir.path().join("bob/examples/refract.rs")]);
        assert!(students[1].exercises.is_empty());
        assert_eq!((students[2].folder.as_ref(), students[2].examples.len()), (None, 1));
        let missing = find(&dir.path().join("nobody"), &[]).expect_err("no such folder");
        assert!(missing.starts_with("cannot read the folder ") && missing.contains("nobody"), "{missing}");
    }
}
