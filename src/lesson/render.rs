//! The renderer: turns a scene into a frame of linear colours, in parallel and deterministically.
//!
//! Rows are rendered in parallel by rayon. Each pixel has its own random stream seeded from
//! (seed, x, y) (see [`crate::lesson::rng`]), and its samples are averaged in a fixed order, so the frame is the same
//! bit for bit whatever the thread count.
//!
//! Anti-aliasing: one sample per pixel goes through the pixel's centre; more go to random points of the
//! pixel, as on the slides, or, with the step [`Step::StratifiedAa`], a square `spp` (4, 9, 16, ...) to a
//! jittered k x k grid and any other count to N-rooks (Latin hypercube) stratification, one sample in each
//! column and each row of an N x N grid.
//!
//! Dispersion (see [`crate::lesson::spectral`]): a scene whose shaders depend on the wavelength is traced once per
//! wavelength band (the slide's K passes; each pass of a pixel has its own random stream, keyed by the pass)
//! or in one pass whose samples carry wavelengths of their own: one each (spectral sampling), or several
//! (hero-wavelength sampling), which follow one path until it meets a dispersive surface
//! ([`TraceContext::met_dispersion`]) and are then traced one by one. The bands' colours are added in double
//! precision, so a surface that looks the same in every band keeps its colour exactly. The frame keeps
//! colours outside the sRGB gamut as they are (negative channels); the picture that is shown maps them
//! ([`crate::lesson::spectral::GamutMapping`]). A scene with nothing dispersive is traced once, in white
//! light, whatever `wavelengths` says.

pub use crate::files::workers::{WORKER_STACK_SIZE, on_workers, thread_pool, worker_stacks};
use crate::lesson::adaptive_aa;
use crate::lesson::beyond::{Step, Steps};
use crate::lesson::camera::CameraFrame;
use crate::lesson::color::Color;
use crate::lesson::diagnostics::{Problems, undeclared_dispersion};
use crate::lesson::error::{Error, Result};
use crate::lesson::frame::Frame;
use crate::lesson::observer::Observer;
use crate::lesson::photon_map::{PhotonMap, PhotonStats, pass_seed};
use crate::lesson::ray::Ray;
pub use crate::lesson::render_settings::{MAX_PIXELS, MAX_SPP, MAX_THREADS, RenderSettings};
pub use crate::lesson::rng::pixel_key;
use crate::lesson::rng::{Rng, key_of, pixel_key_of, shuffled_index};
use crate::lesson::scene::{Counters, PixelSample, Scene, TraceContext};
use crate::lesson::spectral::{Band, SpectralMode, SpectralPlan};
use rayon::prelude::*;
use std::borrow::Cow;
use std::ops::Range;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// What a render produced besides the picture.
#[derive(Clone, Debug)]
pub struct RenderStats {
    /// Wall-clock time of the render (the photon map's construction excluded).
    pub elapsed: Duration,
    /// Worker threads the render ran on.
    pub threads: usize,
    /// Rays of all passes.
    pub counters: Counters,
    /// How wavelengths were traced (white light when the scene has nothing dispersive).
    pub spectral: SpectralPlan,
    /// How the scene's photon map was built (before the render, not counted in `elapsed`), if it has one.
    pub photons: Option<PhotonStats>,
    /// What went wrong, one line each, naming the nodes ([`Problems::report`]): empty for a sound render.
    pub warnings: Vec<String>,
}

impl RenderStats {
    /// Adds a later pass of a progressive caustic: its render time, rays and photon map, and the warnings
    /// not yet given.
    pub fn add_pass(&mut self, pass: RenderStats) {
        self.elapsed += pass.elapsed;
        self.counters.add(&pass.counters);
        if let (Some(all), Some(map)) = (&mut self.photons, pass.photons) {
            all.emitted = all.emitted.saturating_add(map.emitted);
            all.stored += map.stored;
            all.trace_time += map.trace_time;
            all.build_time += map.build_time;
        }
        for warning in pass.warnings {
            if !self.warnings.contains(&warning) {
                self.warnings.push(warning);
            }
        }
    }

