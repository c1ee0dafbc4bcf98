//! Grades a class in one command (docs/class.md): every submission in a folder built against the workbook,
//! run under a time and memory limit, compared with the teacher's reference, its exercises graded; a
//! gradebook (CSV) and a contact sheet (HTML) written.
//!
//!     cargo run --release -p teacher -- hw1/ --reference examples/fresnel.rs --width 320 --height 240

use clap::Parser;
use lecture6::app::limits::{self, Limits};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;
use teacher::class::{Progress, Settings, grade};
use teacher::{chosen_exercises, contact_sheet, gradebook, hand_out, target_folder, workbook};

/// The largest file a student's render may write (its picture; its output goes through a pipe, its two ends
/// kept): far above any picture's size.
const OUTPUT_LIMIT: u64 = 256 << 20;

/// Grades a folder of submissions: a copied example per student (a file, or a folder with the student's
/// examples and exercises).
#[derive(Parser, Debug)]
#[command(name = "class")]
struct Args {
    /// The folder of submissions: `NAME.rs` (a copied example) or `NAME/` (examples, exercise files) each.
    submissions: PathBuf,
    /// The assignment's reference: a picture, or the teacher's example (`.rs`), rendered as the submissions
    /// are. Without it, the pictures and reports are shown to be graded by eye.
    #[arg(long, value_name = "PICTURE|EXAMPLE.rs")]
    reference: Option<PathBuf>,
    /// Width of every render, in pixels.
    #[arg(long, default_value_t = 320)]
    width: u32,
    /// Height of every render, in pixels.
    #[arg(long, default_value_t = 240)]
    height: u32,
    /// Samples per pixel of every render (each example's own default when not given).
    #[arg(long)]
    spp: Option<u32>,
    /// More options for every render, as one string (`--args "--ior 1.33"`).
    #[arg(long, value_name = "OPTIONS", allow_hyphen_values = true)]
    args: Option<String>,
    /// Each student's render is stopped once it has taken this many seconds of processor time (it runs on
    /// one thread, beside others). [default: 10 times what the teacher's example took, at least 5 s; 60 s
    /// without a teacher's example]
    #[arg(long, value_name = "SECONDS", value_parser = seconds)]
    time_limit: Option<Duration>,
    /// Each student's render is stopped past this much memory (address space), in MiB.
    #[arg(long, value_name = "MIB", default_value_t = 2048, value_parser = clap::value_parser!(u64).range(1..))]
    memory_limit: u64,
    /// Each student's build is stopped after this many seconds.
    #[arg(long, value_name = "SECONDS", default_value = "300", value_parser = seconds)]
    build_time_limit: Duration,
    /// The exercises graded, by name, separated by commas (every exercise when not given).
    #[arg(long, value_name = "NAME,NAME")]
    exercises: Option<String>,
    /// Each exercise is stopped after this many seconds.
    #[arg(long, value_name = "SECONDS", default_value = "60", value_parser = seconds)]
    exercise_time_limit: Duration,
    /// The optimisation level of the students' own code (the library keeps the release profile's).
    #[arg(long, default_value_t = 0, value_parser = clap::value_parser!(u8).range(0..=3))]
    opt_level: u8,
    /// The folder the gradebook, contact sheet, pictures and logs go to (SUBMISSIONS-graded beside the
    /// submissions when not given).
    #[arg(long)]
    out: Option<PathBuf>,
}

fn seconds(value: &str) -> Result<Duration, String> {
    limits::seconds("the limit", value)
}

/// One line of progress.
fn progress(step: Progress) {
    let row = match step {
        Progress::Preparing(what) => return println!("class: {what}"),
        Progress::Graded(row) => row,
    };
    let mut parts = Vec::new();
    match row.built.as_ref().map(|b| (&b.program, b.seconds)) {
        Some((Ok(_), seconds)) => parts.push(format!("built in {seconds:.1} s")),
        Some((Err(e), _)) => parts.push(format!("does not build: {e}")),
        None => {}
    }
    if let Some(run) = &row.run {
        let mut part = match &run.outcome {
            Ok(()) => format!("rendered in {:.2} s", run.seconds),
            Err(why) => why.clone(),
        };
        if !row.differences.is_empty() {
            part.push_str(&format!(", defaults unlike the reference's: {}", row.differences.join(", ")));
        }
        if !run.warnings.is_empty() {
            part.push_str(&format!(", {} warning(s)", run.warnings.len()));
        }
        match &row.score {
            Some(Ok(score)) => part.push_str(&format!(", PSNR {:.2} dB", score.psnr)),
            Some(Err(why)) => part.push_str(&format!(", not compared: {why}")),
            None => {}
        }
        parts.push(part);
    }
    if let Some(grades) = &row.grades {
        parts.push(match &grades.failure {
            Some(why) => format!("exercises not graded: {why}"),
            None => format!("exercises {}/{} passed ({:.1} s)", grades.passed(), grades.verdicts.len(), grades.seconds),
        });
    }
    println!("{}: {}", row.student, parts.join("; "));
}

fn main() -> ExitCode {
    let args = Args::parse();
    limits::stop_children_on_signals();
    let workbook = workbook().to_path_buf();
    let exercises = match hand_out::workbook_exercises(&workbook) {
        Ok(all) => chosen_exercises(args.exercises.as_deref(), &all),
        Err(e) => {
            eprintln!("class: error: {e}");
            return ExitCode::from(2);
        }
    };
    let out = args.out.clone().unwrap_or_else(|| {
        let name = args.submissions.file_name().map_or("class".into(), |n| n.to_string_lossy().into_owned());
        args.submissions.with_file_name(format!("{name}-graded"))
    });
    let mut render_args =
        vec!["--width".to_string(), args.width.to_string(), "--height".into(), args.height.to_string()];
    if let Some(spp) = args.spp {
        render_args.extend(["--spp".to_string(), spp.to_string()]);
    }
    render_args.extend(args.args.iter().flat_map(|a| a.split_whitespace().map(String::from)));
    let settings = Settings {
        submissions: args.submissions.clone(),
        out: out.clone(),
        target: target_folder(&workbook),
        workbook,
        reference: args.reference.clone(),
        render_args,
        time_limit: args.time_limit,
        memory_limit: Some(args.memory_limit << 20),
        output_limit: Some(OUTPUT_LIMIT),
        build_limits: Limits { time: args.build_time_limit, memory: None, output: None },
        opt_level: args.opt_level,
        exercises: exercises.clone(),
        exercise_time: args.exercise_time_limit,
    };
    let title = format!("{}: {}", args.submissions.display(), settings.render_args.join(" "));
    let result = grade(&settings, progress).and_then(|class| {
        let (rows, limit) = (&class.rows, &class.time_limit);
        let table = out.join("gradebook.csv");
        // A column per exercise when there are grades to put in them.
        let graded = if rows.iter().any(|row| row.grades.is_some()) { exercises.as_slice() } else { &[] };
        gradebook::write(rows, limit, graded, &table)?;
        contact_sheet::write(rows, limit, &title, settings.reference.is_some(), &out)?;
        Ok((rows.len(), table))
    });
    match result {
        Ok((rows, table)) => {
            println!("class: {rows} rows -> {} and {}", table.display(), out.join("index.html").display());
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("class: error: {e}");
            ExitCode::from(2)
        }
    }
}
