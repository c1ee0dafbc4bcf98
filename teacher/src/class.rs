//! A class graded in one command: every submission built against the workbook in one package
//! ([`crate::class_package`]), run once under the class's limits ([`crate::rendering`]), compared with the
//! teacher's reference when there is one ([`crate::comparison`]), and its exercises graded
//! ([`crate::exercise_grades`]); each stopped alone by a compile error, a panic or a limit. What comes out
//! is one [`Row`] per example (or per student with exercises and no example), for the gradebook and the
//! contact sheet.
//!
//! The builds go one at a time (cargo builds one package at a time in a target folder), and as each
//! program is built it is run, on one thread (`--threads 1`), by one of as many runners as the machine has
//! cores: the students render side by side while the next ones build. Each render's time limit is processor
//! time, fair to programs sharing a busy machine; by default it is [`REFERENCE_MULTIPLE`] times what the
//! teacher's example took, and at least [`LIMIT_FLOOR`] ([`TimeLimit`]).

use crate::class_package::{Built, ClassPackage, placed_as};
use crate::comparison::{Score, compare};
use crate::exercise_grades::{Grades, GradingCopy};
use crate::rendering::{Run, RunLimits, run};
use crate::submissions::{Student, find};
use lecture6::app::limits::Limits;
use std::path::{Path, PathBuf};
use std::sync::mpsc::{Sender, channel};
use std::sync::{Mutex, PoisonError};
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
    /// The options every render gets (the size, the samples, ...), before `--threads 1`, `--print-defaults`
    /// and `-o`.
    pub render_args: Vec<String>,
    /// The processor time each render may take, or `None` for [`TimeLimit::from_reference`]'s.
    pub time_limit: Option<Duration>,
    /// Each render's (and exercise's) address space, in bytes, or `None` for no limit.
    pub memory_limit: Option<u64>,
    /// The largest file a render may write, in bytes, or `None` for no limit.
    pub output_limit: Option<u64>,
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
    /// The settings its program takes without options that differ from the teacher's example's, one each
    /// (`--spp 20000 (the reference's 5)`).
    pub differences: Vec<String>,
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

/// The class graded: its rows, and the time limit their renders had.
#[derive(Clone, Debug, PartialEq)]
pub struct Graded {
    /// One per example (or per student with exercises alone), in the order of the students' names.
    pub rows: Vec<Row>,
    /// Each render's time limit.
    pub time_limit: TimeLimit,
}

/// The reference picture, as the contact sheet shows it (relative to the output folder).
pub const REFERENCE_PICTURE: &str = "pictures/reference.png";

/// The time limit of the builds done once for the class, before any student's: the library for the
/// submissions, the grader for the exercises (a first build of the workbook takes minutes on a busy
/// machine).
pub const PREPARATION_LIMIT: Limits = Limits { time: Duration::from_secs(3600), memory: None, output: None };

/// The default time limit, in multiples of the processor time the teacher's example took: a correct
/// submission three times as slow as the reference (a copy built at a lower optimisation, a scene with a
/// few more objects) is far from it, and processor time varies little with the machine's load.
pub const REFERENCE_MULTIPLE: f64 = 10.0;

/// The least default time limit: a render of a fraction of a second has the start of a program to pay too
/// (its textures read, its scene built), which a busy machine slows down.
pub const LIMIT_FLOOR: Duration = Duration::from_secs(5);

/// The default time limit where there is no teacher's example to time (a reference picture, or none).
pub const LIMIT_WITHOUT_EXAMPLE: Duration = Duration::from_secs(60);

/// A render's wall-clock limit, in multiples of its processor time's: a program that waits instead of
/// computing is stopped too, and a busy machine still gives every program its time. On the project's
/// 2-core machine, at a load of 15 with builds at normal priority, a render under `nice -n 15` got 3% of a
/// core (1.6 s of processor time in 50 s): 100 leaves it room.
pub const WALL_PER_CPU: u32 = 100;

/// Each render's limit of processor time, and where it comes from.
#[derive(Clone, Debug, PartialEq)]
pub struct TimeLimit {
    /// The processor time a render may take.
    pub cpu: Duration,
    /// Where it comes from, in words: `10 x the reference's 0.52 s, at least 5 s`.
    pub why: String,
}

