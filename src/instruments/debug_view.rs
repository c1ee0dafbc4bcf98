//! Debug views (`--view`): false-colour pictures of what the renderer sees and does, instead of the shaded
//! picture, to find out why a homework render looks wrong or where its time goes.
//!
//! - `normals`, `uv`, `depth`: what the camera ray through each pixel's centre hits (the geometry and its
//!   transform, before any shader runs). `uv` shows the hit's coordinates as the texture the surface's
//!   shader names would look them up, after its scaling ([`Shader::texture`], [`Texture::lookup_uv`]; a
//!   layered shader's is its layers' texture, else its blend texture's), so that a floor whose u/v are scene
//!   units shows one ramp per tile of its texture, not a moiré of one ramp per unit; where the shader names
//!   no texture, the surface's own u/v. It is computed from the hit, not from what the shader did: a shader
//!   that reads its texture elsewhere (u and v swapped, coordinates of its own) is not seen in it;
//! - `lookup`, `lookup-value`: what the shader of the surface seen through each pixel's centre actually read
//!   first: where it read its texture (u in red, v in green, wrapped to [0, 1) as in `uv`), and the colour
//!   that read returned. The centre ray is traced as the render traces it, watched by an observer that keeps
//!   the first bitmap look-up the shader of the camera ray's hit made (the view's scale says which reads
//!   are seen), so a shader that swaps u and v shows its u in green; where it matches `uv`, the shader read
//!   where the hit says it should;
//! - `rays`, `shadow-rays`, `depth-reached`: what rendering the pixel cost, counted exactly as the real
//!   render traces it (same samples, same random streams): a heat map of the rays per pixel shows where
//!   the time goes, and what adaptive depth control (`--exhaustive` turns it off) and layer skipping
//!   (`--shade-every-layer` in the layered example) save. The ray counts are shown on a log scale (a matte
//!   surface's few rays and a glass's hundreds both show), the depth reached on a linear one, each with its
//!   legend in a strip below the view ([`DebugImage::picture`], [`Tick`]). Each view's scale runs to its own
//!   largest value, or to one fixed with `--legend-max` ([`Legend`]), which two views can share, so that
//!   the colours of `--view rays` with and without `--exhaustive` compare.
//!
//! Each view comes with its scale, in words, which the example prints.
//!
//! [`Shader::texture`]: crate::lesson::shader::Shader::texture
//! [`Texture::lookup_uv`]: crate::lesson::texture::Texture::lookup_uv

mod legend;

pub use legend::Tick;

use crate::lesson::color::{Color, to_srgb8};
use crate::lesson::error::Result;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::node::Node;
use crate::lesson::observer::{Observer, Stop};
use crate::lesson::ray::Ray;
use crate::lesson::render::{RenderSettings, on_workers, render_row};
use crate::lesson::rng::Rng;
use crate::lesson::scene::{Counters, Scene, TraceContext};
use crate::lesson::shader::Shader;
use crate::lesson::topic::{Recorder, Topic};
use legend::HeatScale;
use rayon::prelude::*;
use std::collections::BTreeSet;

/// Which debug view to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum DebugView {
    /// The outward shading normal of what each pixel sees, as colour: (x, y, z) in [-1, 1] to RGB in [0, 1].
    Normals,
    /// The hit's texture coordinates as the texture the surface's shader names would look them up (after
    /// its scaling; the surface's own u/v where the shader names no texture), wrapped to [0, 1): u in red, v
    /// in green. Not what the shader read: one that swaps u and v before reading is not seen in it (`lookup`
    /// shows that).
    Uv,
    /// Where the shader of each pixel's first hit read its first bitmap (through `ColorSource::at`), wrapped
    /// to [0, 1): u in red, v in green; grey where it read none (reads through `get_tex_color`, a checker's,
    /// the Fresnel texture's and a texture of one's own are not seen).
    Lookup,
    /// The colour returned by the read `lookup` shows (the first texture read of each pixel's first hit), as
    /// a picture shows a colour (sRGB); grey where it read none.
    LookupValue,
    /// The distance from the camera to what each pixel sees: white near, black far.
    Depth,
    /// A heat map of all rays traced per pixel (camera, secondary and shadow rays), on a log scale.
    Rays,
    /// A heat map of the shadow rays traced per pixel, on a log scale.
    ShadowRays,
    /// The deepest ray traced for each pixel (0: the camera ray only), on a linear scale.
    DepthReached,
}

