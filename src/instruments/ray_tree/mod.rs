//! The ray tree of one pixel (the recursion of the slides "Reflection v0.1/v0.2", "Refraction", "Layered
//! Shader", "Fresnel" and "Glossy", made visible): every ray traced for the pixel, what it hit, which shader
//! and layer sent it, what it brought back and why it stopped, as `--trace-pixel X,Y` prints it.
//!
//! A [`RayTree`] is an [`Observer`]: the renderer's core tells it every ray `raytrace` traces, the light the
//! light loop finds and the layers a `Layered` shader shades (see [`crate::lesson::observer`]). No shader
//! reports anything, so a student's own shader is broken down exactly as the shipped ones are.
//!
//! How the colours add up: a shader's colour is made of *terms*, each a factor times what it gathered: the
//! colour a ray it traced brought back, or light found at the surface (ambient light, a lamp reached by a
//! shadow ray, the photon map's caustic estimate). The tree does not see the arithmetic a shader does with
//! them, only what it gathered and what it returned, so it works the factors out when the shader is done:
//!
//! - a layer's terms count the layer's weight times (the weight is handed to `shade_layer`; the slide's loop,
//!   which covers the layers below with each new one, says so too), and a highlight counts as it is (the
//!   light loop adds it as it is);
//! - a ray's own share is what its weight says: the `attenuation` it was spawned with, its weight over the
//!   weight of the ray its shader shaded ([`Ray::spawn`]). A Fresnel mirror ray of weight 0.04 beside a ray
//!   of 0.96 counts 0.04 times, the other 0.96 times;
//! - what the weights do not say is one common factor per channel, shared by every term of the shader
//!   whose factor is not known (its rays and its irradiance): the shader's colour less the known terms over
//!   what the others brought, each ray's times its own share. That is 1 when the shader multiplies each ray
//!   by its attenuation (the tree then shows each ray's own share alone), a mirror's tint over its brightest
//!   channel, 1/N for a glossy average of N rays (the full factor for each ray is its weight), the diffuse
//!   colour for the light a diffuse surface gathers. The tree says so at each ray whose factor has such a
//!   common part ([`Share`]);
//! - what is left (a channel in which the shader gathered nothing but shows colour) is the shader's own
//!   colour, a term of its own.
//!
//! So the shares of all the light terms and of the environment seen by rays that missed add up to the
//! pixel's colour, whatever the shader (what the tests check).
//!
//! At each hit the tree also says what the topic computed there ([`Note`]): the Fresnel reflectance and the
//! weight it gives its layer, a bitmap's u, v and the texels it mixed with their weights, the photon
//! estimate's k, radius and photons: the techniques record them ([`crate::lesson::topic`]).

mod report;

pub use report::describe;

use crate::lesson::color::Color;
use crate::lesson::error::Result;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::observer::{LightTerm, Observer, Stop};
use crate::lesson::ray::Ray;
use crate::lesson::render::{RenderSettings, render_pixel};
use crate::lesson::scene::{Counters, Scene};
use crate::lesson::topic::{Recorder, Topic};

/// What kind of ray a record is, seen from the surface that sent it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    /// A camera ray, the root of a tree.
    Camera,
    /// Sent back to the side of the surface the ray came from (a mirror's ray, a glossy sample).
    Reflection,
    /// Sent through the surface (a refraction).
    Refraction,
}

impl std::fmt::Display for RayKind {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            RayKind::Camera => "camera ray",
            RayKind::Reflection => "reflection",
            RayKind::Refraction => "refraction",
        })
    }
}

/// One part of a shader's colour: `factor` times what a traced ray brought back, or times light found at the
/// surface, or the shader's own colour.
#[derive(Clone, Debug)]
pub struct Term {
    /// What the term's light or ray colour is multiplied by in the shader's colour, per channel (the weights of
    /// the layers it came through included).
    pub factor: Color,
    /// The layers of `Layered` shaders (if any) that produced the term, outermost first, joined by " / ".
    pub layer: String,
    /// What the term is: a traced ray, light found at the surface, or the shader's own colour.
    pub what: TermKind,
    /// For a ray: how its factor was found (its own share and the part it shares with its siblings).
    pub share: Option<Share>,
}

