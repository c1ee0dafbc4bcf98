//! The `Fresnel` texture (slides "Fresnel", "Fresnel Texture"): the fraction of light a dielectric surface
//! reflects at the angle the ray meets it, as a grey colour, meant to drive a `Layered` shader's reflection
//! layer. Schlick's approximation is the slide's; the exact equations are a second mode for comparison.
//! With a dispersive [`Ior`] the reflectance is that of the ray's wavelength.
//! Both give 1 under total internal reflection, so a glass made of a refraction layer and a reflection layer
//! blended by this texture loses no light there (the slide's formula, used as is when leaving the glass,
//! would give less than 1 and let the refraction layer return black for the rest).

use super::{Tex, Texture};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::math::{Vector, faceforward, fresnel, fresnel_exact};
use crate::lesson::ray::Ray;
use crate::lesson::spectral::Ior;
use crate::lesson::topic::{Recorder, Topic, record};
use std::sync::Arc;

/// Which formula the Fresnel texture uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FresnelMode {
    /// Schlick's approximation, as on the slide.
    #[default]
    Schlick,
    /// The exact Fresnel equations for unpolarised light.
    Exact,
}

/// The Fresnel texture (slide "Fresnel Texture"): the reflectance of the surface at the angle the ray meets it,
/// as a grey colour from 0 to 1.
#[derive(Clone, Copy, Debug)]
pub struct Fresnel {
    /// Index of refraction of the object (outside is air, 1.0), possibly depending on the wavelength.
    pub ior: Ior,
    /// Schlick's approximation (the slide's) or the exact equations.
    pub mode: FresnelMode,
}

impl Fresnel {
    /// A Fresnel texture for an object of index `ior` (the same at every wavelength) in air.
    pub fn new(ior: f32, mode: FresnelMode) -> Fresnel {
        Fresnel { ior: Ior::Constant(ior), mode }
    }
    /// A Fresnel texture whose index may depend on the wavelength (a dispersive glass).
    pub fn with_ior(ior: Ior, mode: FresnelMode) -> Fresnel {
        Fresnel { ior, mode }
    }
    /// The reflectance for this ray and hit (the slide's `getTexColor`, as a number).
    #[inline(always)]
    pub fn reflectance(&self, ray: &Ray, info: &IntersectionInfo) -> f32 {
        let (eta, n) = self.interface(ray, info);
        match self.mode {
            FresnelMode::Schlick => fresnel(ray.dir, n, eta),
            FresnelMode::Exact => fresnel_exact(ray.dir, n, eta),
        }
    }

    /// The ratio n1 / n2 of the indices on the ray's side and across the surface, and the normal facing the
    /// ray. Entering, light goes from air (1) into the object (ior); leaving, the other way round: the
    /// slide's "eta flipped when inside". The test is the one `Refraction` makes, so the two always agree on
    /// which side the ray is (and on total internal reflection).
    /// The reflectance as a grey colour, telling `recorder`, if there is one, the values it was computed from
    /// (what the ray tree shows at a hit).
    #[inline(always)]
    pub(super) fn color(&self, ray: &Ray, info: &IntersectionInfo, recorder: Option<&mut dyn Recorder>) -> Color {
        let reflectance = self.reflectance(ray, info);
        record(recorder, || {
            let (eta, n) = self.interface(ray, info);
            let (cos, exact) = ((-n.dot(ray.dir)).clamp(0.0, 1.0), self.mode == FresnelMode::Exact);
            Topic::Fresnel { reflectance, eta, cos, exact }
        });
        Color::gray(reflectance)
    }

    #[inline(always)]
    fn interface(&self, ray: &Ray, info: &IntersectionInfo) -> (f32, Vector) {
        let ior = self.ior.at(ray.wavelength);
        let entering = info.normal.dot(ray.dir) < 0.0;
        (if entering { 1.0 / ior } else { ior }, faceforward(info.normal, ray.dir))
    }
}

impl Texture for Fresnel {
    #[inline]
    fn get_tex_color(&self, ray: &Ray, info: &IntersectionInfo) -> Color {
        Color::gray(self.reflectance(ray, info))
    }

    /// The reflectance, told to `recorder` with the ratio of the indices and the angle it comes from.
    fn is_dispersive(&self) -> bool {
        self.ior.is_dispersive()
    }

    /// The reflectance depends on the angle alone.
    fn reads_uv(&self) -> bool {
        false
    }

    fn into_tex(self: Arc<Self>) -> Tex {
        Tex::Fresnel(*self)
    }
}
