//! [`Tex`]: a texture as a shader stores it. The course reads a texture through its interface (a virtual
//! call in its C++, [`Texture`] here); the workbook keeps the textures it ships as the cases of an enum,
//! and any other texture (a student's own) as one more case, [`Tex::Own`], read through its trait object:
//! a new texture works the moment it compiles.
//!
//! A texture becomes its case by its own [`Texture::into_tex`], which the workbook's textures override and
//! every other texture inherits: nothing asks a value's type. This is the one place that lists the cases,
//! and the one place where the step [`Step::TexelFilter`](crate::lesson::beyond::Step::TexelFilter) is
//! applied: without it a bitmap is read one texel at a time, as on the slide, whatever its filter.

use super::{BitmapTexture, CheckerTexture, Fresnel, Texture};
use crate::lesson::beyond::Steps;
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::topic::Recorder;
use std::sync::Arc;

/// A texture: one of the workbook's, or any other through its trait object.
#[derive(Clone)]
pub enum Tex {
    /// An image.
    Bitmap(BitmapTexture),
    /// A checkerboard.
    Checker(CheckerTexture),
    /// The Fresnel reflectance.
    Fresnel(Fresnel),
    /// Any other texture, through its trait object.
    Own(Arc<dyn Texture>),
}

impl Tex {
    /// The colour at the hit `info` as a render that takes `steps` reads it, telling `recorder`, if there
    /// is one, what the slide's technique computed (the texels a bitmap mixed, the Fresnel reflectance:
    /// [`crate::lesson::topic`]).
    #[inline(always)]
    pub(crate) fn color(
        &self,
        ray: &Ray,
        info: &IntersectionInfo,
        steps: Steps,
        recorder: Option<&mut dyn Recorder>,
    ) -> Color {
        match self {
            Tex::Bitmap(bitmap) => bitmap.read(info, bitmap.filter.under(steps), recorder),
            Tex::Checker(checker) => checker.get_tex_color(ray, info),
            Tex::Fresnel(fresnel) => fresnel.color(ray, info, recorder),
            Tex::Own(texture) => texture.get_tex_color(ray, info),
        }
    }
}

impl Texture for Tex {
    #[inline(always)]
    fn get_tex_color(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        match self {
            Tex::Bitmap(bitmap) => bitmap.get_tex_color(ray, info),
            Tex::Checker(checker) => checker.get_tex_color(ray, info),
            Tex::Fresnel(fresnel) => fresnel.get_tex_color(ray, info),
            Tex::Own(texture) => texture.get_tex_color(ray, info),
        }
    }

    fn lookup_uv(&self, uv: (f32, f32)) -> (f32, f32) {
        match self {
            Tex::Bitmap(bitmap) => bitmap.lookup_uv(uv),
            Tex::Checker(checker) => checker.lookup_uv(uv),
            Tex::Fresnel(fresnel) => fresnel.lookup_uv(uv),
            Tex::Own(texture) => texture.lookup_uv(uv),
        }
    }

    fn reads_uv(&self) -> bool {
        match self {
            Tex::Bitmap(bitmap) => bitmap.reads_uv(),
            Tex::Checker(checker) => checker.reads_uv(),
            Tex::Fresnel(fresnel) => fresnel.reads_uv(),
            Tex::Own(texture) => texture.reads_uv(),
        }
    }

    fn is_dispersive(&self) -> bool {
        match self {
            Tex::Bitmap(bitmap) => bitmap.is_dispersive(),
            Tex::Checker(checker) => checker.is_dispersive(),
            Tex::Fresnel(fresnel) => fresnel.is_dispersive(),
            Tex::Own(texture) => texture.is_dispersive(),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Tex::Bitmap(bitmap) => bitmap.name(),
            Tex::Checker(checker) => checker.name(),
            Tex::Fresnel(fresnel) => fresnel.name(),
            Tex::Own(texture) => texture.name(),
        }
    }

    fn into_tex(self: Arc<Self>) -> Tex {
        Arc::unwrap_or_clone(self)
    }
}
