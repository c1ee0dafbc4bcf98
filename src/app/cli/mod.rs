//! The command line every example shares, and the one function that runs an example end to end:
//! parse the options, build the scene, render, write the picture, compare it with a reference if asked,
//! and print one summary line. The regression tests go through [`Cli::render`], the same path.
//!
//! Errors in user input print one line naming the file or value and exit with code 2 (as clap does for
//! unknown options, whose message is put on one line too), never a panic. What an example prints goes
//! through `console.rs`: a reader that went away (`| head -1`) ends nothing, a full device is one more
//! error.
//!
//! The instruments that render an example again and again (the study, the live window) say what they need of
//! its command line as traits of their own; `instruments.rs` implements them for every example, and
//! `controls.rs` makes the window's controls from the example's command, so the instruments import nothing
//! from here.

pub mod commands;
mod console;
mod controls;
mod defaults;
mod example;
mod help;
mod instruments;
mod options;
mod progress;
mod run;
mod step_effect;
mod values;

pub use console::{print_stderr, print_stdout};
pub use controls::controls;
pub use defaults::{DEFAULTS_MARK, defaults_line};
pub use example::{Cli, Example};
pub use options::{CommonArgs, PhotonArgs, whole_number};
pub use run::{one_line, render_and_report, render_for_test, run, run_as};
