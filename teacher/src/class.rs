//! A class graded in one command: every submission built against the workbook in one package
//! ([`crate::class_package`]), run once under the class's limits ([`crate::rendering`]), compared with the
//! teacher's reference when there is one ([`crate::comparison`]), and its exercises graded
//! ([`crate::exercise_grades`]); one student at a time, each stopped alone by a compile error, a panic or a
//! limit. What comes out is one [`Row`] per example (or per student with exercises and no example), for the
//! gradebook and the contact sheet.

use crate::class_package::{Built, ClassPackage};
use crate::comparison::{Score, compare};
use crate::exercise_grades::{Grades, GradingCopy};
use crate::rendering::{Run, run};
use crate::submissions::{Student, find};
use lecture6::app::limits::Limits;
use std::path::{Path, PathBuf};
use std::time::Duration;

/// What grading a class needs.
#[derive(Clone, Debug)]
pub struct Settings {
    /// The folder of the submissions ([`crate::submissions`]).
    pub submissions: PathBuf,
    /// The folder the gradebook, the contact sheet, the pictures and the logs are written to.
    pub out: PathBuf,
    /// The workbook the submissions are built against.
    pub workbook: PathBuf,
    /// The target folder they are built in (the workbook's, so that its dependencies are built once).
    pub target: PathBuf,
    /// The assignment's reference: a picture, or the teacher's example (`.rs`), rendered as the
    /// submissions are.
    pub reference: Option<PathBuf>,
    /// The options every render gets (the size, the samples, ...), before `-o`.
    pub render_args: Vec<String>,
    /// Each render's limits.
    pub run_limits: Limits,
    /// Each build's limits.
    pub build_limits: Limits,
    /// The optimisation level of the submissions' own code.
    pub opt_level: u8,
    /// The exercises graded.
    pub exercises: Vec<String>,
    /// Each exercise's time limit.
    pub exercise_time: Duration,
}

/// One row of the gradebook: one example of one student (or a student's exercises alone).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The student, and the example's file name when the student has more than one.
    pub student: String,
    /// The example's file, as submitted.
    pub source: Option<PathBuf>,
    /// The name the example was built under (`s003_alice`), which names its picture and logs.
    pub id: String,
    /// Its build.
    pub built: Option<Built>,
    /// Its run, if it built.
    pub run: Option<Run>,
    /// How far its picture is from the reference, if there is one and it rendered (or why it could not be
    /// compared).
    pub score: Option<Result<Score, String>>,
    /// The student's exercises, on the student's first row.
    pub grades: Option<Grades>,
}

impl Row {
    /// The picture, relative to the output folder, if the run wrote one.
    pub fn picture(&self) -> Option<String> {
        self.run.as_ref().filter(|r| r.outcome.is_ok()).map(|_| format!("pictures/{}.png", self.id))
    }

    /// The heat map of its difference from the reference, relative to the output folder, if there is one.
    pub fn heat_map(&self) -> Option<String> {
        matches!(self.score, Some(Ok(_))).then(|| format!("pictures/{}-diff.png", self.id))
    }

    /// The log of what it printed when it ran, relative to the output folder.
    pub fn run_log(&self) -> String {
        format!("logs/{}.run.txt", self.id)
    }
}

/// The reference picture, as the contact sheet shows it (relative to the output folder).
pub const REFERENCE_PICTURE: &str = "pictures/reference.png";

/// The time limit of the builds done once for the class, before any student's: the library for the
/// submissions, the grader for the exercises (a first build of the workbook takes minutes on a busy
/// machine).
pub const PREPARATION_LIMIT: Limits = Limits { time: Duration::from_secs(3600), memory: None, output: None };

