//! The ray tree of one pixel (the recursion of the slides "Reflection v0.1/v0.2", "Refraction", "Layered
//! Shader", "Fresnel" and "Glossy", made visible): every ray traced for the pixel, what it hit, which shader
//! and layer sent it, what it brought back and why it stopped, as `--trace-pixel X,Y` prints it.
//!
//! Recording is switched on by putting a [`RayTree`] in [`TraceContext::recorder`]; the renderer, the light
//! loop and the shaders report to it through [`TraceContext::record`], which does nothing (one test of an
//! `Option`) when no tree is being recorded. A shader written by a student that reports nothing still
//! renders and still appears in the tree, with what it returned; its colour is then shown as not broken
//! down.
//!
//! How the colours add up: a shader's colour is a sum of *terms*, each a factor times either the colour a
//! ray it traced brought back, or light it found at the surface (ambient light, a lamp reached by a shadow
//! ray, the photon map's caustic estimate, a highlight). A ray's share of the pixel is the product of the
//! factors on the path from the camera (its *throughput*) times its colour; the shares of all the light
//! terms and of the environment seen by rays that missed add up to the pixel's colour (what the tests check).

use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::ray::Ray;
use crate::lesson::render::{PixelTrace, RenderSettings, render_pixel};
use crate::lesson::scene::{Scene, TraceContext};
use std::fmt::Write;

/// The last segment of a type's path, without generic arguments: `Reflection` for
/// `lecture6::lesson::shader::reflection::Reflection`. Names shaders, textures and geometry in the ray tree.
pub fn type_label<T: ?Sized>() -> &'static str {
    let name = std::any::type_name::<T>();
    let name = name.split('<').next().unwrap_or(name);
    name.rsplit("::").next().unwrap_or(name)
}

/// What kind of ray a record is, as the shader that traced it says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RayKind {
    Camera,
    Reflection,
    Refraction,
    /// Sample `index` (from 0) of the `count` rays of a glossy reflection.
    GlossySample {
        index: u32,
        count: u32,
    },
    /// A ray from a shader that did not say what kind it is.
    Secondary,
}

impl std::fmt::Display for RayKind {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            RayKind::Camera => write!(f, "camera ray"),
            RayKind::Reflection => write!(f, "reflection"),
            RayKind::Refraction => write!(f, "refraction"),
            RayKind::GlossySample { index, count } => write!(f, "glossy sample {} of {count}", index + 1),
            RayKind::Secondary => write!(f, "secondary ray"),
        }
    }
}

/// Why a ray was not followed further.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop {
    /// It hit nothing: its colour is the environment's.
    Missed,
    /// It was deeper than the scene's `max_depth` (the slide's `MAX_RAY_DEPTH`): black.
    DepthLimit,
    /// Its weight was below the adaptive cut-off (`Scene::min_ray_weight`): black.
    WeightCutoff,
    /// It was deeper than the recursion safety cap: black.
    SafetyCap,
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            Stop::Missed => "missed: environment colour",
            Stop::DepthLimit => "depth limit: black",
            Stop::WeightCutoff => "weight below the adaptive cut-off: black",
            Stop::SafetyCap => "recursion safety cap: black",
        })
    }
}

/// Light a shader found at its hit point, without tracing a ray for it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// The scene's ambient light.
    Ambient,
    /// Lamp `index`, asked by a shadow ray that starts at `from` towards the lamp (`dir`); `visible` says
    /// whether it got there.
    Lamp { index: usize, from: Vector, dir: Vector, visible: bool },
    /// The caustic light of the photon map.
    Photons,
    /// A specular highlight (Phong's) of the lamps that reach the point.
    Highlight,
    /// Total internal reflection in a refraction without a reflection layer: no ray, black.
    TotalInternalReflection,
}

impl std::fmt::Display for LightKind {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        match self {
            LightKind::Ambient => write!(f, "ambient light"),
            LightKind::Lamp { index, from, dir, visible } => write!(
                f,
                "shadow ray to light {index} from {} dir {}: {}",
                vec3(*from),
                vec3(*dir),
                if *visible { "reaches it" } else { "blocked" }
            ),
            LightKind::Photons => write!(f, "photon estimate (caustic light)"),
            LightKind::Highlight => write!(f, "specular highlight"),
            LightKind::TotalInternalReflection => write!(f, "total internal reflection: no refracted ray, black"),
        }
    }
}

/// One part of a shader's colour: `factor` times a traced ray's colour or times light found at the surface.
#[derive(Clone, Debug)]
pub struct Term {
    pub factor: Color,
    /// The layer of a `Layered` shader (if any) that produced the term.
    pub layer: String,
    pub what: TermKind,
}

