//! `Lambert`: a perfectly diffuse surface. Its colour is the diffuse colour times (the scene's ambient light
//! plus, for each light that reaches the point, the light's irradiance times the cosine of its angle, plus the
//! caustic light from the photon map, if the scene has one).

use super::{ColorSource, Shader};
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::light::diffuse_light;
use crate::lesson::math::faceforward;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::Texture;

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

    /// The surface's colour at the hit when its diffuse colour there is `diffuse`: `diffuse` times the light
    /// the point receives.
    #[inline(always)]
    pub fn shade_with(&self, diffuse: Color, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        diffuse * diffuse_light(ctx, info, n)
    }
}

impl Shader for Lambert {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.shade_with(self.color.at(ray, info, ctx), ray, info, ctx)
    }

    fn texture(&self) -> Option<&dyn Texture> {
        self.color.texture()
    }
}
