//! The students' copy of the workbook, with the chosen exercises handed out as blanks and their solutions
//! nowhere in it (docs/class.md):
//!
//!     cargo run --release -p teacher --bin hand-out -- ../lecture6-students --exercises refract,fresnel_schlick

use clap::Parser;
use std::path::PathBuf;
use std::process::ExitCode;
use teacher::{chosen_exercises, hand_out, workbook};

/// Writes the students' copy of the workbook: the exercises handed out as blanks, no history, no solution.
#[derive(Parser, Debug)]
#[command(name = "hand-out")]
struct Args {
    /// The folder to write the copy to (new, or empty).
    copy: PathBuf,
    /// The exercises handed out, by name, separated by commas (every exercise when not given).
    #[arg(long, value_name = "NAME,NAME")]
    exercises: Option<String>,
}

fn main() -> ExitCode {
    let args = Args::parse();
    let workbook = workbook();
    let result = hand_out::workbook_exercises(workbook).and_then(|all| {
        let chosen = chosen_exercises(args.exercises.as_deref(), &all);
        hand_out::hand_out(workbook, &args.copy, &chosen).map(|done| (chosen, done))
    });
    match result {
        Ok((chosen, done)) => {
            println!("hand-out: {} files -> {}", done.files, args.copy.display());
            println!("handed out: {}", chosen.join(", "));
            for (file, exercises) in &done.blanked {
                println!("  the workbook's own {} taken out of {}", exercises.join(", "), file.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("hand-out: error: {e}");
            ExitCode::from(2)
        }
    }
}
