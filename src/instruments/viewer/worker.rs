//! The viewer's render thread: it takes the latest job (new options, a moved camera, or both), cancels
//! nothing itself (the window cancels the job in flight by setting its flag before sending the next), and
//! paints what the progressive renderer draws into the picture the window shows.

use crate::instruments::progressive::{
    Outcome, Update, photon_passes, preview_settings, quick_frame, render_progressive,
};
use crate::instruments::tone_mapping::Film;
use crate::lesson::camera::Camera;
use crate::lesson::color::to_srgb8;
use crate::lesson::error::Result;
use crate::lesson::frame::Frame;
use crate::lesson::render::{RenderSettings, RenderStats, thread_pool};
use crate::lesson::scene::Scene;
use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Builds the scene for new options and the render settings it is rendered with, exactly as the command
/// line's render would (`Cli::prepare`: a scene file's frame size and anti-aliasing included). Parsing them
/// was done by the window; building may be slow: a photon map.
pub type BuildScene = Box<dyn FnOnce() -> Result<(Scene, RenderSettings)> + Send>;

/// What to render next.
pub struct Job {
    /// New options: build the scene again. `None` keeps the scene of the previous job.
    pub rebuild: Option<BuildScene>,
    /// The camera to render from; `None` is the scene's own.
    pub camera: Option<Camera>,
    /// How the picture is exposed and tone mapped on the screen (`--exposure`, `--tonemap`).
    pub film: Film,
    /// The camera is moving: draw one quick frame ([`crate::instruments::progressive::preview_settings`]) and no
    /// refinement.
    pub preview: bool,
    /// Set by the window when it sends the next job.
    pub cancel: Arc<AtomicBool>,
}

/// What the window shows: the picture as far as it is drawn, and how far that is.
pub struct Shown {
    /// 8-bit sRGB, `width` x `height` of the job's settings.
    pub rgb: Vec<u8>,
    /// Width of `rgb`, in pixels.
    pub width: u32,
    /// Height of `rgb`, in pixels.
    pub height: u32,
    /// The rectangle of `rgb` changed since the window was last sent it, as (left, top, right, bottom), the
    /// right and bottom edges excluded; `None` when nothing changed.
    changed: Option<[u32; 4]>,
    /// How the rendered light becomes `rgb`.
    pub film: Film,
    /// Tiles of the full-quality picture drawn, of `tiles_total`.
    pub tiles_done: usize,
    /// Tiles of the full-quality picture in all.
    pub tiles_total: usize,
    /// Samples per pixel of what is shown (1 for the coarse pass and the moving preview).
    pub spp: u32,
    /// When the job being shown started.
    pub started: Instant,
    /// How long the job has taken to draw what is shown (for a finished picture, the render's own time).
    pub elapsed: Duration,
    /// Rays traced for what is shown.
    pub rays: u64,
    /// The finished full-quality picture, in linear light, and its statistics.
    pub finished: Option<(Frame, RenderStats)>,
    /// The scene of the picture shown, for the pixel inspector.
    pub scene: Option<Arc<Scene>>,
    /// The camera of the scene as built, before the window moved it.
    pub scene_camera: Option<Camera>,
    /// The settings of the full-quality picture, as the scene decided them.
    pub settings: Option<RenderSettings>,
    /// Building or rendering failed: the message.
    pub error: Option<String>,
    /// When the moving camera's pictures of the last second were shown: their count is the frame rate.
    pub previews: VecDeque<Instant>,
}

impl Shown {
    fn new() -> Shown {
        Shown {
            rgb: Vec::new(),
            width: 0,
            height: 0,
            changed: None,
            film: Film::default(),
            tiles_done: 0,
            tiles_total: 0,
            spp: 0,
            started: Instant::now(),
            elapsed: Duration::ZERO,
            rays: 0,
            finished: None,
            scene: None,
            scene_camera: None,
            settings: None,
            error: None,
            previews: VecDeque::new(),
        }
    }

