//! `Reflection` (slides "Reflection v0.1", "Reflection v0.2", "Грапави (glossy) отражения", "Симулиране на
//! грапави отражения"): a mirror, perfect or glossy.
//!
//! A perfect mirror (`glossiness` 1) traces one ray in the direction `reflect(ray.dir, n)` with the
//! face-forwarded normal, one level deeper, and multiplies what it brings back by the mirror's colour
//! (`multiplier`; the slide's v0.1 uses 0.8, "20% loss of energy").
//!
//! A glossy mirror (`glossiness` below 1) reflects a cone of rays. As on the slide, for each of
//! `num_samples` samples: take two vectors perpendicular to the normal (step 1, [`OrthonormalBasis`]),
//! a point of the unit disc (step 2, [`DiscSamples`]), scale it by `tan((1 - glossiness) * pi/2)` (step 3:
//! 0 at glossiness 1, unbounded as glossiness goes to 0), add it to the normal along the two vectors and
//! normalise (steps 4-5), reflect about that perturbed normal (step 6), drop the ray if it goes under the
//! surface, and average the rest (step 7). Below the first bounce a glossy mirror traces only
//! [`SECONDARY_GLOSSY_SAMPLES`] rays, as the course does: a reflection seen in a reflection is small and
//! already blurred, and the ray count would otherwise multiply at every level.
//!
//! Deviations from the slides:
//! - the start point is offset by the hit point's error bound ([`Ray::spawn`]) instead of `1e-6 * n` (ledger:
//!   `robust-offsets`);
//! - a sample under the surface is dropped and the average is taken over the samples kept (the slide only
//!   says it must be caught). Should every sample of a shading point be dropped (possible at grazing angles
//!   with a low glossiness), the exact mirror ray is traced instead, so the surface never turns black
//!   (ledger: `glossy-kept-samples`);
//! - a step beyond the slide ([`Step::DiscSamples`]): the disc points may be stratified over the whole
//!   pixel ([`DiscSampler::Joint`], the default: the `num_samples` points of each camera ray are one block of
//!   a set shared by all the pixel's camera rays) or per shading point ([`DiscSampler::Stratified`]) rather
//!   than independent, which gives the same picture with markedly less noise (see
//!   `benches/error_vs_time.rs` and docs/measurements.md); without the step every mirror draws random points;
//! - below [`crate::lesson::branching::SPLIT_DEPTH`] the second ray of a shading point is not traced but
//!   given the first one's colour, as every shader's rays are (the core's branching bound,
//!   [`crate::lesson::branching`]): two white glossy mirrors facing each other would otherwise trace 2^depth
//!   rays for each camera ray (2^60 for `maxTraceDepth 60`, a render that never ends), since a white
//!   mirror's rays keep their full weight and are never pruned. The split depth is the course's default
//!   `maxTraceDepth`, so its scenes trace exactly the course's rays (ledger: `branching-bound`);
//! - each spawned ray's `weight` is scaled by the full multiplier, not by its 1/N share of the average, as
//!   every averaging shader does for adaptive depth control (`Scene::min_ray_weight`): pruning the samples
//!   of an average by their share would darken the picture more the larger `num_samples` is, so that more
//!   samples would converge to a different picture (the step `adaptive-depth`).

use super::{CausticCaster, ColorSource, Material, PhotonScatter, Shader};
use crate::lesson::beyond::Step;
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::helper_ranges;
use crate::lesson::math::{OrthonormalBasis, Vector, faceforward, reflect};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::sampling::{DiscSampler, DiscSamples, random_unit_disc_point};
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;
use std::f32::consts::FRAC_PI_2;
use std::sync::Arc;

impl Shader for Reflection {
    /// The mirror ray, or the glossy cone's average, times the mirror's colour at the hit.
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let multiplier = self.multiplier.at(ray, info, ctx);
        let n = faceforward(info.normal, ray.dir);
        if self.glossiness >= 1.0 {
            return self.trace_mirror(ray, info, n, ctx, multiplier);
        }
        self.shade_glossy(multiplier, ray, info, n, ctx)
    }

    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        Some(self)
    }

    /// The texture of a textured mirror's colour.
    fn texture(&self) -> Option<&dyn Texture> {
        self.multiplier.texture()
    }

    fn into_material(self: Arc<Self>) -> Material {
        Material::Reflection(Arc::unwrap_or_clone(self))
    }
}

