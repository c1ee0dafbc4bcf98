//! Scene of the `photon_map` example (slides "Caustics", "Photon Mapping", "Пример за photon map"): light
//! focused by a glass sphere and thrown by a small mirror, computed by photon mapping.
//!
//! - A point light stands high behind the objects and a low wall, so the shadows fall towards the camera
//!   and the wall's face is in shade.
//! - The glass sphere (Fresnel-blended refraction and reflection, the slides' glass material) floats above the
//!   floor at about the distance where it focuses the light: the bright caustic lies inside its shadow.
//! - The small square mirror on the right is turned so that it reflects the light to a chosen point of the
//!   shaded wall: the bright patch there ("слънчево зайче") is light that, as the slide says, shadow rays
//!   alone could not find.
//!
//! With `--abbe V` the glass disperses light and the caustic turns into a small rainbow (chromatic caustics).
//! The photon map's defaults (`--photons`, `--k`, `--radius`) are this scene's; `--show-photons` draws the
//! stored photons instead of the caustic light, and `--photons 0` shows what the renderer sees without them.

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::Result;
use crate::geometry::{Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::photon_map::PhotonSettings;
use crate::scene::Scene;
use crate::scenes::dispersion::fresnel_glass;
use crate::shader::{Lambert, Reflection};
use crate::spectral::Ior;
use crate::texture::CheckerTexture;
use std::sync::Arc;

/// Caustics by photon mapping: a glass sphere focusing a point light onto the floor, and a small mirror
/// throwing a bright spot.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "photon_map", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// Index of refraction n_d of the glass sphere: higher focuses closer to the sphere.
    #[arg(long, default_value_t = 1.5)]
    pub ior: f32,
    /// Abbe number of the glass sphere (the slide's measure of dispersion; 64 for crown glass, 25 for dense
    /// flint). A finite number makes the caustic chromatic: photons carry wavelengths, and the picture is
    /// traced per wavelength (try it with `--spectral sampled --spp 16`). inf: no dispersion.
    #[arg(long, default_value_t = f32::INFINITY)]
    pub abbe: f32,
}

/// Where the light is.
pub const LIGHT: Vector = Vector::new(5.0, 120.0, 95.0);
/// The glass sphere: its centre and radius.
pub const GLASS_CENTER: Vector = Vector::new(-22.0, 19.0, 20.0);
pub const GLASS_RADIUS: f32 = 12.0;
/// The mirror's centre, and the point of the wall it throws the light's reflection to.
pub const MIRROR_CENTER: Vector = Vector::new(28.0, 10.0, 15.0);
pub const MIRROR_SPOT: Vector = Vector::new(20.0, 22.0, WALL_Z);
/// The low wall at the back: where its face is, and how high it is.
pub const WALL_Z: f32 = 70.0;
pub const WALL_HEIGHT: f32 = 35.0;

impl Example for Args {
    const NAME: &'static str = "photon_map";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let ior = Ior::abbe(self.ior, self.abbe)?;
        let mut scene = Scene::new(Camera {
            position: Vector::new(0.0, 55.0, -100.0),
            pitch: -22.0,
            fov: 70.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.06);
        scene.max_depth = 6;
        scene.lights.push(PointLight::new(LIGHT, Color::WHITE, 20000.0));
        scene.photons = PhotonSettings { count: 400_000, k: 80, max_radius: Some(2.0), show: false };

        let floor = CheckerTexture { color1: Color::gray(0.7), color2: Color::gray(0.55), scaling: 1.0 / 25.0 };
        scene.add(Node::new(Arc::new(Plane::new(0.0, 150.0)), Arc::new(Lambert::new(floor))));

        // The wall: a plane, squeezed to its height and stood up facing the camera. The light is behind it,
        // so its face is in shade: the mirror's spot shows on it.
        let half = 0.5 * WALL_HEIGHT;
        scene.add(
            Node::new(Arc::new(Plane::new(0.0, 80.0)), Arc::new(Lambert::new(Color::gray(0.75))))
                .scale(Vector::new(1.0, 1.0, half / 80.0))
                .rotate(0.0, 90.0, 0.0)
                .translate(Vector::new(0.0, half, WALL_Z)),
        );

        // The slides' glass: a refraction layer, and over it a mirror layer blended by the Fresnel texture.
        let glass = fresnel_glass(ior);
        scene.add(Node::new(Arc::new(Sphere::new(GLASS_CENTER, GLASS_RADIUS)), Arc::new(glass)));

        // The law of reflection: the mirror's normal is halfway between the directions to the light and to
        // the spot. A plane's normal is +Y; roll tilts it, yaw turns it about the vertical.
        let normal = ((LIGHT - MIRROR_CENTER).normalize() + (MIRROR_SPOT - MIRROR_CENTER).normalize()).normalize();
        let roll = normal.y.acos().to_degrees();
        let yaw = normal.z.atan2(normal.x).to_degrees();
        scene.add(
            Node::new(Arc::new(Plane::new(0.0, 4.0)), Arc::new(Reflection::new(0.9)))
                .rotate(yaw, 0.0, roll)
                .translate(MIRROR_CENTER),
        );
        Ok(scene)
    }
}
