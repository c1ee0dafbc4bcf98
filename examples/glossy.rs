//! # Glossy reflections (lecture 6, slides "Грапави (glossy) отражения" to "Резултати (2)")
//!
//! The slide's code: `Reflection::shade` in `src/lesson/shader/reflection.rs` with random points of the unit disc
//! (`src/lesson/sampling.rs`). `--slide` renders this example with the slides' choice of every step beyond them
//! (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change (docs/beyond-the-slides.md).
//!
//! A rough mirror reflects a cone of rays instead of one. The renderer tilts the face-forwarded normal by a
//! point of the unit disc scaled by `tan((1 - glossiness) * pi/2)`, reflects about the tilted normal, drops
//! rays that go under the surface and averages the rest. Look at:
//! - the three spheres, glossiness 0.95, 0.80 and 0.50 from left to right: the floor's tiles and the clouds
//!   stay crisp in the first and melt into an average colour in the last;
//! - the red ball and the wooden box between them: reflections of near things stay sharper than those of
//!   far things (the cone widens with distance);
//! - the noise: `--glossy-samples 2` shows what too few samples do, `--sampler random` the slide's
//!   independent disc points, `--sampler stratified` well-spread points for each camera ray, and the default
//!   `joint` well-spread points for the whole pixel, shared out between its camera rays (the least noise at
//!   the same time; docs/measurements.md).
//!
//! Try: `--glossiness 0.9`, `--glossy-samples 64 --spp 1`, `--sampler random --compare expected/glossy.png`,
//! `--env textures/sky_cubemap`.
//!
//! Homework ideas: make the glossiness a texture (a scratched or fingerprinted mirror); importance-sample a
//! Phong lobe instead of tilting the normal; trace fewer rays where the ray's `weight` is small.

use lecture6::prelude::*;

/// The three glossiness values of the slide, left to right.
pub const SLIDE_GLOSSINESS: [f32; 3] = [0.95, 0.80, 0.50];

/// Glossy reflections: spheres of glossiness 0.95, 0.80 and 0.50 on a tiled floor.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// Give all three spheres this glossiness instead of 0.95, 0.80, 0.50: above 0 (matte) to 1 (a perfect
    /// mirror); 0 itself, an unbounded cone, is refused.
    #[arg(long)]
    pub glossiness: Option<f32>,
    /// Reflected rays averaged per camera ray on a glossy sphere (the slide's num_samples).
    #[arg(long, default_value_t = 4)]
    pub glossy_samples: u32,
    /// How the disc points are chosen: random (independent, as on the slide), stratified (for each camera
    /// ray) or joint (stratified over the whole pixel's camera rays).
    #[arg(long, value_enum, default_value_t = DiscSampler::Joint)]
    pub sampler: DiscSampler,
}

impl Example for Options {
    // 16 anti-aliasing samples x 4 glossy samples lie on the measured error-versus-time Pareto front
    // (docs/measurements.md).
    const DEFAULT_SPP: u32 = 16;

    fn scene(&self) -> Result<Scene> {
        let camera = Camera { position: Vector::new(0.0, 30.0, -95.0), pitch: -10.0, fov: 68.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.15);
        scene.environment = Some(sky()?);
        scene.lights.push(PointLight::new(Vector::new(-70.0, 150.0, -60.0), Color::WHITE, 42000.0));
        scene.add(Node::new(Plane::new(0.0, 300.0), Lambert::new(texture("floor_tiles.png")?.with_tile_size(30.0))));

        // A wall behind the camera, for the mirrors to reflect: the plane stood up facing the scene, the map
        // upright on it.
        let map = texture("world.png")?.with_tile_size(240.0);
        scene.add(
            Node::new(Plane::new(0.0, 240.0), Lambert::new(map))
                .rotate(0.0, 90.0, 0.0)
                .translate(Vector::new(0.0, 0.0, -160.0)),
        );

        // Near things between the mirrors: their reflections stay sharper than those of far things.
        let ball = Phong::new(Color::new(0.75, 0.08, 0.06), 0.4, 60.0);
        scene.add(Node::new(Sphere::new(Vector::new(-20.0, 6.0, 4.0), 6.0), ball));
        scene.add(Node::new(Cube::new(Vector::new(20.0, 5.0, 4.0), 5.0), Lambert::new(texture("wood.png")?)));

        // The three glossy mirrors.
        for (i, slide_glossiness) in SLIDE_GLOSSINESS.into_iter().enumerate() {
            let glossiness = self.glossiness.unwrap_or(slide_glossiness);
            let mirror =
                Reflection::glossy(Color::gray(0.85), glossiness, self.glossy_samples)?.with_sampler(self.sampler);
            let centre = Vector::new(-38.0 + 38.0 * i as f32, 16.0, 24.0);
            scene.add(Node::new(Sphere::new(centre, 16.0), mirror));
        }
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