#[derive(Clone, Debug)]
pub enum TermKind {
    /// The ray with this index in [`RayTree::rays`].
    Ray(usize),
    Light {
        kind: LightKind,
        color: Color,
    },
}

/// Where a ray hit.
#[derive(Clone, Debug)]
pub struct Hit {
    /// The node's name (see [`Node::named`]).
    pub node: String,
    pub distance: f32,
    /// The type of the node's shader.
    pub shader: &'static str,
}

/// One traced ray.
#[derive(Clone, Debug)]
pub struct RayRecord {
    pub depth: u32,
    pub kind: RayKind,
    pub start: Vector,
    pub dir: Vector,
    pub weight: f32,
    /// The shader (and layer) that traced it; empty for a camera ray.
    pub sent_by: String,
    pub hit: Option<Hit>,
    pub stop: Option<Stop>,
    /// The colour it brought back.
    pub color: Color,
    /// The parts of the colour of the surface it hit, as its shader reported them.
    pub terms: Vec<Term>,
}

/// The rays traced for one pixel: one tree per camera ray, in the order they were traced.
#[derive(Clone, Debug, Default)]
pub struct RayTree {
    pub rays: Vec<RayRecord>,
    /// The camera rays: sample s of the pixel is `roots[s]` (for a dispersive scene traced in K passes,
    /// sample s of pass k is `roots[k * spp + s]`).
    pub roots: Vec<usize>,
    /// The rays being traced, innermost last.
    open: Vec<usize>,
    /// What the next ray traced is, as its shader announced.
    next_kind: Option<RayKind>,
    /// The layers of `Layered` shaders being shaded at the hit of the innermost open ray, innermost last.
    layers: Vec<String>,
    /// The layers being shaded at the hits of the other open rays (each ray's shader has its own).
    outer_layers: Vec<Vec<String>>,
}

impl RayTree {
    pub fn new() -> RayTree {
        RayTree::default()
    }

    fn layer_label(&self) -> String {
        self.layers.join(" / ")
    }

    fn current(&mut self) -> Option<&mut RayRecord> {
        self.open.last().map(|&i| &mut self.rays[i])
    }

