//! Glossy reflections as the slides write them (slides "Грапави (glossy) отражения", "Симулиране на грапави
//! отражения"): for each of `num_samples` samples, a random point of the unit disc, scaled by
//! `tan((1 - glossiness) * pi/2)`, tilts the normal in its tangent plane (the
//! [`GlossyCone`]); the ray reflected about the tilted normal is traced, unless it goes under the
//! surface; the rays traced are averaged. Below the first bounce the course's program traces two rays
//! ([`SECONDARY_GLOSSY_SAMPLES`]).
//!
//! Deviation from the slides: should every sample of a point go under the surface, the mirror ray is traced
//! instead, so that the point is not black.

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::{Vector, reflect};
use crate::lesson::ray::Ray;
use crate::lesson::sampling::random_unit_disc_point;
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::{GlossyCone, Reflection, SECONDARY_GLOSSY_SAMPLES};

/// The glossy mirror's colour at the hit, whose face-forwarded normal is `n`, its colour `multiplier`.
pub fn shade(
    mirror: &Reflection,
    ray: &Ray,
    info: &IntersectionInfo,
    n: Vector,
    multiplier: Color,
    ctx: &mut TraceContext,
) -> Color {
    let num_samples =
        if ray.depth == 0 { mirror.num_samples } else { mirror.num_samples.min(SECONDARY_GLOSSY_SAMPLES) };
    let cone = GlossyCone::new(ray.dir, n, mirror.glossiness);
    let mut sum = Color::BLACK;
    let mut traced = 0;
    for _ in 0..num_samples {
        if let Some(dir) = cone.direction(random_unit_disc_point(&mut ctx.rng)) {
            sum += ctx.raytrace(&ray.spawn(info, dir, multiplier.max_channel()));
            traced += 1;
        }
    }
    if traced == 0 {
        return ctx.raytrace(&ray.spawn(info, reflect(ray.dir, n), multiplier.max_channel())) * multiplier;
    }
    sum * multiplier / traced as f32
}
