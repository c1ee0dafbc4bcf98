//! Scene of the `environment` example (slides "Заден фон", "Интерфейс за заден фон"): objects on a small
//! tiled stage in an outdoor environment. Rays that miss every object see the environment: the sky and
//! the fields behind the stage, and, in the mirror sphere, everything around it, including the sun behind
//! the camera. The point light stands where the environment's sun is, so the shadows agree with the sky.
//!
//! `--kind spherical` reads the sky from one equirectangular image (`textures/sky.hdr`), `--kind cubemap`
//! from six cube faces made from it (`textures/sky_cubemap/`): the two pictures should look the same.
//! `--env FILE|FOLDER` (a common option) puts the objects in an environment of your own; the light then
//! stays where the bundled sky's sun is.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::Result;
use crate::geometry::{Cube, Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Phong, Reflection};
use std::sync::Arc;

/// Which of the two bundled environments to use.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Kind {
    /// One equirectangular image: direction to longitude and latitude.
    #[default]
    Spherical,
    /// Six cube faces: the largest component of the direction picks the face.
    Cubemap,
}

/// Environment maps: a mirror sphere and diffuse objects under an HDR sky.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "environment", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// The kind of environment map the bundled sky is read from.
    #[arg(long, value_enum, default_value_t = Kind::Spherical)]
    pub kind: Kind,
}

impl Example for Args {
    const NAME: &'static str = "environment";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let mut scene =
            Scene::new(Camera { position: Vector::new(0.0, 24.0, -75.0), pitch: -6.0, fov: 80.0, ..Camera::default() });
        scene.environment = Some(match self.kind {
            Kind::Spherical => super::sky()?,
            Kind::Cubemap => crate::environment::load(&super::texture_path("sky_cubemap"))?,
        });
        scene.max_depth = 4;
        scene.ambient = Color::new(0.12, 0.14, 0.18);
        // The sun, far away in the direction the sky shows it: about unit irradiance at the stage.
        let distance = 5000.0;
        let sun = crate::assets::sun_direction() * distance;
        scene.lights.push(PointLight::new(sun, Color::new(1.0, 0.92, 0.8), distance * distance));

        let tiles = super::load_texture("floor_tiles.png", None, Default::default())?.with_scaling(30.0);
        scene.add(Node::new(Arc::new(Plane::new(0.0, 60.0)), Arc::new(Lambert::new(tiles))));

        let mirror = Reflection::new(0.9);
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 20.0, 15.0), 20.0)), Arc::new(mirror)));
        let red = Phong::new(Color::new(0.7, 0.1, 0.08), 0.35, 80.0);
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-38.0, 10.0, -5.0), 10.0)), Arc::new(red)));
        let blue = Lambert::new(Color::new(0.12, 0.25, 0.6));
        scene.add(
            Node::new(Arc::new(Cube::new(Vector::ZERO, 9.0)), Arc::new(blue))
                .rotate(30.0, 0.0, 0.0)
                .translate(Vector::new(38.0, 9.0, 0.0)),
        );
        Ok(scene)
    }
}
