//! Shaders (lectures 2-6): what colour a surface has where a ray hits it. A shader may trace further rays
//! through the context (`ctx.raytrace`, the slides' global `raytrace()`), which is how reflection,
//! refraction and layering recurse, and takes the light of the lamps from the light loop
//! ([`light_loop`](crate::lesson::light::light_loop)).

mod glass;
mod lambert;
mod layered;
mod material;
mod phong;
mod reflection;
mod refraction;

pub use glass::fresnel_glass;
pub use lambert::Lambert;
pub use layered::{Layer, Layered, MAX_LAYERS, MAX_SHADES_PER_HIT, shades_per_hit};
pub use material::{IntoShader, Material};
pub use phong::Phong;
pub use reflection::{GlossyCone, Reflection, SECONDARY_GLOSSY_SAMPLES};
pub use refraction::Refraction;

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::{Tex, Texture};
use std::any::Any;
use std::sync::Arc;

/// What a photon does where it hits a surface (see [`CausticCaster::scatter_photon`] and [`crate::lesson::photon_map`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhotonScatter {
    /// The surface is diffuse and the photon ends here. It is stored, its power multiplied by `scale`, if it
    /// was reflected or refracted on its way. `scale` is 1 except where a `Layered` shader chose this layer
    /// at random: then it is one over the probability of that choice.
    Land {
        /// What the photon's power is multiplied by when it is stored: 1, or one over the probability of
        /// the layer chosen.
        scale: f32,
    },
    /// The photon goes on in the unit direction `dir`, its power multiplied by `filter`.
    Continue {
        /// The unit direction the photon goes on in (world space).
        dir: Vector,
        /// What its power is multiplied by, per channel (the mirror's colour, the glass's multiplier).
        filter: Color,
    },
    /// The photon is absorbed.
    Absorb,
}

/// The course's `Shader` interface.
///
/// A new shader implements `shade` alone, and works: with its own rays traced through `ctx.raytrace` and
/// its light taken from [`light_loop`](crate::lesson::light::light_loop) (or
/// [`diffuse_light`](crate::lesson::light::diffuse_light)), it gets the lamps, shadows, the photon map's
/// caustics and the ray tree of `--trace-pixel` without a further line. A ray it traces is made by
/// [`Ray::spawn`], whose `attenuation` is the factor the shader multiplies that ray's colour by, in full for
/// each ray of an average of N, not 1/N of it (the core bounds an average's branching:
/// [`crate::lesson::branching`]). What else a shader may override:
///
/// - a mirror or glass, whose surface photons leave (slide "Photon Mapping"), implements [`CausticCaster`]
///   (where a photon goes next, as `shade` sends its rays) and returns itself from
///   [`Shader::caustic_caster`], so that the lights aim photons at it. Every other surface keeps the
///   default, `None`: photons land on it, and a diffuse shader finds them in its light loop;
/// - **a shader that reads `ray.wavelength` must return `true` from [`Shader::is_dispersive`]** (a dispersive
///   refraction, or a layer holding one): only then does the renderer trace wavelengths for its scene.
///   Otherwise every ray's wavelength is `None` and the shader renders as in white light; the end-of-run
///   report names a shader it catches at this ([`crate::lesson::diagnostics`]). A shader whose texture
///   ([`Shader::texture`]) depends on the wavelength is dispersive by default;
/// - a shader whose colour comes from a texture returns it from [`Shader::texture`], so that `--view uv`
///   shows the coordinates that texture looks up; the default, `None`, shows the surface's own u/v;
/// - [`Shader::name`] names it in the ray tree, its type's name by default.
pub trait Shader: Any + Send + Sync + ShaderObject {
    /// The colour seen along `ray`, which hit a surface as described by `info`.
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color;

