//! Scene of the `refract` example (slides "Refract", "Refraction 0.2"): a glass sphere and a glass slab in
//! front of a checker wall, on a checker floor, under the sky.
//!
//! - The sphere acts as a lens: the wall and the floor behind it appear upside down and magnified.
//! - The slab, turned 40° from the camera, shifts what is behind it sideways without bending it, as a
//!   thick window pane seen at an angle does: a ray leaves it parallel to the way it came in. Near its
//!   edges a ray inside meets a side face beyond the critical angle: total internal reflection, where the
//!   slide's shader returns black (the `fresnel` example sends that light into a reflection instead).
//! - Both objects cast black shadows: the point light's shadow rays do not pass through glass (caustics are
//!   a later topic).
//!
//! `--ior` changes the index of refraction: 1.0 makes the glass vanish, 1.33 is water, 2.42 diamond.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::{Error, Result};
use crate::geometry::{Cube, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Refraction};
use crate::texture::CheckerTexture;
use std::sync::Arc;

/// Refraction: a glass sphere and a glass slab bending the view of a checker wall.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "refract", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Index of refraction of the glass (air is 1).
    #[arg(long, default_value_t = 1.5)]
    pub ior: f32,
}

impl Example for Args {
    const NAME: &'static str = "refract";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        if !(self.ior.is_finite() && self.ior > 0.0) {
            return Err(Error::parameter("ior", self.ior, "must be a positive number"));
        }
        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 28.0, -70.0),
            pitch: -12.0,
            fov: 70.0,
            ..Camera::default()
        });
        scene.environment = Some(super::sky()?);
        // Enough for a ray to pass through both objects: in and out of each.
        scene.max_depth = 8;
        scene.ambient = Color::gray(0.15);
        scene.lights.push(PointLight::new(Vector::new(-60.0, 200.0, -80.0), Color::new(1.0, 0.96, 0.9), 60000.0));
        scene.add(super::checker_floor(150.0, 10.0));

        // The wall: a thin box 120 units square, 65 units behind the objects, in squares of 10 units.
        let checker =
            CheckerTexture { color1: Color::new(0.85, 0.8, 0.6), color2: Color::new(0.1, 0.3, 0.45), scaling: 12.0 };
        scene.add(
            Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), Arc::new(Lambert::new(checker)))
                .scale(Vector::new(60.0, 60.0, 1.0))
                .translate(Vector::new(0.0, 45.0, 80.0)),
        );

        let glass = Arc::new(Refraction::new(self.ior, 0.95));
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-22.0, 16.0, 15.0), 16.0)), glass.clone()));
        // The slab: a glass plate 28 x 32 x 6, turned 40° and standing just above the floor.
        scene.add(
            Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), glass)
                .scale(Vector::new(14.0, 16.0, 3.0))
                .rotate(40.0, 0.0, 0.0)
                .translate(Vector::new(24.0, 16.5, 15.0)),
        );
        Ok(scene)
    }
}
