//! `Lambert`: a perfectly diffuse surface. Its colour is the diffuse colour times (the scene's ambient light
//! plus, for each light that reaches the point, the light's irradiance times the cosine of its angle, plus the
//! caustic light from the photon map, if the scene has one).

use super::{ColorSource, Material, Shader};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::light::diffuse_light;
use crate::lesson::math::faceforward;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;
use std::sync::Arc;

/// A perfectly diffuse (matte) surface, lit by the light loop (lectures 2-3).
#[derive(Clone)]
pub struct Lambert {
    /// The diffuse colour: the fraction of each channel of the incoming light that the surface scatters.
    pub color: ColorSource,
}

impl Lambert {
    /// A Lambert surface of the given colour or texture.
    pub fn new(color: impl Into<ColorSource>) -> Lambert {
        Lambert { color: color.into() }
    }
}

impl Shader for Lambert {
    /// The diffuse colour at the hit times the light the point receives.
    #[inline(always)]
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let diffuse = self.color.at(ray, info, ctx);
        let n = faceforward(info.normal, ray.dir);
        diffuse * diffuse_light(ctx, info, n)
    }

    fn texture(&self) -> Option<&dyn Texture> {
        self.color.texture()
    }

    fn into_material(self: Arc<Self>) -> Material {
        Material::Lambert(Arc::unwrap_or_clone(self))
    }
}
