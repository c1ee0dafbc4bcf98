//! Point lights and shadow rays (lectures 2-3). A point light of `intensity` I at distance d gives
//! I / d^2 (times its colour) to a surface facing it, if nothing stands in between.

use crate::color::Color;
use crate::geometry::IntersectionInfo;
use crate::math::Vector;
use crate::scene::TraceContext;

#[derive(Clone, Copy, Debug)]
pub struct PointLight {
    pub position: Vector,
    pub color: Color,
    /// The course's light "power": irradiance at distance 1 is `color * intensity`.
    pub intensity: f32,
}

impl PointLight {
    pub fn new(position: Vector, color: Color, intensity: f32) -> PointLight {
        PointLight { position, color, intensity }
    }
}

/// Calls `f(to_light, irradiance)` for every light that reaches the hit point, where `n` is the
/// face-forwarded shading normal, `to_light` the unit direction to the light and `irradiance` the light's
/// colour times its intensity over the squared distance (not yet multiplied by the cosine).
///
/// A light behind the surface (`dot(n, to_light) <= 0`) costs no shadow ray.
pub fn for_each_light(ctx: &mut TraceContext, info: &IntersectionInfo, n: Vector, mut f: impl FnMut(Vector, Color)) {
    let scene = ctx.scene;
    for light in &scene.lights {
        let to_light = light.position - info.ip;
        let dist2 = to_light.length_squared();
        let l = to_light / dist2.sqrt();
        if n.dot(l) <= 0.0 || info.geometric_normal.dot(l) * info.geometric_normal.dot(n) <= 0.0 {
            continue;
        }
        if ctx.visible(info, light.position) {
            f(l, light.color * (light.intensity / dist2));
        }
    }
}
