//! Scene of the `fresnel` example (slides "Fresnel", "Fresnel Texture", "Let's build a Fresnel Shader (with
//! layers!)"): the course's own lecture-6 scene, so the picture and the time can be compared with the course's
//! C++ program.
//!
//! - Camera at (0, 60, -120), pitch -30, fov 90; 640 x 480.
//! - A floor plane y = 1, half-size 100, tiled texture with scaling 100, shaded by a `Layered`: Lambert (the
//!   tiles) with a reflection layer (multiplier 0.9) on top at blend 0.02.
//! - A glass sphere at (0, 30, -30), radius 27, IOR 1.6: a `Layered` of a refraction layer (multiplier 0.9)
//!   and a reflection layer (multiplier 0.9) whose blend is the `Fresnel` texture, so the glass reflects
//!   little where it faces the camera and much at its rim, and all under total internal reflection.
//! - One point light at (120, 180, 0), intensity 45000; ambient 0.1; the generated sky as a cube map
//!   (`textures/sky_cubemap/`); max depth 10.
//!
//! `--fresnel schlick|exact` picks the slide's approximation or the exact equations; `--ior` changes the glass.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::environment::CubemapEnvironment;
use crate::error::{Error, Result};
use crate::geometry::{Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Layered, Reflection, Refraction, Shader};
use crate::texture::{Fresnel, FresnelMode};
use std::sync::Arc;

/// The course's Fresnel scene: a glass sphere over a slightly reflective tiled floor.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "fresnel", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// How the glass's reflectance is computed: Schlick's approximation (the slide's) or the exact Fresnel
    /// equations.
    #[arg(long, value_enum, default_value_t = FresnelMode::Schlick)]
    pub fresnel: FresnelMode,
    /// Index of refraction of the glass sphere (water 1.33, glass 1.5, the course's 1.6, diamond 2.42).
    #[arg(long, default_value_t = 1.6)]
    pub ior: f32,
}

/// The glass of the slide "Let's build a Fresnel Shader (with layers!)": refraction at the bottom, reflection
/// on top with the Fresnel reflectance as its blend, so the two share the light as the Fresnel equations say.
pub fn fresnel_glass(ior: f32, mode: FresnelMode, multiplier: f32) -> Layered {
    let mut glass = Layered::new();
    glass.add_layer(Arc::new(Refraction::new(ior, multiplier)), Color::WHITE, None);
    glass.add_layer(Arc::new(Reflection::new(multiplier)), Color::WHITE, Some(Arc::new(Fresnel::new(ior, mode))));
    glass
}

/// Checks an index of refraction given on the command line.
fn check_ior(name: &'static str, ior: f32) -> Result<f32> {
    if ior.is_finite() && ior > 0.0 { Ok(ior) } else { Err(Error::parameter(name, ior, "must be a positive number")) }
}

impl Example for Args {
    const NAME: &'static str = "fresnel";
    const DEFAULT_SPP: u32 = 5;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let ior = check_ior("--ior", self.ior)?;
        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 60.0, -120.0),
            yaw: 0.0,
            pitch: -30.0,
            roll: 0.0,
            fov: 90.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.1);
        scene.max_depth = 10;
        scene.lights.push(PointLight::new(Vector::new(120.0, 180.0, 0.0), Color::WHITE, 45000.0));
        scene.environment = Some(Arc::new(CubemapEnvironment::load(&super::texture_path("sky_cubemap"))?));

        let tiles = super::load_texture("floor_tiles.png", None, Default::default())?.with_scaling(100.0);
        let mut floor = Layered::new();
        floor.add_layer(Arc::new(Lambert::new(tiles)), Color::WHITE, None);
        floor.add_layer(Arc::new(Reflection::new(0.9)), Color::gray(0.02), None);
        scene.add(Node::new(Arc::new(Plane::new(1.0, 100.0)), Arc::new(floor)));

        let glass: Arc<dyn Shader> = Arc::new(fresnel_glass(ior, self.fresnel, 0.9));
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 30.0, -30.0), 27.0)), glass));
        Ok(scene)
    }
}