/// How a ray's factor was found (see the module documentation): `factor` = the weights of the layers it came
/// through, times `own`, times `common`.
#[derive(Clone, Copy, Debug)]
pub struct Share {
    /// Its own share, from its weight: its weight over the weight of the ray its shader shaded (the
    /// `attenuation` of [`Ray::spawn`]); `None` where that ray's weight is 0 (and 1 counts instead).
    pub own: Option<f32>,
    /// The rest of its factor, per channel, worked out from the shader's colour: common to it and the other
    /// terms of its shader whose factor was not known. White where its own share is its whole factor.
    pub common: Color,
    /// The other rays of its shader that share `common`.
    pub rays: usize,
    /// The light terms (irradiance) of its shader that share `common`.
    pub lights: usize,
}

/// What the tree says at a hit beyond its terms: what a technique computed there, or a layer's weight.
#[derive(Clone, Debug)]
pub struct Note {
    /// For a topic, the layers being shaded when it was computed; for a layer's weight, that layer.
    pub layer: String,
    /// How many layers deep it was made (0 at the hit's own shader).
    depth: usize,
    /// What it says.
    pub what: NoteKind,
    /// The pass of a progressive caustic it was made in, and how many passes there are; `None` for a render
    /// of one photon map.
    pub photon_pass: Option<(u32, u32)>,
}

/// What a [`Note`] says.
#[derive(Clone, Debug)]
pub enum NoteKind {
    /// A technique's values ([`crate::lesson::topic`]).
    Topic(Topic),
    /// The layer counts this many times in the colour of the shader it is a layer of (its blend, times what
    /// the layers above it let through).
    LayerWeight(Color),
}

/// What a [`Term`] multiplies its factor by.
#[derive(Clone, Debug)]
pub enum TermKind {
    /// The ray with this index in [`RayTree::rays`].
    Ray(usize),
    /// Light the light loop found.
    Light {
        /// Which light: ambient, a lamp, the photon map's caustic light, or a highlight.
        kind: LightTerm,
        /// What was found: an irradiance (the shader multiplies it by its colour) or, for a highlight, light
        /// added as it is.
        color: Color,
    },
    /// Colour the shader returned beyond everything it gathered, in the channels where it gathered nothing.
    Own {
        /// That colour, in linear RGB.
        color: Color,
    },
}

/// Where a ray hit.
#[derive(Clone, Debug)]
pub struct Hit {
    /// The node's name (see [`Node::named`](crate::lesson::node::Node::named)).
    pub node: String,
    /// The ray parameter of the hit: its distance from the ray's start (the ray's direction is unit).
    pub distance: f32,
    /// The type of the node's shader.
    pub shader: &'static str,
    /// The surface's geometric normal there: which side a ray the shader sends goes to.
    normal: Vector,
}

/// One traced ray.
#[derive(Clone, Debug)]
pub struct RayRecord {
    /// 0 for a camera ray; each reflection or refraction adds 1 ([`Ray::depth`]).
    pub depth: u32,
    /// Camera ray, reflection or refraction, judged by the side of the surface it leaves to.
    pub kind: RayKind,
    /// Where it starts, in world space (around the camera when the scene was moved there, see
    /// [`Scene::relative_to_camera`]).
    pub start: Vector,
    /// Its unit direction.
    pub dir: Vector,
    /// How much it can still change its pixel ([`Ray::weight`]).
    pub weight: f32,
    /// The shader (and layer) that traced it; empty for a camera ray.
    pub sent_by: String,
    /// What it hit; `None` when it hit nothing or was not traced (see `stop`).
    pub hit: Option<Hit>,
    /// Why it was not followed further (it missed, or was cut off before being traced); `None` when it hit a
    /// surface and was shaded.
    pub stop: Option<Stop>,
    /// The colour it brought back.
    pub color: Color,
    /// The parts of the colour of the surface it hit.
    pub terms: Vec<Term>,
    /// What the techniques computed at the hit, and the weights of its layers, in the order they were found.
    pub notes: Vec<Note>,
}

/// The terms of one shader being run (a hit's shader, or one layer of a `Layered` one) that are still open.
#[derive(Clone, Debug)]
struct Scope {
    /// The layer's label; empty for the hit's own shader.
    label: String,
    /// Its terms are `terms[first..]` of the ray being shaded.
    first: usize,
    /// The weight of the ray its shader sees: a ray it traces has its own share of it.
    weight: f32,
}

