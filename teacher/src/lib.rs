//! The teacher's tools for lecture 6 (not a slide's lesson): grading a class in one command, and handing the
//! exercises out without their solutions. The teacher's page is docs/class.md.
//!
//! - `cargo run --release -p teacher -- SUBMISSIONS --reference REF.png`: [`class::grade`] builds, runs and
//!   compares every submission, and writes the [`gradebook`] (CSV) and the [`contact_sheet`] (HTML).
//! - `cargo run --release -p teacher --bin hand-out -- COPY --exercises refract,fresnel_schlick`:
//!   [`hand_out::hand_out`] writes the students' copy.

pub mod blanking;
pub mod class;
pub mod class_package;
pub mod comparison;
pub mod contact_sheet;
pub mod exercise_grades;
pub mod gradebook;
pub mod hand_out;
pub mod kept_output;
pub mod rendering;
pub mod student_readme;
pub mod submissions;

use std::path::{Path, PathBuf};

/// The workbook this crate belongs to: the folder above it.
pub fn workbook() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("teacher/ lies in the workbook")
}

/// The target folder cargo builds the workbook into: `CARGO_TARGET_DIR`, or its `target/`.
pub fn target_folder(workbook: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| workbook.join("target"), PathBuf::from)
}

/// A list of exercises given on the command line (`refract,fresnel_schlick`), or every one of `all` for
/// `None`.
pub fn chosen_exercises(list: Option<&str>, all: &[String]) -> Vec<String> {
    match list {
        None => all.to_vec(),
        Some(list) => list.split(',').map(str::trim).filter(|s| !s.is_empty()).map(String::from).collect(),
    }
}
