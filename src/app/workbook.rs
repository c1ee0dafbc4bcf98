//! What the workbook's examples share that is not a slide's lesson: the bundled textures (under
//! `textures/`, made by `cargo run --bin make-assets`), the sky, a checker floor, the mirror room of the two
//! reflection examples and the dark studio of the dispersion example. A homework built on an example uses
//! them the same way, or its own files in their place.

use crate::lesson::bitmap::{Bitmap, Filter};
use crate::lesson::camera::Camera;
use crate::lesson::color::Color;
use crate::lesson::environment::{self, CubemapEnvironment, Environment};
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::{Cube, Plane, Sphere};
use crate::lesson::light::PointLight;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::scene::Scene;
use crate::lesson::shader::{Lambert, Phong, Reflection};
use crate::lesson::texture::{BitmapTexture, CheckerTexture};
use std::f32::consts::{PI, TAU};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The path of a bundled texture (under the workbook's `textures/`, wherever it is run from).
pub fn texture_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("textures").join(name)
}

/// Loads the bundled texture `name` (bilinearly filtered, repeating).
pub fn texture(name: &str) -> Result<BitmapTexture> {
    load_texture(name, None, Filter::default())
}

/// Loads a bundled texture, or the student's own file in its place when `custom` is given.
pub fn load_texture(name: &str, custom: Option<&Path>, filter: Filter) -> Result<BitmapTexture> {
    let path = custom.map_or_else(|| texture_path(name), Path::to_path_buf);
    Ok(BitmapTexture::new(Arc::new(Bitmap::load(&path)?)).with_filter(filter))
}

/// The bundled sky (`textures/sky.hdr`) as an equirectangular environment.
pub fn sky() -> Result<Arc<dyn Environment>> {
    environment::load(&texture_path("sky.hdr"))
}

/// The same sky as six cube faces (`textures/sky_cubemap/`).
pub fn sky_cubemap() -> Result<Arc<dyn Environment>> {
    Ok(Arc::new(CubemapEnvironment::load(&texture_path("sky_cubemap"))?))
}

/// The direction of the bundled sky's sun.
pub fn sun_direction() -> Vector {
    crate::app::assets::sun_direction()
}

/// A square floor of `2 * half_size` units at y = 0, in light and dark grey squares of `square` units.
pub fn checker_floor(half_size: f32, square: f32) -> Node {
    let checker = CheckerTexture { color1: Color::gray(0.75), color2: Color::gray(0.18), scaling: 1.0 / square };
    Node::new(Plane::new(0.0, half_size), Lambert::new(checker))
}

/// The scene of the reflection examples (`reflect_v01`, `reflect_v02`): two mirror spheres reflecting
/// `multiplier` of the light and a red ball on a checker floor under the sky; with `facing_mirrors`, two
/// large framed mirrors facing each other along the camera's axis, one 140 units in front of the camera and
/// one 40 units behind it. The caller sets the depth limit, which is what the two examples are about.
pub fn mirror_room(multiplier: f32, facing_mirrors: bool) -> Result<Scene> {
    if !(0.0..=1.0).contains(&multiplier) {
        return Err(Error::parameter("--multiplier", multiplier, "must be between 0 and 1"));
    }
    // The camera looks along +Z at the height of the mirrors' centres, square-on to them.
    let mut scene = Scene::new(Camera { position: Vector::new(0.0, 30.0, -40.0), fov: 75.0, ..Camera::default() });
    // The sky and the frames' wood are read side by side, on two threads.
    let (sky, wood) = rayon::join(sky, || facing_mirrors.then(|| texture("wood.png")).transpose());
    scene.environment = Some(sky?);
    scene.ambient = Color::gray(0.15);
    scene.lights.push(PointLight::new(Vector::new(-80.0, 250.0, 20.0), Color::new(1.0, 0.96, 0.9), 75000.0));
    scene.add(checker_floor(150.0, 20.0));

    // One mirror shader and one wooden frame shader, shared by the nodes that use them.
    let mirror = Arc::new(Reflection::new(multiplier));
    scene.add(Node::new(Sphere::new(Vector::new(-28.0, 15.0, 45.0), 15.0), mirror.clone()));
    scene.add(Node::new(Sphere::new(Vector::new(28.0, 15.0, 45.0), 15.0), mirror.clone()));
    scene.add(Node::new(
        Sphere::new(Vector::new(0.0, 8.0, 70.0), 8.0),
        Phong::new(Color::new(0.75, 0.12, 0.08), 0.3, 60.0),
    ));

    if let Some(wood) = wood? {
        // Each mirror is a thin box in a slightly larger wooden frame just behind it.
        let wood = Arc::new(Lambert::new(wood));
        for z in [100.0f32, -80.0] {
            let behind = z + z.signum();
            scene.add(
                Node::new(Cube::new(Vector::ZERO, 1.0), mirror.clone())
                    .scale(Vector::new(60.0, 30.0, 0.5))
                    .translate(Vector::new(0.0, 30.0, z)),
            );
            scene.add(
                Node::new(Cube::new(Vector::ZERO, 1.0), wood.clone())
                    .scale(Vector::new(64.0, 34.0, 1.0))
                    .translate(Vector::new(0.0, 30.0, behind)),
            );
        }
    }
    Ok(scene)
}

/// The dispersion example's studio: dark, lit by one bright vertical slit (a narrow strip of the
/// environment) and a ring of small square lamps, with a dim sky above the horizon and a dim checkered
/// ground below it, so that refraction shows against it.
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
        let off = (azimuth - self.azimuth + PI).rem_euclid(TAU) - PI;
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
