//! The grading: each exercise's facts (see [`facts`](crate::facts)), then the picture of the workbook's example
//! that uses it, and a verdict per exercise. Shared by the [`report`](crate::report) and the grader's own
//! tests (`exercises/tests/grader.rs`), which hand it wrong or blank functions and pretend pictures.

use crate::facts::Facts;
use crate::hooks::drawing_around_blanks;
use lecture6::app::limits::{self, Ending, Limits};
use std::any::Any;
use std::collections::HashMap;
use std::fmt;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::process::Command;
use std::time::Duration;

/// One exercise: its name (its file is `exercises/src/<name>.rs`), whether it is handed out, whether the
/// workbook's own function for it is taken out of this copy (`exercises::TAKEN_OUT`), how its facts are
/// checked, and the example whose default picture checks it. The exercises' crate lists them
/// (`exercises::grading::workbook`).
pub struct Exercise {
    pub name: &'static str,
    pub handed_out: bool,
    pub taken_out: bool,
    pub facts: Box<dyn Fn() -> Facts>,
    pub example: &'static str,
}

impl Exercise {
    pub fn new(
        name: &'static str,
        (handed_out, taken_out): (bool, bool),
        facts: impl Fn() -> Facts + 'static,
        example: &'static str,
    ) -> Exercise {
        Exercise { name, handed_out, taken_out, facts: Box::new(facts), example }
    }
}

/// The exercises each picture the grader checks is drawn with, in the order of the slides: what the
/// workbook's example, rendered at its default settings, asks the exercises' hooks for (the grader's own
/// tests list them while drawing, `drawing_and_listing_hooks`). In a students' copy, where the workbook's own
/// function of an exercise handed out is not there to draw around its blank, the render stops at the first
/// blank it meets, and this table names the others the picture waits for.
pub const PICTURES: &[(&str, &[&str])] = &[
    ("bitmap_textures", &["bilinear", "faceforward"]),
    ("model_transform", &["bilinear", "transform_inverse", "faceforward"]),
    ("fresnel", &["bilinear", "cube_map", "faceforward", "refract", "layered_blend", "fresnel_schlick"]),
    ("reflect_v02", &["bilinear", "transform_inverse", "faceforward"]),
    ("refract", &["bilinear", "transform_inverse", "faceforward", "refract"]),
    (
        "layered",
        &[
            "bilinear",
            "transform_inverse",
            "cube_map",
            "faceforward",
            "refract",
            "layered_blend",
            "fresnel_schlick",
            "fresnel_exact",
        ],
    ),
    ("glossy", &["bilinear", "transform_inverse", "faceforward", "glossy_disc", "glossy_cone"]),
    (
        "photon_map",
        &["transform_inverse", "faceforward", "refract", "layered_blend", "fresnel_schlick", "photon_estimate"],
    ),
];

/// The exercises the picture of `example` is drawn with ([`PICTURES`]; none for an example not in it).
pub fn uses(example: &str) -> &'static [&'static str] {
    PICTURES.iter().find(|(name, _)| *name == example).map_or(&[], |(_, uses)| uses)
}

/// What the grader says of one exercise.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// Every fact holds and the example's picture is the expected one.
    Passed { example: String },
    /// A fact does not hold, or the picture differs: the first wrong value, in words.
    Failed(String),
    /// A `todo!()` is left in it: the text it carries (the exercises' blanks name their exercise and
    /// function: `todo!("glossy_disc: concentric_disc")`), empty for a bare `todo!()`.
    NotWritten(String),
    /// Every fact holds, but the picture also needs other exercises that are not written yet: their names,
    /// every one the picture uses that is blank, in the order of the slides (empty when a blank's `todo!()`
    /// did not name its exercise), and those of them whose workbook's own function this copy has not (which
    /// leaving out of `HANDED_OUT` would not help).
    PictureWaits { example: String, on: Vec<String>, taken_out: Vec<String> },
    /// Left out of `HANDED_OUT`: the workbook's own function is used.
    NotHandedOut,
    /// Left out of `HANDED_OUT` in a copy that has not the workbook's own function for it either: its
    /// `todo!()` stops every picture that uses it.
    LeftOutWithoutOwn,
}

