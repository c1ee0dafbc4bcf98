//! `Phong`: Lambert's diffuse term plus a specular highlight `specular * irradiance * cos(gamma)^exponent`,
//! where gamma is the angle between the light's mirror direction and the direction to the eye (as in the
//! course's Phong shader). Caustic light from the photon map, if the scene has one, adds to the diffuse term.

use super::{ColorSource, Material, Shader};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::light::light_loop;
use crate::lesson::math::{faceforward, reflect};
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;
use std::sync::Arc;

/// A diffuse surface with the lamps' highlights on it (the course's Phong shader).
#[derive(Clone)]
pub struct Phong {
    /// The diffuse colour, as [`Lambert`](super::Lambert)'s; the highlight takes the lamp's colour, not this one.
    pub color: ColorSource,
    /// Strength of the highlight.
    pub specular: f32,
    /// Sharpness of the highlight: larger is smaller and sharper.
    pub exponent: f32,
}

impl Phong {
    /// A Phong surface of the given colour, highlight strength and highlight exponent.
    pub fn new(color: impl Into<ColorSource>, specular: f32, exponent: f32) -> Phong {
        Phong { color: color.into(), specular, exponent }
    }
}

impl Shader for Phong {
    /// The diffuse colour at the hit times the light the point receives, plus the lamps' highlights.
    #[inline]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let diffuse_color = self.color.at(ray, info, ctx);
        let n = faceforward(info.normal, ray.dir);
        let light = light_loop(ctx, info, n, |l, irradiance| {
            let cos_gamma = (-ray.dir).dot(reflect(-l, n));
            if cos_gamma > 0.0 { irradiance * (self.specular * cos_gamma.powf(self.exponent)) } else { Color::BLACK }
        });
        diffuse_color * light.irradiance + light.highlights
    }

    fn texture(&self) -> Option<&dyn Texture> {
        self.color.texture()
    }

    fn into_material(self: Arc<Self>) -> Material {
        Material::Phong(Arc::unwrap_or_clone(self))
    }
}
