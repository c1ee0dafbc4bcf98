//! Scene of the `dispersion` example (slides "Хроматично пречупване (дисперсия)", "Симулиране на хроматично
//! пречупване"): glass whose index of refraction depends on the wavelength splits white light into colours.
//!
//! - The environment is a dark studio with one bright white slit: a narrow vertical strip of light
//!   ([`SlitEnvironment`]).
//! - On the left stands a 60-degree prism, turned so that the ray from the camera through its middle passes
//!   it at minimum deviation; the slit is placed where that ray leaves at [`SLIT_WAVELENGTH`], which centres
//!   the spectrum in the face the camera looks through. Looking through the prism, the camera sees the slit
//!   spread into a spectrum: violet bent most, red least.
//! - On the right floats a glass sphere cut from the same glass, made as on the slides' Fresnel material:
//!   a `Layered` shader with a refraction layer under a reflection layer blended by the Fresnel texture.
//!   The slit seen through and in it is fringed with colour ("fire").
//!
//! `--glass` picks the glass: Schott SF11 (dense flint, strong dispersion), N-BK7 (crown, weak), or the
//! slide's description by n_d and Abbe number (`--nd`, `--abbe`; `--abbe inf` is glass without dispersion).

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::environment::Environment;
use crate::error::Result;
use crate::geometry::{Prism, Sphere};
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Layered, Reflection, Refraction};
use crate::spectral::Ior;
use crate::texture::{Fresnel, FresnelMode};
use std::sync::Arc;

/// Which glass the prism and the sphere are made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Glass {
    /// Schott SF11, a dense flint (n_d 1.785, V_d 25.7), by its Sellmeier coefficients.
    Sf11,
    /// Schott N-BK7, a crown glass (n_d 1.517, V_d 64.2), by its Sellmeier coefficients.
    NBk7,
    /// The slide's model: `--nd` and `--abbe`, fitted by Cauchy's equation.
    Abbe,
}

/// Dispersion: a prism fanning a white slit into a spectrum, and a glass sphere with coloured fringes.
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "dispersion", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
    /// The glass of the prism and the sphere.
    #[arg(long, value_enum, default_value_t = Glass::Sf11)]
    pub glass: Glass,
    /// Index of refraction at 587.6 nm, for `--glass abbe`.
    #[arg(long, default_value_t = 1.7847)]
    pub nd: f32,
    /// Abbe number V_d for `--glass abbe`: smaller is more dispersive; `inf` is no dispersion.
    #[arg(long, default_value_t = 25.68)]
    pub abbe: f32,
}

impl Args {
    /// The glass the options ask for.
    pub fn ior(&self) -> Result<Ior> {
        match self.glass {
            Glass::Sf11 => Ok(Ior::SF11),
            Glass::NBk7 => Ok(Ior::N_BK7),
            Glass::Abbe => Ior::abbe(self.nd, self.abbe),
        }
    }
}

/// A dark studio lit by one bright vertical slit (a narrow strip of the environment) and a ring of small
/// square lamps, with a dim sky above the horizon and a dim checkered ground below it, so that refraction
/// shows against it.
#[derive(Clone, Copy, Debug)]
pub struct SlitEnvironment {
    /// Horizontal direction of the slit's centre: the angle from +Z towards +X, radians.
    pub azimuth: f32,
    /// Half the slit's angular width, radians.
    pub half_width: f32,
    /// The slit spans elevations (radians above the horizon) from `bottom` to `top`.
    pub bottom: f32,
    pub top: f32,
    /// Radiance of the slit and the lamps (white light).
    pub radiance: f32,
}

/// The lamps: `LAMPS` squares of `LAMP_SIZE` degrees, evenly spaced around the horizon at `LAMP_ELEVATION`
/// degrees above it.
const LAMPS: f32 = 18.0;
const LAMP_SIZE: f32 = 5.0;
const LAMP_ELEVATION: f32 = 24.0;

