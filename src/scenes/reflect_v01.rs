//! Scene of the `reflect_v01` example (slide "Reflection v0.1"): mirrors that reflect 80% of the light ("20%
//! loss of energy") and **no depth limit**: a reflected ray is traced however deep it goes.
//!
//! - Two mirror spheres stand on a checker floor with a small red sphere between them; each shows the
//!   other, and in it itself again, every image 20% darker.
//! - `--mirrors` adds the slide's danger: two large framed mirrors facing each other, one in front of the
//!   camera and one behind it. A ray that meets them square-on bounces between them for ever; without a
//!   limit every bounce is one more nested `raytrace` call, and the program would die of a stack overflow.
//!   The renderer's hard [`RECURSION_SAFETY_CAP`](crate::scene::RECURSION_SAFETY_CAP) stops those rays
//!   (they return black) and the example prints one line saying so: this is why Reflection v0.2 adds
//!   `MAX_RAY_DEPTH` (the `reflect_v02` example).
//!
//! The scene is shared with `reflect_v02`, which renders the facing mirrors with the depth limit.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::{Error, Result};
use crate::geometry::{Cube, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Phong, Reflection};
use std::sync::Arc;

/// Reflection v0.1: mirrors with 20% loss per bounce and no depth limit.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "reflect_v01", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Put two large mirrors facing each other around the camera: the runaway recursion of v0.1.
    #[arg(long)]
    pub mirrors: bool,
    /// The fraction of light every mirror reflects (the slide's 0.8: "20% loss of energy").
    #[arg(long, default_value_t = 0.8)]
    pub multiplier: f32,
}

impl Example for Args {
    const NAME: &'static str = "reflect_v01";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let mut scene = mirror_scene(self.multiplier, self.mirrors)?;
        // The slide's v0.1 has no depth limit (only the renderer's safety cap remains), and no adaptive depth
        // control either: a ray keeps bouncing however faint it has become, which is the danger it shows.
        scene.max_depth = u32::MAX;
        scene.min_ray_weight = 0.0;
        Ok(scene)
    }
}

/// The mirrors' scene: two mirror spheres reflecting `multiplier` of the light, and with `facing_mirrors`
/// two large mirrors facing each other along the camera's axis. The caller sets the depth limit.
pub fn mirror_scene(multiplier: f32, facing_mirrors: bool) -> Result<Scene> {
    if !(0.0..=1.0).contains(&multiplier) {
        return Err(Error::parameter("multiplier", multiplier, "must be between 0 and 1"));
    }
    // The camera looks along +Z at the height of the mirrors' centres, square-on to them.
    let mut scene = Scene::new(Camera { position: Vector::new(0.0, 30.0, -40.0), fov: 75.0, ..Camera::default() });
    scene.environment = Some(super::sky()?);
    scene.ambient = Color::gray(0.15);
    scene.lights.push(PointLight::new(Vector::new(-80.0, 250.0, 20.0), Color::new(1.0, 0.96, 0.9), 75000.0));
    scene.add(super::checker_floor(150.0, 20.0));

    let mirror = Arc::new(Reflection::new(multiplier));
    scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-28.0, 15.0, 45.0), 15.0)), mirror.clone()));
    scene.add(Node::new(Arc::new(Sphere::new(Vector::new(28.0, 15.0, 45.0), 15.0)), mirror.clone()));
    let red = Arc::new(Phong::new(Color::new(0.75, 0.12, 0.08), 0.3, 60.0));
    scene.add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 8.0, 70.0), 8.0)), red));

    if facing_mirrors {
        // Each mirror is a thin box in a slightly larger wooden frame; they face each other across the
        // scene, one 140 units in front of the camera and one 40 units behind it.
        let wood = Arc::new(Lambert::new(super::load_texture("wood.png", None, Default::default())?));
        let cube = Arc::new(Cube::new(Vector::ZERO, 1.0));
        for z in [100.0, -80.0] {
            let back = if z > 0.0 { 1.0 } else { -1.0 };
            scene.add(
                Node::new(cube.clone(), mirror.clone())
                    .scale(Vector::new(60.0, 30.0, 0.5))
                    .translate(Vector::new(0.0, 30.0, z)),
            );
            scene.add(
                Node::new(cube.clone(), wood.clone()).scale(Vector::new(64.0, 34.0, 1.0)).translate(Vector::new(
                    0.0,
                    30.0,
                    z + back * 1.0,
                )),
            );
        }
    }
    Ok(scene)
}
