//! Reflection as the slides write it (slides "Reflection v0.1", "Reflection v0.2"): one ray in the mirror
//! direction `reflect(ray.dir, n)` with the face-forwarded normal, one level deeper, and what it brings back
//! times the mirror's colour. A glossy mirror ([`super::glossy`]) averages a cone of such rays.

use super::{bitmap_textures, glossy};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::{faceforward, reflect};
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::Reflection;

/// The mirror's colour at the hit.
pub fn shade(mirror: &Reflection, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
    let multiplier = bitmap_textures::color_of(&mirror.multiplier, ray, info);
    let n = faceforward(info.normal, ray.dir);
    if mirror.glossiness < 1.0 {
        return glossy::shade(mirror, ray, info, n, multiplier, ctx);
    }
    let new_ray = ray.spawn(info, reflect(ray.dir, n), multiplier.max_channel());
    ctx.raytrace(&new_ray) * multiplier
}
