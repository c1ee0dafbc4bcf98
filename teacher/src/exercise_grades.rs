//! A student's exercises graded as the student grades them (`cargo test --release -p exercises`), in a
//! students' copy of the workbook ([`crate::hand_out`]) made once for the class: each student's files are
//! put in place of the blanks, the grader runs with its per-exercise time limit, and the blanks are put back
//! for the next student. The copy is built in the release profile, against the workbook's built
//! dependencies; the renderer does not depend on the students' crate, so each student's files compile only
//! that crate and the grader's small program again, in about a second (docs/exercises.md).

use crate::class_package::{cargo, first_error, run_logged};
use crate::hand_out::hand_out;
use lecture6::app::limits::{Ending, Limits};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

/// The pictures the grader draws at most, besides the exercises' facts: one step each.
const PICTURES: u32 = 8;

/// The students' copy the class's exercises are graded in.
pub struct GradingCopy {
    dir: PathBuf,
    target: PathBuf,
    /// Each exercise handed out and its blank, as the copy holds it.
    blanks: Vec<(String, String)>,
}

/// A student's grades.
#[derive(Clone, Debug, PartialEq)]
pub struct Grades {
    /// Each exercise handed out and the grader's verdict (`passed: ...`, `FAILED: ...`, ...).
    pub verdicts: Vec<(String, String)>,
    /// Why there are no verdicts: the first compiler error, or the limit that stopped the grader.
    pub failure: Option<String>,
    /// How long building and running the grader took, in seconds.
    pub seconds: f64,
}

impl Grades {
    /// How many exercises passed.
    pub fn passed(&self) -> usize {
        self.verdicts.iter().filter(|(_, v)| v.starts_with("passed")).count()
    }
}

impl GradingCopy {
    /// Hands out `exercises` of the workbook at `workbook` into the folder `dir` (replacing what an earlier
    /// class left there), to be built into the target folder `target`, and builds its grader with the blanks
    /// under `limits` (its messages into the file `log`).
    pub fn create(
        workbook: &Path,
        dir: &Path,
        target: &Path,
        exercises: &[String],
        limits: &Limits,
        log: &Path,
    ) -> Result<GradingCopy, String> {
        if dir.exists() {
            std::fs::remove_dir_all(dir).map_err(|e| format!("cannot clear {}: {e}", dir.display()))?;
        }
        hand_out(workbook, dir, exercises)?;
        let blanks = exercises
            .iter()
            .map(|name| {
                let file = blank_path(dir, name);
                std::fs::read_to_string(&file)
                    .map(|text| (name.clone(), text))
                    .map_err(|e| format!("cannot read {}: {e}", file.display()))
            })
            .collect::<Result<_, _>>()?;
        let copy = GradingCopy { dir: dir.to_path_buf(), target: target.to_path_buf(), blanks };
        copy.build(limits, log)?;
        Ok(copy)
    }

    /// Grades the exercise files `files` (exercise name, file), each exercise under `exercise_time` (and
    /// `memory`, in bytes), the whole build and grading under `build_time` more; the grader's output into
    /// the file `log`.
    pub fn grade(
        &self,
        files: &[(String, PathBuf)],
        exercise_time: Duration,
        memory: Option<u64>,
        build_time: Duration,
        log: &Path,
    ) -> Result<Grades, String> {
        for (name, blank) in &self.blanks {
            let place = blank_path(&self.dir, name);
            match files.iter().find(|(n, _)| n == name) {
                Some((_, file)) => std::fs::copy(file, &place).map(|_| ()),
                None => std::fs::write(&place, blank),
            }
            .map_err(|e| format!("cannot write {}: {e}", place.display()))?;
        }
        let mut command = self.grader(&["test"]);
        command.env("EXERCISE_TIME_LIMIT", exercise_time.as_secs_f64().to_string());
        if let Some(bytes) = memory {
            command.env("EXERCISE_MEMORY_LIMIT", (bytes >> 20).to_string());
        }
        let steps = self.blanks.len() as u32 + PICTURES;
        let limits = Limits { time: build_time + exercise_time * steps, memory: None, output: None };
        let finished = run_logged(&mut command, &limits, log)?;
        let output = std::fs::read_to_string(log).unwrap_or_default();
        let verdicts = verdicts(&output, &self.blanks);
        let failure = match finished.ending {
            _ if !verdicts.is_empty() => None,
            Ending::TimedOut => {
                Some(format!("the grader was stopped at its time limit of {} s", limits.time.as_secs_f64()))
            }
            ending => Some(
                files
                    .iter()
                    .find_map(|(_, file)| first_error(&output, Some(file)))
                    .unwrap_or_else(|| format!("the grader ended without a report ({ending:?})")),
            ),
        };
        Ok(Grades { verdicts, failure, seconds: finished.elapsed.as_secs_f64() })
    }
}

impl GradingCopy {
    /// `cargo <subcommand>` of the copy's grader.
    fn grader(&self, subcommand: &[&str]) -> Command {
        let mut command = cargo(subcommand);
        command
            .args(["--release", "--message-format", "short", "-p", "exercises", "--test", "grade", "--manifest-path"])
            .arg(self.dir.join("Cargo.toml"))
            .env("CARGO_TARGET_DIR", &self.target);
        command
    }

    /// Builds the grader with the blanks, once, before any student's files, so that no student's time limit
    /// pays for the first build; its messages into the file `log`.
    fn build(&self, limits: &Limits, log: &Path) -> Result<(), String> {
        let finished = run_logged(&mut self.grader(&["test", "--no-run"]), limits, log)?;
        if finished.ending.succeeded() {
            return Ok(());
        }
        let messages = std::fs::read_to_string(log).unwrap_or_default();
        let why = first_error(&messages, None).unwrap_or_else(|| format!("{:?}", finished.ending));
        Err(format!("the exercises' grader does not build with the blanks: {why} (see {})", log.display()))
    }
}

/// Where the copy in `dir` holds the exercise `name`.
fn blank_path(dir: &Path, name: &str) -> PathBuf {
    dir.join("exercises").join("src").join(format!("{name}.rs"))
}

/// The grader's verdict for each exercise of `blanks`, read from its report (`  name  verdict`), in the
/// order of `blanks`; empty when there is no report.
fn verdicts(report: &str, blanks: &[(String, String)]) -> Vec<(String, String)> {
    blanks
        .iter()
        .filter_map(|(name, _)| {
            report.lines().find_map(|line| {
                let rest = line.strip_prefix("  ")?.strip_prefix(name.as_str())?;
                rest.starts_with("  ").then(|| (name.clone(), rest.trim().to_string()))
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_verdicts_are_read_from_the_graders_report() {
        let report = "\nGrading the lecture-6 exercises: ...\n\n  refract            passed: every fact holds\n  \
            fresnel_schlick    FAILED: Head-on ...\n  fresnel_exact      not handed out\n\n1 of 2 exercises handed out passed\n";
        let blanks = [("refract".to_string(), String::new()), ("fresnel_schlick".to_string(), String::new())];
        let grades = Grades { verdicts: verdicts(report, &blanks), failure: None, seconds: 0.0 };
        assert_eq!(
            grades.verdicts,
            [
                ("refract".to_string(), "passed: every fact holds".to_string()),
                ("fresnel_schlick".to_string(), "FAILED: Head-on ...".to_string())
            ]
        );
        assert_eq!(grades.passed(), 1);
        assert!(verdicts("error[E0425]: cannot find value", &blanks).is_empty());
    }
}
