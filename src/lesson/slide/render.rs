//! The render loop of the slides' reading: for every pixel, `spp` camera rays (through its centre for one,
//! at random points of the pixel otherwise), each traced with the slides' [`raytrace()`](super::raytrace()), averaged; a
//! dispersive scene is rendered once per wavelength pass ([`super::dispersion`]); a scene that asks for caustics
//! gets the slides' photon map first ([`super::photon_mapping`]).
//!
//! The rows are rendered in parallel, and every pixel draws its random numbers from a stream of its own
//! (seeded by the seed, the pixel and the pass), so the picture is the same for any number of threads.

use super::dispersion::{self, Pass};
use super::model_transform::{closest_hit, slide_nodes};
use super::photon_mapping::PhotonMap;
use super::{Slides, raytrace};
use crate::lesson::adaptive_aa::SAMPLES_PER_REFINED_PIXEL;
use crate::lesson::camera::CameraFrame;
use crate::lesson::color::Color;
use crate::lesson::diagnostics::{Problems, undeclared_dispersion};
use crate::lesson::error::Result;
use crate::lesson::frame::Frame;
use crate::lesson::ray::Ray;
use crate::lesson::render::{RenderSettings, RenderStats, thread_pool};
use crate::lesson::rng::Rng;
use crate::lesson::scene::{Counters, Scene, TraceContext};
use crate::lesson::spectral::SpectralPlan;
use rayon::prelude::*;
use std::time::Instant;

/// Keeps the random streams of the slides' passes apart from the default reading's.
const SLIDE_STREAM: u64 = 0x534c_4944_4553_0000;

/// Renders the scene as the slides do. `settings.wavelengths` is the number of passes K of a dispersive
/// scene. The course's adaptive anti-aliasing (a scene file's `wantAA`) is not on the slides: a scene that
/// asks for it gets the five samples it would give an edge pixel, in every pixel.
pub fn render(scene: &Scene, settings: &RenderSettings) -> Result<(Frame, RenderStats)> {
    settings.check()?;
    scene.check()?;
    let settings = &match settings.adaptive_aa {
        true => RenderSettings { spp: SAMPLES_PER_REFINED_PIXEL, adaptive_aa: false, ..*settings },
        false => *settings,
    };
    let pool = thread_pool(settings.threads)?;
    let photon_map = pool.install(|| PhotonMap::build(scene, settings.seed))?;
    let slides = Slides { nodes: slide_nodes(&scene.nodes), photon_map: photon_map.as_ref() };
    let start = Instant::now();
    let camera = scene.camera.frame(settings.width, settings.height);
    let (passes, bands) = dispersion::passes(scene, settings.wavelengths);
    let mut frame = Frame::new(settings.width, settings.height);
    let mut counters = Counters::default();
    for (k, pass) in passes.iter().enumerate() {
        let (pixels, pass_counters) = pool.install(|| render_pass(scene, &slides, &camera, settings, pass, k));
        for (sum, c) in frame.pixels.iter_mut().zip(pixels) {
            *sum += c * pass.color;
        }
        counters.add(&pass_counters);
    }
    let elapsed = start.elapsed();
    let (w, h) = (settings.width, settings.height);
    let hits = |scene: &Scene, ray: &Ray| closest_hit(&slide_nodes(&scene.nodes), ray).is_some();
    let trace = |scene: &Scene, rng, ray: &Ray| {
        let slides = Slides { nodes: slide_nodes(&scene.nodes), ..slides };
        let mut ctx = TraceContext::new(scene, rng);
        ctx.slides = Some(&slides);
        raytrace(&mut ctx, ray)
    };
    counters.problems.undeclared_dispersion = undeclared_dispersion(scene, &camera, w, h, hits, trace);
    let stats = RenderStats {
        elapsed,
        threads: pool.current_num_threads(),
        warnings: Problems::report(&counters, scene),
        counters,
        spectral: bands.map_or(SpectralPlan::White, SpectralPlan::Passes),
        photons: photon_map.as_ref().map(|map| map.stats),
    };
    Ok((frame, stats))
}

/// One pass of the frame, row by row in parallel, and the rays it traced.
fn render_pass(
    scene: &Scene,
    slides: &Slides,
    camera: &CameraFrame,
    settings: &RenderSettings,
    pass: &Pass,
    k: usize,
) -> (Vec<Color>, Counters) {
    let w = settings.width as usize;
    let mut pixels = vec![Color::BLACK; w * settings.height as usize];
    let counters = pixels
        .par_chunks_mut(w)
        .enumerate()
        .map(|(y, row)| {
            // One context for the row, its counters adding up the row's rays; every pixel its own random stream.
            let mut ctx = TraceContext::new(scene, Rng::for_keys(&[]));
            ctx.slides = Some(slides);
            for (x, pixel) in row.iter_mut().enumerate() {
                ctx.rng = Rng::for_keys(&[settings.seed, x as u64, y as u64, SLIDE_STREAM, k as u64]);
                let mut sum = Color::BLACK;
                for _ in 0..settings.spp {
                    let (dx, dy) =
                        if settings.spp == 1 { (0.5, 0.5) } else { (ctx.rng.next_f32(), ctx.rng.next_f32()) };
                    let camera_ray = camera.get_screen_ray(x as f32 + dx, y as f32 + dy);
                    let ray = Ray { wavelength: pass.wavelength, ..camera_ray };
                    let color = raytrace(&mut ctx, &ray);
                    sum += settings.sample(color, &mut ctx.counters);
                }
                *pixel = sum / settings.spp as f32;
            }
            ctx.counters
        })
        .reduce(Counters::default, |mut a, b| {
            a.add(&b);
            a
        });
    (pixels, counters)
}
