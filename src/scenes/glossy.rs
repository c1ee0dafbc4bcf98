//! Scene of the `glossy` example (slides "Грапави (glossy) отражения" to "Резултати (2)"): three mirror
//! spheres of glossiness 0.95, 0.80 and 0.50, as on the slide, on a tiled floor.
//!
//! - What they reflect: the floor, a red ball and a wooden box standing between them (near, so their
//!   reflections show how the blur grows with distance from the mirror), a wall with a world map behind the
//!   camera, and the workbook's HDR sky with its clouds (`--env` puts any other environment there).
//! - The blur comes from averaging `--glossy-samples` reflected rays per camera ray (the slide's
//!   `num_samples`); below the first bounce the spheres trace 2 rays each, as in the course.
//! - `--sampler random` picks the disc points as the slide does, independently; `stratified` (the default)
//!   spreads them evenly, and gives the same picture with less noise for the same time.
//!
//! The defaults, 16 anti-aliasing samples x 4 glossy samples (64 glossy rays per pixel), lie on the measured
//! error-versus-time Pareto front; the README's "Run time versus error" section shows the measurements.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::environment;
use crate::error::Result;
use crate::geometry::{Cube, Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::sampling::DiscSampler;
use crate::scene::Scene;
use crate::shader::{Lambert, Phong, Reflection};
use std::sync::Arc;

/// The three glossiness values of the slide, left to right.
pub const SLIDE_GLOSSINESS: [f32; 3] = [0.95, 0.80, 0.50];

/// Glossy reflections: spheres of glossiness 0.95, 0.80 and 0.50 on a tiled floor.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "glossy", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Give all three spheres this glossiness (0 matte .. 1 perfect mirror) instead of 0.95, 0.80, 0.50.
    #[arg(long)]
    pub glossiness: Option<f32>,
    /// Reflected rays averaged per camera ray on a glossy sphere (the slide's num_samples).
    #[arg(long, default_value_t = 4)]
    pub glossy_samples: u32,
    /// How the disc points are chosen: random (independent, as on the slide) or stratified.
    #[arg(long, value_enum, default_value_t = DiscSampler::Stratified)]
    pub sampler: DiscSampler,
}

impl Example for Args {
    const NAME: &'static str = "glossy";
    const DEFAULT_SPP: u32 = 16;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 30.0, -95.0),
            pitch: -10.0,
            fov: 68.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.15);
        scene.environment = Some(environment::load(&super::texture_path("sky.hdr"))?);
        scene.lights.push(PointLight::new(Vector::new(-70.0, 150.0, -60.0), Color::WHITE, 42000.0));

        let floor = super::load_texture("floor_tiles.png", None, Default::default())?.with_scaling(30.0);
        scene.add(Node::new(Arc::new(Plane::new(0.0, 300.0)), Arc::new(Lambert::new(floor))));

        // A wall behind the camera: the plane stood up facing the scene, the map upright on it.
        let map = super::load_texture("world.png", None, Default::default())?.with_scaling(240.0);
        scene.add(
            Node::new(Arc::new(Plane::new(0.0, 240.0)), Arc::new(Lambert::new(map)))
                .rotate(0.0, 90.0, 0.0)
                .translate(Vector::new(0.0, 0.0, -160.0)),
        );

        let ball = Phong::new(Color::new(0.75, 0.08, 0.06), 0.4, 60.0);
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-20.0, 6.0, 4.0), 6.0)), Arc::new(ball)));
        let wood = super::load_texture("wood.png", None, Default::default())?;
        scene.add(Node::new(Arc::new(Cube::new(Vector::new(20.0, 5.0, 4.0), 5.0)), Arc::new(Lambert::new(wood))));

        for (i, slide_glossiness) in SLIDE_GLOSSINESS.into_iter().enumerate() {
            let glossiness = self.glossiness.unwrap_or(slide_glossiness);
            let mirror =
                Reflection::glossy(Color::gray(0.85), glossiness, self.glossy_samples)?.with_sampler(self.sampler);
            let centre = Vector::new(-38.0 + 38.0 * i as f32, 16.0, 24.0);
            scene.add(Node::new(Arc::new(Sphere::new(centre, 16.0)), Arc::new(mirror)));
        }
        Ok(scene)
    }
}