/// The rays traced for one pixel: one tree per camera ray, in the order they were traced.
#[derive(Clone, Debug, Default)]
pub struct RayTree {
    /// Every ray traced for the pixel, in the order traced; [`TermKind::Ray`] and `roots` index it.
    pub rays: Vec<RayRecord>,
    /// The camera rays: sample s of the pixel is `roots[s]` (for a dispersive scene traced in K passes,
    /// sample s of pass k is `roots[k * spp + s]`; for a progressive caustic, the passes' camera rays one
    /// pass after another, see `photon_passes`).
    pub roots: Vec<usize>,
    /// For a progressive caustic, where each pass's camera rays begin in `roots` (pass p, from 1, at
    /// `photon_passes[p - 1]`); empty for a render of one photon map.
    pub photon_passes: Vec<usize>,
    /// The pass of a progressive caustic being traced, and how many passes there are.
    photon_pass: Option<(u32, u32)>,
    /// The rays being traced, innermost last, each with the shaders (and layers) running at its hit.
    open: Vec<(usize, Vec<Scope>)>,
    /// Which terms of each open ray already have their factor: `fixed[i]` for the ray `open[i]`.
    fixed: Vec<Vec<bool>>,
}

impl RayTree {
    /// An empty tree, to be filled by the render of one pixel as its [`Observer`].
    pub fn new() -> RayTree {
        RayTree::default()
    }

    /// The pass of a progressive caustic that camera ray `sample` belongs to, and how many passes there are;
    /// `None` for a render of one photon map.
    pub fn photon_pass_of(&self, sample: usize) -> Option<(u32, u32)> {
        let passes = self.photon_passes.len() as u32;
        let pass = self.photon_passes.iter().filter(|&&first| first <= sample).count() as u32;
        (passes > 0).then_some((pass, passes))
    }

    /// The labels of the layers being shaded at the innermost open ray's hit.
    fn layer_label(&self) -> String {
        let scopes = self.open.last().map_or(&[][..], |(_, scopes)| &scopes[..]);
        scopes.iter().filter(|s| !s.label.is_empty()).map(|s| s.label.as_str()).collect::<Vec<_>>().join(" / ")
    }

    /// Adds a term to the innermost open ray, its factor already known (`fixed`) or still to be worked out.
    fn push_term(&mut self, what: TermKind, fixed: bool) {
        let layer = self.layer_label();
        if let (Some(&(id, _)), Some(flags)) = (self.open.last(), self.fixed.last_mut()) {
            self.rays[id].terms.push(Term { factor: Color::WHITE, layer, what, share: None });
            flags.push(fixed);
        }
    }

    /// Adds a note, labelled `layer`, to the innermost open ray.
    fn push_note(&mut self, layer: String, what: NoteKind) {
        if let Some((id, scopes)) = self.open.last() {
            self.rays[*id].notes.push(Note { layer, depth: scopes.len(), what, photon_pass: self.photon_pass });
        }
    }

    /// What term `term` brought, before its factor.
    fn value(&self, term: &Term) -> Color {
        match term.what {
            TermKind::Ray(child) => self.rays[child].color,
            TermKind::Light { color, .. } | TermKind::Own { color } => color,
        }
    }