    /// This shader as a caustic caster, if photons leave its surface by reflection or refraction (a mirror,
    /// glass, or a `Layered` shader holding one); `None`, the default, for a surface that neither reflects
    /// nor refracts, on which photons land.
    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        None
    }

    /// Whether the result depends on the ray's wavelength, `ray.wavelength` (a dispersive refraction, a layer
    /// holding one). The renderer traces wavelengths only for scenes where some shader says so, and splits a
    /// hero-wavelength path only where it hits one: **a shader that reads `ray.wavelength` must return
    /// `true`**, or it is traced in white light (`ray.wavelength` is `None`) and shows nothing of the
    /// spectrum. The renderer cannot see the read: after a render it tries each shader that says `false` at
    /// one point of its node, in white light and at two wavelengths, and the end-of-run report names one that
    /// gives them different colours ([`crate::lesson::diagnostics::undeclared_dispersion`]). By default,
    /// whether the texture this shader names ([`Shader::texture`]) depends on the wavelength
    /// ([`Texture::is_dispersive`]).
    fn is_dispersive(&self) -> bool {
        self.texture().is_some_and(|t| t.is_dispersive())
    }

    /// The texture this shader reads its colour from at the hit's u/v, if any. `--view uv` shows the
    /// coordinates that texture looks up ([`Texture::lookup_uv`]); for `None`, the default (a shader that
    /// reads no texture), it shows the surface's own u/v and says so.
    fn texture(&self) -> Option<&dyn Texture> {
        None
    }

    /// What the ray tree (`--trace-pixel`) calls this shader: its type's name.
    fn name(&self) -> &'static str {
        crate::lesson::type_label::<Self>()
    }

    /// The shader as a node or a layer stores it ([`Material`]): for any shader but the workbook's own, the
    /// case that calls it through its trait object, [`Material::Own`]. A new shader leaves it as it is.
    fn into_material(self: Arc<Self>) -> Material {
        Material::Own(self.into_object())
    }
}

/// Any sized [`Shader`] as a trait object: what [`Shader::into_material`] keeps of a shader that is not one
/// of the workbook's. Implemented for every shader; nothing to write.
pub trait ShaderObject {
    /// The shader behind a trait object.
    fn into_object(self: Arc<Self>) -> Arc<dyn Shader>;
}

impl<S: Shader> ShaderObject for S {
    fn into_object(self: Arc<Self>) -> Arc<dyn Shader> {
        self
    }
}

/// A surface that photons leave by reflection or refraction (slide "Photon Mapping"): a mirror, glass, or a
/// `Layered` shader holding one. Its shader returns it from [`Shader::caustic_caster`].
pub trait CausticCaster {
    /// What a photon travelling along `ray` does where it hits this surface, as `shade` would send a ray:
    /// where it goes next ([`PhotonScatter::Continue`]), or that it is absorbed (total internal reflection
    /// in a refraction without a reflection layer).
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, rng: &mut Rng) -> PhotonScatter;
}

/// Whether `shader` makes its object a caustic caster, which the lights aim photons at (whether a scene has
/// one that a light shines on is [`crate::lesson::scene::Scene::can_have_caustics`]).
pub fn is_caustic_caster(shader: &dyn Shader) -> bool {
    shader.caustic_caster().is_some()
}

/// What a photon does where it hits a surface with `shader`: what its caustic caster says, or, on a surface
/// that neither reflects nor refracts, it lands.
pub fn scatter_photon(shader: &dyn Shader, ray: &Ray, info: &IntersectionInfo, rng: &mut Rng) -> PhotonScatter {
    match shader.caustic_caster() {
        Some(caster) => caster.scatter_photon(ray, info, rng),
        None => PhotonScatter::Land { scale: 1.0 },
    }
}

/// A constant colour or a texture: how the course's shaders take their diffuse colour.
#[derive(Clone)]
pub enum ColorSource {
    /// The same colour everywhere (linear RGB).
    Color(Color),
    /// A texture's colour at the hit's u/v.
    Texture(Tex),
}

impl ColorSource {
    /// The colour at the hit `info` (for a texture: [`Texture::get_tex_color`]).
    pub fn get(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        match self {
            ColorSource::Color(c) => *c,
            ColorSource::Texture(t) => t.get_tex_color(ray, info),
        }
    }

    /// The texture, if the colour comes from one (what a shader of this colour returns from
    /// [`Shader::texture`]).
    pub fn texture(&self) -> Option<&dyn Texture> {
        match self {
            ColorSource::Color(_) => None,
            ColorSource::Texture(t) => Some(t),
        }
    }
}

impl From<Color> for ColorSource {
    fn from(c: Color) -> ColorSource {
        ColorSource::Color(c)
    }
}

impl<T: Texture> From<T> for ColorSource {
    fn from(t: T) -> ColorSource {
        ColorSource::Texture(Arc::new(t).into_tex())
    }
}
