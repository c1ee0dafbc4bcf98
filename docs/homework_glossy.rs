//! Homework: a glossy mirror of my own, `n` rays averaged, as a ball on a checkered floor under the sky. Save
//! as `examples/hw1.rs`; `cargo run --release --example hw1` renders it, `cargo test --release --example hw1`
//! builds this file alone and runs its test (the module `tests` at its end).

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

/// The homework's scene: my glossy ball, beside a matte one, on a checkered floor under the sky.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// How many rays the glossy ball averages at each point it is hit.
    #[arg(long, default_value_t = 8)]
    pub rays: u32,
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let camera = Camera::look_at(Vector::new(0.0, 25.0, -70.0), Vector::new(0.0, 12.0, 0.0), 60.0);
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 4;
        scene.lights.push(PointLight::new(Vector::new(-60.0, 150.0, -80.0), Color::WHITE, 40000.0));
        scene.environment = Some(sky()?);
        scene.add(checker_floor(150.0, 20.0).named("floor"));
        let glossy = TintedGlossy { tint: Color::new(0.95, 0.85, 0.7), glossiness: 0.9, n: self.rays };
        scene.add(Node::new(Sphere::new(Vector::new(-8.0, 12.0, 0.0), 12.0), glossy).named("glossy ball"));
        let matte = Lambert::new(Color::new(0.2, 0.4, 0.8));
        scene.add(Node::new(Sphere::new(Vector::new(18.0, 7.0, -8.0), 7.0), matte).named("matte ball"));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The homework renders, small, and the end-of-run report says nothing: no NaN, no ray that finds the
    /// surface it left, no shader that returns more light than its rays and its lamps bring it.
    #[test]
    fn renders_without_a_warning() {
        render_for_test::<Options>(&["--width", "80", "--height", "60", "--spp", "1"]);
    }
}