    /// Starts showing a picture of `settings`' size (keeping what is shown while the size stays).
    fn start(&mut self, settings: &RenderSettings, tiles_total: usize) {
        if (self.width, self.height) != (settings.width, settings.height) {
            self.rgb = vec![0; settings.width as usize * settings.height as usize * 3];
            (self.width, self.height) = (settings.width, settings.height);
            self.changed = None;
        }
        self.tiles_done = 0;
        self.tiles_total = tiles_total;
        self.started = Instant::now();
        self.rays = 0;
        self.finished = None;
        self.error = None;
    }

    /// Marks the rectangle from (`x0`, `y0`) to (`x1`, `y1`) (excluded) as changed.
    fn mark(&mut self, [x0, y0, x1, y1]: [u32; 4]) {
        self.changed = Some(match self.changed {
            Some([a0, b0, a1, b1]) => [a0.min(x0), b0.min(y0), a1.max(x1), b1.max(y1)],
            None => [x0, y0, x1, y1],
        });
    }

    /// The rectangle changed since the last call, as (x, y, width, height), and its pixels row by row; `None`
    /// when nothing changed.
    pub fn take_changed(&mut self) -> Option<([u32; 4], Vec<u8>)> {
        let [x0, y0, x1, y1] = self.changed.take()?;
        let row = |y: u32| {
            let start = (y as usize * self.width as usize + x0 as usize) * 3;
            &self.rgb[start..start + (x1 - x0) as usize * 3]
        };
        Some(([x0, y0, x1 - x0, y1 - y0], (y0..y1).flat_map(row).copied().collect()))
    }

    /// Paints a smaller (or equal) frame stretched over the whole picture, each of its pixels a block.
    pub fn paint_stretched(&mut self, frame: &Frame) {
        let (w, h) = (self.width as usize, self.height as usize);
        for y in 0..h {
            let fy = (y * frame.height as usize / h) as u32;
            for x in 0..w {
                let fx = (x * frame.width as usize / w) as u32;
                self.rgb[(y * w + x) * 3..][..3]
                    .copy_from_slice(&to_srgb8(self.film.developed(frame.get(fx, fy), false)));
            }
        }
        self.mark([0, 0, self.width, self.height]);
    }

    fn paint_tile(&mut self, tile: &crate::instruments::progressive::Tile) {
        let w = self.width as usize;
        for (i, &c) in tile.pixels.iter().enumerate() {
            let (x, y) = (tile.x as usize + i % tile.width as usize, tile.y as usize + i / tile.width as usize);
            self.rgb[(y * w + x) * 3..][..3].copy_from_slice(&to_srgb8(self.film.developed(c, false)));
        }
        self.tiles_done += 1;
        self.rays += tile.rays;
        self.mark([tile.x, tile.y, tile.x + tile.width, tile.y + tile.height]);
    }
}

/// The render thread and what it shows.
pub struct Worker {
    jobs: Sender<Job>,
    /// What the window shows, painted by the render thread: lock it to read.
    pub shown: Arc<Mutex<Shown>>,
    /// The cancel flag of the last job sent, and whether it is a moving preview.
    current: Option<(Arc<AtomicBool>, bool)>,
}

impl Worker {
    /// Starts the render thread on a pool of `threads` workers; `repaint` asks the window to redraw.
    pub fn start(threads: Option<usize>, repaint: impl Fn() + Send + Sync + 'static) -> Result<Worker> {
        let pool = thread_pool(threads)?;
        let (jobs, inbox) = channel();
        let shown = Arc::new(Mutex::new(Shown::new()));
        let painted = shown.clone();
        std::thread::spawn(move || serve(&pool, &inbox, &painted, &repaint));
        Ok(Worker { jobs, shown, current: None })
    }

    /// Cancels the job in flight and starts `job`; but a preview of the moving camera lets the preview in
    /// flight finish: the camera moves at every redraw of the window, faster than a preview is drawn, so
    /// cancelling each for the next would show none. The render thread then draws the latest. The finished
    /// picture shown is forgotten: it is no longer the picture of the job asked for, so "Save" and "Compare"
    /// wait for the next.
    pub fn submit(&mut self, job: Job) {
        let preview = job.preview;
        if let Some((cancel, was_preview)) = self.current.replace((job.cancel.clone(), preview))
            && !(preview && was_preview)
        {
            cancel.store(true, Ordering::Relaxed);
        }
        // After the cancel: a job that finishes now sees it, and keeps its picture to itself.
        self.shown.lock().expect("the render thread never panics holding the picture").finished = None;
        // The thread ends only with the window.
        let _ = self.jobs.send(job);
    }
}

