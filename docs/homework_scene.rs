//! Homework: a checkered floor, two glasses of different IOR, a textured globe, a mirror, and a shader of
//! my own. Save as `examples/hw1.rs` and run `cargo run --release --example hw1`.

use lecture6::prelude::*;

/// My shader: a matte surface in bands, `a` and `b` alternating every `width` units of height.
struct Bands {
    a: Color,
    b: Color,
    width: f32,
}

impl Shader for Bands {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        // The height in the world the scene is built in (`info.ip` may be relative to the camera).
        let height = ctx.scene.world_position(info.ip).y;
        let even = (height / self.width).floor().rem_euclid(2.0) == 0.0;
        let color = if even { self.a } else { self.b };
        color * diffuse_light(ctx, info, faceforward(info.normal, ray.dir))
    }
}

/// The homework's scene (it has no options of its own yet).
#[derive(clap::Args, Clone, Debug)]
pub struct Options {}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let camera = Camera::look_at(Vector::new(0.0, 45.0, -110.0), Vector::new(0.0, 15.0, 0.0), 75.0);
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 10;
        scene.lights.push(PointLight::new(Vector::new(-60.0, 150.0, -80.0), Color::WHITE, 40000.0));
        scene.environment = Some(sky()?);
        scene.add(checker_floor(150.0, 20.0).named("floor"));
        scene.add(
            Node::new(
                Sphere::new(Vector::new(-45.0, 15.0, 0.0), 15.0),
                fresnel_glass(1.33, FresnelMode::Schlick, 0.95),
            )
            .named("water"),
        );
        scene.add(
            Node::new(Sphere::new(Vector::new(-10.0, 15.0, 0.0), 15.0), fresnel_glass(1.6, FresnelMode::Schlick, 0.95))
                .named("glass"),
        );
        let globe = Lambert::new(texture("world.png")?);
        scene.add(
            Node::new(Sphere::new(Vector::ZERO, 1.0), globe)
                .scale(Vector::splat(15.0))
                .rotate(30.0, 0.0, 0.0)
                .translate(Vector::new(25.0, 15.0, 0.0))
                .named("globe"),
        );
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 1.0), Reflection::new(0.9))
                .scale(Vector::new(40.0, 25.0, 1.0))
                .translate(Vector::new(0.0, 25.0, 60.0))
                .named("mirror"),
        );
        let bands = Bands { a: Color::new(0.9, 0.5, 0.1), b: Color::new(0.1, 0.3, 0.8), width: 4.0 };
        scene.add(Node::new(Sphere::new(Vector::new(40.0, 10.0, -45.0), 10.0), bands).named("bands"));
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
