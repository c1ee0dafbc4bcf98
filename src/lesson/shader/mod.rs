//! Shaders (lectures 2-6): what colour a surface has where a ray hits it. A shader may trace further rays
//! through the context (`ctx.raytrace`, the slides' global `raytrace()`), which is how reflection,
//! refraction and layering recurse.

mod glass;
mod lambert;
mod layered;
mod phong;
mod reflection;
mod refraction;

pub use glass::fresnel_glass;
pub use lambert::Lambert;
pub use layered::Layered;
pub use phong::Phong;
pub use reflection::{GlossyCone, Reflection, SECONDARY_GLOSSY_SAMPLES};
pub use refraction::Refraction;

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;
use std::sync::Arc;

/// What a photon does where it hits a surface (see [`Shader::scatter_photon`] and [`crate::lesson::photon_map`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhotonScatter {
    /// The surface is diffuse and the photon ends here. It is stored, its power multiplied by `scale`, if it
    /// was reflected or refracted on its way. `scale` is 1 except where a `Layered` shader chose this layer
    /// at random: then it is one over the probability of that choice.
    Land { scale: f32 },
    /// The photon goes on in the unit direction `dir`, its power multiplied by `filter`.
    Continue { dir: Vector, filter: Color },
    /// The photon is absorbed.
    Absorb,
}

/// The course's `Shader` interface.
///
/// A new shader implements `shade` and says how it takes part in photon mapping (the last two methods):
///
/// - a diffuse surface (it uses [`light_loop`](crate::lesson::light::light_loop) or
///   [`diffuse_light`](crate::lesson::light::diffuse_light), which bring it the lamps' light and the caustic light
///   of the photon map alike): `scatter_photon` returns [`PhotonScatter::Land`] with `scale: 1.0`, and
///   `casts_caustics` returns `false`;
/// - a mirror or glass: `scatter_photon` returns where the photon goes next ([`PhotonScatter::Continue`]),
///   as `shade` sends its rays, and `casts_caustics` returns `true`, so that the lights aim photons at it;
/// - a surface that swallows light (a black body, a shader that only shows a debug colour):
///   [`PhotonScatter::Absorb`] and `false`.
pub trait Shader: Send + Sync {
    /// The colour seen along `ray`, which hit a surface as described by `info`.
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color;

    /// Photon mapping (slide "Photon Mapping"): what a photon travelling along `ray` does where it hits this
    /// surface (see [`crate::lesson::photon_map`]).
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, rng: &mut Rng) -> PhotonScatter;

    /// Whether photons can leave this surface by reflection or refraction (whether `scatter_photon` can
    /// return [`PhotonScatter::Continue`]): that makes its object a caustic caster, which the lights aim
    /// photons at.
    fn casts_caustics(&self) -> bool;

    /// Whether the result depends on the ray's wavelength (a dispersive refraction, or a layer holding one).
    /// The renderer traces wavelengths separately only for scenes where some shader says so.
    fn is_dispersive(&self) -> bool {
        false
    }

    /// What the ray tree (`--trace-pixel`) calls this shader: its type's name.
    fn name(&self) -> &'static str {
        crate::instruments::ray_tree::type_label::<Self>()
    }
}

/// Anything that can be a node's or a layer's shader: a shader, or a shader shared with other nodes
/// (`Arc<Reflection>`, `Arc<dyn Shader>`).
pub trait IntoShader {
    fn into_shader(self) -> Arc<dyn Shader>;
}

impl<S: Shader + 'static> IntoShader for S {
    fn into_shader(self) -> Arc<dyn Shader> {
        Arc::new(self)
    }
}

impl<S: Shader + 'static> IntoShader for Arc<S> {
    fn into_shader(self) -> Arc<dyn Shader> {
        self
    }
}

impl IntoShader for Arc<dyn Shader> {
    fn into_shader(self) -> Arc<dyn Shader> {
        self
    }
}

/// A constant colour or a texture: how the course's shaders take their diffuse colour.
#[derive(Clone)]
pub enum ColorSource {
    Color(Color),
    Texture(Arc<dyn Texture>),
}

impl ColorSource {
    pub fn get(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        match self {
            ColorSource::Color(c) => *c,
            ColorSource::Texture(t) => t.get_tex_color(ray, info),
        }
    }
}

impl From<Color> for ColorSource {
    fn from(c: Color) -> ColorSource {
        ColorSource::Color(c)
    }
}

impl<T: Texture + 'static> From<T> for ColorSource {
    fn from(t: T) -> ColorSource {
        ColorSource::Texture(Arc::new(t))
    }
}