    /// The shader whose terms are `terms[first..]` of the innermost open ray returned `color`, shading a ray
    /// of weight `weight`: works out the factor of the terms that have none yet (see the module
    /// documentation), adds the shader's own colour if some is left, and marks them all as known.
    fn settle(&mut self, first: usize, color: Color, weight: f32) {
        let (Some(&(id, _)), Some(fixed)) = (self.open.last(), self.fixed.last()) else {
            return;
        };
        let terms = &self.rays[id].terms[first..];
        // Each open term's own share: a ray's from its weight, 1 for light (and for a ray whose weight says
        // nothing).
        let own: Vec<Option<f32>> = terms
            .iter()
            .map(|term| match term.what {
                TermKind::Ray(child) => {
                    Some(self.rays[child].weight / weight).filter(|s| weight > 0.0 && s.is_finite())
                }
                _ => None,
            })
            .collect();
        let (mut known, mut gathered, mut magnitude) = (Color::BLACK, Color::BLACK, color.0.abs());
        let (mut rays, mut lights) = (0, 0);
        for ((term, &is_fixed), own) in terms.iter().zip(&fixed[first..]).zip(&own) {
            let part = self.value(term);
            if is_fixed {
                known += term.factor * part;
                magnitude += (term.factor * part).0.abs();
            } else {
                let part = part * own.unwrap_or(1.0);
                gathered += part;
                magnitude += part.0.abs();
                match term.what {
                    TermKind::Ray(_) => rays += 1,
                    _ => lights += 1,
                }
            }
        }
        // Per channel: the common factor of the open terms, and what is left where they brought nothing.
        let rest = color - known;
        let common =
            Color::new(ratio(rest.r(), gathered.r()), ratio(rest.g(), gathered.g()), ratio(rest.b(), gathered.b()));
        let own_colour = rest - common * gathered;
        let count = terms.len();
        let terms = &mut self.rays[id].terms[first..];
        for ((term, &is_fixed), &own) in terms.iter_mut().zip(&fixed[first..]).zip(&own) {
            if !is_fixed {
                term.factor = common * own.unwrap_or(1.0);
                if let TermKind::Ray(_) = term.what {
                    term.share = Some(Share { own, common, rays: rays - 1, lights });
                }
            }
        }
        // What is left beyond the rounding of the shader's own sums is colour of its own.
        let rounding = magnitude * ((count + 4) as f32 * f32::EPSILON);
        if (own_colour.0.abs() - rounding).max_element() > 0.0 {
            self.push_term(TermKind::Own { color: own_colour }, true);
        }
        if let Some(flags) = self.fixed.last_mut() {
            flags[first..].iter_mut().for_each(|f| *f = true);
        }
    }

    /// What the terms of ray `id` add up to: its colour.
    pub fn terms_sum(&self, id: usize) -> Color {
        self.rays[id].terms.iter().fold(Color::BLACK, |sum, term| sum + term.factor * self.value(term))
    }

    /// The pixel colour the tree of ray `id` explains, starting from throughput `throughput`: the sum, over
    /// every light term, every shader's own colour and every ray that missed, of its light times the product
    /// of the factors on its way.
    pub fn explained(&self, id: usize, throughput: Color) -> Color {
        let ray = &self.rays[id];
        if ray.hit.is_none() {
            return throughput * ray.color;
        }
        let mut sum = Color::BLACK;
        for term in &ray.terms {
            let t = throughput * term.factor;
            sum += match term.what {
                TermKind::Ray(child) => self.explained(child, t),
                TermKind::Light { color, .. } | TermKind::Own { color } => t * color,
            };
        }
        sum
    }
}

impl Observer for RayTree {
    fn photon_pass_begins(&mut self, pass: u32, passes: u32) {
        self.photon_passes.push(self.roots.len());
        self.photon_pass = Some((pass, passes));
    }

    fn ray_begins(&mut self, ray: &Ray) {
        let id = self.rays.len();
        let layer = self.layer_label();
        let (kind, sent_by) = match self.open.last().map(|&(parent, _)| &self.rays[parent]) {
            None => (RayKind::Camera, String::new()),
            Some(parent) => {
                let (shader, normal) = parent.hit.as_ref().map_or(("", Vector::ZERO), |h| (h.shader, h.normal));
                let through = ray.dir.dot(normal) * parent.dir.dot(normal) > 0.0;
                let kind = if through { RayKind::Refraction } else { RayKind::Reflection };
                (kind, if layer.is_empty() { shader.to_string() } else { format!("{shader}, {layer}") })
            }
        };
        if self.open.is_empty() {
            self.roots.push(id);
        } else {
            self.push_term(TermKind::Ray(id), false);
        }
        self.rays.push(RayRecord {
            depth: ray.depth,
            kind,
            start: ray.start,
            dir: ray.dir,
            weight: ray.weight,
            sent_by,
            hit: None,
            stop: None,
            color: Color::BLACK,
            terms: Vec::new(),
            notes: Vec::new(),
        });
        self.open.push((id, vec![Scope { label: String::new(), first: 0, weight: ray.weight }]));
        self.fixed.push(Vec::new());
    }

    fn ray_hits(&mut self, node: &str, shader: &'static str, info: &IntersectionInfo) {
        if let Some(&(id, _)) = self.open.last() {
            self.rays[id].hit =
                Some(Hit { node: node.to_string(), distance: info.distance, shader, normal: info.geometric_normal });
        }
    }

    fn light_found(&mut self, light: LightTerm, color: Color) {
        self.push_term(TermKind::Light { kind: light, color }, !light.is_irradiance());
    }