/// The render thread's loop: the latest job first (the ones it replaces are skipped, but a scene they
/// asked to rebuild is still rebuilt).
fn serve(pool: &rayon::ThreadPool, inbox: &Receiver<Job>, shown: &Mutex<Shown>, repaint: &(dyn Fn() + Sync)) {
    let mut scene: Option<(Arc<Scene>, RenderSettings)> = None;
    while let Ok(mut job) = inbox.recv() {
        while let Ok(next) = inbox.try_recv() {
            let rebuild = job.rebuild.take();
            job = next;
            job.rebuild = job.rebuild.or(rebuild);
        }
        if let Err(e) = pool.install(|| run_job(job, &mut scene, shown, repaint)) {
            shown.lock().expect("the window never panics holding the picture").error = Some(e.to_string());
        }
        repaint();
    }
}

/// Draws `job` with the scene built last (`scene`, with the settings it decided), or first builds a new one.
fn run_job(
    job: Job,
    scene: &mut Option<(Arc<Scene>, RenderSettings)>,
    shown: &Mutex<Shown>,
    repaint: &(dyn Fn() + Sync),
) -> Result<()> {
    let lock = || shown.lock().expect("the window never panics holding the picture");
    if let Some(build) = job.rebuild {
        let (built, settings) = build()?;
        lock().scene_camera = Some(built.camera);
        // With the tree over its nodes that `render` builds: a camera moved later keeps it.
        *scene = Some((Arc::new(built.prepared().into_owned()), settings));
    }
    // Options change only with a rebuild: the settings are the ones the scene decided then.
    let Some((base, settings)) = scene.as_ref() else { return Ok(()) };
    let settings = *settings;
    let scene = match job.camera {
        Some(camera) => {
            let mut moved = (**base).clone();
            moved.camera = camera;
            Arc::new(moved)
        }
        None => base.clone(),
    };
    {
        let mut shown = lock();
        shown.scene = Some(scene.clone());
        shown.settings = Some(settings);
        shown.film = job.film;
    }
    // A progressive caustic's passes each draw every tile again.
    let tiles_total = crate::instruments::progressive::tiles(settings.width, settings.height).len()
        * photon_passes(&scene, &settings) as usize;
    lock().start(&settings, tiles_total);
    if job.preview {
        if let Some((frame, counters)) = quick_frame(&scene, &preview_settings(&settings), &job.cancel)? {
            let mut shown = lock();
            shown.paint_stretched(&frame);
            let now = Instant::now();
            shown.previews.retain(|t| now.duration_since(*t) < Duration::from_secs(1));
            shown.previews.push_back(now);
            (shown.spp, shown.rays, shown.elapsed) = (1, counters.total(), shown.started.elapsed());
        }
        return Ok(());
    }
    let on_update = |update: Update| {
        let mut shown = lock();
        match update {
            Update::Coarse(frame) => {
                shown.paint_stretched(frame);
                shown.spp = 1;
            }
            Update::Tile(tile) => {
                shown.paint_tile(tile);
                shown.spp = settings.spp;
            }
            // The average of a progressive caustic's passes so far, whole: its tiles were painted one by one.
            Update::Passes { frame, .. } => shown.paint_stretched(frame),
        }
        shown.elapsed = shown.started.elapsed();
        repaint();
    };
    if let Outcome::Finished(frame, stats) = render_progressive(&scene, &settings, &job.cancel, &on_update)? {
        let mut shown = lock();
        // Replaced while its last tile was drawn: the next job's picture is the one to show.
        if job.cancel.load(Ordering::Relaxed) {
            return Ok(());
        }
        // The finished picture, whole: the adaptive anti-aliasing changes it after the last tile.
        shown.paint_stretched(&frame);
        (shown.rays, shown.elapsed) = (stats.counters.total(), stats.elapsed);
        shown.finished = Some((frame, *stats));
    }
    Ok(())
}
