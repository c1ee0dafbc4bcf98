//! Debug views (`--view`): false-colour pictures of what the renderer sees and does, instead of the shaded
//! picture, to find out why a homework render looks wrong or where its time goes.
//!
//! - `normals`, `uv`, `depth`: what the camera ray through each pixel's centre hits (the geometry and its
//!   transform, before any shader runs). `uv` shows the coordinates the texture of the surface's shader
//!   looks up, after its scaling ([`Shader::texture`], [`Texture::lookup_uv`]; a layered shader's is its
//!   layers' texture, else its blend texture's), so that a floor whose u/v are scene units shows one ramp
//!   per tile of its texture, not a moiré of one ramp per unit; where the shader names no texture, the
//!   surface's own u/v;
//! - `rays`, `shadow-rays`, `depth-reached`: what rendering the pixel cost, counted exactly as the real
//!   render traces it (same samples, same random streams): a heat map of the rays per pixel shows where
//!   the time goes, and what adaptive depth control (`--exhaustive` turns it off) and layer skipping
//!   (`--shade-every-layer` in the layered example) save. The ray counts are shown on a log scale (a matte
//!   surface's few rays and a glass's hundreds both show), the depth reached on a linear one, each with its
//!   legend in a strip below the view ([`DebugImage::picture`], [`Tick`]).
//!
//! Each view comes with its scale, in words, which the example prints.
//!
//! [`Shader::texture`]: crate::lesson::shader::Shader::texture
//! [`Texture::lookup_uv`]: crate::lesson::texture::Texture::lookup_uv

mod legend;

pub use legend::Tick;

use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::node::Node;
use crate::lesson::render::{RenderSettings, render_row, thread_pool};
use crate::lesson::scene::{Counters, Scene};
use legend::HeatScale;
use rayon::prelude::*;
use std::collections::BTreeSet;

/// Which debug view to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum DebugView {
    /// The outward shading normal of what each pixel sees, as colour: (x, y, z) in [-1, 1] to RGB in [0, 1].
    Normals,
    /// The texture coordinates the surface's texture looks up (after its scaling; the surface's own u/v
    /// where the shader reads no texture), wrapped to [0, 1): u in red, v in green.
    Uv,
    /// The distance from the camera to what each pixel sees: white near, black far.
    Depth,
    /// A heat map of all rays traced per pixel (camera, secondary and shadow rays), on a log scale.
    Rays,
    /// A heat map of the shadow rays traced per pixel, on a log scale.
    ShadowRays,
    /// The deepest ray traced for each pixel (0: the camera ray only), on a linear scale.
    DepthReached,
}

/// A debug view: the picture, the range of the quantity it shows and its scale in words.
pub struct DebugImage {
    /// The false-colour view, of the render's size: the quantity mapped straight to 8-bit codes (no sRGB
    /// encoding).
    pub image: image::RgbImage,
    /// What `--view` writes: for the heat views (`rays`, `shadow-rays`, `depth-reached`), `image` with its
    /// legend in a strip below it (so that pixel (x, y) of the picture is pixel (x, y) of the render, and the
    /// picture is taller than the render by the strip); for the others, `image` alone.
    pub picture: image::RgbImage,
    /// The smallest and the largest value shown (over the pixels that hit something, for the geometric
    /// views): normal components, u/v, distances, ray counts or depths.
    pub range: (f32, f32),
    /// How to read the colours.
    pub scale: String,
    /// The labelled ticks of the heat views' legend, left to right; none for the other views.
    pub ticks: Vec<Tick>,
}

/// Where no surface is seen, the geometric views show this colour (a dark blue no value maps to); the heat
/// views on a log scale show it for a count of 0.
const NO_HIT: [u8; 3] = [0, 0, 96];

/// What one pixel of a view measured: a normal, texture coordinates and where they come from, a number (a
/// distance, a count), or nothing hit.
#[derive(Clone, Copy)]
enum Sample {
    Normal([f32; 3]),
    TexCoords([f32; 2], UvSource),
    Number(f32),
    Nothing,
}

