//! The live viewer (feature `viewer`): `--window` on any example opens a window in which the picture builds
//! up while it renders (the course's program shows it row by row at lecture 6, bucket by bucket with a
//! fly-through camera in its later versions), the example's options are controls, and the camera moves.
//!
//! - [`controls`]: the side panel's controls, generated from the example's clap command;
//! - [`fly`]: the interactive camera;
//! - [`worker`]: the render thread, drawing with [`crate::instruments::progressive`];
//! - [`window`]: the window itself (egui through eframe).
//!
//! The finished picture is the one the same options write without `--window`, byte for byte (see
//! [`crate::instruments::progressive`]).

pub mod controls;
pub mod fly;
pub mod window;
pub mod worker;

use crate::app::cli::{Cli, Example};
use std::ffi::OsString;
use std::process::ExitCode;

/// Opens the window for the example called `name`, with the options `args` (as given, without the program
/// name) already parsed into `cli`. Without a display: one line and exit code 2.
pub fn run<E: Example>(name: &str, cli: Cli<E>, args: Vec<OsString>) -> ExitCode {
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|d| !d.is_empty()));
    if !has_display {
        eprintln!("{name}: no display: DISPLAY is not set; run the window under an X server (or xvfb-run)");
        return ExitCode::from(2);
    }
    match window::open(name, cli, &args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // The windowing library's message ends with the cause, after where in its source it arose.
            let cause = e.rsplit(": ").next().unwrap_or(&e);
            let display = std::env::var("DISPLAY").unwrap_or_default();
            eprintln!("{name}: no display: cannot open a window on DISPLAY={display}: {cause}");
            ExitCode::from(2)
        }
    }
}