/// `names` as the verdicts list them: `` `a`, `b` ``.
fn quoted(names: &[String]) -> String {
    names.iter().map(|name| format!("`{name}`")).collect::<Vec<_>>().join(", ")
}

impl fmt::Display for Verdict {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Verdict::Passed { example } => {
                write!(f, "passed: every fact holds, and the picture of `{example}` matches expected/{example}.png")
            }
            Verdict::Failed(why) => write!(f, "FAILED: {why}"),
            Verdict::NotWritten(what) if what.is_empty() => write!(f, "not yet written: a todo!() is still there"),
            Verdict::NotWritten(what) => write!(f, "not yet written: todo!(\"{what}\") is still there"),
            Verdict::PictureWaits { example, on, .. } if on.is_empty() => write!(
                f,
                "every fact holds; the picture of `{example}` is not checked yet: it also needs a function with a \
                 todo!() in it"
            ),
            Verdict::PictureWaits { example, on, taken_out } => {
                let (which, them) = if on.len() == 1 { ("which is", "it") } else { ("which are", "them") };
                write!(
                    f,
                    "every fact holds; the picture of `{example}` is not checked yet: it also needs {}, {which} not \
                     written yet",
                    quoted(on)
                )?;
                // Leaving an exercise out of HANDED_OUT draws with the workbook's own function, where the copy
                // has one: the advice names only those.
                let own: Vec<String> = on.iter().filter(|name| !taken_out.contains(name)).cloned().collect();
                if own.is_empty() {
                    write!(f, ": write {them}, and the picture is checked (this copy does not hold the workbook's own)")
                } else if own.len() == on.len() {
                    write!(
                        f,
                        " (or leave {them} out of HANDED_OUT in exercises/src/lib.rs to draw the picture with the workbook's own)"
                    )
                } else {
                    write!(
                        f,
                        ": write them, or leave {} out of HANDED_OUT in exercises/src/lib.rs to draw with the \
                         workbook's own (this copy does not hold the workbook's own {})",
                        quoted(&own),
                        quoted(taken_out)
                    )
                }
            }
            Verdict::NotHandedOut => write!(f, "not handed out (the workbook's own function is used)"),
            Verdict::LeftOutWithoutOwn => write!(
                f,
                "not handed out, and this copy does not hold the workbook's own function either: every picture that uses \
                 it stops at its todo!() (put it back in HANDED_OUT in exercises/src/lib.rs and write it)"
            ),
        }
    }
}