impl TimeLimit {
    /// The default: [`REFERENCE_MULTIPLE`] times the processor time `reference_cpu` the teacher's example
    /// took, and at least [`LIMIT_FLOOR`]; rounded up to a tenth of a second.
    pub fn from_reference(reference_cpu: Duration) -> TimeLimit {
        let seconds = (reference_cpu.as_secs_f64() * REFERENCE_MULTIPLE).max(LIMIT_FLOOR.as_secs_f64());
        TimeLimit {
            cpu: Duration::from_secs_f64((seconds * 10.0).ceil() / 10.0),
            why: format!(
                "{REFERENCE_MULTIPLE} x the reference's {:.2} s, at least {} s",
                reference_cpu.as_secs_f64(),
                LIMIT_FLOOR.as_secs_f64()
            ),
        }
    }

    /// The limit `--time-limit` gave.
    pub fn given(cpu: Duration) -> TimeLimit {
        TimeLimit { cpu, why: "--time-limit".to_string() }
    }

    /// The limit where there is no teacher's example to time.
    pub fn without_example() -> TimeLimit {
        TimeLimit { cpu: LIMIT_WITHOUT_EXAMPLE, why: "no teacher's example to time".to_string() }
    }

    /// The limit in one line: `6.2 s of processor time (10 x the reference's 0.62 s, at least 5 s)`.
    pub fn describe(&self) -> String {
        format!("{} s of processor time ({})", self.cpu.as_secs_f64(), self.why)
    }

    /// The limits of a render under this one, with the memory and output limits of `settings`; its
    /// wall-clock limit is [`WALL_PER_CPU`] times its processor time's.
    fn run_limits(&self, settings: &Settings) -> RunLimits {
        let limits =
            Limits { time: self.cpu * WALL_PER_CPU, memory: settings.memory_limit, output: settings.output_limit };
        RunLimits { limits, cpu: self.cpu }
    }
}

/// What [`grade`] is doing.
#[derive(Clone, Copy, Debug)]
pub enum Progress<'a> {
    /// A step done once for the class, in words, as it starts.
    Preparing(&'a str),
    /// A row, done.
    Graded(&'a Row),
}

/// Grades the class of `settings`, telling `progress` what it does.
pub fn grade(settings: &Settings, mut progress: impl FnMut(Progress)) -> Result<Graded, String> {
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
        let package = ClassPackage::new(&settings.workbook, &settings.target, settings.opt_level);
        progress(Progress::Preparing("building the workbook's library for the class (once)"));
        package.build_library(&PREPARATION_LIMIT, &out.join("logs").join("library.build.txt"))?;
        Some(package)
    };
    let given = settings.time_limit.map(TimeLimit::given);
    let (reference, reference_run, time_limit) = match (&settings.reference, &package) {
        (Some(_), Some(package)) if teachers.is_some() => {
            progress(Progress::Preparing("building and timing the teacher's example"));
            let (picture, run) = render_reference(settings, package, given.as_ref())?;
            let cpu = Duration::from_secs_f64(run.cpu_seconds.unwrap_or(run.seconds));
            (Some(picture), Some(run), given.unwrap_or_else(|| TimeLimit::from_reference(cpu)))
        }
        (Some(picture), _) => {
            let image = lecture6::instruments::compare::load_reference(picture).map_err(|e| e.to_string())?;
            let shown = out.join(REFERENCE_PICTURE);
            image.save(&shown).map_err(|e| format!("cannot write {}: {e}", shown.display()))?;
            (Some(picture.clone()), None, given.unwrap_or_else(TimeLimit::without_example))
        }
        (None, _) => (None, None, given.unwrap_or_else(TimeLimit::without_example)),
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
    let class = Class {
        settings,
        package: package.as_ref(),
        reference: reference.as_deref(),
        reference_defaults: reference_run.map(|r| r.defaults).unwrap_or_default(),
        limits: time_limit.run_limits(settings),
        copy: copy.as_ref(),
    };
    let jobs: Vec<Job> = rows
        .iter()
        .zip(&owners)
        .map(|(row, &owner)| Job {
            id: row.id.clone(),
            source: row.source.clone(),
            folder: students[owner].folder.clone(),
            exercises: row.grades.is_some().then(|| students[owner].exercises.clone()),
        })
        .collect();
    class.grade_rows(&jobs, &mut rows, &mut progress)?;
    Ok(Graded { rows, time_limit })
}

/// What one row asks to be done.
struct Job {
    /// The row's id.
    id: String,
    /// Its example, if it has one.
    source: Option<PathBuf>,
    /// The folder its example runs in (its student's, or the workbook's for `None`).
    folder: Option<PathBuf>,
    /// Its student's exercise files, on the student's first row.
    exercises: Option<Vec<(String, PathBuf)>>,
}

/// A part of a row, done.
enum Done {
    /// Its example's build.
    Built(usize, Built),
    /// Its example's run, and its picture's score.
    Ran(usize, Run, Option<Result<Score, String>>),
    /// Its exercises' grades.
    Graded(usize, Grades),
}

/// The class's work, prepared: what the rows are built, run, compared and graded with.
struct Class<'a> {
    settings: &'a Settings,
    package: Option<&'a ClassPackage>,
    reference: Option<&'a Path>,
    reference_defaults: Vec<(String, String)>,
    limits: RunLimits,
    copy: Option<&'a GradingCopy>,
}

