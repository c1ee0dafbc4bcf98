//! `lecture6-viewer`: the live window of the lecture6 workbook. An example run with `--window` starts it
//! and talks to it through its standard input and output (`lecture6_viewer_protocol::wire`): the
//! example renders, the window shows the picture building up, the example's options as controls, the steps
//! beyond the slides as check boxes, the camera, and a clicked pixel's ray tree.
//!
//! It is a program of its own, the workspace member `viewer/`, so that the library every example links
//! compiles no window toolkit (egui through OpenGL on X11, which load libGL and libX11 at run time):
//! `cargo build --release -p lecture6-viewer` builds it once, beside the examples. It shares only the
//! protocol with the library, not the library itself, so that building it compiles the library not again
//! (docs/building.md).

mod layout;
mod link;
mod window;

use lecture6_viewer_protocol::wire::{Report, receive};
use link::Link;
use std::io::BufReader;
use std::process::ExitCode;
use window::Start;

fn main() -> ExitCode {
    let mut reports = BufReader::new(std::io::stdin());
    let start = match receive::<Report>(&mut reports) {
        Ok(Report::Hello { name, controls, ui_scale, pixel }) => Start { name, controls, ui_scale, pixel },
        _ => {
            eprintln!(
                "lecture6-viewer: the window of an example's --window, started by it: \
                 cargo run --release --example fresnel -- --window"
            );
            return ExitCode::from(2);
        }
    };
    let name = start.name.clone();
    match window::open(start, Link::new(reports)) {
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
