//! The gradebook: one CSV table of the class, one row per [`Row`], for a spreadsheet.
//!
//! Columns: `student`, `example` (the file), `built` (yes/no), `first_error` (the compiler's first error, or
//! the limit that stopped the build), `run` (`ok`, or why it did not finish: its panic's message, its error,
//! the limit that stopped it), `run_seconds` (the run's wall-clock time), `cpu_seconds` (its processor
//! time), `time_limit` (the processor time it was given, and where that comes from: `6.2 s of processor time
//! (10 x the reference's 0.62 s, at least 5 s)`), `render_seconds` and `rays_millions` (from its summary
//! line), `warnings` (the end-of-run report's warnings, ` | ` between them), `settings` (where the
//! program's defaults differ from the teacher's example's: `--spp 20000 (the reference's 5)`, ` | ` between
//! them), `rmse` and `psnr` (against the reference; `psnr` is 99 for an equal picture), when exercises were
//! graded `exercises_passed` (`3/11`) and one column per exercise with the grader's verdict, and `picture`
//! and `log` (files in the output folder).

use crate::class::{Row, TimeLimit};
use std::path::Path;

/// Writes the gradebook of `rows`, whose renders had `time_limit` (with a column per exercise of
/// `exercises`, none for none), to the file `path`.
pub fn write(rows: &[Row], time_limit: &TimeLimit, exercises: &[String], path: &Path) -> Result<(), String> {
    let fail = |e: csv::Error| format!("cannot write {}: {e}", path.display());
    let mut table = csv::Writer::from_path(path).map_err(fail)?;
    let mut header: Vec<String> = [
        "student",
        "example",
        "built",
        "first_error",
        "run",
        "run_seconds",
        "cpu_seconds",
        "time_limit",
        "render_seconds",
        "rays_millions",
        "warnings",
        "settings",
        "rmse",
        "psnr",
    ]
    .map(String::from)
    .to_vec();
    if !exercises.is_empty() {
        header.push("exercises_passed".to_string());
        header.extend(exercises.iter().cloned());
    }
    header.extend(["picture".to_string(), "log".to_string()]);
    table.write_record(&header).map_err(fail)?;
    for row in rows {
        table.write_record(record(row, time_limit, exercises)).map_err(fail)?;
    }
    table.flush().map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// The fields of one row.
fn record(row: &Row, time_limit: &TimeLimit, exercises: &[String]) -> Vec<String> {
    let number = |x: Option<f64>, decimals: usize| x.map_or(String::new(), |x| format!("{x:.decimals$}"));
    let example = row.source.as_ref().and_then(|p| p.file_name()).map_or(String::new(), |n| n.to_string_lossy().into());
    let (built, first_error) = match row.built.as_ref().map(|b| &b.program) {
        None => (String::new(), String::new()),
        Some(Ok(_)) => ("yes".to_string(), String::new()),
        Some(Err(e)) => ("no".to_string(), e.clone()),
    };
    let run = row.run.as_ref();
    let score = row.score.as_ref();
    let mut fields = vec![
        row.student.clone(),
        example,
        built,
        first_error,
        run.map_or(String::new(), |r| r.outcome.clone().err().unwrap_or_else(|| "ok".to_string())),
        number(run.map(|r| r.seconds), 3),
        number(run.and_then(|r| r.cpu_seconds), 3),
        run.map_or(String::new(), |_| time_limit.describe()),
        number(run.and_then(|r| r.render_seconds), 3),
        number(run.and_then(|r| r.rays_millions), 2),
        run.map_or(String::new(), |r| r.warnings.join(" | ")),
        row.differences.join(" | "),
        match score {
            Some(Ok(s)) => format!("{:.3}", s.rmse),
            Some(Err(why)) => why.clone(),
            None => String::new(),
        },
        number(score.and_then(|s| s.as_ref().ok()).map(|s| s.psnr), 2),
    ];
    match &row.grades {
        _ if exercises.is_empty() => {}
        None => fields.extend(std::iter::repeat_n(String::new(), exercises.len() + 1)),
        Some(grades) => {
            fields.push(match &grades.failure {
                Some(why) => why.clone(),
                None => format!("{}/{}", grades.passed(), grades.verdicts.len()),
            });
            for name in exercises {
                let verdict = grades.verdicts.iter().find(|(n, _)| n == name).map(|(_, v)| v.clone());
                fields.push(verdict.unwrap_or_default());
            }
        }
    }
    fields.push(row.picture().unwrap_or_default());
    fields.push(if row.run.is_some() { row.run_log() } else { String::new() });
    fields
}