impl Class<'_> {
    /// Does the `jobs` of `rows`: one thread builds each example and grades each student's exercises in turn
    /// (cargo builds one package at a time in a target folder), and as many threads as the machine has cores
    /// run the programs built, as they come. `progress` is told of each row once it is whole.
    fn grade_rows(&self, jobs: &[Job], rows: &mut [Row], progress: &mut impl FnMut(Progress)) -> Result<(), String> {
        let runners = std::thread::available_parallelism().map_or(1, |n| n.get());
        let (done, finished) = channel::<Result<Done, String>>();
        let (queue, queued) = channel::<(usize, PathBuf)>();
        let queued = Mutex::new(queued);
        std::thread::scope(|scope| {
            for _ in 0..runners {
                let (done, queued) = (done.clone(), &queued);
                scope.spawn(move || {
                    loop {
                        // The queue's lock is held while waiting for a program, not while running it.
                        let next = queued.lock().unwrap_or_else(PoisonError::into_inner).recv();
                        let Ok((index, program)) = next else { break };
                        let ran = self.run_one(&jobs[index], &program).map(|(run, score)| Done::Ran(index, run, score));
                        let _ = done.send(ran);
                    }
                });
            }
            let builder = done.clone();
            scope.spawn(move || self.build_all(jobs, &queue, &builder));
            drop(done);
            let mut first_failure = None;
            let mut whole = vec![false; rows.len()];
            let mut graded = vec![false; rows.len()];
            for message in finished {
                let index = match message {
                    Ok(Done::Built(index, built)) => {
                        rows[index].built = Some(built);
                        index
                    }
                    Ok(Done::Ran(index, run, score)) => {
                        // A program whose scene cannot be built prints no depth among its defaults (the
                        // error names what is wrong): its settings are not compared with the reference's.
                        let scene_built = run.outcome.is_ok() || run.defaults.iter().any(|(o, _)| o == "--max-depth");
                        rows[index].differences = match scene_built {
                            true => differences(&run.defaults, &self.reference_defaults),
                            false => Vec::new(),
                        };
                        (rows[index].run, rows[index].score) = (Some(run), score);
                        index
                    }
                    Ok(Done::Graded(index, grades)) => {
                        (rows[index].grades, graded[index]) = (Some(grades), true);
                        index
                    }
                    Err(failure) => {
                        first_failure.get_or_insert(failure);
                        continue;
                    }
                };
                let row = &rows[index];
                let built = row.source.is_none() || row.built.is_some();
                let ran = row.built.as_ref().is_none_or(|b| b.program.is_err()) || row.run.is_some();
                if built && ran && (row.grades.is_none() || graded[index]) && !whole[index] {
                    whole[index] = true;
                    progress(Progress::Graded(row));
                }
            }
            first_failure.map_or(Ok(()), Err)
        })
    }

    /// Builds each job's example in turn, queueing each program built to be run, and grades each job's
    /// exercises; each done part told to `done`. Stops at the first failure of the class's own (a log that
    /// cannot be written), told to `done` too.
    fn build_all(&self, jobs: &[Job], queue: &Sender<(usize, PathBuf)>, done: &Sender<Result<Done, String>>) {
        let out = &self.settings.out;
        for (index, job) in jobs.iter().enumerate() {
            if let (Some(source), Some(package)) = (&job.source, self.package) {
                let log = out.join("logs").join(format!("{}.build.txt", job.id));
                let built = match package.build(&job.id, source, &self.settings.build_limits, &log) {
                    Ok(built) => built,
                    Err(failure) => {
                        let _ = done.send(Err(failure));
                        return;
                    }
                };
                if let Ok(program) = &built.program {
                    let _ = queue.send((index, program.clone()));
                }
                let _ = done.send(Ok(Done::Built(index, built)));
            }
            if let (Some(copy), Some(files)) = (self.copy, &job.exercises) {
                let log = out.join("logs").join(format!("{}.exercises.txt", job.id));
                let (settings, memory) = (self.settings, self.settings.memory_limit);
                let grades = copy.grade(files, settings.exercise_time, memory, settings.build_limits.time, &log);
                let failed = grades.is_err();
                let _ = done.send(grades.map(|grades| Done::Graded(index, grades)));
                if failed {
                    return;
                }
            }
        }
    }

    /// Runs the job's `program` and compares its picture with the reference.
    fn run_one(&self, job: &Job, program: &Path) -> Result<(Run, Option<Result<Score, String>>), String> {
        let (settings, out) = (self.settings, &self.settings.out);
        let picture = out.join("pictures").join(format!("{}.png", job.id));
        let dir = job.folder.as_deref().unwrap_or(&settings.workbook);
        let log = out.join("logs").join(format!("{}.run.txt", job.id));
        let mut result = run(program, &render_args(settings), &picture, dir, &self.limits, &log)?;
        // A panic's place names the example by its file name, as the compiler's errors do.
        if let Some(source) = &job.source {
            let file = source.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            result.outcome = result.outcome.map_err(|why| why.replace(&placed_as(&job.id), &file));
        }
        let score = match (&result.outcome, self.reference) {
            (Ok(()), Some(reference)) => {
                Some(compare(&picture, reference, &out.join(format!("pictures/{}-diff.png", job.id))))
            }
            _ => None,
        };
        Ok((result, score))
    }
}

