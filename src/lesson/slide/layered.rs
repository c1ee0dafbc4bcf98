//! The Layered shader as the slide writes it (slide "Layered Shader"): the layers from the bottom up, each
//! blended over what the ones below made,
//!
//! ```text
//! res = 0;  for each layer, bottom to top:  res = res * (1 - blend) + layer_color * blend
//! ```
//!
//! where a layer's blend is its colour times its blend texture (the Fresnel texture of the glass). Every
//! layer is shaded, whatever its blend.
//!
//! Deviation from the slide: a blend is clamped to [0, 1], the range of an opacity (as in the workbook's
//! [`Layered`]).

use super::{bitmap_textures, shade as shade_layer};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::Layered;
use glam::Vec3A;

/// The layered surface's colour at the hit.
pub fn shade(layered: &Layered, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    let mut res = Color::BLACK;
    for layer in layered.layers() {
        let blend = match &layer.blend_tex {
            Some(texture) => layer.blend * bitmap_textures::texture_color(&**texture, ray, info),
            None => layer.blend,
        };
        let blend = Color(blend.0.clamp(Vec3A::ZERO, Vec3A::ONE));
        let layer_color = shade_layer(&*layer.shader, ray, info, ctx);
        res = res * (Color::WHITE - blend) + layer_color * blend;
    }
    res
}
