//! `raytrace` as the slides write it (slides "Reflection v0.1" and "Reflection v0.2"): black past
//! `MAX_RAY_DEPTH`, the environment where the ray hits nothing, the hit node's shader otherwise; and the
//! diffuse shaders' light loop with its shadow rays and the photon map's caustic light.
//!
//! Deviation from the slides: past [`RECURSION_SAFETY_CAP`] a ray returns black whatever `MAX_RAY_DEPTH`
//! says, so that Reflection v0.1's facing mirrors end instead of overflowing the stack.

use super::model_transform::{SlideNode, closest_hit, intersect, slide_nodes};
use super::{environment, shade};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::light::Lighting;
use crate::lesson::math::Vector;
use crate::lesson::ray::{Ray, spawn_point};
use crate::lesson::scene::{RECURSION_SAFETY_CAP, TraceContext};
use std::borrow::Cow;

/// The slides' `raytrace(ray)`: the colour seen along the ray.
pub fn raytrace(ctx: &mut TraceContext, ray: &Ray) -> Color {
    if ray.depth > ctx.scene.max_depth {
        return Color::BLACK;
    }
    if ray.depth > RECURSION_SAFETY_CAP {
        ctx.counters.capped_rays += 1;
        return Color::BLACK;
    }
    ctx.counters.rays_by_depth[(ray.depth as usize).min(15)] += 1;
    let scene = ctx.scene;
    match closest_hit(&nodes(ctx), ray) {
        Some((info, node)) => shade(&*node.shader, ray, &info, ctx),
        None => scene.environment.as_ref().map_or(Color::BLACK, |env| environment::get(&**env, ray.dir)),
    }
}

/// Whether the point `to` can be seen from the hit point `from`: a shadow ray, tested against every node.
pub fn visible(ctx: &mut TraceContext, from: &IntersectionInfo, to: Vector) -> bool {
    ctx.counters.shadow_rays += 1;
    let start = spawn_point(from.ip, from.geometric_normal, from.error, to - from.ip);
    let to_light = to - start;
    let distance = to_light.length();
    let ray = Ray::new(start, to_light / distance);
    !nodes(ctx).iter().any(|node| intersect(node, &ray, distance).is_some())
}

/// The scene's nodes as the slides' loop meets them: those the render prepared, or, in a context that is
/// not the slides' render's, the scene's own looked at now.
fn nodes<'a>(ctx: &TraceContext<'a>) -> Cow<'a, [SlideNode<'a>]> {
    match ctx.slides {
        Some(slides) => Cow::Borrowed(&slides.nodes),
        None => Cow::Owned(slide_nodes(&ctx.scene.nodes)),
    }
}

/// The light loop of the diffuse shaders (see [`crate::lesson::light::light_loop`], whose contract it
/// keeps): ambient light, each lamp that a shadow ray reaches times the cosine of its angle, and the caustic
/// light of the slides' photon map.
pub fn light_loop(
    ctx: &mut TraceContext,
    info: &IntersectionInfo,
    n: Vector,
    mut each_lamp: impl FnMut(Vector, Color) -> Color,
) -> Lighting {
    let scene = ctx.scene;
    let mut lighting = Lighting { irradiance: scene.ambient, highlights: Color::BLACK };
    for light in &scene.lights {
        let to_light = light.position - info.ip;
        let dist2 = to_light.length_squared();
        let l = to_light / dist2.sqrt();
        if n.dot(l) > 0.0 && visible(ctx, info, light.position) {
            let lamp = light.color * (light.intensity / dist2);
            lighting.irradiance += lamp * n.dot(l);
            lighting.highlights += each_lamp(l, lamp);
        }
    }
    if let Some(map) = ctx.slides.and_then(|slides| slides.photon_map) {
        lighting.irradiance += map.irradiance(info.ip, n);
    }
    lighting
}
