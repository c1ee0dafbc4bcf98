//! The course's adaptive anti-aliasing (`wantAA` in its scene files; format spec, appendix A.2): every pixel
//! gets one sample; then each pixel that differs from one of its (up to eight) neighbours by more than
//! [`THRESHOLD`] in some channel, both clamped to 1, gets four more, and becomes the plain average of its
//! five samples. Edges and fine texture get five samples, flat areas one.
//!
//! Deviation from the course: the course's five samples sit at (0, 0), (0.6, 0), (0, 0.6), (0.3, 0.3) and
//! (0.6, 0.6) from the pixel's corner, centred on (0.3, 0.3); here the same pattern is moved by 0.2 so that
//! it centres on the pixel's centre, where the workbook's single sample goes: the first sample is the
//! ordinary one through the centre, and the picture is not shifted by 0.2 pixels against the workbook's
//! other renders (ledger: `centred-aa-pattern`).
//!
//! Samplers that spread their points over a whole pixel ([`PixelSample`]): every pixel is rendered as one
//! that may get [`SAMPLES_PER_REFINED_PIXEL`] samples, the first pass tracing sample 0 of them and this
//! pass samples 1 to 4, with the pixel's own key; so a refined pixel's five samples share one point set, as
//! five samples of an ordinary render would.

use crate::lesson::camera::CameraFrame;
use crate::lesson::color::Color;
use crate::lesson::frame::Frame;
use crate::lesson::observer::Observer;
use crate::lesson::render_settings::RenderSettings;
use crate::lesson::rng::{Rng, pixel_key};
use crate::lesson::sampling::PixelSample;
use crate::lesson::scene::{Counters, Scene, TraceContext};
use rayon::prelude::*;

/// The largest difference from a neighbour (per channel, after clamping both to 1) a pixel may have
/// without getting more samples.
pub const THRESHOLD: f32 = 0.1;

/// Where the four extra samples go in a marked pixel, from its top-left corner (the first sample is at
/// its centre, (0.5, 0.5)).
pub const EXTRA_SAMPLES: [(f32, f32); 4] = [(0.2, 0.2), (0.8, 0.2), (0.2, 0.8), (0.8, 0.8)];

/// The samples of a refined pixel: its first and the extra ones.
pub const SAMPLES_PER_REFINED_PIXEL: u32 = 1 + EXTRA_SAMPLES.len() as u32;

/// A salt for the random streams of the extra samples (a glossy surface draws random numbers).
const AA_KEY: u64 = 0x4144_4150_5449_5645;

/// Which pixels of a frame of single samples differ from a neighbour by more than [`THRESHOLD`] (found in
/// parallel, on the current rayon pool: nine reads per pixel are a serial step otherwise).
pub fn marked(frame: &Frame) -> Vec<bool> {
    let w = frame.width;
    (0..frame.pixels.len()).into_par_iter().map(|i| marked_at(frame, i as u32 % w, i as u32 / w)).collect()
}

/// Whether pixel (x, y) of a frame of single samples differs from one of its neighbours in the frame by
/// more than [`THRESHOLD`] in some channel, both clamped to 1: whether the adaptive pass refines it. The
/// frame may be a piece of the picture around the pixel (`--trace-pixel` renders only the pixel's
/// neighbourhood); a pixel on the picture's border has fewer neighbours.
pub fn marked_at(frame: &Frame, x: u32, y: u32) -> bool {
    let (w, h) = (frame.width as i64, frame.height as i64);
    let at = |x: i64, y: i64| frame.pixels[(y * w + x) as usize].0.min(glam::Vec3A::ONE);
    let (x, y) = (x as i64, y as i64);
    let own = at(x, y);
    (-1..=1).any(|dy| {
        (-1..=1).any(|dx| {
            let (nx, ny) = (x + dx, y + dy);
            (0..w).contains(&nx) && (0..h).contains(&ny) && (own - at(nx, ny)).abs().max_element() > THRESHOLD
        })
    })
}

/// The adaptive pass over a frame of single samples: four more samples in every marked pixel, which
/// becomes the average of its five. Returns the rays traced. Deterministic: each pixel has its own random
/// stream, keyed by the seed and the pixel. The samples are clamped as `settings` say
/// ([`RenderSettings::sample`]).
pub fn refine(scene: &Scene, camera: &CameraFrame, settings: &RenderSettings, frame: &mut Frame) -> Counters {
    let marks = marked(frame);
    let w = frame.width as usize;
    frame
        .pixels
        .par_chunks_mut(w)
        .zip(marks.par_chunks(w))
        // One row per task, as in the first pass: the marked pixels gather along edges, so rows differ.
        .with_max_len(1)
        .enumerate()
        .map(|(y, (row, marks))| {
            let mut counters = Counters::default();
            for (x, pixel) in row.iter_mut().enumerate().filter(|(x, _)| marks[*x]) {
                *pixel = refine_pixel(scene, camera, settings, (x as u32, y as u32), *pixel, &mut counters, None);
            }
            counters
        })
        .reduce(Counters::default, |mut a, b| {
            a.add(&b);
            a
        })
}

/// The colour of the marked pixel `(x, y)` whose first sample is `first`: the average of its five samples.
/// Traces the four extra samples, counting their rays in `counters` and telling `observer`, if given, what
/// the recursion does (`--trace-pixel` records them as the pixel's camera rays 1 to 4).
pub fn refine_pixel(
    scene: &Scene,
    camera: &CameraFrame,
    settings: &RenderSettings,
    (x, y): (u32, u32),
    first: Color,
    counters: &mut Counters,
    observer: Option<&mut dyn Observer>,
) -> Color {
    let rng = Rng::for_keys(&[settings.seed, x as u64, y as u64, AA_KEY]);
    let mut ctx = TraceContext::new(scene, rng);
    ctx.observer = observer.map(|o| o as &mut dyn Observer);
    let pixel_key = pixel_key(&[settings.seed, x as u64, y as u64]);
    let mut sum = first;
    for (index, (dx, dy)) in (1..).zip(EXTRA_SAMPLES) {
        ctx.pixel_sample = Some(PixelSample { index, count: SAMPLES_PER_REFINED_PIXEL, pixel_key });
        let color = ctx.raytrace(&camera.get_screen_ray(x as f32 + dx, y as f32 + dy));
        sum += settings.sample(color, &mut ctx.counters);
    }
    counters.add(&ctx.counters);
    sum / SAMPLES_PER_REFINED_PIXEL as f32
}