    /// The photon pass before the render (tracing the photons and building their map); zero without one.
    pub fn photon_pass(&self) -> Duration {
        self.photons.as_ref().map_or(Duration::ZERO, |p| p.trace_time + p.build_time)
    }
}

/// Where in its pixel each anti-aliasing sample goes: through its centre for one sample; for more, random
/// points of the pixel (the slide's) or, with the step [`Step::StratifiedAa`], stratified ones (see the module
/// documentation).
pub struct Stratifier {
    spp: u32,
    /// Whether the samples are stratified ([`Step::StratifiedAa`]).
    stratified: bool,
    /// k when spp = k * k (a jittered grid), else 0 (N-rooks).
    grid: u32,
    /// N-rooks: the key of the current pixel's random permutation of the rows (see [`shuffled_index`]).
    rows_key: u32,
}

impl Stratifier {
    /// The sample positions for `spp` samples per pixel under `steps`: random ones, or, with the step, a
    /// jittered grid when `spp` is a square and N-rooks otherwise.
    pub fn new(spp: u32, steps: Steps) -> Stratifier {
        let k = (spp as f64).sqrt().round() as u32;
        let stratified = steps.has(Step::StratifiedAa);
        Stratifier { spp, stratified, grid: if k * k == spp { k } else { 0 }, rows_key: 0 }
    }

    /// Prepares the samples of a new pixel: N-rooks draws the pixel's permutation of the rows.
    pub fn start_pixel(&mut self, rng: &mut Rng) {
        if self.stratified && self.grid == 0 && self.spp > 1 {
            self.rows_key = rng.next_u32();
        }
    }

    /// The position of sample `s` within the pixel, in [0, 1)^2.
    #[inline(always)]
    pub fn offset(&self, s: u32, rng: &mut Rng) -> (f32, f32) {
        if self.spp == 1 {
            return (0.5, 0.5);
        }
        if !self.stratified {
            return (rng.next_f32(), rng.next_f32());
        }
        beyond!(StratifiedAa);
        let (col, row, n) = match self.grid {
            0 => (s, shuffled_index(s, self.spp, self.rows_key), self.spp),
            k => (s % k, s / k, k),
        };
        ((col as f32 + rng.next_f32()) / n as f32, (row as f32 + rng.next_f32()) / n as f32)
    }
}

/// What a render tells about how far it has got, counted in camera samples: the command line draws its
/// progress bar with it ([`render_with_progress`]). Called from the worker threads.
pub trait Progress: Sync {
    /// The render will trace `samples` camera samples in all.
    fn begin(&self, samples: u64);
    /// `samples` more camera samples are done.
    fn advance(&self, samples: u64);
    /// The render is over.
    fn end(&self);
}

/// Renders the scene. Fails, before any work, on settings or a scene that cannot be rendered. A dispersive
/// scene is traced as `settings.spectral` says; any other in one white pass.
pub fn render(scene: &Scene, settings: &RenderSettings) -> Result<(Frame, RenderStats)> {
    render_with_progress(scene, settings, None)
}

/// [`render`], telling `progress`, if given, how far it has got.
pub fn render_with_progress(
    scene: &Scene,
    settings: &RenderSettings,
    progress: Option<&dyn Progress>,
) -> Result<(Frame, RenderStats)> {
    match &scene.photon_map {
        Some(first) if settings.photon_passes > 1 => render_photon_passes(scene, first, settings, progress),
        _ => RenderJob::for_scene(scene, settings)?.render(progress),
    }
}

