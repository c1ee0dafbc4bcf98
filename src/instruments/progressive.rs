//! Progressive rendering: the picture building up on screen while it renders, as the course's program shows
//! it (row by row at lecture 6, bucket by bucket in its later versions). The live viewer draws with it; it
//! needs no window, so the tests drive it directly.
//!
//! A progressive render is a fast coarse pass (one sample through each pixel's centre at a quarter of the
//! resolution in each direction), then the full picture in square tiles, nearest the centre of the image
//! first, at the quality the settings ask for. Every pixel's random stream depends only on (seed, x, y), so
//! the tiles, in whatever order and on whatever thread, add up to exactly the picture [`render`] gives. The
//! course's adaptive anti-aliasing, which compares each pixel with its neighbours, runs once the last tile
//! is drawn, as it does after [`render`]'s rows.
//!
//! A render can be cancelled: it checks a flag before each row of the coarse pass and before each tile, so
//! once the flag is set every worker finishes at most the tile it is drawing and stops.
//!
//! The functions run on the current rayon pool: call them inside [`crate::lesson::render::thread_pool`]'s
//! `install`, whose threads have the stack that deep ray trees need.
//!
//! [`render`]: crate::lesson::render::render

use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::frame::Frame;
use crate::lesson::render::{PassAverage, RenderJob, RenderSettings, RenderStats, photon_pass};
use crate::lesson::scene::{Counters, Scene};
use rayon::prelude::*;
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

/// The side of a tile, in pixels.
pub const TILE_SIZE: u32 = 32;

/// The coarse pass has 1/COARSE_SCALE of the picture's resolution in each direction.
pub const COARSE_SCALE: u32 = 4;

/// A rectangle of pixels of the picture and, once drawn, their colours (row by row) and the rays traced
/// for them.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile {
    /// The tile's left edge: the column of its first pixel.
    pub x: u32,
    /// The tile's top edge: the row of its first pixel.
    pub y: u32,
    /// Width in pixels (smaller than [`TILE_SIZE`] at the picture's right edge).
    pub width: u32,
    /// Height in pixels (smaller than [`TILE_SIZE`] at the picture's bottom edge).
    pub height: u32,
    /// The tile's linear colours, row by row from its top-left pixel; empty until it is drawn.
    pub pixels: Vec<Color>,
    /// All rays traced for the tile (camera, secondary and shadow rays); 0 until it is drawn.
    pub rays: u64,
}

