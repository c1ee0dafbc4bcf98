//! The grader: each exercise's facts (see [`facts`]), then the picture of the workbook's example that uses
//! it, and a verdict per exercise. Shared by the report (`exercises/tests/grade.rs`) and the grader's own tests
//! (`exercises/tests/grader.rs`), which hand it wrong or blank functions and pretend pictures.

#![allow(dead_code)] // each test binary uses its own part of this module

pub mod facts;

use facts::Facts;
use lecture6::lesson::exercise_hooks::drawing_around_blanks;
use std::any::Any;
use std::collections::HashMap;
use std::fmt;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// One exercise: its name (its file is `exercises/src/<name>.rs`), whether it is handed out, how its facts
/// are checked, and the example whose default picture uses it.
pub struct Exercise {
    pub name: &'static str,
    pub handed_out: bool,
    pub facts: Box<dyn Fn() -> Facts>,
    pub example: &'static str,
}

impl Exercise {
    pub fn new(
        name: &'static str,
        handed_out: bool,
        facts: impl Fn() -> Facts + 'static,
        example: &'static str,
    ) -> Exercise {
        Exercise { name, handed_out, facts: Box::new(facts), example }
    }
}

/// The workbook's exercises, in the order of the slides, checked with the functions in the `exercises` crate.
pub fn workbook() -> Vec<Exercise> {
    use exercises::*;
    vec![
        Exercise::new(
            "bilinear",
            handed_out::BILINEAR,
            || facts::bilinear(|x, y, texel| bilinear::bilinear(x, y, texel)),
            "bitmap_textures",
        ),
        Exercise::new(
            "transform_inverse",
            handed_out::TRANSFORM_INVERSE,
            || facts::transform_inverse(transform_inverse::inverse),
            "model_transform",
        ),
        Exercise::new("cube_map", handed_out::CUBE_MAP, || facts::cube_map(cube_map::cube_face_uv), "fresnel"),
        Exercise::new(
            "faceforward",
            handed_out::FACEFORWARD,
            || facts::faceforward(faceforward::faceforward),
            "reflect_v02",
        ),
        Exercise::new("refract", handed_out::REFRACT, || facts::refract(refract::refract), "refract"),
        Exercise::new(
            "layered_blend",
            handed_out::LAYERED_BLEND,
            || facts::layered_blend(layered_blend::layer_weight),
            "layered",
        ),
        Exercise::new(
            "fresnel_schlick",
            handed_out::FRESNEL_SCHLICK,
            || facts::fresnel_schlick(fresnel_schlick::fresnel),
            "fresnel",
        ),
        Exercise::new(
            "fresnel_exact",
            handed_out::FRESNEL_EXACT,
            || facts::fresnel_exact(fresnel_exact::fresnel_exact),
            "layered",
        ),
        Exercise::new(
            "glossy_disc",
            handed_out::GLOSSY_DISC,
            || facts::glossy_disc(|random| glossy_disc::random_unit_disc_point(random), glossy_disc::concentric_disc),
            "glossy",
        ),
        Exercise::new(
            "glossy_cone",
            handed_out::GLOSSY_CONE,
            || facts::glossy_cone(glossy_cone::glossy_scaling, glossy_cone::glossy_direction),
            "glossy",
        ),
        Exercise::new(
            "photon_estimate",
            handed_out::PHOTON_ESTIMATE,
            || facts::photon_estimate(photon_estimate::irradiance_estimate),
            "photon_map",
        ),
    ]
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
    /// every one the picture met (empty when a blank's `todo!()` did not name its exercise).
    PictureWaits { example: String, on: Vec<String> },
    /// Set to `false` in `exercises::handed_out`: the workbook's own function is used.
    NotHandedOut,
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
            Verdict::PictureWaits { example, on } if on.is_empty() => write!(
                f,
                "every fact holds; the picture of `{example}` is not checked yet: it also needs a function with a \
                 todo!() in it"
            ),
            Verdict::PictureWaits { example, on } => {
                let names = on.iter().map(|name| format!("`{name}`")).collect::<Vec<_>>().join(", ");
                let (which, them) = if on.len() == 1 { ("which is", "it") } else { ("which are", "them") };
                write!(
                    f,
                    "every fact holds; the picture of `{example}` is not checked yet: it also needs {names}, {which} \
                     not written yet (or leave {them} out of HANDED_OUT in exercises/src/lib.rs to draw the picture \
                     with the workbook's own)"
                )
            }
            Verdict::NotHandedOut => write!(f, "not handed out (the workbook's own function is used)"),
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
#[derive(Clone, Debug)]
enum Picture {
    Expected,
    Differs(String),
    /// The texts of the `todo!()`s of the blanks it met.
    Needs(Vec<String>),
}

/// Grades every exercise: its facts first (a `todo!()` or a panic in one exercise does not stop the others),
/// then, if they hold, the picture `check_picture(example)` renders and compares (`Err` says how it differs;
/// a blank met while drawing it means the picture waits for it). The picture is drawn around the blanks
/// (`drawing_around_blanks`: each blank met is named and the workbook's own function drawn instead), so that
/// every exercise a picture needs is named in one run. Each example is rendered once however many exercises
/// it checks.
pub fn grade(exercises: &[Exercise], check_picture: &dyn Fn(&str) -> Result<(), String>) -> Vec<Verdict> {
    let mut pictures: HashMap<&str, Picture> = HashMap::new();
    let mut picture = |example: &'static str| {
        pictures
            .entry(example)
            .or_insert_with(|| {
                let (outcome, blanks) =
                    drawing_around_blanks(|| catch_unwind(AssertUnwindSafe(|| check_picture(example))));
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
            })
            .clone()
    };
    exercises
        .iter()
        .map(|exercise| {
            if !exercise.handed_out {
                return Verdict::NotHandedOut;
            }
            match catch_unwind(AssertUnwindSafe(|| (exercise.facts)())) {
                Ok(Ok(())) => {}
                Ok(Err(why)) => return Verdict::Failed(why),
                Err(payload) => {
                    let message = panic_message(payload.as_ref());
                    return match not_written(&message) {
                        Some(what) => Verdict::NotWritten(what),
                        None => Verdict::Failed(format!("it panicked: {message}")),
                    };
                }
            }
            let example = exercise.example.to_string();
            match picture(exercise.example) {
                Picture::Expected => Verdict::Passed { example },
                Picture::Differs(why) => Verdict::Failed(format!("every fact holds, but {why}")),
                Picture::Needs(blanks) => match blanks.iter().find(|what| exercise_of(what) == exercise.name) {
                    Some(what) => Verdict::NotWritten(what.clone()),
                    None => {
                        let mut on: Vec<String> = blanks.iter().map(|what| exercise_of(what).to_string()).collect();
                        on.dedup();
                        on.retain(|name| !name.is_empty());
                        Verdict::PictureWaits { example, on }
                    }
                },
            }
        })
        .collect()
}

/// The report: one line per exercise, then the count.
pub fn report(exercises: &[Exercise], verdicts: &[Verdict]) -> String {
    let width = exercises.iter().map(|e| e.name.len()).max().unwrap_or(0);
    let mut lines: Vec<String> =
        exercises.iter().zip(verdicts).map(|(e, v)| format!("  {:<width$}  {v}", e.name)).collect();
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
