//! `Lambert`: a perfectly diffuse surface. Its colour is the diffuse colour times (the scene's ambient light
//! plus, for each light that reaches the point, the light's irradiance times the cosine of its angle, plus the
//! caustic light from the photon map, if the scene has one).

use super::{ColorSource, Material, Shader};
use crate::lesson::beyond::Step;
use crate::lesson::bitmap::Filter;
use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::light::diffuse_light;
use crate::lesson::math::faceforward;
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::texture::{Tex, Texture};
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

// How the course's shaders read their diffuse colour (Lambert's first; Phong's and a mirror's multiplier
// the same way).
impl ColorSource {
    /// The colour at the hit `info` as the render's reading reads it ([`TraceContext::raytrace`]'s scene's
    /// steps: one texel of a bitmap under `--slide`, its filter otherwise), what the texture computed told to
    /// the ray tree when one watches. The course's shaders read their colours so; a shader of a student's
    /// may too.
    #[inline(always)]
    pub fn at(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        match self {
            ColorSource::Color(c) => *c,
            ColorSource::Texture(t) => {
                let filters = matches!(t, Tex::Bitmap(bitmap) if bitmap.filter != Filter::Nearest);
                ctx.counters.steps_reached[Step::TexelFilter as usize] += filters as u64;
                t.color(ray, info, ctx.scene.steps, ctx.recorder())
            }
        }
    }
}
