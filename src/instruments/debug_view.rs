//! Debug views (`--view`): false-colour pictures of what the renderer sees and does, instead of the shaded
//! picture, to find out why a homework render looks wrong or where its time goes.
//!
//! - `normals`, `uv`, `depth`: what the camera ray through each pixel's centre hits (the geometry and its
//!   transform, before any shader runs);
//! - `rays`, `shadow-rays`, `depth-reached`: what rendering the pixel cost, counted exactly as the real
//!   render traces it (same samples, same random streams): a heat map of the rays per pixel shows where
//!   the time goes, and what adaptive depth control (`--exhaustive` turns it off) and layer skipping
//!   (`--shade-every-layer` in the layered example) save.
//!
//! Each view comes with its scale, in words, which the example prints.

use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::render::{RenderSettings, render_row, thread_pool};
use crate::lesson::scene::{Counters, Scene};
use rayon::prelude::*;

/// Which debug view to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum DebugView {
    /// The outward shading normal of what each pixel sees, as colour: (x, y, z) in [-1, 1] to RGB in [0, 1].
    Normals,
    /// The texture coordinates, wrapped to [0, 1): u in red, v in green.
    Uv,
    /// The distance from the camera to what each pixel sees: white near, black far.
    Depth,
    /// A heat map of all rays traced per pixel (camera, secondary and shadow rays).
    Rays,
    /// A heat map of the shadow rays traced per pixel.
    ShadowRays,
    /// The deepest ray traced for each pixel (0: the camera ray only).
    DepthReached,
}

/// A debug view: the picture, the range of the quantity it shows and its scale in words.
pub struct DebugImage {
    /// The false-colour picture: the quantity mapped straight to 8-bit codes (no sRGB encoding).
    pub image: image::RgbImage,
    /// The smallest and the largest value shown (over the pixels that hit something, for the geometric
    /// views): normal components, u/v, distances, ray counts or depths.
    pub range: (f32, f32),
    /// How to read the colours.
    pub scale: String,
}

/// Where no surface is seen, the geometric views show this colour (a dark blue no value maps to).
const NO_HIT: [u8; 3] = [0, 0, 96];

/// What one pixel of a view measured: a colour-coded vector (normals, uv) or a number, or nothing hit.
#[derive(Clone, Copy)]
enum Sample {
    Vector([f32; 3]),
    Number(f32),
    Nothing,
}

/// Draws the view of the scene at the size `settings` gives, on `settings.threads` threads.
pub fn render_view(scene: &Scene, settings: &RenderSettings, view: DebugView) -> Result<DebugImage> {
    settings.check()?;
    let (w, h) = (settings.width, settings.height);
    let camera = scene.camera.frame(w, h);
    let pixels: Vec<(u32, u32)> = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).collect();
    let measure = |&(x, y): &(u32, u32)| -> Sample {
        match view {
            DebugView::Normals | DebugView::Uv | DebugView::Depth => {
                let ray = camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
                match scene.closest_hit(&ray) {
                    None => Sample::Nothing,
                    Some((info, _)) => match view {
                        DebugView::Normals => Sample::Vector(info.normal.to_array()),
                        DebugView::Uv => {
                            let (u, v) = info.uv();
                            Sample::Vector([u - u.floor(), v - v.floor(), 0.0])
                        }
                        _ => Sample::Number(info.distance),
                    },
                }
            }
            _ => unreachable!("cost views are measured by rows"),
        }
    };
    let geometric = matches!(view, DebugView::Normals | DebugView::Uv | DebugView::Depth);
    let samples = thread_pool(settings.threads)?.install(|| -> Result<Vec<Sample>> {
        if geometric {
            return Ok(pixels.par_iter().map(measure).collect());
        }
        let rows = (0..h).into_par_iter().map(|y| render_row(scene, settings, y, 0..w)).collect::<Result<Vec<_>>>()?;
        Ok(rows.iter().flatten().map(|p| Sample::Number(cost(view, &p.counters))).collect())
    })?;
    let (lo, hi) = samples.iter().fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), s| match s {
        Sample::Vector(v) => (v.iter().fold(lo, |a, &b| a.min(b)), v.iter().fold(hi, |a, &b| a.max(b))),
        Sample::Number(v) => (lo.min(*v), hi.max(*v)),
        Sample::Nothing => (lo, hi),
    });
    let range = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };
    let to_unit = |v: f32| if range.1 > range.0 { (v - range.0) / (range.1 - range.0) } else { 0.0 };
    let colour = |s: &Sample| -> [u8; 3] {
        match (view, *s) {
            (_, Sample::Nothing) => NO_HIT,
            (DebugView::Normals, Sample::Vector(n)) => n.map(|c| unit_to_u8((c + 1.0) * 0.5)),
            (_, Sample::Vector(v)) => v.map(unit_to_u8),
            (DebugView::Depth, Sample::Number(d)) => [unit_to_u8(1.0 - to_unit(d)); 3],
            (_, Sample::Number(v)) => heat(to_unit(v)),
        }
    };
    let bytes = samples.iter().flat_map(colour).collect();
    let image = image::RgbImage::from_raw(w, h, bytes).expect("one colour per pixel");
    let scale = describe(view, range);
    Ok(DebugImage { image, range, scale })
}

/// The quantity a cost view shows for a pixel whose rays `counters` counted.
fn cost(view: DebugView, counters: &Counters) -> f32 {
    match view {
        DebugView::ShadowRays => counters.shadow_rays as f32,
        DebugView::DepthReached => counters.rays_by_depth.iter().rposition(|&n| n > 0).unwrap_or(0) as f32,
        _ => counters.total() as f32,
    }
}

fn describe(view: DebugView, (lo, hi): (f32, f32)) -> String {
    let ramp = "black, purple, red, orange, yellow, white";
    match view {
        DebugView::Normals => {
            "RGB = (normal + 1) / 2: red +x (right), green +y (up), blue +z (away from the default camera); \
             dark blue: nothing hit"
                .to_string()
        }
        DebugView::Uv => "red = u, green = v, wrapped to [0, 1); dark blue: nothing hit".to_string(),
        DebugView::Depth => {
            format!("white = distance {lo:.3} (nearest), black = {hi:.3} (farthest); dark blue: nothing hit")
        }
        DebugView::Rays => format!("rays per pixel, camera + secondary + shadow: {ramp} = {lo} to {hi}"),
        DebugView::ShadowRays => format!("shadow rays per pixel: {ramp} = {lo} to {hi}"),
        DebugView::DepthReached => {
            format!("deepest ray per pixel: {ramp} = depth {lo} to {hi} (0: the camera ray only)")
        }
    }
}

fn unit_to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// A false-colour ramp for t in [0, 1]: black, purple, red, orange, yellow, white (a perceptually ordered
/// "inferno"-like scale, readable in greyscale too).
pub fn heat(t: f32) -> [u8; 3] {
    const STOPS: [Color; 6] = [
        Color::new(0.0, 0.0, 0.0),
        Color::new(0.35, 0.05, 0.45),
        Color::new(0.8, 0.15, 0.25),
        Color::new(0.97, 0.5, 0.05),
        Color::new(0.98, 0.85, 0.2),
        Color::new(1.0, 1.0, 1.0),
    ];
    let x = t.clamp(0.0, 1.0) * (STOPS.len() - 1) as f32;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f32;
    let c = STOPS[i] * (1.0 - f) + STOPS[i + 1] * f;
    c.to_array().map(unit_to_u8)
}
