//! The live viewer: `--window` on any example opens a window in which the picture builds up while it
//! renders (the course's program shows it row by row at lecture 6, bucket by bucket with a fly-through
//! camera in its later versions), the example's options are controls, and the camera moves.
//!
//! The window is a program of its own, `lecture6-viewer` (the workspace member `viewer/`, built once with
//! `cargo build --release -p lecture6-viewer`), so that the library every example links compiles no window
//! toolkit: `--window` starts it beside the example and talks to it through a pipe ([`wire`]). The example
//! keeps everything that needs its scene: it reads the window's controls with its own command line, builds
//! and renders the scene, moves its camera, saves, compares and traces pixels ([`session`]); the window
//! draws what it is sent and sends what is clicked, dragged and pressed. The two share only the crate
//! `lecture6-viewer-protocol` (`viewer/protocol/`), which depends on nothing, so that building the window
//! never compiles the library again.
//!
//! - [`controls`]: the side panel's controls, one per option of the example's command line, and a check box
//!   per step beyond the slides (from `lecture6-viewer-protocol`);
//! - [`fly`]: the interactive camera;
//! - [`worker`]: the render thread, drawing with [`crate::instruments::progressive`];
//! - [`session`]: the example's side of the window;
//! - [`wire`]: the messages between the two (from `lecture6-viewer-protocol`).
//!
//! The finished picture is the one the same options write without `--window`, byte for byte (see
//! [`crate::instruments::progressive`]).
//!
//! The window knows nothing of the command line: the application hands it the example's options as an
//! [`ExampleOptions`] and their controls, made from the example's command.

pub mod fly;
pub mod session;
pub mod worker;

pub use lecture6_viewer_protocol::{controls, wire};

use crate::instruments::tone_mapping::Film;
use crate::lesson::error::{Error, Result};
use crate::lesson::render::RenderSettings;
use crate::lesson::scene::Scene;
use controls::Controls;
use session::Session;
use std::io::{BufReader, BufWriter};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::channel;
use wire::{Request, receive, send};

/// The window's program, as cargo names the binary of the workspace member `viewer/`.
pub const VIEWER_PROGRAM: &str = "lecture6-viewer";

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
    /// The interface's scale (`--ui-scale`).
    fn ui_scale(&self) -> f32;
    /// The pixel whose ray tree the window shows from the start (`--trace-pixel`).
    fn pixel(&self) -> Option<(u32, u32)>;
}

/// Opens the window for the example called `name`, with its `options` and their `controls`, and serves it
/// until it is closed. Without the viewer's program, or without a display: one line and exit code 2.
pub fn run<O: ExampleOptions>(name: &str, options: O, controls: Controls) -> ExitCode {
    let program = match viewer_program() {
        Ok(program) => program,
        Err(missing) => {
            eprintln!(
                "{name}: --window needs the viewer, built once with `cargo build{} -p {VIEWER_PROGRAM}` (not found: \
                 {})",
                profile_option(&missing),
                missing.display()
            );
            return ExitCode::from(2);
        }
    };
    let has_display = ["DISPLAY", "WAYLAND_DISPLAY"].iter().any(|v| std::env::var_os(v).is_some_and(|d| !d.is_empty()));
    if !has_display {
        eprintln!("{name}: no display: DISPLAY is not set; run the window under an X server (or xvfb-run)");
        return ExitCode::from(2);
    }
    let child = Command::new(&program).stdin(Stdio::piped()).stdout(Stdio::piped()).spawn();
    let mut child = match child {
        Ok(child) => child,
        Err(e) => {
            eprintln!("{name}: cannot start the viewer {}: {e}", program.display());
            return ExitCode::from(2);
        }
    };
    let served = match (child.stdin.take(), child.stdout.take()) {
        (Some(to_window), Some(from_window)) => {
            serve(name, options, controls, BufWriter::new(to_window), BufReader::new(from_window))
        }
        _ => Err(Error::parameter("the viewer", program.display(), "no pipe to it")),
    };
    if let Err(e) = served {
        eprintln!("{name}: error: {e}");
        let _ = child.kill();
    }
    // The window says itself why it could not open (no display): its exit code is the example's.
    match child.wait() {
        Ok(status) => ExitCode::from(status.code().map_or(2, |code| u8::try_from(code).unwrap_or(2))),
        Err(e) => {
            eprintln!("{name}: the viewer: {e}");
            ExitCode::from(2)
        }
    }
}

/// What the example's loop waits for: a request of the window, something drawn, or the window gone.
enum Event {
    Request(Request),
    Painted,
    Closed,
}

/// Serves the window at the other end of `to_window` and `from_window` until it closes: answers its
/// requests and sends what the render thread draws (as fast as the window takes it: what is drawn meanwhile
/// goes in one message).
fn serve<O: ExampleOptions>(
    name: &str,
    options: O,
    controls: Controls,
    mut to_window: impl std::io::Write,
    mut from_window: impl std::io::Read + Send + 'static,
) -> Result<()> {
    let (events, inbox) = channel();
    let pending = Arc::new(AtomicBool::new(false));
    let (painted, flag) = (events.clone(), pending.clone());
    let mut session = Session::new(name, options, move || {
        if !flag.swap(true, Ordering::AcqRel) {
            let _ = painted.send(Event::Painted);
        }
    })?;
    std::thread::spawn(move || {
        while let Ok(request) = receive(&mut from_window) {
            if events.send(Event::Request(request)).is_err() {
                return;
            }
        }
        let _ = events.send(Event::Closed);
    });
    let mut reports = vec![session.hello(controls)];
    loop {
        for report in reports.drain(..) {
            // A window that went away ends the session as closing it does.
            if send(&mut to_window, &report).is_err() {
                return Ok(());
            }
        }
        reports = match inbox.recv() {
            Ok(Event::Request(request)) => session.handle(request),
            Ok(Event::Painted) => {
                pending.store(false, Ordering::Release);
                session.painted()
            }
            Ok(Event::Closed) | Err(_) => return Ok(()),
        };
    }
}

/// The viewer's program: beside the example's binary's folder (`target/release/examples/fresnel` finds
/// `target/release/lecture6-viewer`), or in it. Where it was looked for first when it is in neither.
fn viewer_program() -> std::result::Result<PathBuf, PathBuf> {
    let file = format!("{VIEWER_PROGRAM}{}", std::env::consts::EXE_SUFFIX);
    let exe = std::env::current_exe().unwrap_or_default();
    let folder = exe.parent().unwrap_or(Path::new("."));
    let candidates = [folder.parent().map(|p| p.join(&file)), Some(folder.join(&file))];
    let candidates: Vec<PathBuf> = candidates.into_iter().flatten().collect();
    candidates.iter().find(|p| p.is_file()).cloned().ok_or_else(|| candidates[0].clone())
}

/// The option of `cargo build` that builds into the folder of `program` (`target/release/...`: `--release`).
fn profile_option(program: &Path) -> String {
    match program.parent().and_then(Path::file_name).and_then(|p| p.to_str()) {
        Some("debug") => String::new(),
        Some("release") | None => " --release".to_string(),
        Some(profile) => format!(" --profile {profile}"),
    }
}