    /// `raytrace` starts tracing `ray`.
    pub fn begin(&mut self, ray: &Ray) {
        let id = self.rays.len();
        let kind =
            self.next_kind.take().unwrap_or(if self.open.is_empty() { RayKind::Camera } else { RayKind::Secondary });
        let layer = self.layer_label();
        let sent_by = match self.current() {
            None => String::new(),
            Some(parent) => {
                let shader = parent.hit.as_ref().map_or("", |h| h.shader);
                if layer.is_empty() { shader.to_string() } else { format!("{shader}, {layer}") }
            }
        };
        match self.current() {
            None => self.roots.push(id),
            Some(parent) => parent.terms.push(Term { factor: Color::WHITE, layer, what: TermKind::Ray(id) }),
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
        });
        self.open.push(id);
        self.outer_layers.push(std::mem::take(&mut self.layers));
    }

    /// The ray being traced hit `node` of `scene`; its shader is about to run.
    pub fn hit(&mut self, scene: &Scene, node: &Node, info: &IntersectionInfo) {
        let name = scene.node_name(node);
        if let Some(ray) = self.current() {
            ray.hit = Some(Hit { node: name, distance: info.distance, shader: node.shader.name() });
        }
    }

    /// The ray being traced is finished: it brought back `color` (and stopped for `stop`, if it did).
    pub fn end(&mut self, color: Color, stop: Option<Stop>) {
        if let Some(id) = self.open.pop() {
            self.rays[id].color = color;
            self.rays[id].stop = stop;
            self.layers = self.outer_layers.pop().unwrap_or_default();
        }
    }

    /// The next ray the shader traces is of this kind.
    pub fn next_ray(&mut self, kind: RayKind) {
        self.next_kind = Some(kind);
    }

    /// The shader found light `color` of this kind at its hit point.
    pub fn light(&mut self, kind: LightKind, color: Color) {
        let layer = self.layer_label();
        if let Some(ray) = self.current() {
            ray.terms.push(Term { factor: Color::WHITE, layer, what: TermKind::Light { kind, color } });
        }
    }

    /// How many terms the shader of the ray being traced has reported so far: a mark for [`RayTree::scale`].
    pub fn mark(&self) -> usize {
        self.open.last().map_or(0, |&i| self.rays[i].terms.len())
    }

    /// The shader multiplies everything it reported since `mark` by `factor`.
    pub fn scale(&mut self, mark: usize, factor: Color) {
        if let Some(ray) = self.current() {
            for term in ray.terms.iter_mut().skip(mark) {
                term.factor *= factor;
            }
        }
    }

    /// A `Layered` shader starts shading one of its layers (described by `label`).
    pub fn enter_layer(&mut self, label: String) {
        self.layers.push(label);
    }

    /// ... and is done with it.
    pub fn leave_layer(&mut self) {
        self.layers.pop();
    }

    /// What the terms of ray `id` add up to (its colour, when its shader reported every part of it).
    pub fn terms_sum(&self, id: usize) -> Color {
        let mut sum = Color::BLACK;
        for term in &self.rays[id].terms {
            sum += term.factor
                * match term.what {
                    TermKind::Ray(child) => self.rays[child].color,
                    TermKind::Light { color, .. } => color,
                };
        }
        sum
    }

    /// The pixel colour the tree of ray `id` explains, starting from throughput `throughput`: the sum, over
    /// every light term and every ray that missed, of its light times the product of the factors on its way.
    pub fn explained(&self, id: usize, throughput: Color) -> Color {
        let ray = &self.rays[id];
        if ray.stop == Some(Stop::Missed) {
            return throughput * ray.color;
        }
        let mut sum = Color::BLACK;
        for term in &ray.terms {
            let t = throughput * term.factor;
            sum += match term.what {
                TermKind::Ray(child) => self.explained(child, t),
                TermKind::Light { color, .. } => t * color,
            };
        }
        sum
    }

    /// The tree of camera ray `sample` as indented text.
    pub fn to_text(&self, sample: usize) -> String {
        let mut out = String::new();
        if let Some(&root) = self.roots.get(sample) {
            self.write_ray(&mut out, root, Color::WHITE, 0);
        }
        out
    }

    fn write_ray(&self, out: &mut String, id: usize, throughput: Color, indent: usize) {
        let ray = &self.rays[id];
        let pad = "  ".repeat(indent);
        let _ = writeln!(
            out,
            "{pad}{} (depth {}) from {} dir {}, weight {:.4}",
            ray.kind,
            ray.depth,
            vec3(ray.start),
            vec3(ray.dir),
            ray.weight
        );
        if let Some(hit) = &ray.hit {
            let _ = writeln!(out, "{pad}  hits {} at distance {:.4}, shader {}", hit.node, hit.distance, hit.shader);
        }
        if let Some(stop) = ray.stop {
            let _ = writeln!(out, "{pad}  stops: {stop}");
        }
        let _ =
            writeln!(out, "{pad}  returns {}; its share of the pixel {}", rgb(ray.color), rgb(throughput * ray.color));
        for term in &ray.terms {
            let layer = if term.layer.is_empty() { String::new() } else { format!("{}: ", term.layer) };
            match term.what {
                TermKind::Ray(child) => {
                    let _ = writeln!(out, "{pad}  + {layer}{} times", factor(term.factor));
                    self.write_ray(out, child, throughput * term.factor, indent + 2);
                }
                TermKind::Light { kind, color } => {
                    let _ = writeln!(
                        out,
                        "{pad}  + {layer}{} times {kind}: {}; share of the pixel {}",
                        factor(term.factor),
                        rgb(color),
                        rgb(throughput * term.factor * color)
                    );
                }
            }
        }
        if ray.hit.is_some() {
            let rest = ray.color - self.terms_sum(id);
            if rest.0.abs().max_element() > 1e-4 * ray.color.max_channel().max(1.0) {
                let _ = writeln!(out, "{pad}  - not broken down by its shader: {}", rgb(rest));
            }
        }
    }

    /// The tree of camera ray `sample` as JSON (one object per ray, its terms nested).
    pub fn to_json(&self, sample: usize) -> String {
        let mut out = String::new();
        match self.roots.get(sample) {
            Some(&root) => self.write_json(&mut out, root, Color::WHITE),
            None => out.push_str("null"),
        }
        out
    }

    fn write_json(&self, out: &mut String, id: usize, throughput: Color) {
        let ray = &self.rays[id];
        let _ = write!(
            out,
            "{{\"depth\":{},\"kind\":{},\"start\":{},\"dir\":{},\"weight\":{},\"sent_by\":{},",
            ray.depth,
            json_str(&ray.kind.to_string()),
            json_vec(ray.start.to_array()),
            json_vec(ray.dir.to_array()),
            json_num(ray.weight),
            json_str(&ray.sent_by)
        );
        match &ray.hit {
            Some(h) => {
                let _ = write!(
                    out,
                    "\"hit\":{{\"node\":{},\"distance\":{},\"shader\":{}}},",
                    json_str(&h.node),
                    json_num(h.distance),
                    json_str(h.shader)
                );
            }
            None => out.push_str("\"hit\":null,"),
        }
        let stop = ray.stop.map_or("null".to_string(), |s| json_str(&s.to_string()));
        let _ = write!(
            out,
            "\"stop\":{stop},\"color\":{},\"throughput\":{},\"terms\":[",
            json_vec(ray.color.to_array()),
            json_vec(throughput.to_array())
        );
        for (i, term) in ray.terms.iter().enumerate() {
            if i > 0 {
                out.push(',');
            }
            let _ =
                write!(out, "{{\"factor\":{},\"layer\":{},", json_vec(term.factor.to_array()), json_str(&term.layer));
            match term.what {
                TermKind::Ray(child) => {
                    out.push_str("\"ray\":");
                    self.write_json(out, child, throughput * term.factor);
                }
                TermKind::Light { kind, color } => {
                    let _ = write!(
                        out,
                        "\"light\":{},\"color\":{}",
                        json_str(&kind.to_string()),
                        json_vec(color.to_array())
                    );
                }
            }
            out.push('}');
        }
        out.push_str("]}");
    }
}

