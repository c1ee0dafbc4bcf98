//! `Reflection` (slides "Reflection v0.1", "Reflection v0.2"): a mirror. The reflected ray starts at the hit
//! point, goes in the direction `reflect(ray.dir, n)` with the face-forwarded normal, one level deeper, and
//! what it brings back is multiplied by the mirror's colour (`multiplier`; the slide's v0.1 uses 0.8,
//! "20% loss of energy").
//!
//! Deviation from the slides: the start point is offset by the hit point's error bound
//! ([`Ray::spawn`](crate::ray::Ray::spawn)) instead of `1e-6 * n`.

use super::{ColorSource, Shader};
use crate::color::Color;
use crate::geometry::IntersectionInfo;
use crate::math::{faceforward, reflect};
use crate::photon_map::PhotonScatter;
use crate::ray::Ray;
use crate::rng::Rng;
use crate::scene::TraceContext;

#[derive(Clone)]
pub struct Reflection {
    /// The colour of the mirror: what fraction of each channel it reflects. May come from a texture.
    pub multiplier: ColorSource,
}

impl Reflection {
    /// A grey mirror reflecting the fraction `multiplier` of the light.
    pub fn new(multiplier: f32) -> Reflection {
        Reflection { multiplier: Color::gray(multiplier).into() }
    }
}

impl Shader for Reflection {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let multiplier = self.multiplier.get(ray, info);
        let n = faceforward(info.normal, ray.dir);
        let dir = reflect(ray.dir, n);
        let new_ray = ray.spawn(info.ip, info.geometric_normal, info.error, dir, multiplier.max_channel());
        ctx.raytrace(&new_ray) * multiplier
    }

    /// A photon is mirrored like a ray, its power multiplied by the mirror's colour.
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, _rng: &mut Rng) -> PhotonScatter {
        let dir = reflect(ray.dir, faceforward(info.normal, ray.dir));
        PhotonScatter::Continue { dir, filter: self.multiplier.get(ray, info) }
    }

    fn casts_caustics(&self) -> bool {
        true
    }
}