// The slides' mirror and glossy mirror first; the constructors after them.
impl Reflection {
    /// The perfect mirror ray (the slide's Reflection v0.2): one ray in the mirror direction, one level
    /// deeper, and what it brings back times the mirror's colour `m`.
    #[inline(always)]
    fn trace_mirror(&self, ray: &Ray, info: &IntersectionInfo, n: Vector, ctx: &mut TraceContext, m: Color) -> Color {
        let new_ray = ray.spawn(info, reflect(ray.dir, n), m.max_channel());
        ctx.raytrace(&new_ray) * m
    }

    /// The glossy mirror's colour at the hit when its colour there is `multiplier`: the average of its cone
    /// of rays (the slide's steps 1-7).
    #[inline(never)]
    fn shade_glossy(
        &self,
        multiplier: Color,
        ray: &Ray,
        info: &IntersectionInfo,
        n: Vector,
        ctx: &mut TraceContext,
    ) -> Color {
        let steps = ctx.scene.steps;
        let num_samples =
            if ray.depth == 0 { self.num_samples } else { self.num_samples.min(SECONDARY_GLOSSY_SAMPLES) };
        let cone = GlossyCone::from_scene(ray.dir, n, self.glossiness);
        // The slide's random points, or, with the step, the mirror's own sampler; the first bounce of a
        // camera ray may share its pixel's set of points (the joint sampler), deeper bounces take their own.
        ctx.counters.steps_reached[Step::DiscSamples as usize] += (self.sampler != DiscSampler::Random) as u64;
        let sampler = if steps.has(Step::DiscSamples) { self.sampler } else { DiscSampler::Random };
        let disc = match ctx.pixel_sample {
            Some(sample) if ray.depth == 0 => {
                DiscSamples::for_pixel_sample(sampler, &sample, num_samples, &mut ctx.rng)
            }
            _ => DiscSamples::new(sampler, &mut ctx.rng),
        };
        let attenuation = multiplier.max_channel();
        let mut sum = Color::BLACK;
        let mut kept = 0u32;
        for i in 0..num_samples {
            if let Some(dir) = cone.direction(disc.point(i, &mut ctx.rng)) {
                sum += ctx.raytrace(&ray.spawn(info, dir, attenuation));
                kept += 1;
            }
        }
        if kept == 0 {
            return self.trace_mirror(ray, info, n, ctx, multiplier);
        }
        sum * multiplier / kept as f32
    }
}

/// Rays a glossy mirror traces for a ray that is itself a reflection or refraction (depth > 0); the course
/// uses 2. The core's bound on every shader's branching ([`crate::lesson::branching`]) allows the same.
pub const SECONDARY_GLOSSY_SAMPLES: u32 = crate::lesson::branching::SECONDARY_SPLIT;

/// The most rays a glossy mirror averages per shading point: twenty times the slide's 200, and low enough
/// that a mistyped count is refused at once instead of rendering for days.
pub const MAX_GLOSSY_SAMPLES: u32 = 4096;

/// A mirror, perfect or glossy (slides "Reflection v0.2" and "Грапави (glossy) отражения").
#[derive(Clone)]
pub struct Reflection {
    /// The colour of the mirror: what fraction of each channel it reflects. May come from a texture.
    pub multiplier: ColorSource,
    /// 1 is a perfect mirror; lower values blur the reflection more, 0 is a matte surface.
    pub glossiness: f32,
    /// Rays traced per shading point of a camera ray when `glossiness` is below 1.
    pub num_samples: u32,
    /// How the points of the unit disc are chosen.
    pub sampler: DiscSampler,
}

impl Reflection {
    /// A perfect grey mirror reflecting the fraction `multiplier` of the light.
    pub fn new(multiplier: f32) -> Reflection {
        Reflection::mirror(Color::gray(multiplier))
    }

    /// A perfect mirror of colour `multiplier` (a colour or a texture).
    pub fn mirror(multiplier: impl Into<ColorSource>) -> Reflection {
        Reflection { multiplier: multiplier.into(), glossiness: 1.0, num_samples: 1, sampler: DiscSampler::default() }
    }

