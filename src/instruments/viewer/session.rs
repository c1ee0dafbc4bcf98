//! The example's side of the window: it reads the window's requests as the command line would read the
//! same options, renders on its [`Worker`], saves, compares and traces pixels, and reports what the window
//! shows. It needs no window: the tests drive it directly, request by request.

use super::ExampleOptions;
use super::controls::Controls;
use super::fly::{Motion, as_code, moved};
use super::wire::{CameraShown, Report, Request, Status};
use super::worker::{Job, Worker};
use crate::files::output::keeps_linear_light;
use crate::instruments::compare::{self, Reference};
use crate::instruments::ray_tree::{self, PixelPos, TraceFormat};
use crate::lesson::camera::Camera;
use crate::lesson::error::Result;
use crate::lesson::frame::Frame;
use crate::lesson::render::thread_pool;
use std::sync::Arc;
use std::sync::atomic::AtomicBool;
use std::time::Duration;

/// One example's window, seen from the example.
pub struct Session<O: ExampleOptions> {
    name: String,
    /// The options of the picture shown (the last valid ones).
    options: O,
    /// The render thread and what it shows.
    pub worker: Worker,
    /// The camera the window moved to; `None` while it is the scene's own.
    camera: Option<Camera>,
    /// A pixel the window asked about before there was a scene to trace it in: answered once there is.
    waiting: Option<(u32, u32)>,
}

impl<O: ExampleOptions> Session<O> {
    /// Starts the render thread and the first render, of the example called `name` with `options`;
    /// `repaint` is called whenever the render thread has drawn something.
    pub fn new(name: &str, options: O, repaint: impl Fn() + Send + Sync + 'static) -> Result<Session<O>> {
        let worker = Worker::start(options.threads(), repaint)?;
        let mut session = Session { name: name.to_string(), options, worker, camera: None, waiting: None };
        session.submit(true, false);
        Ok(session)
    }

    /// The first report: the example's name, its options as `controls`, the interface's scale and the
    /// pixel to trace first.
    pub fn hello(&self, controls: Controls) -> Report {
        Report::Hello {
            name: self.name.clone(),
            controls,
            ui_scale: self.options.ui_scale(),
            pixel: self.options.pixel(),
        }
    }

    /// Answers one request of the window.
    pub fn handle(&mut self, request: Request) -> Vec<Report> {
        let message = |text: String| vec![Report::Message { text }];
        match request {
            Request::Options { controls } => match O::from_controls(&controls) {
                Ok(options) => {
                    self.options = options;
                    self.submit(true, false);
                    message(String::new())
                }
                Err(e) => message(e),
            },
            Request::Move { forward, right, up, yaw, pitch, roll, distance } => {
                if let Some(camera) = self.current_camera() {
                    let motion = Motion { forward, right, up, yaw, pitch, roll };
                    self.camera = Some(moved(&camera, &motion, distance));
                    self.submit(false, true);
                }
                Vec::new()
            }
            Request::Settle {} => {
                self.submit(false, false);
                Vec::new()
            }
            Request::ResetCamera {} => {
                self.camera = None;
                self.submit(false, false);
                Vec::new()
            }
            Request::Inspect { x, y } => {
                self.waiting = Some((x, y));
                self.answer_waiting()
            }
            Request::Save { ext } => message(self.save(&ext)),
            Request::Compare {} => self.compare(),
        }
    }

    /// The camera shown: the one the window moved to, or the scene's (once there is a scene).
    fn current_camera(&self) -> Option<Camera> {
        self.camera.or_else(|| self.worker.shown.lock().ok()?.scene_camera)
    }

    /// What the render thread drew since the last call: the changed pixels, and how far the picture is;
    /// and the ray tree of a pixel asked about before there was a scene.
    pub fn painted(&mut self) -> Vec<Report> {
        let mut reports = self.answer_waiting();
        let camera = self.current_camera().map(|camera| {
            let p = camera.position;
            CameraShown {
                text: format!(
                    "camera ({:.2}, {:.2}, {:.2}) yaw {:.1} pitch {:.1} roll {:.1} fov {:.1}",
                    p.x, p.y, p.z, camera.yaw, camera.pitch, camera.roll, camera.fov
                ),
                code: as_code(&camera),
                distance: p.length(),
                fov: camera.fov,
            }
        });
        let mut shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
        if let Some(([x, y, w, h], rgb)) = shown.take_changed() {
            reports.push(Report::Pixels { width: shown.width, height: shown.height, x, y, w, h, rgb });
        }
        let recent = shown.previews.iter().filter(|t| t.elapsed() < Duration::from_secs(1)).count();
        let status = Status {
            spp: shown.spp,
            tiles_done: shown.tiles_done as u32,
            tiles_total: shown.tiles_total as u32,
            seconds: shown.elapsed.as_secs_f64(),
            rays: shown.rays,
            frames_last_second: recent as u32,
            finished: shown.finished.is_some(),
            error: shown.error.clone(),
            camera,
        };
        reports.push(Report::Status { status });
        reports
    }