/// The progressive caustic ([`RenderSettings::photon_passes`]): pass 1 renders the scene as it is, with its
/// photon map `first`; every later pass renders it with a photon map of its own
/// ([`PhotonMap::build_pass`]) and the pass's own seed for the pixels too, so that the passes are
/// independent renders; the pictures are averaged. One pass's map and picture live at a time, beside the sum
/// of the pictures: memory does not grow with the passes. The statistics add up the passes' (their photon
/// maps' too).
fn render_photon_passes(
    scene: &Scene,
    first: &Arc<PhotonMap>,
    settings: &RenderSettings,
    progress: Option<&dyn Progress>,
) -> Result<(Frame, RenderStats)> {
    let passes = settings.photon_passes;
    first.check_passes(passes)?;
    let bar = progress.map(|inner| PassesProgress { inner, passes: passes as u64, begun: AtomicBool::new(false) });
    let progress = bar.as_ref().map(|p| p as &dyn Progress);
    let (mut frame, mut stats) = RenderJob::for_scene(scene, settings)?.render(progress)?;
    let mut average = PassAverage::new(frame.pixels.len());
    average.add(&frame);
    for pass in 2..=passes {
        let (pass_scene, pass_settings) = on_workers(settings.threads, |_| photon_pass(scene, first, settings, pass))??;
        let (pass_frame, pass_stats) = RenderJob::for_scene(&pass_scene, &pass_settings)?.render(progress)?;
        average.add(&pass_frame);
        stats.add_pass(pass_stats);
    }
    if let Some(bar) = &bar {
        bar.inner.end();
    }
    average.write_into(&mut frame);
    Ok((frame, stats))
}

/// Pass `pass` (from 2) of a progressive caustic whose first pass's map is `first`: the scene with the pass's
/// own photon map ([`PhotonMap::build_pass`]) and the settings with the pass's own seed for the pixels too,
/// so that the passes are independent renders. The map lives as long as the pass's scene.
pub fn photon_pass(
    scene: &Scene,
    first: &Arc<PhotonMap>,
    settings: &RenderSettings,
    pass: u32,
) -> Result<(Scene, RenderSettings)> {
    let mut pass_scene = scene.clone();
    pass_scene.photon_map = PhotonMap::build_pass(scene, first, settings.seed, pass)?.map(Arc::new);
    Ok((pass_scene, RenderSettings { seed: pass_seed(settings.seed, pass), ..*settings }))
}

/// The average of the pictures of a progressive caustic's passes, kept as their sum (in `f64`, so that the
/// order of the passes is the only order of the additions): memory does not grow with the passes.
pub struct PassAverage {
    sum: Vec<[f64; 3]>,
    passes: u32,
}

impl PassAverage {
    /// No pass yet, for pictures of `pixels` pixels.
    pub fn new(pixels: usize) -> PassAverage {
        PassAverage { sum: vec![[0.0; 3]; pixels], passes: 0 }
    }

    /// Adds the picture of the next pass.
    pub fn add(&mut self, frame: &Frame) {
        self.add_pixels(&frame.pixels);
    }

    /// Adds the pixels of the next pass (all of them, or the one pixel of [`render_pixel`]).
    pub fn add_pixels(&mut self, pixels: &[Color]) {
        for (s, c) in self.sum.iter_mut().zip(pixels) {
            s.iter_mut().zip(c.to_array()).for_each(|(s, v)| *s += v as f64);
        }
        self.passes += 1;
    }

    /// The average of the passes added at pixel `index`.
    pub fn at(&self, index: usize) -> Color {
        to_color(self.sum[index].map(|v| v / self.passes.max(1) as f64))
    }

    /// The average at pixel `index` were `color` the next pass's colour there: what is shown of a pass being
    /// drawn.
    pub fn with_next(&self, index: usize, color: Color) -> Color {
        let n = (self.passes + 1) as f64;
        let mut s = self.sum[index];
        s.iter_mut().zip(color.to_array()).for_each(|(s, v)| *s = (*s + v as f64) / n);
        to_color(s)
    }

    /// Writes the average of the passes added into `frame`'s pixels.
    pub fn write_into(&self, frame: &mut Frame) {
        for (index, pixel) in frame.pixels.iter_mut().enumerate() {
            *pixel = self.at(index);
        }
    }
}