impl DebugView {
    /// Whether the view is a heat map (`rays`, `shadow-rays`, `depth-reached`), with a legend below it.
    pub fn is_heat(self) -> bool {
        matches!(self, DebugView::Rays | DebugView::ShadowRays | DebugView::DepthReached)
    }
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
    /// views): normal components, u/v, colour channels read (linear), distances, ray counts or depths.
    pub range: (f32, f32),
    /// How to read the colours.
    pub scale: String,
    /// The labelled ticks of the heat views' legend, left to right; none for the other views.
    pub ticks: Vec<Tick>,
}

/// How a heat view's legend is drawn: the top of its scale and the size of its text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Legend {
    /// The value shown white, at the top of the scale (`--legend-max`): fixed, so that two views drawn with
    /// the same one show the same count in the same colour; the scale then starts at 1 (a count) or 0 (the
    /// depth reached), and larger values are white too. `None`: the scale runs over the view's own values.
    pub max: Option<u32>,
    /// The interface scale of the legend's text (`--ui-scale`).
    pub ui_scale: f32,
}

impl Default for Legend {
    fn default() -> Legend {
        Legend { max: None, ui_scale: 1.0 }
    }
}

/// Where no surface is seen, the geometric views show this colour (a dark blue no value maps to); the heat
/// views on a log scale show it for a count of 0.
const NO_HIT: [u8; 3] = [0, 0, 96];

/// Where the first hit's shader read no texture seen, the `lookup` views show this mid grey (in `lookup`
/// no coordinates map to it: their blue is 0).
const NOTHING_READ: [u8; 3] = [128, 128, 128];

/// What one pixel of a view measured: a normal, texture coordinates and where they come from, a colour read
/// and who read it, a shader that read nothing seen, a number (a distance, a count), or nothing hit.
#[derive(Clone, Copy)]
enum Sample {
    Normal([f32; 3]),
    TexCoords([f32; 2], Source),
    Value(Color, Source),
    NothingRead(Source),
    Number(f32),
    Nothing,
}

