//! Bitmap textures as the course's program reads them (slide "Bitmap текстури"): the hit's u/v, divided
//! by the texture's tile size (the course's `scaling`), pick one texel of the image: no filtering between
//! texels.

use crate::lesson::bitmap::{Bitmap, Wrap};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::floor;
use crate::lesson::ray::Ray;
use crate::lesson::shader::ColorSource;
use crate::lesson::texture::{BitmapTexture, Texture};
use std::any::Any;

/// The texel of `bitmap` that the texture coordinates (u, v) fall in (one image per unit; u across, v down),
/// the coordinates outside [0, 1) wrapped as `wrap` says.
pub fn texel(bitmap: &Bitmap, u: f32, v: f32, wrap: (Wrap, Wrap)) -> Color {
    let (w, h) = (bitmap.width(), bitmap.height());
    let x = floor(u * w as f32) as i64;
    let y = floor(v * h as f32) as i64;
    bitmap.get_pixel(wrap.0.texel(x, w), wrap.1.texel(y, h))
}

/// A texture's colour at the hit: a bitmap texture's one texel, any other texture's own colour.
pub fn texture_color(texture: &dyn Texture, ray: &Ray, info: &IntersectionInfo) -> Color {
    match (texture as &dyn Any).downcast_ref::<BitmapTexture>() {
        Some(bitmap) => {
            let (u, v) = info.uv();
            texel(&bitmap.bitmap, u / bitmap.tile_size, v / bitmap.tile_size, bitmap.wrap)
        }
        None => texture.get_tex_color(ray, info),
    }
}

/// A shader's colour, constant or from a texture.
pub fn color_of(source: &ColorSource, ray: &Ray, info: &IntersectionInfo) -> Color {
    match source {
        ColorSource::Color(c) => *c,
        ColorSource::Texture(texture) => texture_color(&**texture, ray, info),
    }
}