/// The progress of all the passes of a progressive caustic as one bar: begun once for every pass's samples,
/// ended after the last pass.
struct PassesProgress<'p> {
    inner: &'p dyn Progress,
    passes: u64,
    begun: AtomicBool,
}

impl Progress for PassesProgress<'_> {
    fn begin(&self, samples: u64) {
        if !self.begun.swap(true, Ordering::Relaxed) {
            self.inner.begin(samples * self.passes);
        }
    }
    fn advance(&self, samples: u64) {
        self.inner.advance(samples);
    }
    fn end(&self) {}
}

/// What `settings` ask of the scene's wavelengths: white light when nothing in it is dispersive, the slide's K
/// passes when the scene does not take the step [`Step::HeroWavelengths`].
pub fn spectral_plan(scene: &Scene, settings: &RenderSettings) -> SpectralPlan {
    let mode = if scene.steps.has(Step::HeroWavelengths) { settings.spectral } else { SpectralMode::Passes };
    SpectralPlan::new(scene.is_dispersive(), mode, settings.wavelengths, scene.illuminant)
}

/// Renders the scene with the given wavelength plan, whether or not the scene needs it (tests use this to
/// check that a non-dispersive material gives the same picture in every plan).
pub fn render_with_plan(scene: &Scene, settings: &RenderSettings, plan: SpectralPlan) -> Result<(Frame, RenderStats)> {
    RenderJob::new(scene, settings, plan)?.render(None)
}

/// One render's fixed parts, checked once: the scene prepared for tracing ([`Scene::prepared`]), the
/// settings, the wavelength plan and the camera set up for the frame's size. Every way of rendering pixels
/// ([`render`], [`render_pixel`], [`render_row`], the progressive renderer's tiles) goes through
/// [`RenderJob::render_row`], so a pixel's colour is the same whichever renders it.
pub struct RenderJob<'a> {
    scene: Cow<'a, Scene>,
    settings: RenderSettings,
    plan: SpectralPlan,
    camera: CameraFrame,
}