/// What a progressive render shows as it goes.
pub enum Update<'a> {
    /// The coarse pass, complete: a small frame to be shown stretched over the picture.
    Coarse(&'a Frame),
    /// One tile of the full picture, final (of a progressive caustic's later pass: averaged with the passes
    /// before).
    Tile(&'a Tile),
    /// A pass of a progressive caustic is done: the average of the passes so far.
    Passes {
        /// The pass done, counted from 1 (the first pass's end is not told: its tiles are the picture).
        pass: u32,
        /// The passes in all.
        passes: u32,
        /// The average of passes 1 to `pass`.
        frame: &'a Frame,
    },
}

/// How a progressive render ended.
#[derive(Debug)]
pub enum Outcome {
    /// Every tile was drawn: the picture, the same as [`crate::lesson::render::render`]'s, and its statistics,
    /// whose rays are the render's too (the coarse pass's are not counted).
    Finished(Frame, Box<RenderStats>),
    /// The cancel flag was set before the last tile.
    Cancelled,
}

/// The tiles of a `width` x `height` picture (not yet drawn), those nearest the centre first.
pub fn tiles(width: u32, height: u32) -> Vec<Tile> {
    let mut tiles: Vec<Tile> = (0..height.div_ceil(TILE_SIZE))
        .flat_map(|j| (0..width.div_ceil(TILE_SIZE)).map(move |i| (i * TILE_SIZE, j * TILE_SIZE)))
        .map(|(x, y)| Tile {
            x,
            y,
            width: TILE_SIZE.min(width - x),
            height: TILE_SIZE.min(height - y),
            pixels: Vec::new(),
            rays: 0,
        })
        .collect();
    // Twice the distance from the tile's centre to the picture's, in whole pixels (so the sort is exact).
    let distance = |t: &Tile| {
        let dx = (2 * t.x + t.width).abs_diff(width) as u64;
        let dy = (2 * t.y + t.height).abs_diff(height) as u64;
        dx * dx + dy * dy
    };
    tiles.sort_by_key(distance);
    tiles
}

/// The settings of the coarse pass of a render with `settings`: one sample per pixel at 1/COARSE_SCALE of
/// the resolution (at least one pixel each way).
pub fn coarse_settings(settings: &RenderSettings) -> RenderSettings {
    RenderSettings {
        width: settings.width.div_ceil(COARSE_SCALE),
        height: settings.height.div_ceil(COARSE_SCALE),
        spp: 1,
        progress: false,
        ..*settings
    }
}

/// At most this many pixels are rendered while the viewer's camera moves (320 x 240, one sample each).
pub const PREVIEW_PIXELS: u32 = 320 * 240;

/// The settings of the picture the viewer draws while the camera moves: one sample per pixel, the picture's
/// size divided by the smallest whole factor that brings it to at most [`PREVIEW_PIXELS`].
pub fn preview_settings(settings: &RenderSettings) -> RenderSettings {
    let pixels = settings.width as f64 * settings.height as f64;
    let factor = (pixels / PREVIEW_PIXELS as f64).sqrt().ceil().max(1.0) as u32;
    RenderSettings {
        width: settings.width.div_ceil(factor),
        height: settings.height.div_ceil(factor),
        spp: 1,
        progress: false,
        ..*settings
    }
}

/// Renders the whole of a (small) picture with `settings`, rows in parallel, unless `cancel` is set first:
/// the coarse pass, and the picture the viewer shows while the camera moves. Returns the frame and the rays
/// traced, or `None` if cancelled.
pub fn quick_frame(scene: &Scene, settings: &RenderSettings, cancel: &AtomicBool) -> Result<Option<(Frame, Counters)>> {
    let job = RenderJob::for_scene(scene, settings)?;
    Ok(quick_frame_of(&job, settings, cancel))
}

/// [`quick_frame`] of a job made already.
fn quick_frame_of(job: &RenderJob, settings: &RenderSettings, cancel: &AtomicBool) -> Option<(Frame, Counters)> {
    let mut frame = Frame::new(settings.width, settings.height);
    let width = settings.width;
    let rows: Option<Vec<Counters>> = frame
        .pixels
        .par_chunks_mut(width as usize)
        .enumerate()
        .map(|(y, row)| (!cancel.load(Ordering::Relaxed)).then(|| job.render_row(0..width, y as u32, row, None, None)))
        .collect();
    rows.map(|rows| {
        let mut counters = Counters::default();
        rows.iter().for_each(|c| counters.add(c));
        (frame, counters)
    })
}

/// Renders `scene` progressively: the coarse pass, then the tiles of the full picture, each given to
/// `on_update` as soon as it is done (from the worker thread that drew it). Stops, with
/// [`Outcome::Cancelled`], once `cancel` is set: every worker finishes at most the tile it is drawing.
///
/// A progressive caustic ([`RenderSettings::photon_passes`] above 1) goes on pass by pass, as
/// [`crate::lesson::render::render`] renders it: each later pass's tiles are shown averaged with the passes
/// before ([`PassAverage::with_next`]), and each finished pass's average as a whole picture
/// ([`Update::Passes`]), so the caustic sharpens on the screen; the finished picture is `render`'s.
pub fn render_progressive(
    scene: &Scene,
    settings: &RenderSettings,
    cancel: &AtomicBool,
    on_update: &(dyn Fn(Update) + Sync),
) -> Result<Outcome> {
    let job = RenderJob::for_scene(scene, settings)?;
    let scene = job.scene();
    let passes = photon_passes(scene, settings);
    if let (Some(first), true) = (&scene.photon_map, passes > 1) {
        first.check_passes(passes)?;
    }
    let coarse = coarse_settings(settings);
    let coarse_job = RenderJob::new(scene, &coarse, job.plan().clone())?;
    let start = Instant::now();
    let Some((coarse, _)) = quick_frame_of(&coarse_job, &coarse, cancel) else {
        return Ok(Outcome::Cancelled);
    };
    on_update(Update::Coarse(&coarse));
    let Some((mut frame, counters)) = draw_tiles(&job, settings, cancel, &|tile| on_update(Update::Tile(tile))) else {
        return Ok(Outcome::Cancelled);
    };
    let mut stats = job.stats(start.elapsed(), rayon::current_num_threads(), counters);
    let Some(first) = scene.photon_map.as_ref().filter(|_| passes > 1) else {
        return Ok(Outcome::Finished(frame, Box::new(stats)));
    };
    let mut average = PassAverage::new(frame.pixels.len());
    average.add(&frame);
    for pass in 2..=passes {
        if cancel.load(Ordering::Relaxed) {
            return Ok(Outcome::Cancelled);
        }
        let (pass_scene, pass_settings) = photon_pass(scene, first, settings, pass)?;
        let pass_job = RenderJob::for_scene(&pass_scene, &pass_settings)?;
        let pass_start = Instant::now();
        let averaged = |tile: &Tile| {
            let mut shown = tile.clone();
            for (i, c) in shown.pixels.iter_mut().enumerate() {
                let (x, y) = (tile.x + i as u32 % tile.width, tile.y + i as u32 / tile.width);
                *c = average.with_next((y * settings.width + x) as usize, *c);
            }
            on_update(Update::Tile(&shown));
        };
        let Some((pass_frame, counters)) = draw_tiles(&pass_job, &pass_settings, cancel, &averaged) else {
            return Ok(Outcome::Cancelled);
        };
        stats.add_pass(pass_job.stats(pass_start.elapsed(), rayon::current_num_threads(), counters));
        average.add(&pass_frame);
        average.write_into(&mut frame);
        on_update(Update::Passes { pass, passes, frame: &frame });
    }
    Ok(Outcome::Finished(frame, Box::new(stats)))
}

/// How many passes a render of `scene` with `settings` draws: [`RenderSettings::photon_passes`] for a scene
/// with a photon map, else one.
pub fn photon_passes(scene: &Scene, settings: &RenderSettings) -> u32 {
    if scene.photon_map.is_some() { settings.photon_passes.max(1) } else { 1 }
}

/// Draws every tile of `job`'s picture, nearest the centre first, on every worker of the current pool, each
/// given to `on_tile` once drawn; then the course's adaptive anti-aliasing, which looks at each pixel's
/// neighbours. The picture (the same as the job's whole render) and its rays, or `None` once `cancel` is set.
fn draw_tiles(
    job: &RenderJob,
    settings: &RenderSettings,
    cancel: &AtomicBool,
    on_tile: &(dyn Fn(&Tile) + Sync),
) -> Option<(Frame, Counters)> {
    let tiles = tiles(settings.width, settings.height);
    let next = AtomicUsize::new(0);
    let frame = Mutex::new(Frame::new(settings.width, settings.height));
    // The picture's rays, as the plain render counts them: the coarse pass is only shown.
    let counters = Mutex::new(Counters::default());
    // Every worker takes the next tile in order until none is left or the render is cancelled.
    rayon::broadcast(|_| {
        let mut rays = Counters::default();
        while !cancel.load(Ordering::Relaxed) {
            let Some(tile) = tiles.get(next.fetch_add(1, Ordering::Relaxed)) else { break };
            let mut tile = Tile { pixels: vec![Color::BLACK; (tile.width * tile.height) as usize], ..tile.clone() };
            let (xs, ys) = (tile.x..tile.x + tile.width, tile.y..tile.y + tile.height);
            let tile_rays = job.render_rect(xs, ys, &mut tile.pixels);
            tile.rays = tile_rays.total();
            rays.add(&tile_rays);
            on_tile(&tile);
            let mut frame = frame.lock().expect("no worker panics holding the frame");
            for (row, colors) in tile.pixels.chunks(tile.width as usize).enumerate() {
                let start = ((tile.y + row as u32) * settings.width + tile.x) as usize;
                frame.pixels[start..start + colors.len()].copy_from_slice(colors);
            }
        }
        counters.lock().expect("no worker panics holding the counters").add(&rays);
    });
    if next.load(Ordering::Relaxed) < tiles.len() || cancel.load(Ordering::Relaxed) {
        return None;
    }
    let mut frame = frame.into_inner().expect("no worker panicked");
    let mut counters = counters.into_inner().expect("no worker panicked");
    // The course's adaptive anti-aliasing looks at each pixel's neighbours: once every tile is drawn.
    if settings.adaptive_aa {
        counters.add(&job.refine(&mut frame));
    }
    Some((frame, counters))
}