/// Where the u/v of a pixel of the `uv` or `lookup` views come from, named for their scale text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Source {
    /// `uv`: the coordinates this texture (its type's name) looks up, after its scaling.
    Texture(&'static str),
    /// `uv`: the surface's own u/v, under this shader (its type's name), which reads no texture it names.
    Surface(&'static str),
    /// `lookup`: what this shader read.
    ReadBy(&'static str),
    /// `lookup`: this shader read no texture seen.
    NothingReadBy(&'static str),
}

/// What the pixels of a view measured, all together: the range of their values, the smallest ray count of
/// at least 1 (where a log scale starts) and where the `uv` and `lookup` views' coordinates come from.
struct Summary {
    lo: f32,
    hi: f32,
    smallest_count: f32,
    sources: BTreeSet<Source>,
}

impl Summary {
    fn new() -> Summary {
        Summary { lo: f32::INFINITY, hi: f32::NEG_INFINITY, smallest_count: f32::INFINITY, sources: BTreeSet::new() }
    }

    /// The summary with `sample` counted too.
    fn add(mut self, sample: Sample) -> Summary {
        let mut extend = |values: &[f32]| {
            for &v in values {
                (self.lo, self.hi) = (self.lo.min(v), self.hi.max(v));
            }
        };
        match sample {
            Sample::Normal(n) => extend(&n),
            Sample::TexCoords(uv, source) => {
                extend(&uv);
                self.sources.insert(source);
            }
            Sample::Value(color, source) => {
                extend(&color.to_array());
                self.sources.insert(source);
            }
            Sample::NothingRead(source) => {
                self.sources.insert(source);
            }
            Sample::Number(v) => {
                extend(&[v]);
                if v >= 1.0 {
                    self.smallest_count = self.smallest_count.min(v);
                }
            }
            Sample::Nothing => {}
        }
        self
    }

    /// Two summaries of disjoint sets of pixels as one.
    fn merge(mut self, other: Summary) -> Summary {
        (self.lo, self.hi) = (self.lo.min(other.lo), self.hi.max(other.hi));
        self.smallest_count = self.smallest_count.min(other.smallest_count);
        self.sources.extend(other.sources);
        self
    }
}

/// Draws the view of the scene at the size `settings` gives, on `settings.threads` threads. Its memory is a
/// few bytes a pixel, less than a render's frame: the geometric views measure each pixel twice (once for
/// the range of the values, once for the colours; the lookup views trace its centre ray twice) rather than
/// keep what they measured, and the heat views keep one number a pixel of what the pixel's rays cost.
pub fn render_view(scene: &Scene, settings: &RenderSettings, view: DebugView) -> Result<DebugImage> {
    render_view_with(scene, settings, view, Legend::default())
}

/// [`render_view`] with the heat views' legend drawn as `legend` says.
pub fn render_view_with(
    scene: &Scene,
    settings: &RenderSettings,
    view: DebugView,
    legend: Legend,
) -> Result<DebugImage> {
    settings.check()?;
    let (w, h) = (settings.width, settings.height);
    let pixels = w as usize * h as usize;
    let camera = scene.camera.frame(w, h);
    let geometric = !view.is_heat();
    let looked_up = matches!(view, DebugView::Lookup | DebugView::LookupValue);
    // The lookup views trace the centre rays: in the scene as a render traces it.
    let traced = if looked_up {
        scene.check()?;
        Some(scene.prepared())
    } else {
        None
    };
    // On the run's worker threads when it is called on one (one pool for the run), else on a pool of its own.
    let (bytes, range, heat_scale, sources) = on_workers(settings.threads, |_| -> Result<_> {
        let costs: Vec<f32> = if geometric {
            Vec::new()
        } else {
            let row_costs = |y: u32| -> Result<Vec<f32>> {
                Ok(render_row(scene, settings, y, 0..w)?.iter().map(|p| cost(view, &p.counters)).collect())
            };
            (0..h).into_par_iter().map(row_costs).collect::<Result<Vec<_>>>()?.concat()
        };
        let sample = |i: usize| -> Sample {
            if !geometric {
                return Sample::Number(costs[i]);
            }
            let (x, y) = ((i % w as usize) as f32, (i / w as usize) as f32);
            let ray = camera.get_screen_ray(x + 0.5, y + 0.5);
            if let Some(traced) = &traced {
                return looked_up_sample(view, first_read(traced, &ray, &[settings.seed, x as u64, y as u64]));
            }
            match scene.closest_hit(&ray) {
                None => Sample::Nothing,
                Some((info, node)) => match view {
                    DebugView::Normals => Sample::Normal(info.normal.to_array()),
                    DebugView::Uv => texture_uv(&info, node),
                    _ => Sample::Number(info.distance),
                },
            }
        };
        let summary = (0..pixels)
            .into_par_iter()
            .fold(Summary::new, |s, i| s.add(sample(i)))
            .reduce(Summary::new, Summary::merge);
        let range = if summary.lo <= summary.hi { (summary.lo, summary.hi) } else { (0.0, 0.0) };
        let heat_scale = heat_scale(view, summary.smallest_count, range, legend.max);
        let colour = |s: Sample| -> [u8; 3] {
            match (view, s) {
                (_, Sample::Nothing) => NO_HIT,
                (_, Sample::Normal(n)) => n.map(|c| unit_to_u8((c + 1.0) * 0.5)),
                (_, Sample::TexCoords([u, v], _)) => [unit_to_u8(u), unit_to_u8(v), 0],
                (_, Sample::Value(color, _)) => to_srgb8(color),
                (_, Sample::NothingRead(_)) => NOTHING_READ,
                (DebugView::Depth, Sample::Number(d)) => {
                    let near_to_far = if range.1 > range.0 { (d - range.0) / (range.1 - range.0) } else { 0.0 };
                    [unit_to_u8(1.0 - near_to_far); 3]
                }
                (_, Sample::Number(v)) => heat_scale.and_then(|scale| scale.position(v)).map_or(NO_HIT, heat),
            }
        };
        let mut bytes = Vec::with_capacity(pixels * 3);
        bytes.par_extend((0..pixels).into_par_iter().flat_map_iter(|i| colour(sample(i))));
        Ok((bytes, range, heat_scale, summary.sources))
    })??;
    let image = image::RgbImage::from_raw(w, h, bytes).expect("one colour per pixel");
    let mut scale = describe(view, range, heat_scale, &sources);
    if let (Some(top), Some(_)) = (legend.max, heat_scale) {
        scale += &format!("; the scale's top is fixed by --legend-max {top}");
        if range.1 > top as f32 {
            scale += &format!(": the largest value, {}, is above it and shown white", range.1);
        }
    }
    let (picture, ticks) = match heat_scale {
        Some(heat_scale) => legend::with_legend(&image, heat_scale, &legend_caption(view), legend.ui_scale)?,
        None => (image.clone(), Vec::new()),
    };
    Ok(DebugImage { image, picture, range, scale, ticks })
}

/// What a `lookup` view shows for a pixel whose centre ray's shader read `read` first: where it read,
/// wrapped to [0, 1), or the colour it got.
fn looked_up_sample(view: DebugView, read: FirstRead) -> Sample {
    match read {
        FirstRead::Missed => Sample::Nothing,
        FirstRead::Nothing { shader } => Sample::NothingRead(Source::NothingReadBy(shader)),
        FirstRead::Read { shader, color, .. } if view == DebugView::LookupValue => {
            Sample::Value(color, Source::ReadBy(shader))
        }
        FirstRead::Read { shader, uv: (u, v), .. } => {
            Sample::TexCoords([u - u.floor(), v - v.floor()], Source::ReadBy(shader))
        }
    }
}

/// What the shader of a camera ray's hit read first.
#[derive(Clone, Copy, Debug, PartialEq)]
enum FirstRead {
    /// The ray hit nothing.
    Missed,
    /// The hit's shader, called `shader`, read a bitmap first at (u, v) (after the texture's scaling, before
    /// wrapping: one image per unit), which gave `color` (linear light).
    Read {
        /// The hit's shader's name.
        shader: &'static str,
        /// Where the read looked up.
        uv: (f32, f32),
        /// The colour the read returned: its texels' weighted sum.
        color: Color,
    },
    /// The hit's shader, called `shader`, made no read the core records.
    Nothing {
        /// The hit's shader's name.
        shader: &'static str,
    },
}

/// Traces `ray` in the prepared `scene`, drawing its random numbers from a stream keyed by `keys`, and says
/// what the shader of its hit read first: where it read (u and v) and what it got back, rather than where
/// the hit says it should read (`--view uv`).
///
/// The ray is traced as the render traces a camera ray, with an observer ([`crate::lesson::observer`]) that
/// keeps the first texture look-up the core records at the first hit: the texels a bitmap mixed, which a
/// shader reads through `ColorSource::at` (every shader of the workbook, and a student's that reads its
/// texture as `docs/homework-api.md` shows), and which a `Layered` shader's layers and blend textures read so
/// too. Nothing of it runs in a render: the core records a look-up only for an observer. What the core does
/// not record is not seen: a read through `Texture::get_tex_color` (or `ColorSource::get`) called directly,
/// a checker's, a texture of a student's own, and the Fresnel texture (which reads no u/v); a surface whose
/// shader read only such textures shows as one that read none.
fn first_read(scene: &Scene, ray: &Ray, keys: &[u64]) -> FirstRead {
    let mut watch = Watch::default();
    let mut ctx = TraceContext::new(scene, Rng::for_keys(keys));
    ctx.observer = Some(&mut watch);
    ctx.raytrace(ray);
    drop(ctx);
    match (watch.shader, watch.read) {
        (None, _) => FirstRead::Missed,
        (Some(shader), Some((uv, color))) => FirstRead::Read { shader, uv, color },
        (Some(shader), None) => FirstRead::Nothing { shader },
    }
}

/// The observer of one camera ray's trace: how deep the ray being traced is (1: the camera ray), the shader
/// of the camera ray's hit, and the first look-up recorded while that shader ran (not while a ray it traced
/// was being shaded).
#[derive(Default)]
struct Watch {
    depth: u32,
    shader: Option<&'static str>,
    read: Option<((f32, f32), Color)>,
}

impl Recorder for Watch {
    fn record(&mut self, topic: &Topic) {
        if let (1, Some(_), None, Topic::Texels { u, v, texels }) = (self.depth, self.shader, self.read, topic) {
            let color = texels.iter().fold(Color::BLACK, |sum, t| sum + t.color * t.weight);
            self.read = Some(((*u, *v), color));
        }
    }
}

impl Observer for Watch {
    fn ray_begins(&mut self, _ray: &Ray) {
        self.depth += 1;
    }

    fn ray_hits(&mut self, _node: &str, shader: &'static str, _info: &IntersectionInfo) {
        if self.depth == 1 {
            self.shader = Some(shader);
        }
    }

    fn ray_ends(&mut self, _color: Color, _stop: Option<Stop>) {
        self.depth -= 1;
    }
}

/// What the `uv` view shows for a hit on `node`: the hit's coordinates as the texture its shader names
/// would look them up (the shader's `texture()`, then the texture's `lookup_uv`), or, under a shader that
/// names no texture, the surface's own u/v; wrapped to [0, 1).
fn texture_uv(info: &IntersectionInfo, node: &Node) -> Sample {
    let ((u, v), source) = match node.shader.texture() {
        Some(texture) => (texture.lookup_uv(info.uv()), Source::Texture(texture.name())),
        None => (info.uv(), Source::Surface(node.shader.name())),
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
/// of at least 1 (`smallest_count`, infinite when there is none) to the largest; the depth reached (a few
/// small whole numbers) evenly over its range. With a fixed top `max`, from 1 (a count) or 0 (a depth) to
/// it. `None` for the geometric views.
fn heat_scale(view: DebugView, smallest_count: f32, (lo, hi): (f32, f32), max: Option<u32>) -> Option<HeatScale> {
    let max = max.map(|m| m as f32);
    match view {
        DebugView::Normals | DebugView::Uv | DebugView::Depth | DebugView::Lookup | DebugView::LookupValue => None,
        DebugView::DepthReached => Some(match max {
            Some(hi) => HeatScale::Linear { lo: 0.0, hi },
            None => HeatScale::Linear { lo, hi },
        }),
        DebugView::Rays | DebugView::ShadowRays => Some(match max {
            Some(hi) => HeatScale::Log { lo: 1.0, hi },
            None => {
                HeatScale::Log { lo: if smallest_count.is_finite() { smallest_count } else { 1.0 }, hi: hi.max(1.0) }
            }
        }),
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
    sources: &BTreeSet<Source>,
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
        DebugView::Lookup | DebugView::LookupValue => describe_lookup(view, (lo, hi), sources),
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
            "deepest ray per pixel, on a linear scale: {ramp} = depth {heat_lo} to {heat_hi} (0: the camera ray only); \
             {legend}"
        ),
    }
}

/// The names `pick` takes from `sources`, joined, or "none seen".
fn names(sources: &BTreeSet<Source>, pick: impl Fn(Source) -> Option<&'static str>) -> String {
    let names: Vec<&str> = sources.iter().filter_map(|&s| pick(s)).collect();
    if names.is_empty() { "none seen".to_string() } else { names.join(", ") }
}

/// The `uv` view's scale: what the red and green are on the surfaces seen, naming the textures whose
/// coordinates it shows and the shaders under which it shows the surface's own u/v.
fn describe_uv(sources: &BTreeSet<Source>) -> String {
    let textures = names(sources, |s| if let Source::Texture(name) = s { Some(name) } else { None });
    let surfaces = names(sources, |s| if let Source::Surface(name) = s { Some(name) } else { None });
    format!(
        "red = u, green = v, wrapped to [0, 1): the hit's coordinates, where the shader names a texture \
         ({textures}) as that texture looks them up after its scaling (one ramp per tile of the texture), not what \
         the shader itself read (--view lookup shows that); elsewhere ({surfaces}), the surface's own u/v; dark \
         blue: nothing hit"
    )
}

/// The `lookup` views' scale: what the colours are, naming the shaders whose reads are shown and those
/// seen reading none, which reads count as first and which are not seen.
fn describe_lookup(view: DebugView, (lo, hi): (f32, f32), sources: &BTreeSet<Source>) -> String {
    let read = names(sources, |s| if let Source::ReadBy(name) = s { Some(name) } else { None });
    let unread = names(sources, |s| if let Source::NothingReadBy(name) = s { Some(name) } else { None });
    let what = match view {
        DebugView::LookupValue => format!(
            "the colour returned by the first texture read of the shader of the surface seen through the pixel's \
             centre (read by: {read}), linear values from {lo:.3} to {hi:.3} shown as the render shows a colour \
             (sRGB, clipped to [0, 1])"
        ),
        _ => format!(
            "red = u, green = v, wrapped to [0, 1): where the shader of the surface seen through the pixel's centre \
             made its first texture read (read by: {read}), after the texture's scaling (--view uv: where the hit \
             says it should read)"
        ),
    };
    format!(
        "{what}; a Layered shader reads its layers, each one's blend texture first, from the bottom up under \
         --slide and from the top down with layer pruning (the default); grey: no read seen (under: {unread}); seen are a bitmap's reads \
         through ColorSource::at, not reads through get_tex_color, a checker's, the Fresnel texture's or a texture \
         of one's own; dark blue: nothing hit"
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