impl<'a> RenderJob<'a> {
    /// Checks the settings and the scene (and that adaptive anti-aliasing is not asked of a dispersive
    /// plan), and prepares the scene for tracing if it is not yet.
    pub fn new(scene: &'a Scene, settings: &RenderSettings, plan: SpectralPlan) -> Result<RenderJob<'a>> {
        settings.check()?;
        scene.check()?;
        if settings.adaptive_aa && plan != SpectralPlan::White {
            return Err(Error::parameter("anti-aliasing", "adaptive", "it renders scenes without dispersion only"));
        }
        let camera = scene.camera.frame(settings.width, settings.height);
        Ok(RenderJob { scene: scene.prepared(), settings: *settings, plan, camera })
    }

    /// [`RenderJob::new`] with the wavelengths [`spectral_plan`] asks for, the scene checked before that
    /// asks it anything: every Layered shader asks its layers whether they are dispersive, and a graph of
    /// shared layers past [`crate::lesson::shader::MAX_SHADES_PER_HIT`] would take as long to ask as to render.
    pub fn for_scene(scene: &'a Scene, settings: &RenderSettings) -> Result<RenderJob<'a>> {
        scene.check()?;
        RenderJob::new(scene, settings, spectral_plan(scene, settings))
    }

    /// The scene as this job traces it.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The wavelength plan the job follows.
    pub fn plan(&self) -> &SpectralPlan {
        &self.plan
    }

    /// The whole frame, rows in parallel on a pool of `settings.threads` workers, then the course's adaptive
    /// anti-aliasing if the settings ask for it.
    pub fn render(&self, progress: Option<&dyn Progress>) -> Result<(Frame, RenderStats)> {
        let start = Instant::now();
        let (w, h) = (self.settings.width, self.settings.height);
        let (frame, counters, threads) = on_workers(self.settings.threads, |threads| {
            let mut frame = Frame::new(w, h);
            if let Some(progress) = progress {
                progress.begin(w as u64 * h as u64 * self.settings.spp as u64);
            }
            let mut counters = frame
                .pixels
                .par_chunks_mut(w as usize)
                // One row per task: rows cost very different amounts (sky against glass), and rayon's default
                // splitting into a few large chunks leaves a thread idle at the end.
                .with_max_len(1)
                .enumerate()
                .map(|(y, row)| self.render_row(0..w, y as u32, row, None, progress))
                .reduce(Counters::default, |mut a, b| {
                    a.add(&b);
                    a
                });
            if let Some(progress) = progress {
                progress.end();
            }
            if self.settings.adaptive_aa {
                counters.add(&self.refine(&mut frame));
            }
            (frame, counters, threads)
        })?;
        Ok((frame, self.stats(start.elapsed(), threads, counters)))
    }

    /// The course's adaptive anti-aliasing over a frame of this job's single samples (on the current rayon
    /// pool): see [`adaptive_aa::refine`]. Returns the rays traced.
    pub fn refine(&self, frame: &mut Frame) -> Counters {
        adaptive_aa::refine(&self.scene, &self.camera, &self.settings, frame)
    }

    /// What a render of this job that took `elapsed` on `threads` workers and traced `counters` reports.
    /// The end-of-run report includes the check for shaders that read the wavelength without saying so
    /// ([`undeclared_dispersion`]).
    pub fn stats(&self, elapsed: Duration, threads: usize, mut counters: Counters) -> RenderStats {
        let (w, h) = (self.settings.width, self.settings.height);
        counters.problems.undeclared_dispersion = undeclared_dispersion(&self.scene, &self.camera, w, h);
        RenderStats {
            elapsed,
            threads,
            warnings: Problems::report(&counters, &self.scene),
            counters,
            spectral: self.plan.clone(),
            photons: self.scene.photon_map.as_ref().map(|map| map.stats),
        }
    }

    /// Renders the pixels `xs` of row `y` into `out` on the calling thread, and returns the rays traced:
    /// the colours [`render`] gives them, since every pixel's random streams depend only on (seed, x, y).
    /// `observer`, if given, is told what the recursion does; `progress` is told of every few pixels done.
    pub fn render_row<'o>(
        &'o self,
        xs: Range<u32>,
        y: u32,
        out: &mut [Color],
        observer: Option<&'o mut dyn Observer>,
        progress: Option<&dyn Progress>,
    ) -> Counters {
        let mut tracer = PixelTracer::new(self, observer);
        let mut since_report = 0;
        let spp = self.settings.spp as u64;
        for (pixel, x) in out.iter_mut().zip(xs) {
            *pixel = tracer.pixel(x, y);
            since_report += 1;
            // Reported every few pixels, not once per row: a row that runs away still moves the bar.
            if let Some(progress) = progress
                && since_report == PROGRESS_PIXELS
            {
                progress.advance(since_report * spp);
                since_report = 0;
            }
        }
        if let Some(progress) = progress
            && since_report > 0
        {
            progress.advance(since_report * spp);
        }
        tracer.ctx.counters
    }

    /// Renders the pixels `xs` of the rows `ys` into `out`, row by row, on the calling thread (the
    /// progressive renderer's tiles), and returns the rays traced.
    pub fn render_rect(&self, xs: Range<u32>, ys: Range<u32>, out: &mut [Color]) -> Counters {
        let mut counters = Counters::default();
        for (y, row) in ys.zip(out.chunks_mut(xs.len())) {
            counters.add(&self.render_row(xs.clone(), y, row, None, None));
        }
        counters
    }

    /// The pixels `xs` of row `y`, as [`render`] renders them, each with its own ray counters; `observer`
    /// sees every ray traced for them. With adaptive anti-aliasing the single samples of the pixels around
    /// them are rendered too (not counted): they decide which of the pixels the adaptive pass refines.
    fn render_pixels<'o>(&'o self, y: u32, xs: Range<u32>, observer: Option<&'o mut dyn Observer>) -> Vec<PixelTrace> {
        let xs = xs.start..xs.end.min(self.settings.width);
        let mut tracer = PixelTracer::new(self, observer);
        let mut pixels: Vec<PixelTrace> = xs
            .clone()
            .map(|x| {
                let color = tracer.pixel(x, y);
                PixelTrace { color, counters: std::mem::take(&mut tracer.ctx.counters) }
            })
            .collect();
        if self.settings.adaptive_aa && !xs.is_empty() {
            let (width, height) = (self.settings.width, self.settings.height);
            let (x0, x1) = (xs.start.saturating_sub(1), (xs.end + 1).min(width));
            let (y0, y1) = (y.saturating_sub(1), (y + 2).min(height));
            let mut around = Frame::new(x1 - x0, y1 - y0);
            self.render_rect(x0..x1, y0..y1, &mut around.pixels);
            for (pixel, x) in pixels.iter_mut().zip(xs) {
                if adaptive_aa::marked_at(&around, x - x0, y - y0) {
                    let observer = tracer.ctx.observer.as_deref_mut().map(|o| o as &mut dyn Observer);
                    pixel.color = adaptive_aa::refine_pixel(
                        &self.scene,
                        &self.camera,
                        &self.settings,
                        (x, y),
                        pixel.color,
                        &mut pixel.counters,
                        observer,
                    );
                }
            }
        }
        pixels
    }
}