    /// A glossy mirror of colour `multiplier`, averaging `num_samples` rays per shading point. Fails on a
    /// glossiness outside (0, 1] or a sample count of zero. Glossiness 0, the slide's "fully matte" end,
    /// is refused: its cone, `tan(pi/2)`, is unbounded, so nearly every sample would go under the surface
    /// and the surface would show the mirror ray instead.
    pub fn glossy(multiplier: impl Into<ColorSource>, glossiness: f32, num_samples: u32) -> Result<Reflection> {
        if !(glossiness > 0.0 && glossiness <= 1.0) {
            return Err(Error::parameter(
                "glossiness",
                glossiness,
                "must be above 0 and at most 1 (at 0 the cone, tan(pi/2), is unbounded)",
            ));
        }
        if !(1..=MAX_GLOSSY_SAMPLES).contains(&num_samples) {
            return Err(Error::parameter(
                "number of glossy samples",
                num_samples,
                format!("must be 1 to {MAX_GLOSSY_SAMPLES}"),
            ));
        }
        Ok(Reflection { multiplier: multiplier.into(), glossiness, num_samples, sampler: DiscSampler::default() })
    }

    /// The same mirror with another disc sampler.
    pub fn with_sampler(mut self, sampler: DiscSampler) -> Reflection {
        self.sampler = sampler;
        self
    }
}

impl CausticCaster for Reflection {
    /// A photon is reflected like a ray, its power multiplied by the mirror's colour: by a glossy mirror in
    /// one direction of the cone, drawn at random (the mirror direction should the draw go under the
    /// surface), so that glossy mirrors cast blurred caustics.
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, rng: &mut Rng) -> PhotonScatter {
        let n = faceforward(info.normal, ray.dir);
        let mirror = reflect(ray.dir, n);
        let dir = if self.glossiness >= 1.0 {
            mirror
        } else {
            GlossyCone::from_scene(ray.dir, n, self.glossiness).direction(random_unit_disc_point(rng)).unwrap_or(mirror)
        };
        PhotonScatter::Continue { dir, filter: self.multiplier.get(ray, info) }
    }
}

/// The cone of glossy reflections of one incoming direction at one surface point (steps 1, 3-6 of the
/// slide's algorithm): turns a point of the unit disc into a reflected direction.
#[derive(Clone, Copy, Debug)]
pub struct GlossyCone {
    incoming: Vector,
    basis: OrthonormalBasis,
    /// `tan((1 - glossiness) * pi/2)`: how far the normal may tilt, as a tangent.
    scaling: f32,
}

impl GlossyCone {
    /// The cone for the unit incoming direction `incoming` at a surface whose unit normal `n` faces it. A
    /// `glossiness` outside (0, 1] (a value a shader reads from a texture, unclamped) is named in the
    /// end-of-run report against the node whose shader passed it ([`crate::lesson::helper_ranges`]).
    pub fn new(incoming: Vector, n: Vector, glossiness: f32) -> GlossyCone {
        if !(glossiness > 0.0 && glossiness <= 1.0) {
            helper_ranges::note(glossiness);
        }
        GlossyCone::from_scene(incoming, n, glossiness)
    }

    /// [`GlossyCone::new`] for the course's glossy mirror, whose glossiness is checked from the scene
    /// (`crate::app::parameter_ranges`), not at each hit.
    #[inline(always)]
    pub(crate) fn from_scene(incoming: Vector, n: Vector, glossiness: f32) -> GlossyCone {
        GlossyCone { incoming, basis: OrthonormalBasis::new(n), scaling: glossy_scaling(glossiness) }
    }

    /// The reflection about the normal tilted by the disc point (x, y), or `None` when it goes under the
    /// surface.
    pub fn direction(&self, (x, y): (f32, f32)) -> Option<Vector> {
        exercise!(glossy_direction(self.incoming, &self.basis, self.scaling, (x, y)));
        let normal = self.basis.normal;
        let perturbed = (normal + self.basis.to_world(x * self.scaling, y * self.scaling, 0.0)).normalize();
        let dir = reflect(self.incoming, perturbed);
        (dir.dot(normal) > 0.0).then_some(dir)
    }
}

/// How far a point of the unit disc tilts the normal, as a tangent, for a surface of this glossiness (step 3
/// of the slide's algorithm): `tan((1 - glossiness) * pi/2)`, 0 for a perfect mirror, unbounded towards a
/// matte surface.
pub fn glossy_scaling(glossiness: f32) -> f32 {
    exercise!(glossy_scaling(glossiness));
    ((1.0 - glossiness) * FRAC_PI_2).tan()
}