/// The text of a panic's payload.
pub fn panic_message(payload: &(dyn Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic without a message".to_string())
}

/// The prefix of the message of `todo!()`.
const TODO: &str = "not yet implemented";

/// For the message of a `todo!(...)` panic, the text in the `todo!()` (empty for a bare one); `None` for any
/// other panic.
pub fn not_written(message: &str) -> Option<String> {
    let rest = message.strip_prefix(TODO)?;
    Some(rest.strip_prefix(": ").unwrap_or(rest).to_string())
}

/// The exercise the text of a blank's `todo!("name: function")` names.
fn exercise_of(what: &str) -> &str {
    what.split(':').next().unwrap_or(what)
}

/// How a picture came out.
#[derive(Clone, Debug, PartialEq)]
pub enum Picture {
    Expected,
    Differs(String),
    /// The texts of the `todo!()`s of the blanks it met.
    Needs(Vec<String>),
}

/// Checks `exercise`'s facts, under its own `catch_unwind`: `Ok` when they all hold, or the verdict they
/// give (a `todo!()` is "not yet written", any other panic a failure).
pub fn check_facts(exercise: &Exercise) -> Result<(), Verdict> {
    match catch_unwind(AssertUnwindSafe(|| (exercise.facts)())) {
        Ok(Ok(())) => Ok(()),
        Ok(Err(why)) => Err(Verdict::Failed(why)),
        Err(payload) => {
            let message = panic_message(payload.as_ref());
            Err(match not_written(&message) {
                Some(what) => Verdict::NotWritten(what),
                None => Verdict::Failed(format!("it panicked: {message}")),
            })
        }
    }
}

/// Draws and checks the picture of `example` with `check_picture` (`Err` says how it differs), around the
/// blanks (`drawing_around_blanks`: each blank met is named and the workbook's own function drawn instead),
/// so that every exercise a picture needs is named in one run.
pub fn draw_picture(example: &str, check_picture: &dyn Fn(&str) -> Result<(), String>) -> Picture {
    let (outcome, blanks) = drawing_around_blanks(|| catch_unwind(AssertUnwindSafe(|| check_picture(example))));
    match outcome {
        _ if !blanks.is_empty() => Picture::Needs(blanks),
        Ok(Ok(())) => Picture::Expected,
        Ok(Err(why)) => Picture::Differs(why),
        Err(payload) => {
            let message = panic_message(payload.as_ref());
            match not_written(&message) {
                Some(what) => Picture::Needs(vec![what]),
                None => Picture::Differs(format!("rendering `{example}` panicked: {message}")),
            }
        }
    }
}

/// Grades every exercise in this process: its facts first (a `todo!()` or a panic in one exercise does not
/// stop the others), then, if they hold, the picture `check_picture(example)` renders and compares (see
/// [`draw_picture`]). Each example is rendered once however many exercises it checks. An exercise that
/// never returns stops the grading here: [`grade_isolated`] gives each a time limit.
pub fn grade(exercises: &[Exercise], check_picture: &dyn Fn(&str) -> Result<(), String>) -> Vec<Verdict> {
    grade_with(exercises, &check_facts, &|example| draw_picture(example, check_picture))
}

/// The verdicts, from each exercise's facts (`facts`) and the picture of each example (`picture`, asked once
/// an example). A picture that needs blanks waits on every one of them it uses ([`uses`]), met or not: in a
/// students' copy the render stops at the first.
fn grade_with(
    exercises: &[Exercise],
    facts: &dyn Fn(&Exercise) -> Result<(), Verdict>,
    picture: &dyn Fn(&str) -> Picture,
) -> Vec<Verdict> {
    let checked: Vec<Result<(), Verdict>> = exercises
        .iter()
        .map(|exercise| match (exercise.handed_out, exercise.taken_out) {
            (true, _) => facts(exercise),
            (false, false) => Err(Verdict::NotHandedOut),
            (false, true) => Err(Verdict::LeftOutWithoutOwn),
        })
        .collect();
    // The exercises whose function stops a picture: blanks, and those with no function at all.
    let blank: Vec<&str> = exercises
        .iter()
        .zip(&checked)
        .filter(|(_, checked)| matches!(checked, Err(Verdict::NotWritten(_) | Verdict::LeftOutWithoutOwn)))
        .map(|(exercise, _)| exercise.name)
        .collect();
    let mut pictures: HashMap<&str, Picture> = HashMap::new();
    exercises
        .iter()
        .zip(checked)
        .map(|(exercise, checked)| {
            if let Err(verdict) = checked {
                return verdict;
            }
            let example = exercise.example.to_string();
            match pictures.entry(exercise.example).or_insert_with(|| picture(exercise.example)).clone() {
                Picture::Expected => Verdict::Passed { example },
                Picture::Differs(why) => Verdict::Failed(format!("every fact holds, but {why}")),
                Picture::Needs(blanks) => match blanks.iter().find(|what| exercise_of(what) == exercise.name) {
                    Some(what) => Verdict::NotWritten(what.clone()),
                    None => {
                        let met = |name: &str| blanks.iter().any(|what| exercise_of(what) == name);
                        let waits = |e: &&Exercise| {
                            met(e.name) || (blank.contains(&e.name) && uses(&example).contains(&e.name))
                        };
                        let on: Vec<&Exercise> = exercises.iter().filter(waits).collect();
                        let taken_out = on.iter().filter(|e| e.taken_out).map(|e| e.name.to_string()).collect();
                        let on = on.iter().map(|e| e.name.to_string()).collect();
                        Verdict::PictureWaits { example, on, taken_out }
                    }
                },
            }
        })
        .collect()
}

/// The environment variable that gives each exercise's time limit, in seconds ([`DEFAULT_TIME_LIMIT`]
/// without it).
pub const TIME_LIMIT_VARIABLE: &str = "EXERCISE_TIME_LIMIT";

/// An exercise's time limit when [`TIME_LIMIT_VARIABLE`] is not set: each check takes well under a second,
/// and each picture a few seconds in the default (dev) build, on a busy machine too.
pub const DEFAULT_TIME_LIMIT: Duration = Duration::from_secs(60);

/// The environment variable that gives each step's memory limit, in mebibytes (no limit without it).
pub const MEMORY_LIMIT_VARIABLE: &str = "EXERCISE_MEMORY_LIMIT";

/// The limits of each step of [`grade_isolated`], from the environment: one line naming the variable and its
/// value if it is not a positive number.
pub fn limits_from_environment() -> Result<Limits, String> {
    let time = match std::env::var(TIME_LIMIT_VARIABLE) {
        Ok(value) => limits::seconds(TIME_LIMIT_VARIABLE, &value)?,
        Err(_) => DEFAULT_TIME_LIMIT,
    };
    let memory = match std::env::var(MEMORY_LIMIT_VARIABLE) {
        Ok(value) => match value.trim().parse::<u64>() {
            Ok(mib) if mib > 0 => Some(mib << 20),
            _ => return Err(format!("{MEMORY_LIMIT_VARIABLE} {value:?}: must be a positive number of mebibytes")),
        },
        Err(_) => None,
    };
    Ok(Limits { time, memory, output: None })
}

/// The environment variable that tells a grading process it is a step of [`grade_isolated`]:
/// `facts:<exercise>` or `picture:<example>`.
const STEP_VARIABLE: &str = "EXERCISE_GRADING_STEP";

/// The environment variable that names the file a step writes its outcome to.
const OUTCOME_VARIABLE: &str = "EXERCISE_GRADING_OUTCOME";

/// Grades every exercise as [`grade`] does, with each exercise's facts and each example's picture checked in
/// a process of its own, `child()` (a program that calls [`run_step_if_asked`] first), under `limits`: an
/// exercise that loops forever, overflows its stack or eats the memory fails, stopped at its limit, and the
/// others are graded on.
pub fn grade_isolated(exercises: &[Exercise], limits: &Limits, child: &dyn Fn() -> Command) -> Vec<Verdict> {
    let seconds = limits.time.as_secs_f64();
    let facts = |exercise: &Exercise| match run_step(&format!("facts:{}", exercise.name), limits, child) {
        Ok(outcome) => match outcome.split_once('\n').unwrap_or((outcome.as_str(), "")) {
            ("hold", _) => Ok(()),
            ("not written", what) => Err(Verdict::NotWritten(what.to_string())),
            (_, why) => Err(Verdict::Failed(why.to_string())),
        },
        Err(StepEnd::TimedOut) => Err(Verdict::Failed(format!(
            "stopped at its time limit of {seconds} s before its facts were all checked (does it loop forever?)"
        ))),
        Err(StepEnd::Crashed(how)) => Err(Verdict::Failed(format!("checking its facts {how}"))),
    };
    let picture = |example: &str| match run_step(&format!("picture:{example}"), limits, child) {
        Ok(outcome) => match outcome.split_once('\n').unwrap_or((outcome.as_str(), "")) {
            ("expected", _) => Picture::Expected,
            ("needs", blanks) => Picture::Needs(blanks.lines().map(str::to_string).collect()),
            (_, why) => Picture::Differs(why.to_string()),
        },
        Err(StepEnd::TimedOut) => Picture::Differs(format!(
            "drawing `{example}` was stopped at the time limit of {seconds} s (does an exercise it uses loop \
             forever?)"
        )),
        Err(StepEnd::Crashed(how)) => Picture::Differs(format!("drawing `{example}` {how}")),
    };
    grade_with(exercises, &facts, &picture)
}

/// How a step of [`grade_isolated`] ended without an outcome.
enum StepEnd {
    /// Stopped at its time limit.
    TimedOut,
    /// Ended otherwise, or could not start: what happened, in words.
    Crashed(String),
}

/// Runs one step in a process `child()` under `limits`: the outcome it wrote, or how it ended without one.
fn run_step(step: &str, limits: &Limits, child: &dyn Fn() -> Command) -> Result<String, StepEnd> {
    let cannot = |e: std::io::Error| StepEnd::Crashed(format!("could not be started: {e}"));
    let outcome = tempfile::NamedTempFile::new().map_err(cannot)?;
    let mut command = child();
    command.env(STEP_VARIABLE, step).env(OUTCOME_VARIABLE, outcome.path());
    let finished = limits::run(&mut command, limits).map_err(cannot)?;
    let text = std::fs::read_to_string(outcome.path()).unwrap_or_default();
    match finished.ending {
        Ending::Exited(0) if !text.is_empty() => Ok(text),
        Ending::TimedOut => Err(StepEnd::TimedOut),
        Ending::Signal(6) => Err(StepEnd::Crashed("crashed (it aborted: a stack overflow, or memory ran out)".into())),
        Ending::Signal(signal) => Err(StepEnd::Crashed(format!("crashed (signal {signal})"))),
        Ending::Exited(code) => Err(StepEnd::Crashed(format!("ended without an outcome (exit code {code})"))),
    }
}

/// In a process [`grade_isolated`] started: runs the step it asks of `exercises` (its facts, or an example's
/// picture with `check_picture`), writes the outcome and returns `true`. `false` in any other process.
pub fn run_step_if_asked(exercises: &[Exercise], check_picture: &dyn Fn(&str) -> Result<(), String>) -> bool {
    let (Ok(step), Ok(outcome)) = (std::env::var(STEP_VARIABLE), std::env::var(OUTCOME_VARIABLE)) else {
        return false;
    };
    let text = match step.split_once(':') {
        Some(("facts", name)) => match exercises.iter().find(|e| e.name == name).map(check_facts) {
            Some(Ok(())) => "hold".to_string(),
            Some(Err(Verdict::NotWritten(what))) => format!("not written\n{what}"),
            Some(Err(verdict)) => format!("failed\n{}", failure(&verdict)),
            None => format!("failed\nthe grader has no exercise `{name}`"),
        },
        Some(("picture", example)) => match draw_picture(example, check_picture) {
            Picture::Expected => "expected".to_string(),
            Picture::Differs(why) => format!("differs\n{why}"),
            Picture::Needs(blanks) => format!("needs\n{}", blanks.join("\n")),
        },
        _ => format!("failed\nthe grader has no step `{step}`"),
    };
    if let Err(e) = std::fs::write(&outcome, text) {
        eprintln!("grade: cannot write the outcome of {step} to {outcome}: {e}");
    }
    true
}

/// What a failed verdict says after its "FAILED: ".
fn failure(verdict: &Verdict) -> String {
    match verdict {
        Verdict::Failed(why) => why.clone(),
        other => other.to_string(),
    }
}

/// The report: one line per exercise, then the count.
pub fn report(exercises: &[Exercise], verdicts: &[Verdict]) -> String {
    let width = exercises.iter().map(|e| e.name.len()).max().unwrap_or(0);
    let mut lines: Vec<String> =
        exercises.iter().zip(verdicts).map(|(e, v)| format!("  {:<width$}  {v}", e.name)).collect();
    // An exercise left out of a copy's HANDED_OUT without the workbook's own is still one of its own.
    let handed_out = verdicts.iter().filter(|v| **v != Verdict::NotHandedOut).count();
    let passed = verdicts.iter().filter(|v| matches!(v, Verdict::Passed { .. })).count();
    lines.push(String::new());
    lines.push(format!(
        "{passed} of {handed_out} exercises handed out passed (each is the file exercises/src/<name>.rs)."
    ));
    lines.join("\n")
}

/// Whether every exercise handed out passed.
pub fn all_passed(verdicts: &[Verdict]) -> bool {
    verdicts.iter().all(|v| matches!(v, Verdict::Passed { .. } | Verdict::NotHandedOut))
}