impl TraceContext<'_> {
    /// Reports to the ray tree being recorded, if there is one (see [`crate::instruments::ray_tree`]); costs one test of an
    /// `Option` otherwise. `report` runs only when a tree is recorded, so it may format names freely.
    #[inline(always)]
    pub fn record(&mut self, report: impl FnOnce(&mut RayTree)) {
        if let Some(tree) = self.recorder.as_deref_mut() {
            report(tree);
        }
    }

    /// A mark for [`RayTree::scale`]: how many terms the current shader has reported (0 when not recording).
    #[inline(always)]
    pub fn record_mark(&self) -> usize {
        self.recorder.as_deref().map_or(0, RayTree::mark)
    }
}

fn vec3(v: Vector) -> String {
    format!("({:.3}, {:.3}, {:.3})", v.x, v.y, v.z)
}

fn rgb(c: Color) -> String {
    format!("rgb({:.4}, {:.4}, {:.4})", c.r(), c.g(), c.b())
}

/// A factor: one number when it is grey, else its three channels.
fn factor(c: Color) -> String {
    if c.r() == c.g() && c.g() == c.b() { format!("{:.4}", c.r()) } else { rgb(c) }
}

fn json_num(v: f32) -> String {
    if v.is_finite() { format!("{v}") } else { "null".to_string() }
}

fn json_vec(v: [f32; 3]) -> String {
    format!("[{},{},{}]", json_num(v[0]), json_num(v[1]), json_num(v[2]))
}

/// A JSON string literal (quotes, backslashes and control characters escaped).
fn json_str(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A pixel named on the command line as `X,Y` (from the top left).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelPos {
    pub x: u32,
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

/// Renders pixel `pixel` of the picture `settings` describe, as the render would, recording its ray tree.
pub fn trace(scene: &Scene, settings: &RenderSettings, pixel: PixelPos) -> Result<PixelTrace> {
    render_pixel(scene, settings, pixel.x, pixel.y, true)
}

/// The report of pixel `pixel`, traced with its ray tree recorded (`trace`, from [`render_pixel`]): the
/// tree of its camera ray `sample`, as `--trace-pixel` prints it and the viewer shows a clicked pixel.
pub fn describe(name: &str, pixel: PixelPos, trace: &PixelTrace, sample: usize, format: TraceFormat) -> Result<String> {
    let empty = RayTree::new();
    let tree = trace.tree.as_deref().unwrap_or(&empty);
    let Some(&root) = tree.roots.get(sample) else {
        return Err(Error::parameter(
            "--trace-sample",
            sample,
            format!("the pixel has {} camera rays (numbered from 0)", tree.roots.len()),
        ));
    };
    Ok(match format {
        TraceFormat::Json => format!(
            "{{\"example\":{},\"pixel\":[{},{}],\"sample\":{sample},\"samples\":{},\"pixel_color\":{},\"tree\":{}}}\n",
            json_str(name),
            pixel.x,
            pixel.y,
            tree.roots.len(),
            json_vec(trace.color.to_array()),
            tree.to_json(sample)
        ),
        TraceFormat::Text => format!(
            "{name}: pixel ({}, {}) is {}, the mean of {} camera rays ({} rays and shadow rays in all)\n\
             camera ray {sample} (numbered from 0) returns {}; the shares of the light found on its tree add up \
             to {}:\n{}",
            pixel.x,
            pixel.y,
            rgb(trace.color),
            tree.roots.len(),
            trace.counters.total(),
            rgb(tree.rays[root].color),
            rgb(tree.explained(root, Color::WHITE)),
            tree.to_text(sample)
        ),
    })
}