/// How many pixels a row renders between two reports to the progress bar.
const PROGRESS_PIXELS: u64 = 64;

/// One pixel rendered alone, exactly as [`render`] renders it (same samples, same random streams).
#[derive(Clone, Debug)]
pub struct PixelTrace {
    /// The pixel's linear colour, as [`render`] writes it into the frame.
    pub color: Color,
    /// The rays traced for the pixel.
    pub counters: Counters,
}

/// Renders pixel (x, y) of the frame `settings` describe, as [`render`] would (the course's adaptive
/// anti-aliasing included: a pixel it refines gets its five samples; a progressive caustic's pixel once per
/// pass, each with the pass's own photon map, averaged as the passes' pictures are), counting its rays and
/// telling `observer`, if given, what the recursion does (see [`crate::lesson::observer`]; `--trace-pixel`
/// records the ray tree so).
pub fn render_pixel(
    scene: &Scene,
    settings: &RenderSettings,
    x: u32,
    y: u32,
    observer: Option<&mut dyn Observer>,
) -> Result<PixelTrace> {
    if x >= settings.width || y >= settings.height {
        return Err(Error::parameter(
            "pixel",
            format!("{x},{y}"),
            format!("is outside the {}x{} picture", settings.width, settings.height),
        ));
    }
    match &scene.photon_map {
        Some(first) if settings.photon_passes > 1 => photon_passes_pixel(scene, first, settings, (x, y), observer),
        _ => {
            let job = RenderJob::for_scene(scene, settings)?;
            Ok(job.render_pixels(y, x..x + 1, observer.map(|o| o as &mut dyn Observer)).remove(0))
        }
    }
}

/// [`render_pixel`] of a progressive caustic whose first pass's map is `first`: the pixel of each pass, with
/// the pass's own photon map and seed ([`photon_pass`]), averaged as [`render_photon_passes`] averages the
/// passes' pictures; `observer` is told where each pass begins.
fn photon_passes_pixel(
    scene: &Scene,
    first: &Arc<PhotonMap>,
    settings: &RenderSettings,
    (x, y): (u32, u32),
    mut observer: Option<&mut dyn Observer>,
) -> Result<PixelTrace> {
    let passes = settings.photon_passes;
    first.check_passes(passes)?;
    let (mut average, mut counters) = (PassAverage::new(1), Counters::default());
    for pass in 1..=passes {
        if let Some(o) = observer.as_deref_mut() {
            o.photon_pass_begins(pass, passes);
        }
        let watching = observer.as_deref_mut().map(|o| o as &mut dyn Observer);
        let traced = if pass == 1 {
            RenderJob::for_scene(scene, settings)?.render_pixels(y, x..x + 1, watching).remove(0)
        } else {
            let (pass_scene, pass_settings) =
                on_workers(settings.threads, |_| photon_pass(scene, first, settings, pass))??;
            RenderJob::for_scene(&pass_scene, &pass_settings)?.render_pixels(y, x..x + 1, watching).remove(0)
        };
        average.add_pixels(&[traced.color]);
        counters.add(&traced.counters);
    }
    Ok(PixelTrace { color: average.at(0), counters })
}