/// What [`grade`] is doing.
#[derive(Clone, Copy, Debug)]
pub enum Progress<'a> {
    /// A step done once for the class, in words, as it starts.
    Preparing(&'a str),
    /// A row, done.
    Graded(&'a Row),
}

/// Grades the class of `settings`, telling `progress` what it does.
pub fn grade(settings: &Settings, mut progress: impl FnMut(Progress)) -> Result<Vec<Row>, String> {
    // The submissions are built from the package's folder and run in their own: every path from the root.
    let settings = &Settings {
        submissions: absolute(&settings.submissions)?,
        out: absolute(&settings.out)?,
        workbook: absolute(&settings.workbook)?,
        target: absolute(&settings.target)?,
        reference: settings.reference.as_deref().map(absolute).transpose()?,
        ..settings.clone()
    };
    let exercise_names: Vec<&str> = settings.exercises.iter().map(String::as_str).collect();
    let students = find(&settings.submissions, &exercise_names)?;
    let out = &settings.out;
    for folder in ["pictures", "logs"] {
        let dir = out.join(folder);
        std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    }
    let (mut rows, owners) = rows(&students);
    let mut sources: Vec<(String, PathBuf)> =
        rows.iter().filter_map(|row| Some((row.id.clone(), row.source.clone()?))).collect();
    let teachers = settings.reference.as_ref().filter(|r| r.extension().is_some_and(|e| e == "rs"));
    if let Some(source) = teachers {
        sources.push(("reference".to_string(), source.clone()));
    }
    // The package, when there is an example to build in it.
    let package = if sources.is_empty() {
        None
    } else {
        let dir = out.join("build");
        let package = ClassPackage::create(&dir, &settings.workbook, &settings.target, &sources, settings.opt_level)?;
        progress(Progress::Preparing("building the workbook's library for the class (once)"));
        package.build_library(&PREPARATION_LIMIT, &out.join("logs").join("library.build.txt"))?;
        Some(package)
    };
    let reference = match (&settings.reference, &package) {
        (None, _) => None,
        (Some(_), Some(package)) if teachers.is_some() => Some(render_reference(settings, package)?),
        (Some(picture), _) => {
            let image = lecture6::instruments::compare::load_reference(picture).map_err(|e| e.to_string())?;
            let shown = out.join(REFERENCE_PICTURE);
            image.save(&shown).map_err(|e| format!("cannot write {}: {e}", shown.display()))?;
            Some(picture.clone())
        }
    };
    let copy = if students.iter().any(|s| !s.exercises.is_empty()) {
        progress(Progress::Preparing("handing out the exercises and building their grader (once)"));
        let log = out.join("logs").join("grader.build.txt");
        let grading = out.join("grading");
        Some(GradingCopy::create(
            &settings.workbook,
            &grading,
            &settings.target,
            &settings.exercises,
            &PREPARATION_LIMIT,
            &log,
        )?)
    } else {
        None
    };
    for (row, student) in rows.iter_mut().zip(owners.iter().map(|&i| &students[i])) {
        if let (Some(source), Some(package)) = (row.source.clone(), &package) {
            build_and_run(settings, package, row, &source, student.folder.as_deref(), reference.as_deref())?;
        }
        if let (Some(copy), Some(grades)) = (&copy, &mut row.grades) {
            let log = out.join("logs").join(format!("{}.exercises.txt", row.id));
            let memory = settings.run_limits.memory;
            *grades =
                copy.grade(&student.exercises, settings.exercise_time, memory, settings.build_limits.time, &log)?;
        }
        progress(Progress::Graded(row));
    }
    Ok(rows)
}

/// The rows of `students`, before anything is built: one per example, and the exercises on each student's
/// first (a row of their own for a student with no example); and for each row, its student's index.
fn rows(students: &[Student]) -> (Vec<Row>, Vec<usize>) {
    let (mut rows, mut owners) = (Vec::new(), Vec::new());
    for (index, student) in students.iter().enumerate() {
        let mut sources: Vec<Option<PathBuf>> = student.examples.iter().cloned().map(Some).collect();
        if sources.is_empty() {
            sources.push(None);
        }
        let several = sources.len() > 1;
        for (k, source) in sources.into_iter().enumerate() {
            let name = match (&source, several) {
                (Some(path), true) => {
                    format!("{}/{}", student.name, path.file_name().unwrap_or_default().to_string_lossy())
                }
                _ => student.name.clone(),
            };
            let grades = (k == 0 && !student.exercises.is_empty()).then(|| Grades {
                verdicts: Vec::new(),
                failure: None,
                seconds: 0.0,
            });
            let id = id(rows.len() + 1, &student.name);
            rows.push(Row { id, student: name, source, built: None, run: None, score: None, grades });
            owners.push(index);
        }
    }
    (rows, owners)
}

/// The name the `index`th row's example is built under: `s007_alice` (a crate's name: letters, digits and
/// underscores, unique by its number).
fn id(index: usize, student: &str) -> String {
    let name: String = student
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c.to_ascii_lowercase() } else { '_' })
        .take(32)
        .collect();
    format!("s{index:03}_{name}")
}

/// Builds the row's example, runs it, and compares its picture with `reference`.
fn build_and_run(
    settings: &Settings,
    package: &ClassPackage,
    row: &mut Row,
    source: &Path,
    folder: Option<&Path>,
    reference: Option<&Path>,
) -> Result<(), String> {
    let out = &settings.out;
    let built = package.build(
        &row.id,
        source,
        &settings.build_limits,
        &out.join("logs").join(format!("{}.build.txt", row.id)),
    )?;
    if let Ok(program) = &built.program {
        let picture = out.join("pictures").join(format!("{}.png", row.id));
        let args = render_args(settings, &picture);
        let dir = folder.unwrap_or(&settings.workbook);
        let mut result = run(program, &args, dir, &settings.run_limits, &out.join(row.run_log()))?;
        // A panic's place names the example by its file name, as the compiler's errors do.
        let file = source.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        result.outcome = result.outcome.map_err(|why| why.replace(source.to_string_lossy().as_ref(), &file));
        if let (Ok(()), Some(reference)) = (&result.outcome, reference) {
            row.score = Some(compare(&picture, reference, &out.join(format!("pictures/{}-diff.png", row.id))));
        }
        row.run = Some(result);
    }
    row.built = Some(built);
    Ok(())
}

/// The options of a render writing `picture`.
fn render_args(settings: &Settings, picture: &Path) -> Vec<String> {
    let mut args = settings.render_args.clone();
    args.extend(["-o".to_string(), picture.to_string_lossy().into_owned()]);
    args
}

/// Builds and renders the teacher's example as the submissions are; its picture is the reference.
fn render_reference(settings: &Settings, package: &ClassPackage) -> Result<PathBuf, String> {
    let out = &settings.out;
    let source = settings.reference.as_deref().unwrap_or(Path::new(""));
    let built =
        package.build("reference", source, &settings.build_limits, &out.join("logs").join("reference.build.txt"))?;
    let program = built.program.map_err(|e| format!("the reference {} does not build: {e}", source.display()))?;
    let picture = out.join(REFERENCE_PICTURE);
    let log = out.join("logs").join("reference.run.txt");
    let result = run(&program, &render_args(settings, &picture), &settings.workbook, &settings.run_limits, &log)?;
    result.outcome.map_err(|e| format!("the reference {} did not render: {e}", source.display()))?;
    Ok(picture)
}

/// `path` from the root, so that the package's manifest finds it.
fn absolute(path: &Path) -> Result<PathBuf, String> {
    std::path::absolute(path).map_err(|e| format!("cannot find {}: {e}", path.display()))
}
