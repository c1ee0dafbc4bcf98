//! Textures (slides "Bitmap текстури", "Текстури", "Fresnel Texture"): anything that gives a colour for a
//! point of a surface. A texture can colour a surface (a diffuse texture) or drive any other property of a
//! shader: a layer's blend, a reflection's colour, ... (slide "Примери за текстури").

mod bitmap;
mod checker;
mod fresnel;
mod tex;

pub use bitmap::BitmapTexture;
pub use checker::CheckerTexture;
pub use fresnel::{Fresnel, FresnelMode};
pub use tex::Tex;

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use std::any::Any;
use std::sync::Arc;

/// The course's `Texture` interface.
pub trait Texture: Any + Send + Sync + TextureObject {
    /// The texture's colour where `ray` hit the surface described by `info`.
    fn get_tex_color(&self, ray: &Ray, info: &IntersectionInfo) -> Color;

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

    /// The texture as a shader stores it ([`Tex`]): for any texture but the workbook's own, the case that
    /// calls it through its trait object, [`Tex::Own`]. A new texture leaves it as it is.
    fn into_tex(self: Arc<Self>) -> Tex {
        Tex::Own(self.into_object())
    }
}

/// Any sized [`Texture`] as a trait object: what [`Texture::into_tex`] keeps of a texture that is not one of
/// the workbook's. Implemented for every texture; nothing to write.
pub trait TextureObject {
    /// The texture behind a trait object.
    fn into_object(self: Arc<Self>) -> Arc<dyn Texture>;
}

impl<T: Texture> TextureObject for T {
    fn into_object(self: Arc<Self>) -> Arc<dyn Texture> {
        self
    }
}
