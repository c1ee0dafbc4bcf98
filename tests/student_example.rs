//! A student's own example, built and tested as the student builds and tests it: `cargo test --release
//! --example hw1` in the workbook's folder, which compiles the homework's file alone (the library is built
//! already) and runs the test module at its end, the recipe of docs/tests.md and docs/homework-api.md.
//!
//! - The API page's homework, docs/homework_glossy.rs (a glossy mirror averaging N rays, as the page says to
//!   write one), with every doc comment taken out, builds without a warning (no lint holds a student's
//!   example to the library's documentation rules) and passes its own test.
//! - The same homework with the naive sum (its N rays added up and not divided by N) fails its own test,
//!   which prints the end-of-run report's line on the shader that made the light.
//!
//! A test program of its own, apart from tests/workbook/: each test puts its homework in `examples/` for as
//! long as it runs, and cargo runs its test programs one after another, so no other test sees the file. The
//! homework is built with the profile and into the target folder this test was built with, so only the
//! homework's file is compiled.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The API page's homework, as the page shows it.
const HOMEWORK: &str = include_str!("../docs/homework_glossy.rs");

/// The line of the homework that averages its rays, and the naive sum a student writes instead.
const MEAN: &str = "sum * self.tint / kept as f32";
const NAIVE_SUM: &str = "sum * self.tint";

/// A homework file in `examples/`, removed when dropped.
struct Homework {
    name: &'static str,
    path: PathBuf,
}

impl Homework {
    /// Writes `text` as `examples/<name>.rs`.
    fn new(name: &'static str, text: &str) -> Homework {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples").join(format!("{name}.rs"));
        std::fs::write(&path, text).unwrap();
        Homework { name, path }
    }

    /// `cargo test --example <name>`, with this test's profile and target folder: the homework's own test.
    fn test(&self) -> Output {
        // This program is <target>/<profile>/deps/<name>: the homework goes to the same folder and profile.
        let exe = std::env::current_exe().unwrap();
        let profile_dir = exe.parent().and_then(Path::parent).unwrap();
        let target = profile_dir.parent().unwrap();
        let profile = match profile_dir.file_name().unwrap().to_str().unwrap() {
            "debug" => "dev",
            other => other,
        };
        Command::new(env!("CARGO"))
            .args(["test", "--profile", profile, "--example", self.name, "--target-dir"])
            .arg(target)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .unwrap()
    }
}

impl Drop for Homework {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.path);
    }
}

/// What a run printed, both streams.
fn printed(out: &Output) -> String {
    format!("{}\n{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr))
}

#[test]
fn a_homework_without_a_doc_comment_builds_without_a_warning_and_passes_its_own_test() {
    let undocumented: String = HOMEWORK
        .lines()
        .filter(|line| !line.trim_start().starts_with("///") && !line.starts_with("//!"))
        .map(|line| format!("{line}\n"))
        .collect();
    assert!(undocumented.contains("pub struct TintedGlossy {\n    pub tint: Color,"), "{undocumented}");
    let homework = Homework::new("zz_student_undocumented", &undocumented);
    let out = homework.test();
    assert!(out.status.success(), "{}", printed(&out));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("warning"), "{stderr}");
    assert!(String::from_utf8_lossy(&out.stdout).contains("test tests::renders_without_a_warning ... ok"));
}

#[test]
fn the_naive_sum_fails_the_homeworks_own_test_naming_the_shader() {
    assert_eq!(HOMEWORK.matches(MEAN).count(), 1);
    let homework = Homework::new("zz_student_naive_sum", &HOMEWORK.replace(MEAN, NAIVE_SUM));
    let out = homework.test();
    assert!(!out.status.success(), "{}", printed(&out));
    let text = printed(&out);
    assert!(text.contains("test tests::renders_without_a_warning ... FAILED"), "{text}");
    assert!(
        text.contains("adds up N rays without dividing by N") && text.contains("glossy ball (TintedGlossy)"),
        "{text}"
    );
}