/// Where the u/v of a pixel of the `uv` view come from, named for its scale text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum UvSource {
    /// The coordinates this texture (its type's name) looks up, after its scaling.
    Texture(&'static str),
    /// The surface's own u/v, under this shader (its type's name), which reads no texture it names.
    Surface(&'static str),
}

/// Draws the view of the scene at the size `settings` gives, on `settings.threads` threads.
pub fn render_view(scene: &Scene, settings: &RenderSettings, view: DebugView) -> Result<DebugImage> {
    settings.check()?;
    let (w, h) = (settings.width, settings.height);
    let camera = scene.camera.frame(w, h);
    let pixels: Vec<(u32, u32)> = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).collect();
    let measure = |&(x, y): &(u32, u32)| -> Sample {
        let ray = camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
        match scene.closest_hit(&ray) {
            None => Sample::Nothing,
            Some((info, node)) => match view {
                DebugView::Normals => Sample::Normal(info.normal.to_array()),
                DebugView::Uv => texture_uv(&info, node),
                _ => Sample::Number(info.distance),
            },
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
        Sample::Normal(v) => (v.iter().fold(lo, |a, &b| a.min(b)), v.iter().fold(hi, |a, &b| a.max(b))),
        Sample::TexCoords([u, v], _) => (lo.min(*u).min(*v), hi.max(*u).max(*v)),
        Sample::Number(v) => (lo.min(*v), hi.max(*v)),
        Sample::Nothing => (lo, hi),
    });
    let range = if lo <= hi { (lo, hi) } else { (0.0, 0.0) };
    let heat_scale = heat_scale(view, &samples, range);
    let colour = |s: &Sample| -> [u8; 3] {
        match (view, *s) {
            (_, Sample::Nothing) => NO_HIT,
            (_, Sample::Normal(n)) => n.map(|c| unit_to_u8((c + 1.0) * 0.5)),
            (_, Sample::TexCoords([u, v], _)) => [unit_to_u8(u), unit_to_u8(v), 0],
            (DebugView::Depth, Sample::Number(d)) => {
                let near_to_far = if range.1 > range.0 { (d - range.0) / (range.1 - range.0) } else { 0.0 };
                [unit_to_u8(1.0 - near_to_far); 3]
            }
            (_, Sample::Number(v)) => heat_scale.and_then(|scale| scale.position(v)).map_or(NO_HIT, heat),
        }
    };
    let bytes = samples.iter().flat_map(colour).collect();
    let image = image::RgbImage::from_raw(w, h, bytes).expect("one colour per pixel");
    let sources: BTreeSet<UvSource> = samples
        .iter()
        .filter_map(|s| match s {
            Sample::TexCoords(_, source) => Some(*source),
            _ => None,
        })
        .collect();
    let scale = describe(view, range, heat_scale, &sources);
    let (picture, ticks) = match heat_scale {
        Some(heat_scale) => legend::with_legend(&image, heat_scale, &legend_caption(view))?,
        None => (image.clone(), Vec::new()),
    };
    Ok(DebugImage { image, picture, range, scale, ticks })
}

/// What the `uv` view shows for a hit on `node`: the coordinates the texture of its shader looks up
/// (the shader's `texture()`, then the texture's `lookup_uv`), or, under a shader that names no texture,
/// the surface's own u/v; wrapped to [0, 1).
fn texture_uv(info: &IntersectionInfo, node: &Node) -> Sample {
    let ((u, v), source) = match node.shader.texture() {
        Some(texture) => (texture.lookup_uv(info.uv()), UvSource::Texture(texture.name())),
        None => (info.uv(), UvSource::Surface(node.shader.name())),
    };
    Sample::TexCoords([u - u.floor(), v - v.floor()], source)
}

