//! The live viewer (feature `viewer`): `--window` on any example opens a window in which the picture builds
//! up while it renders (the course's program shows it row by row at lecture 6, bucket by bucket with a
//! fly-through camera in its later versions), the example's options are controls, and the camera moves.
//!
//! - [`controls`]: the side panel's controls, one per option of the example's command line;
//! - [`fly`]: the interactive camera;
//! - [`pixel_panel`]: a clicked pixel's ray tree;
//! - [`worker`]: the render thread, drawing with [`crate::instruments::progressive`];
//! - [`window`]: the window itself (egui through eframe).
//!
//! The finished picture is the one the same options write without `--window`, byte for byte (see
//! [`crate::instruments::progressive`]).
//!
//! The window knows nothing of the command line: the application hands it the example's options as an
//! [`ExampleOptions`] and their controls, made from the example's command.

pub mod controls;
pub mod fly;
pub mod pixel_panel;
pub mod window;
pub mod worker;

use crate::instruments::tone_mapping::Film;
use crate::lesson::error::Result;
use crate::lesson::render::RenderSettings;
use crate::lesson::scene::Scene;
use controls::Controls;
use std::path::PathBuf;
use std::process::ExitCode;

/// The options of the example the window shows, as the application reads them from a command line: the
/// window shows them as [`Controls`], reads them back after a change, and builds, renders, saves and
/// compares through them. The application implements it for every example's command line.
pub trait ExampleOptions: Clone + Send + 'static {
    /// The options the controls spell ([`Controls::args`]), read as the example's command line reads them
    /// and checked as far as they can be before the scene is built; an error is one line naming the value.
    fn from_controls(controls: &Controls) -> std::result::Result<Self, String>;
    /// The scene and the render settings exactly as the command line's render prepares them: a scene file's
    /// frame size and anti-aliasing included, the photon map built. May be slow (a photon map).
    fn prepare(&self) -> Result<(Scene, RenderSettings)>;
    /// How the rendered light becomes the picture shown and saved (exposure, tone mapping, gamut).
    fn film(&self) -> Film;
    /// The render threads asked for; `None` is one per core.
    fn threads(&self) -> Option<usize>;
    /// Where "Save" writes the picture of the example called `name` (with the extension of the format saved).
    fn output_path(&self, name: &str) -> PathBuf;
    /// The reference "Compare" compares the picture of the example called `name` with.
    fn reference(&self, name: &str) -> PathBuf;
}

/// Opens the window for the example called `name`, with its `options` and their `controls`. Without a
/// display: one line and exit code 2.
pub fn run<O: ExampleOptions>(name: &str, options: O, controls: Controls) -> ExitCode {
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|d| !d.is_empty()));
    if !has_display {
        eprintln!("{name}: no display: DISPLAY is not set; run the window under an X server (or xvfb-run)");
        return ExitCode::from(2);
    }
    match window::open(name, options, controls) {
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
