//! The renderer's one observation hook: how an instrument (the ray tree of `--trace-pixel`, the viewer's
//! clicked pixel) watches the slides' recursion without being part of it.
//!
//! An [`Observer`] put into `TraceContext::observer` is told what the recursion does, by the core alone:
//! `TraceContext::raytrace` reports every ray it traces, what the ray hits and what colour it brings back;
//! the light loop (`light::light_loop`) reports the light it finds at a surface point; and
//! `TraceContext::shade_layer` reports the layers of a `Layered` shader; and the techniques of the slides
//! say what they computed at the point being shaded (the Fresnel reflectance, a bitmap's texels, the photon
//! estimate: [`crate::lesson::topic`]), which an observer hears as a [`Recorder`]. A shader never reports anything:
//! a student's shader that traces its rays with `ctx.raytrace` and takes its light from the light loop is
//! observed exactly as the shipped ones are. With no observer (every render but one pixel's), each report is
//! one test of an `Option`.
//!
//! Not on the slides: the course's renderer has no such hook; it is what lets the workbook show the ray tree
//! of a pixel without a line of recording code in the lesson.

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use crate::lesson::topic::Recorder;

/// Why `TraceContext::raytrace` did not follow a ray further.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// It hit nothing: its colour is the environment's.
    Missed,
    /// It was deeper than the scene's `max_depth` (the slide's `MAX_RAY_DEPTH`): black.
    DepthLimit,
    /// Its weight was below the adaptive cut-off (`Scene::min_ray_weight`): black.
    WeightCutoff,
    /// It was deeper than the recursion safety cap: black.
    SafetyCap,
    /// Its shading point had used its budget of rays: its traced siblings' mean colour (see
    /// `branching.rs`).
    Shared,
    /// Its branch of the ray tree had traced [`crate::lesson::branching::RAYS_PER_BRANCH`] rays: black.
    BranchBudget,
}

impl std::fmt::Display for Stop {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str(match self {
            Stop::Missed => "missed: environment colour",
            Stop::DepthLimit => "depth limit: black",
            Stop::WeightCutoff => "weight below the adaptive cut-off: black",
            Stop::SafetyCap => "recursion safety cap: black",
            Stop::Shared => "over its shading point's budget of rays: the mean of its traced siblings",
            Stop::BranchBudget => "over its branch's budget of rays: black",
        })
    }
}

/// A term of the light loop's sum at the surface point being shaded, found without tracing a ray for it:
/// the ambient light, a lamp (with its shadow ray), the photon map's caustic light, or a shader's highlight.
/// Not a light of the scene: those are `PointLight`s (`light.rs`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightTerm {
    /// The scene's ambient light (irradiance).
    Ambient,
    /// Lamp `index`, asked by a shadow ray that starts at `from` towards the lamp (`dir`); `visible` says
    /// whether it got there. Its colour is the irradiance it brings, the cosine included.
    Lamp {
        /// The lamp's index in the scene's `lights`.
        index: usize,
        /// The surface point the shadow ray leaves from, in world space.
        from: Vector,
        /// The unit direction from `from` to the lamp.
        dir: Vector,
        /// True when nothing stands between the point and the lamp.
        visible: bool,
    },
    /// The caustic light of the photon map (irradiance).
    Photons,
    /// What the shader added of its own for lamp `index` (Phong's highlight): a colour seen as it is, not an
    /// irradiance the shader multiplies by its diffuse colour.
    Highlight {
        /// The lamp's index in the scene's `lights`.
        index: usize,
    },
}

impl LightTerm {
    /// Whether this light is an irradiance, which the shader multiplies by its colour (all but highlights).
    pub fn is_irradiance(&self) -> bool {
        !matches!(self, LightTerm::Highlight { .. })
    }
}

/// What an instrument is told about the recursion (see the module documentation). Every method has an
/// empty default, so an observer implements only what it needs; as a [`Recorder`] it hears what the
/// techniques computed.
pub trait Observer: Recorder {
    /// `raytrace` starts tracing `ray`.
    fn ray_begins(&mut self, _ray: &Ray) {}
    /// The ray being traced hit the node named `node` (its name in the scene, `Scene::node_name`), whose
    /// shader is called `shader`, as `info` describes; the shader is about to run.
    fn ray_hits(&mut self, _node: &str, _shader: &'static str, _info: &IntersectionInfo) {}
    /// The light loop found the term `light`, of colour `color`, at the point being shaded.
    fn light_found(&mut self, _light: LightTerm, _color: Color) {}
    /// A `Layered` shader starts shading a layer at the point being shaded: the layer's shader, called
    /// `shader`, blended by the texture called `blend_texture` if it has one, sees `ray` (whose weight the
    /// layer's may scale).
    fn layer_begins(&mut self, _shader: &'static str, _blend_texture: Option<&'static str>, _ray: &Ray) {}
    /// ... and is done with it: the layer's shader returned `color`, which counts `weight` times.
    fn layer_ends(&mut self, _color: Color, _weight: Color) {}
    /// The slide's Layered loop covers the layers it has shaded so far at this point with the next one, of
    /// opacity `blend`: what they gave counts `1 - blend` times.
    fn layers_covered(&mut self, _blend: Color) {}
    /// The ray being traced is finished: it brought back `color`, and was not followed for `stop`, if given.
    fn ray_ends(&mut self, _color: Color, _stop: Option<Stop>) {}
    /// A pass of a progressive caustic begins: the pixel is rendered once per pass, each with a photon map of
    /// its own (the render setting [`photon_passes`](crate::lesson::render::RenderSettings::photon_passes)),
    /// and the camera rays traced after this are pass `pass`'s (from 1) of `passes`. Not told for a render of
    /// one photon map.
    fn photon_pass_begins(&mut self, _pass: u32, _passes: u32) {}
}
