//! The renderer: turns a scene into a frame of linear colours, in parallel and deterministically.
//!
//! Rows are rendered in parallel by rayon. Each pixel has its own random stream seeded from
//! (seed, x, y) (see [`crate::rng`]), and its samples are averaged in a fixed order, so the frame is the same
//! bit for bit whatever the thread count.
//!
//! Anti-aliasing: with `spp` samples per pixel, a square `spp` (4, 9, 16, ...) is a jittered k x k grid;
//! any other count uses N-rooks (Latin hypercube) stratification, one sample in each column and each row
//! of an N x N grid. One sample per pixel goes through the pixel's centre.

use crate::color::{Color, to_srgb8};
use crate::error::{Error, Result};
use crate::rng::Rng;
use crate::scene::{Counters, Scene, TraceContext};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::io::IsTerminal;
use std::path::Path;
use std::time::{Duration, Instant};

/// The largest frame the renderer accepts, in pixels (64 Mpx, 1 GiB of linear colour).
pub const MAX_PIXELS: u64 = 1 << 26;

/// How to render a scene.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Anti-aliasing samples per pixel.
    pub spp: u32,
    /// Worker threads; `None` uses every core.
    pub threads: Option<usize>,
    /// Seed of every random choice; the same seed gives the same picture.
    pub seed: u64,
    /// Show a progress bar on stderr (only when stderr is a terminal).
    pub progress: bool,
}

impl Default for RenderSettings {
    fn default() -> RenderSettings {
        RenderSettings { width: 640, height: 480, spp: 1, threads: None, seed: 1, progress: false }
    }
}

impl RenderSettings {
    /// Rejects sizes and counts that make no sense or would exhaust memory.
    pub fn check(&self) -> Result<()> {
        if self.width == 0 || self.height == 0 {
            return Err(Error::parameter("image size", format!("{}x{}", self.width, self.height), "must not be zero"));
        }
        if self.width as u64 * self.height as u64 > MAX_PIXELS {
            return Err(Error::parameter(
                "image size",
                format!("{}x{}", self.width, self.height),
                format!("more than {MAX_PIXELS} pixels"),
            ));
        }
        if self.spp == 0 {
            return Err(Error::parameter("samples per pixel", 0, "must be at least 1"));
        }
        if self.threads == Some(0) {
            return Err(Error::parameter("thread count", 0, "must be at least 1"));
        }
        Ok(())
    }
}

/// A rendered picture in linear light, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Color>,
}

impl Frame {
    pub fn new(width: u32, height: u32) -> Frame {
        Frame { width, height, pixels: vec![Color::BLACK; width as usize * height as usize] }
    }
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.pixels[(y * self.width + x) as usize]
    }
    /// The frame encoded as 8-bit sRGB.
    pub fn to_rgb8(&self) -> image::RgbImage {
        let bytes = self.pixels.iter().flat_map(|&c| to_srgb8(c)).collect();
        image::RgbImage::from_raw(self.width, self.height, bytes).expect("frame size matches its pixels")
    }
    /// The frame as linear floats.
    pub fn to_rgb32f(&self) -> image::Rgb32FImage {
        let values = self.pixels.iter().flat_map(|c| c.to_array()).collect();
        image::Rgb32FImage::from_raw(self.width, self.height, values).expect("frame size matches its pixels")
    }
    /// A frame from an 8-bit sRGB image (decoded to linear light).
    pub fn from_rgb8(img: &image::RgbImage) -> Frame {
        let table = crate::color::srgb8_to_linear_table();
        let pixels = img.pixels().map(|p| Color::new(table[p[0] as usize], table[p[1] as usize], table[p[2] as usize]));
        Frame { width: img.width(), height: img.height(), pixels: pixels.collect() }
    }

    /// Writes the frame: `.png` as 8-bit sRGB, `.exr` and `.hdr` as linear floats. The image goes to a
    /// temporary file beside the target first and is renamed over it only when complete, so a failure never
    /// destroys an earlier picture.
    pub fn save(&self, path: &Path) -> Result<()> {
        let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
        let format = match ext.as_deref() {
            Some("png") => image::ImageFormat::Png,
            Some("exr") => image::ImageFormat::OpenExr,
            Some("hdr") => image::ImageFormat::Hdr,
            _ => return Err(Error::file("cannot write image", path, "the name must end in .png, .exr or .hdr")),
        };
        save_atomically(path, |tmp| match format {
            image::ImageFormat::Png => self.to_rgb8().save_with_format(tmp, format),
            _ => self.to_rgb32f().save_with_format(tmp, format),
        })
    }
}