impl Environment for SlitEnvironment {
    fn get(&self, dir: Vector) -> Color {
        let elevation = dir.y.clamp(-1.0, 1.0).asin();
        let azimuth = dir.x.atan2(dir.z);
        let off =
            (azimuth - self.azimuth + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI;
        if off.abs() < self.half_width && elevation > self.bottom && elevation < self.top {
            return Color::gray(self.radiance);
        }
        let (az, el) = (azimuth.to_degrees(), elevation.to_degrees());
        let spacing = 360.0 / LAMPS;
        // Lamps sit every `spacing` degrees from the slit's azimuth.
        let from_lamp = (az - self.azimuth.to_degrees() + 0.5 * spacing).rem_euclid(spacing) - 0.5 * spacing;
        if from_lamp.abs() < 0.5 * LAMP_SIZE && (el - LAMP_ELEVATION).abs() < 0.5 * LAMP_SIZE {
            return Color::gray(self.radiance);
        }
        if dir.y >= 0.0 {
            // Sky: brightest at the horizon.
            Color::new(0.05, 0.06, 0.09) * (1.0 - dir.y) + Color::new(0.01, 0.012, 0.02) * dir.y
        } else {
            // Ground: a checker of 10-degree cells.
            let cell = |a: f32| (a / 10.0).floor() as i32;
            let dark = (cell(az) + cell(el)).rem_euclid(2) == 0;
            if dark { Color::gray(0.015) } else { Color::gray(0.04) }
        }
    }
}

/// Glass as on the slides' Fresnel material: a refraction layer under a reflection layer whose blend is the
/// Fresnel reflectance, both using the same (possibly dispersive) index.
pub fn fresnel_glass(ior: Ior) -> Layered {
    let mut glass = Layered::new();
    glass.add_layer(Arc::new(Refraction::with_ior(ior, 1.0)), Color::WHITE, None);
    glass.add_layer(
        Arc::new(Reflection::new(1.0)),
        Color::WHITE,
        Some(Arc::new(Fresnel::with_ior(ior, FresnelMode::Schlick))),
    );
    glass
}

/// The wavelength (nm) whose minimum-deviation ray through the prism's centre meets the slit.
pub const SLIT_WAVELENGTH: f32 = 560.0;

/// The prism's apex angle, degrees.
pub const APEX_ANGLE: f32 = 60.0;

/// The angle by which a prism of apex angle `apex` (degrees) and index `n` turns a ray passing it
/// symmetrically (minimum deviation), in degrees: `2 asin(n sin(A/2)) - A`. None if no ray gets through.
pub fn minimum_deviation(apex: f32, n: f32) -> Option<f32> {
    let s = n * (0.5 * apex.to_radians()).sin();
    (s < 1.0).then(|| 2.0 * s.asin().to_degrees() - apex)
}

impl Example for Args {
    const NAME: &'static str = "dispersion";
    const DEFAULT_SPP: u32 = 2;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let ior = self.ior()?;
        let mut scene = Scene::new(Camera { position: Vector::ZERO, fov: 60.0, ..Camera::default() });
        scene.max_depth = 5;

        // The prism, left of the view. The ray from the camera to its centre has azimuth `view`; at minimum
        // deviation it crosses the prism parallel to the base, turned by half the deviation, so the base faces
        // the side it bends to. Turning the canonical prism (base towards -Z) by `yaw` puts it there. (An
        // index with no ray through the prism, n sin(A/2) >= 1, leaves the slit straight ahead.)
        let centre = Vector::new(-2.6, 0.0, 10.0);
        let view = centre.x.atan2(centre.z).to_degrees();
        let deviation = minimum_deviation(APEX_ANGLE, ior.at(Some(SLIT_WAVELENGTH))).unwrap_or(0.0);
        let inside = view + 0.5 * deviation;
        let yaw = 90.0 - inside;
        scene.add(
            Node::new(Arc::new(Prism::new(APEX_ANGLE, 1.8, 2.4)), Arc::new(fresnel_glass(ior)))
                .rotate(yaw, 0.0, 0.0)
                .translate(centre),
        );

        // The gem: a sphere of the same glass.
        scene.add(Node::new(Arc::new(Sphere::new(Vector::new(2.8, -0.3, 10.0), 2.1)), Arc::new(fresnel_glass(ior))));

        // The slit, where the prism's central ray leaves it.
        scene.environment = Some(Arc::new(SlitEnvironment {
            azimuth: (view + deviation).to_radians(),
            half_width: 0.4f32.to_radians(),
            bottom: (-8.0f32).to_radians(),
            top: 12.0f32.to_radians(),
            radiance: 6.0,
        }));
        Ok(scene)
    }
}
