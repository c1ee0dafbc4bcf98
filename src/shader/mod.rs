//! Shaders (lectures 2-6): what colour a surface has where a ray hits it. A shader may trace further rays
//! through the context (`ctx.raytrace`, the slides' global `raytrace()`), which is how reflection,
//! refraction and layering recurse.

mod lambert;
mod layered;
mod phong;
mod reflection;
mod refraction;

pub use lambert::Lambert;
pub use layered::Layered;
pub use phong::Phong;
pub use reflection::{GlossyCone, Reflection, SECONDARY_GLOSSY_SAMPLES};
pub use refraction::Refraction;

use crate::color::Color;
use crate::geometry::IntersectionInfo;
use crate::photon_map::PhotonScatter;
use crate::ray::Ray;
use crate::rng::Rng;
use crate::scene::TraceContext;
use crate::texture::Texture;
use std::sync::Arc;

/// The course's `Shader` interface.
pub trait Shader: Send + Sync {
    /// The colour seen along `ray`, which hit a surface as described by `info`.
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color;

    /// Whether the result depends on the ray's wavelength (a dispersive refraction, or a layer holding one).
    /// The renderer traces wavelengths separately only for scenes where some shader says so.
    fn is_dispersive(&self) -> bool {
        false
    }

    /// Photon mapping (slide "Photon Mapping"): what a photon travelling along `ray` does where it hits this
    /// surface. The default is a diffuse surface, where the photon lands; mirrors, glass and layers override
    /// it (see [`crate::photon_map`]).
    fn scatter_photon(&self, _ray: &Ray, _info: &IntersectionInfo, _rng: &mut Rng) -> PhotonScatter {
        PhotonScatter::Land { scale: 1.0 }
    }

    /// Whether photons can leave this surface by reflection or refraction, which makes its object a caustic
    /// caster that the lights aim photons at.
    fn casts_caustics(&self) -> bool {
        false
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