/// The settings of `defaults` that are not the reference's `reference` (none without a reference's): each
/// as `--spp 20000 (the reference's 5)`, or `--ior: none (the reference's 1.5)` for one the reference has
/// and the submission does not.
fn differences(defaults: &[(String, String)], reference: &[(String, String)]) -> Vec<String> {
    let value = |settings: &[(String, String)], option: &str| {
        settings.iter().find(|(o, _)| o == option).map(|(_, v)| v.clone())
    };
    let mut differences = Vec::new();
    for (option, theirs) in reference {
        match value(defaults, option) {
            Some(ours) if ours == *theirs => {}
            Some(ours) => differences.push(format!("{option} {ours} (the reference's {theirs})")),
            None if !defaults.is_empty() => differences.push(format!("{option}: none (the reference's {theirs})")),
            None => {}
        }
    }
    if !reference.is_empty() {
        for (option, ours) in defaults.iter().filter(|(o, _)| value(reference, o).is_none()) {
            differences.push(format!("{option} {ours} (the reference has no {option})"));
        }
    }
    differences
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
            rows.push(Row {
                id,
                student: name,
                source,
                built: None,
                run: None,
                score: None,
                differences: Vec::new(),
                grades,
            });
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

/// The options of every render: the class's, one thread (the students render side by side), and the line
/// of the program's defaults.
fn render_args(settings: &Settings) -> Vec<String> {
    let mut args = settings.render_args.clone();
    args.extend(["--threads", "1", "--print-defaults"].map(String::from));
    args
}

/// Builds and renders the teacher's example as the submissions are, under the limit `given` or
/// [`LIMIT_WITHOUT_EXAMPLE`]: its picture is the reference, and its run says the time it took and its
/// defaults.
fn render_reference(
    settings: &Settings,
    package: &ClassPackage,
    given: Option<&TimeLimit>,
) -> Result<(PathBuf, Run), String> {
    let out = &settings.out;
    let source = settings.reference.as_deref().unwrap_or(Path::new(""));
    let built =
        package.build("reference", source, &settings.build_limits, &out.join("logs").join("reference.build.txt"))?;
    let program = built.program.map_err(|e| format!("the reference {} does not build: {e}", source.display()))?;
    let picture = out.join(REFERENCE_PICTURE);
    let log = out.join("logs").join("reference.run.txt");
    let limits = given.cloned().unwrap_or_else(TimeLimit::without_example).run_limits(settings);
    let result = run(&program, &render_args(settings), &picture, &settings.workbook, &limits, &log)?;
    result.outcome.clone().map_err(|e| format!("the reference {} did not render: {e}", source.display()))?;
    Ok((picture, result))
}

/// `path` from the root, so that the package's manifest finds it.
fn absolute(path: &Path) -> Result<PathBuf, String> {
    std::path::absolute(path).map_err(|e| format!("cannot find {}: {e}", path.display()))
}
