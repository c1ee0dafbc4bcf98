//! `Refraction` (slides "Refract", "Refraction 0.2"): a transparent surface that bends rays by Snell's law.
//! Whether the ray enters or leaves the object is decided from the normal *before* it is face-forwarded (so
//! this shader needs outward normals and closed objects); entering, light goes from air into the material,
//! so the ratio passed to `refract` is 1 / ior; leaving, it is ior. Under total internal reflection the
//! shader returns black, as on the slide (a Fresnel-blended glass, built with `Layered`, sends that light
//! into its reflection layer instead).
//!
//! Dispersion (slide "Хроматично пречупване"): the index may depend on the wavelength ([`Ior`]); the shader
//! uses the index at the ray's wavelength, and white rays (no wavelength) see n_d.
//!
//! Deviation from the slides: the new ray starts at the hit point offset by its error bound to the side the
//! refracted ray goes to ([`Ray::spawn`](crate::lesson::ray::Ray::spawn)), instead of `1e-6 * ray.dir` (ledger:
//! `robust-offsets`).

use super::{CausticCaster, Material, PhotonScatter, Shader};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::{Vector, faceforward, refract};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::TraceContext;
use crate::lesson::spectral::Ior;
use std::sync::Arc;

/// A transparent surface that bends rays by Snell's law (slide "Refraction 0.2"); glass without Fresnel's
/// reflection, which [`fresnel_glass`](super::fresnel_glass) adds.
#[derive(Clone, Copy, Debug)]
pub struct Refraction {
    /// Index of refraction of the material (glass about 1.5), possibly depending on the wavelength; the
    /// outside is air (1.0).
    pub ior: Ior,
    /// Fraction of the light that passes.
    pub multiplier: f32,
}

impl Refraction {
    /// A refraction of index `ior` (the same at every wavelength) letting through the fraction `multiplier` of
    /// the light.
    pub fn new(ior: f32, multiplier: f32) -> Refraction {
        Refraction { ior: Ior::Constant(ior), multiplier }
    }
    /// A refraction whose index may depend on the wavelength (a dispersive glass).
    pub fn with_ior(ior: Ior, multiplier: f32) -> Refraction {
        Refraction { ior, multiplier }
    }

    /// The unit direction of the refracted ray (for the ray's wavelength), or `None` under total internal
    /// reflection.
    #[inline(always)]
    fn refracted(&self, ray: &Ray, info: &IntersectionInfo) -> Option<Vector> {
        let entering = info.normal.dot(ray.dir) < 0.0;
        let ior = self.ior.at(ray.wavelength);
        let eta = if entering { 1.0 / ior } else { ior };
        let n = faceforward(info.normal, ray.dir);
        refract(ray.dir, n, eta).map(Vector::normalize)
    }
}

impl Shader for Refraction {
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let Some(dir) = self.refracted(ray, info) else {
            return Color::BLACK; // total internal reflection
        };
        let new_ray = ray.spawn(info, dir, self.multiplier);
        ctx.raytrace(&new_ray) * self.multiplier
    }

    fn is_dispersive(&self) -> bool {
        self.ior.is_dispersive()
    }

    fn caustic_caster(&self) -> Option<&dyn CausticCaster> {
        Some(self)
    }

    fn into_material(self: Arc<Self>) -> Material {
        Material::Refraction(*self)
    }
}

impl CausticCaster for Refraction {
    /// A photon is refracted like a ray (and absorbed under total internal reflection, as the ray is).
    fn scatter_photon(&self, ray: &Ray, info: &IntersectionInfo, _rng: &mut Rng) -> PhotonScatter {
        match self.refracted(ray, info) {
            Some(dir) => PhotonScatter::Continue { dir, filter: Color::gray(self.multiplier) },
            None => PhotonScatter::Absorb,
        }
    }
}