/// Renders the pixels `xs` of row `y` as [`render`] would (adaptive anti-aliasing included), each with its
/// own ray counters. The debug views use it.
pub fn render_row(scene: &Scene, settings: &RenderSettings, y: u32, xs: Range<u32>) -> Result<Vec<PixelTrace>> {
    Ok(RenderJob::for_scene(scene, settings)?.render_pixels(y, xs, None))
}

/// A salt for the random streams of wavelength passes, so that they differ from the white pass's.
const PASS_KEY: u64 = 0x5045_4354_5241_4c00;

/// A salt for the random streams of the wavelengths of spectral and hero sampling, kept apart from the
/// pixel's own stream so that the camera rays are those of the white render.
const WAVELENGTH_KEY: u64 = 0x5741_5645_4c45_4e47;

/// Renders pixels one after another: the samples of each pixel, in every wavelength pass the plan asks for,
/// all through one [`TraceContext`] whose counters add up the pixels' rays.
struct PixelTracer<'j> {
    job: &'j RenderJob<'j>,
    ctx: TraceContext<'j>,
    stratifier: Stratifier,
    /// The [`PixelSample::count`] of every pixel: the spp, or what adaptive anti-aliasing may give a pixel.
    samples_per_pixel: u32,
}

impl<'j> PixelTracer<'j> {
    fn new(job: &'j RenderJob<'j>, observer: Option<&'j mut dyn Observer>) -> Self {
        let settings = &job.settings;
        let samples_per_pixel =
            if settings.adaptive_aa { adaptive_aa::SAMPLES_PER_REFINED_PIXEL } else { settings.spp };
        let mut ctx = TraceContext::new(&job.scene, Rng::for_keys(&[]));
        ctx.observer = observer;
        PixelTracer { job, ctx, stratifier: Stratifier::new(settings.spp, job.scene.steps), samples_per_pixel }
    }

    /// Starts the samples of a pixel (or of one wavelength pass of it) whose random stream is keyed by
    /// `stream_keys`: its own random stream, its sample positions, a fresh shading point for its camera rays.
    /// Returns its [`PixelSample::pixel_key`].
    fn start_pixel(&mut self, stream_keys: &[u64]) -> u64 {
        let key = key_of(stream_keys);
        self.ctx.rng = Rng::for_key(key);
        self.ctx.restart_pixel();
        self.stratifier.start_pixel(&mut self.ctx.rng);
        pixel_key_of(key)
    }

    /// The camera ray of sample `s` of pixel (x, y), which is about to be traced as sample `s` of the pixel
    /// whose key is `pixel_key`.
    #[inline(always)]
    fn camera_ray(&mut self, x: u32, y: u32, s: u32, pixel_key: u64) -> Ray {
        self.ctx.pixel_sample = Some(PixelSample { index: s, count: self.samples_per_pixel, pixel_key });
        let (dx, dy) = self.stratifier.offset(s, &mut self.ctx.rng);
        self.job.camera.get_screen_ray(x as f32 + dx, y as f32 + dy)
    }

    /// The average of the pixel's samples, all traced at `wavelength`, with the random stream keyed by
    /// `stream_keys`.
    fn samples(&mut self, x: u32, y: u32, stream_keys: &[u64], wavelength: Option<f32>) -> Color {
        let pixel_key = self.start_pixel(stream_keys);
        let settings = &self.job.settings;
        let mut sum = Color::BLACK;
        for s in 0..settings.spp {
            let ray = Ray { wavelength, ..self.camera_ray(x, y, s, pixel_key) };
            let color = self.ctx.raytrace(&ray);
            sum += settings.sample(color, &mut self.ctx.counters);
        }
        sum / settings.spp as f32
    }