/// The quantity a cost view shows for a pixel whose rays `counters` counted.
fn cost(view: DebugView, counters: &Counters) -> f32 {
    match view {
        DebugView::ShadowRays => counters.shadow_rays as f32,
        DebugView::DepthReached => counters.rays_by_depth.iter().rposition(|&n| n > 0).unwrap_or(0) as f32,
        _ => counters.total() as f32,
    }
}

/// How a heat view places its values on the ramp: the ray counts by their logarithm, from the smallest count
/// of at least 1 to the largest; the depth reached (a few small whole numbers) evenly over its range. `None`
/// for the geometric views.
fn heat_scale(view: DebugView, samples: &[Sample], (lo, hi): (f32, f32)) -> Option<HeatScale> {
    match view {
        DebugView::Normals | DebugView::Uv | DebugView::Depth => None,
        DebugView::DepthReached => Some(HeatScale::Linear { lo, hi }),
        DebugView::Rays | DebugView::ShadowRays => {
            let counted = samples.iter().filter_map(|s| match s {
                Sample::Number(v) if *v >= 1.0 => Some(*v),
                _ => None,
            });
            let smallest = counted.fold(f32::INFINITY, f32::min);
            Some(HeatScale::Log { lo: if smallest.is_finite() { smallest } else { 1.0 }, hi: hi.max(1.0) })
        }
    }
}

/// The caption of a heat view's legend: what is counted, and on which scale.
fn legend_caption(view: DebugView) -> String {
    match view {
        DebugView::Rays => "rays per pixel (camera, secondary and shadow rays), log scale".to_string(),
        DebugView::ShadowRays => "shadow rays per pixel, log scale; dark blue: none".to_string(),
        _ => "deepest ray per pixel (0: the camera ray only), linear scale".to_string(),
    }
}

fn describe(
    view: DebugView,
    (lo, hi): (f32, f32),
    heat_scale: Option<HeatScale>,
    sources: &BTreeSet<UvSource>,
) -> String {
    let ramp = "black, purple, red, orange, yellow, white";
    let (heat_lo, heat_hi) = heat_scale.map_or((lo, hi), HeatScale::ends);
    let legend = "the legend below the view marks the values between";
    match view {
        DebugView::Normals => {
            "RGB = (normal + 1) / 2: red +x (right), green +y (up), blue +z (away from the default camera); \
             dark blue: nothing hit"
                .to_string()
        }
        DebugView::Uv => describe_uv(sources),
        DebugView::Depth => {
            format!("white = distance {lo:.3} (nearest), black = {hi:.3} (farthest); dark blue: nothing hit")
        }
        DebugView::Rays => format!(
            "rays per pixel, camera + secondary + shadow, on a log scale: {ramp} = {heat_lo} to {heat_hi}; {legend}"
        ),
        DebugView::ShadowRays => {
            format!("shadow rays per pixel, on a log scale: {ramp} = {heat_lo} to {heat_hi}; dark blue: none; {legend}")
        }
        DebugView::DepthReached => format!(
            "deepest ray per pixel, on a linear scale: {ramp} = depth {lo} to {hi} (0: the camera ray only); {legend}"
        ),
    }
}

/// The `uv` view's scale: what the red and green are on the surfaces seen, naming the textures whose
/// coordinates it shows and the shaders under which it shows the surface's own u/v.
fn describe_uv(sources: &BTreeSet<UvSource>) -> String {
    let names = |textures: bool| -> String {
        let names: Vec<&str> = sources
            .iter()
            .filter_map(|s| match *s {
                UvSource::Texture(name) if textures => Some(name),
                UvSource::Surface(name) if !textures => Some(name),
                _ => None,
            })
            .collect();
        if names.is_empty() { "none seen".to_string() } else { names.join(", ") }
    };
    format!(
        "red = u, green = v, wrapped to [0, 1): where the shader reads a texture ({}), the coordinates the \
         texture looks up, after its scaling (one ramp per tile of the texture); elsewhere ({}), the surface's \
         own u/v; dark blue: nothing hit",
        names(true),
        names(false)
    )
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