/// Writes a file through `write`, which is given a temporary path beside `path`; the temporary file is
/// renamed over `path` only when it is complete, so a failure never destroys an earlier file.
pub fn save_atomically(path: &Path, write: impl FnOnce(&Path) -> image::ImageResult<()>) -> Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Error::file("cannot create the folder for", path, e))?;
    }
    let name = path.file_name().map(|n| n.to_string_lossy()).unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let result = write(&tmp)
        .map_err(|e| Error::file("cannot write image", path, e))
        .and_then(|()| std::fs::rename(&tmp, path).map_err(|e| Error::file("cannot write image", path, e)));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// What a render produced besides the picture.
#[derive(Clone, Debug)]
pub struct RenderStats {
    pub elapsed: Duration,
    pub threads: usize,
    pub counters: Counters,
}

/// Where in its pixel each anti-aliasing sample goes (see the module documentation).
pub struct Stratifier {
    spp: u32,
    /// k when spp = k * k (a jittered grid), else 0 (N-rooks).
    grid: u32,
    /// N-rooks: the row of the N x N grid that sample s uses, a fresh permutation per pixel.
    rows: Vec<u32>,
}

impl Stratifier {
    pub fn new(spp: u32) -> Stratifier {
        let k = (spp as f64).sqrt().round() as u32;
        Stratifier { spp, grid: if k * k == spp { k } else { 0 }, rows: (0..spp).collect() }
    }

    /// Prepares the samples of a new pixel.
    pub fn start_pixel(&mut self, rng: &mut Rng) {
        if self.grid == 0 {
            for i in (1..self.spp).rev() {
                self.rows.swap(i as usize, rng.below(i + 1) as usize);
            }
        }
    }

    /// The position of sample `s` within the pixel, in [0, 1)^2.
    pub fn offset(&self, s: u32, rng: &mut Rng) -> (f32, f32) {
        if self.spp == 1 {
            return (0.5, 0.5);
        }
        let (col, row, n) = match self.grid {
            0 => (s, self.rows[s as usize], self.spp),
            k => (s % k, s / k, k),
        };
        ((col as f32 + rng.next_f32()) / n as f32, (row as f32 + rng.next_f32()) / n as f32)
    }
}

/// Renders the scene. Fails, before any work, on settings or a scene that cannot be rendered.
pub fn render(scene: &Scene, settings: &RenderSettings) -> Result<(Frame, RenderStats)> {
    settings.check()?;
    scene.check()?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(settings.threads.unwrap_or(0))
        .build()
        .map_err(|e| Error::parameter("thread count", settings.threads.unwrap_or(0), e))?;
    let start = Instant::now();
    let (w, h) = (settings.width, settings.height);
    let camera = scene.camera.frame(w, h);
    let bar = if settings.progress && std::io::stderr().is_terminal() {
        let bar = ProgressBar::new(h as u64);
        bar.set_style(
            ProgressStyle::with_template("{elapsed_precise} [{bar:40}] {pos}/{len} rows, {eta} left")
                .expect("valid template")
                .progress_chars("=> "),
        );
        bar
    } else {
        ProgressBar::hidden()
    };
    let mut frame = Frame::new(w, h);
    let counters = pool.install(|| {
        frame
            .pixels
            .par_chunks_mut(w as usize)
            .enumerate()
            .map(|(y, row)| {
                let mut counters = Counters::default();
                let mut stratifier = Stratifier::new(settings.spp);
                for (x, pixel) in row.iter_mut().enumerate() {
                    let mut ctx = TraceContext::new(scene, Rng::for_pixel(settings.seed, x as u32, y as u32));
                    stratifier.start_pixel(&mut ctx.rng);
                    let mut sum = Color::BLACK;
                    for s in 0..settings.spp {
                        let (dx, dy) = stratifier.offset(s, &mut ctx.rng);
                        let ray = camera.get_screen_ray(x as f32 + dx, y as f32 + dy);
                        sum += ctx.raytrace(&ray).sanitized();
                    }
                    *pixel = sum / settings.spp as f32;
                    counters.add(&ctx.counters);
                }
                bar.inc(1);
                counters
            })
            .reduce(Counters::default, |mut a, b| {
                a.add(&b);
                a
            })
    });
    bar.finish_and_clear();
    let stats = RenderStats { elapsed: start.elapsed(), threads: pool.current_num_threads(), counters };
    Ok((frame, stats))
}
