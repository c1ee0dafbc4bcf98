//! The report of `cargo test -p exercises`: grades every exercise handed out and prints one line for each:
//! passed, FAILED with the first wrong value, or not yet written. An exercise passes when its facts hold and
//! the workbook's example that uses it, rendered at its default settings with the student's functions, is
//! within the regression tests' tolerance of `expected/`. A picture that differs is saved with a heat map of
//! the difference under `target/exercises/`.
//!
//! Each exercise's facts, and each picture, are checked in a process of their own under a time limit
//! (`EXERCISE_TIME_LIMIT` seconds, 60 without it; `EXERCISE_MEMORY_LIMIT` mebibytes of memory, none without
//! it): an exercise that loops forever fails, stopped at its limit, and the others are graded on.
//!
//! The pictures are rendered at full size and compared with `expected/`, the pictures a student sees in the
//! README and renders with the plain workbook (the grader's own tests also compare a solution's picture with
//! the workbook's own drawn in the same build, `drawing_with_the_workbooks_own`). The eight pictures take
//! about ten seconds together, in the default (dev) build too, whose dependencies are optimised.

use crate::grading::{self, Exercise};
use lecture6::app::cli::{Cli, Example};
use lecture6::instruments::compare::{
    Difference, REGRESSION_MAX_RMSE, REGRESSION_PIXELS_PER_LARGE, difference, heat_map, load_reference,
};
use lecture6::lesson::frame::Frame;
use std::path::Path;
use std::process::ExitCode;

/// The workspace root: the workbook.
fn root() -> &'static Path {
    let grader = Path::new(env!("CARGO_MANIFEST_DIR"));
    grader.parent().and_then(Path::parent).expect("exercises/grader/ lies in the workbook")
}

/// Renders one of the workbook's examples with the options `args`, as its binary would.
pub fn render(example: &str, args: &[&str]) -> Result<Frame, String> {
    fn render_as<E: Example>(name: &str, args: &[&str]) -> Result<Frame, String> {
        let cli = Cli::<E>::parse_args(name, args.iter().copied()).map_err(|e| e.to_string())?;
        cli.render().map(|(frame, _)| frame).map_err(|e| e.to_string())
    }
    macro_rules! by_name {
        ($($name:ident),*) => {
            match example {
                $(stringify!($name) => render_as::<crate::examples::$name::Options>(example, args),)*
                _ => Err(format!("the workbook has no example `{example}`")),
            }
        };
    }
    every_example!(by_name)
}

/// Renders `example` and compares it with `expected/<example>.png` under the regression tests' rule; on a
/// difference, saves the picture and a heat map under `target/exercises/` and says how far it is.
fn check_picture(example: &str) -> Result<(), String> {
    let actual = render(example, &["--quiet"])?.to_rgb8();
    let expected_path = root().join("expected").join(format!("{example}.png"));
    let expected = load_reference(&expected_path).map_err(|e| e.to_string())?;
    let d = difference(&actual, &expected).map_err(|e| e.to_string())?;
    if d.within_regression_tolerance() {
        return Ok(());
    }
    // Saved under the workbook's target/, and named from its root as a student's commands name files.
    let folder = Path::new("target").join("exercises");
    let (picture, diff) = (folder.join(format!("{example}.png")), folder.join(format!("{example}-diff.png")));
    std::fs::create_dir_all(root().join(&folder)).map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
    actual.save(root().join(&picture)).map_err(|e| format!("cannot write {}: {e}", picture.display()))?;
    heat_map(&actual, &expected)
        .map_err(|e| e.to_string())?
        .save(root().join(&diff))
        .map_err(|e| format!("cannot write {}: {e}", diff.display()))?;
    Err(format!(
        "the picture of `{example}` is not the expected one: {} of its {} pixels differ from expected/{example}.png \
         by more than {} levels (at most {} may) and the RMSE is {:.2} levels (at most {REGRESSION_MAX_RMSE}); yours \
         is {}, the difference {} (the picture also uses the other exercises: fix those that fail first)",
        d.large_pixels,
        d.pixels,
        Difference::LARGE,
        d.pixels / REGRESSION_PIXELS_PER_LARGE,
        d.rmse_8bit,
        picture.display(),
        diff.display(),
    ))
}

/// The grader's program: grades `exercises` (with the student's functions registered with the renderer) and
/// prints the report; or, asked by an earlier run of it, one step of that grading.
pub fn main(exercises: &[Exercise]) -> ExitCode {
    // A blank's todo!() is reported in the verdict; any other panic is printed as usual, with its place.
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if grading::not_written(&grading::panic_message(info.payload())).is_none() {
            default_hook(info);
        }
    }));
    // A step of the grading in a process of its own, started by the grading below.
    if grading::run_step_if_asked(exercises, &check_picture) {
        return ExitCode::SUCCESS;
    }
    let limits = match grading::limits_from_environment() {
        Ok(limits) => limits,
        Err(e) => {
            eprintln!("grade: error: {e}");
            return ExitCode::from(2);
        }
    };
    let this = match std::env::current_exe() {
        Ok(path) => path,
        Err(e) => {
            eprintln!("grade: error: cannot find the grader's own program: {e}");
            return ExitCode::from(2);
        }
    };
    lecture6::app::limits::stop_children_on_signals();
    println!(
        "\nGrading the lecture-6 exercises: facts first, then the picture of the example that uses each; each \
         exercise stopped after {} s ({} sets it).\n",
        limits.time.as_secs_f64(),
        grading::TIME_LIMIT_VARIABLE
    );
    let verdicts = grading::grade_isolated(exercises, &limits, &|| std::process::Command::new(&this));
    println!("{}\n", grading::report(exercises, &verdicts));
    if grading::all_passed(&verdicts) { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