    fn pixel(&mut self, x: u32, y: u32) -> Color {
        let seed = self.job.settings.seed;
        match &self.job.plan {
            SpectralPlan::White => self.samples(x, y, &[seed, x as u64, y as u64], None),
            SpectralPlan::Passes(bands) => {
                let mut sum = [0.0f64; 3];
                for (k, band) in bands.iter().enumerate() {
                    let stream_keys = [seed, x as u64, y as u64, PASS_KEY, k as u64];
                    add_weighted(&mut sum, band, self.samples(x, y, &stream_keys, Some(band.centre())));
                }
                to_color(sum)
            }
            SpectralPlan::Sampled => self.wavelength_samples(x, y, 1, false),
            &SpectralPlan::Hero { per_path } => self.wavelength_samples(x, y, per_path, true),
        }
    }

    /// Spectral sampling in one pass: the pixel's `spp` samples share out `per_path * spp` equal bands of the
    /// spectrum, each sample `per_path` of them spread evenly over it (bands `b`, `b + spp`, `b + 2 spp`, ...,
    /// `b` a different one for every sample, in an order of the pixel's own), its wavelengths at the same
    /// jittered place in each band. Every sample's path is traced at each of its wavelengths and weighted by
    /// the band's colour; every band is seen once, so that the bands' colours add up to the light's. With
    /// `split` (hero-wavelength sampling) the path is first traced at the first of its wavelengths (the hero)
    /// only, and if it met nothing dispersive, what it brought back holds for every wavelength: the sample
    /// counts as white light, `1 / spp` of the light's colour, as in a white render. Only a path that met
    /// dispersive glass is traced again for the others (from the camera: the part before the glass is the
    /// same for every wavelength).
    fn wavelength_samples(&mut self, x: u32, y: u32, per_path: u32, split: bool) -> Color {
        beyond!(HeroWavelengths);
        let settings = &self.job.settings;
        let (seed, spp, illuminant) = (settings.seed, settings.spp, self.job.scene.illuminant);
        let pixel_key = self.start_pixel(&[seed, x as u64, y as u64]);
        let mut wavelength_rng = Rng::for_keys(&[seed, x as u64, y as u64, WAVELENGTH_KEY]);
        let bands_key = wavelength_rng.next_u32();
        // Paths that met nothing dispersive, as a white render adds them; the others, band by band.
        let mut white = Color::BLACK;
        let mut spectral = [0.0f64; 3];
        for s in 0..spp {
            let camera_ray = self.camera_ray(x, y, s, pixel_key);
            let first = shuffled_index(s, spp, bands_key);
            let u = wavelength_rng.next_f32();
            for j in 0..per_path {
                let band = Band::nth(first + j * spp, per_path * spp, illuminant);
                self.ctx.met_dispersion = false;
                let ray = Ray { wavelength: Some(band.at(u)), ..camera_ray };
                let c = settings.sample(self.ctx.raytrace(&ray), &mut self.ctx.counters);
                if split && j == 0 && !self.ctx.met_dispersion {
                    white += c;
                    break;
                }
                add_weighted(&mut spectral, &band, c);
            }
        }
        let light = illuminant.white();
        white / spp as f32 * to_color(light) + to_color(spectral)
    }
}

/// Adds a colour seen in `band`, multiplied by the band's colour, to a double-precision sum.
fn add_weighted(sum: &mut [f64; 3], band: &Band, c: Color) {
    for ((s, w), v) in sum.iter_mut().zip(band.weight).zip(c.to_array()) {
        *s += w * v as f64;
    }
}

fn to_color(sum: [f64; 3]) -> Color {
    Color::new(sum[0] as f32, sum[1] as f32, sum[2] as f32)
}
