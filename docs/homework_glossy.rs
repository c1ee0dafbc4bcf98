use lecture6::lesson::sampling::random_unit_disc_point;
use lecture6::lesson::shader::GlossyCone;
use lecture6::prelude::*;

/// A tinted glossy mirror of my own: `n` rays in the glossy cone, drawn with the pixel's generator, averaged.
pub struct TintedGlossy {
    pub tint: Color,
    pub glossiness: f32,
    pub n: u32,
}

impl Shader for TintedGlossy {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let normal = faceforward(info.normal, ray.dir);
        let cone = GlossyCone::new(ray.dir, normal, self.glossiness);
        // What each ray's colour is multiplied by: the tint, in full (not 1/n of it).
        let attenuation = self.tint.max_channel();
        let (mut sum, mut kept) = (Color::BLACK, 0);
        for _ in 0..self.n {
            // A random point of the unit disc tilts the mirror direction; None if it went under the surface.
            if let Some(dir) = cone.direction(random_unit_disc_point(&mut ctx.rng)) {
                sum += ctx.raytrace(&ray.spawn(info, dir, attenuation));
                kept += 1;
            }
        }
        if kept == 0 {
            return ctx.raytrace(&ray.spawn(info, reflect(ray.dir, normal), attenuation)) * self.tint;
        }
        sum * self.tint / kept as f32
    }
}
