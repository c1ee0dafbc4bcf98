//! Textures (slides "Bitmap текстури", "Текстури", "Fresnel Texture"): anything that gives a colour for a
//! point of a surface. A texture can colour a surface (a diffuse texture) or drive any other property of a
//! shader: a layer's blend, a reflection's colour, ... (slide "Примери за текстури").

mod bitmap;
mod checker;
mod fresnel;

pub use bitmap::BitmapTexture;
pub use checker::CheckerTexture;
pub use fresnel::{Fresnel, FresnelMode};

use crate::lesson::beyond::Steps;
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::topic::Recorder;
use std::any::Any;

/// The course's `Texture` interface.
pub trait Texture: Any + Send + Sync {
    /// The texture's colour where `ray` hit the surface described by `info`.
    fn get_tex_color(&self, ray: &Ray, info: &IntersectionInfo) -> Color;

    /// The colour as a render that takes `steps` reads it ([`crate::lesson::beyond`]): by default
    /// [`Texture::get_tex_color`], whatever the steps; a bitmap texture reads one texel without the step
    /// `TexelFilter`. A texture whose reading depends on no step leaves it as it is.
    fn color_with(&self, ray: &Ray, info: &IntersectionInfo, _steps: Steps) -> Color {
        self.get_tex_color(ray, info)
    }

    /// [`Texture::color_with`], telling `recorder` what the slide's technique computed for it (the Fresnel
    /// reflectance, the texels a bitmap mixed; [`crate::lesson::topic`]): what the ray tree shows at a hit.
    /// By default `color_with`, which tells nothing.
    fn color_recorded(&self, ray: &Ray, info: &IntersectionInfo, steps: Steps, _recorder: &mut dyn Recorder) -> Color {
        self.color_with(ray, info, steps)
    }

    /// The coordinates this texture looks its colour up at, for a point of a surface whose texture
    /// coordinates are `uv` (the hit's `info.uv()`): after the texture's own scaling, before any wrapping.
    /// `--view uv` shows them, wrapped to [0, 1), one ramp per tile of the texture. The default, for a
    /// texture that reads the surface's u/v as they are (or does not read them at all): `uv` unchanged.
    fn lookup_uv(&self, uv: (f32, f32)) -> (f32, f32) {
        uv
    }

    /// Whether the colour depends on the surface's u/v at all: `true` by default; `false` for a texture of
    /// the angle alone (the Fresnel texture), which `--view uv` then does not name as the source of a
    /// layered surface's coordinates.
    fn reads_uv(&self) -> bool {
        true
    }

    /// Whether the colour depends on the ray's wavelength (a dispersive Fresnel texture), so that the
    /// renderer must trace wavelengths separately: **a texture that reads `ray.wavelength` must return
    /// `true`**, as a shader must ([`crate::lesson::shader::Shader::is_dispersive`], which asks the texture
    /// the shader names; a `Layered` shader asks its blend textures).
    fn is_dispersive(&self) -> bool {
        false
    }

    /// What the ray tree (`--trace-pixel`) calls this texture: its type's name.
    fn name(&self) -> &'static str {
        crate::lesson::type_label::<Self>()
    }
}