    /// Renders again: with the options' scene built anew (`rebuild`), or from the moved camera, as the quick
    /// `preview` while it moves.
    fn submit(&mut self, rebuild: bool, preview: bool) {
        let options = self.options.clone();
        self.worker.submit(Job {
            rebuild: rebuild.then(|| Box::new(move || options.prepare()) as _),
            camera: self.camera,
            film: self.options.film(),
            preview,
            cancel: Arc::new(AtomicBool::new(false)),
        });
    }

    /// The finished picture, if the render has finished.
    fn finished(&self) -> Option<Frame> {
        let shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
        shown.finished.as_ref().map(|(frame, _)| frame.clone())
    }

    /// Saves the finished picture as `.ext` where the command line would write it (`--output`, or
    /// `out/<name>.png`), developed as it develops it: the PNG is its file, byte for byte. Says where, or why
    /// not.
    fn save(&self, ext: &str) -> String {
        let Some(frame) = self.finished() else { return "the picture is not finished yet".to_string() };
        let path = self.options.output_path(&self.name).with_extension(ext);
        let picture = self.options.film().develop(frame, keeps_linear_light(&path));
        match picture.save(&path) {
            Ok(()) => format!("saved {}", path.display()),
            Err(e) => e.to_string(),
        }
    }

    /// Compares the finished picture with the reference (`--compare`'s, or `expected/<name>.png`) as
    /// `--compare` does: the heat map with its colour bar, and the figures in words.
    fn compare(&self) -> Vec<Report> {
        let Some(frame) = self.finished() else { return Vec::new() };
        let reference = self.options.reference(&self.name);
        let comparison = Reference::load(&reference).and_then(|expected| {
            expected.check_size(&reference, frame.width, frame.height)?;
            compare::compare(&self.options.film().develop(frame, keeps_linear_light(&reference)), &expected)
        });
        match comparison {
            Ok(comparison) => {
                let heat = &comparison.heat_map;
                let text = format!("compared with {}: {comparison}", reference.display());
                let (width, height) = heat.dimensions();
                vec![Report::HeatMap { width, height, rgb: heat.as_raw().clone() }, Report::Message { text }]
            }
            Err(e) => vec![Report::Message { text: e.to_string() }],
        }
    }

    /// The ray tree of the pixel the window asked about, once there is a scene to trace it in; nothing
    /// before, or for a pixel outside the picture.
    fn answer_waiting(&mut self) -> Vec<Report> {
        let Some((x, y)) = self.waiting else { return Vec::new() };
        let shown = self.worker.shown.lock().expect("the render thread never panics holding the picture");
        let (Some(scene), Some(settings)) = (shown.scene.clone(), shown.settings) else { return Vec::new() };
        self.waiting = None;
        if x >= settings.width || y >= settings.height {
            return Vec::new();
        }
        let i = (y as usize * shown.width as usize + x as usize) * 3;
        let on_screen = match shown.rgb.get(i..i + 3) {
            Some(&[r, g, b]) if (shown.width, shown.height) == (settings.width, settings.height) => {
                format!("shown as sRGB ({r}, {g}, {b})")
            }
            _ => "not drawn yet".to_string(),
        };
        drop(shown);
        // On a pool's thread: a deep ray tree needs its stack.
        let traced = thread_pool(Some(1))
            .and_then(|pool| pool.install(|| ray_tree::trace(&scene, &settings, PixelPos { x, y })));
        let (sees, tree) = match traced {
            Ok(trace) => {
                let first_hit = trace.tree.roots.first().and_then(|&root| trace.tree.rays[root].hit.clone());
                let sees = match first_hit {
                    Some(hit) => {
                        format!("sees node {}, shader {}, at distance {:.3}", hit.node, hit.shader, hit.distance)
                    }
                    None => "sees nothing: the environment".to_string(),
                };
                let tree = ray_tree::describe(&self.name, PixelPos { x, y }, &trace, 0, TraceFormat::Text);
                (sees, tree.unwrap_or_else(|e| e.to_string()))
            }
            Err(e) => (e.to_string(), String::new()),
        };
        let sees = format!("pixel ({x}, {y}), {on_screen}: {sees}");
        vec![Report::Picked { x, y, sees, tree }]
    }
}