    fn layer_begins(&mut self, shader: &'static str, blend_texture: Option<&'static str>, ray: &Ray) {
        let source = blend_texture.map_or(String::new(), |name| format!(", blend {name}"));
        let label = format!("layer {shader}{source}");
        if let Some((id, scopes)) = self.open.last_mut() {
            scopes.push(Scope { label, first: self.rays[*id].terms.len(), weight: ray.weight });
        }
    }

    fn layer_ends(&mut self, color: Color, weight: Color) {
        let Some(scope) = self.open.last().and_then(|(_, scopes)| scopes.last()).cloned() else {
            return;
        };
        self.settle(scope.first, color, scope.weight);
        if let Some((id, scopes)) = self.open.last_mut() {
            scopes.pop();
            for term in &mut self.rays[*id].terms[scope.first..] {
                term.factor *= weight;
            }
        }
        self.push_note(scope.label, NoteKind::LayerWeight(weight));
    }

    fn layers_covered(&mut self, blend: Color) {
        let Some((id, scopes)) = self.open.last() else {
            return;
        };
        let (first, depth, through) = (scopes.last().map_or(0, |s| s.first), scopes.len(), Color::WHITE - blend);
        let ray = &mut self.rays[*id];
        ray.terms[first..].iter_mut().for_each(|term| term.factor *= through);
        for note in ray.notes.iter_mut().filter(|note| note.depth == depth) {
            if let NoteKind::LayerWeight(weight) = &mut note.what {
                *weight *= through;
            }
        }
    }

    fn ray_ends(&mut self, color: Color, stop: Option<Stop>) {
        if let Some(&(id, _)) = self.open.last().filter(|&&(id, _)| self.rays[id].hit.is_some()) {
            self.settle(0, color, self.rays[id].weight);
        }
        if let Some((id, _)) = self.open.pop() {
            self.rays[id].color = color;
            self.rays[id].stop = stop;
            self.fixed.pop();
        }
    }
}

impl Recorder for RayTree {
    fn record(&mut self, topic: &Topic) {
        let layer = self.layer_label();
        self.push_note(layer, NoteKind::Topic(topic.clone()));
    }
}

/// `numerator / denominator`, or 0 where the denominator is 0 (nothing gathered in that channel: what the
/// shader shows there is its own colour).
fn ratio(numerator: f32, denominator: f32) -> f32 {
    if denominator == 0.0 { 0.0 } else { numerator / denominator }
}

/// A pixel named on the command line as `X,Y` (from the top left).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelPos {
    /// Column, counted from the left edge (0).
    pub x: u32,
    /// Row, counted from the top edge (0).
    pub y: u32,
}

impl std::str::FromStr for PixelPos {
    type Err = String;
    fn from_str(s: &str) -> std::result::Result<PixelPos, String> {
        let parse = |v: &str| v.trim().parse::<u32>().ok();
        match s.split_once(',').map(|(x, y)| (parse(x), parse(y))) {
            Some((Some(x), Some(y))) => Ok(PixelPos { x, y }),
            _ => Err(format!("'{s}' is not a pixel: expected X,Y, two whole numbers such as 320,200")),
        }
    }
}

/// How `--trace-pixel` prints the tree.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum TraceFormat {
    /// An indented tree to read.
    #[default]
    Text,
    /// One JSON object per ray, its terms nested, for tools.
    Json,
}

/// A pixel rendered with its ray tree recorded.
#[derive(Clone, Debug)]
pub struct TracedPixel {
    /// The pixel's linear colour, as the render gives it: the mean of its camera samples' colours (for a
    /// dispersive scene traced in passes, the passes' colour-weighted sum; for a progressive caustic, the
    /// mean of its passes' colours).
    pub color: Color,
    /// The rays traced for the pixel.
    pub counters: Counters,
    /// Every ray traced for the pixel, and how their colours add up to it.
    pub tree: RayTree,
}

/// Renders pixel `pixel` of the picture `settings` describe, exactly as the render would, recording its ray
/// tree.
pub fn trace(scene: &Scene, settings: &RenderSettings, pixel: PixelPos) -> Result<TracedPixel> {
    let mut tree = RayTree::new();
    let rendered = render_pixel(scene, settings, pixel.x, pixel.y, Some(&mut tree))?;
    Ok(TracedPixel { color: rendered.color, counters: rendered.counters, tree })
}
