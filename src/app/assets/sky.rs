//! The generated sky (slide "Заден фон"): a procedural outdoor environment with a sun, a sky that pales
//! towards a hazy horizon, a few clouds and a ground of fields, in linear light (the sun is far brighter
//! than white). It is written once as an equirectangular Radiance HDR image, `sky.hdr`, and once as a cube
//! map made from that image, `sky_cubemap/{posx,...}.hdr`, so both environments show the same world.

use super::{fbm, lattice, mix};
use crate::lesson::bitmap::Bitmap;
use crate::lesson::color::Color;
use crate::lesson::environment::{
    CubeFace, Environment, SphericalEnvironment, cube_face_direction, equirect_direction,
};
use crate::lesson::math::Vector;
use image::{Rgb, Rgb32FImage};
use std::sync::{Arc, OnceLock};

/// Size of the equirectangular sky.
const SKY_SIZE: (u32, u32) = (512, 256);
/// Size of each cube face.
const FACE_SIZE: u32 = 128;

/// Where the sun is: 30° above the horizon, behind the default camera and to its right.
pub fn sun_direction() -> Vector {
    let (elevation, azimuth) = (30f32.to_radians(), 140f32.to_radians());
    Vector::new(elevation.cos() * azimuth.sin(), elevation.sin(), elevation.cos() * azimuth.cos())
}

/// Angular radius of the sun's disc (larger than the real 0.27° so that it spans several texels).
const SUN_RADIUS_DEGREES: f32 = 2.0;
/// Radiance of the sun's disc: bright enough to stay white after several reflections.
const SUN: [f32; 3] = [60.0, 54.0, 44.0];

/// The radiance seen in the unit direction `d`.
fn sky_radiance(d: Vector) -> [f32; 3] {
    let sun = sun_direction();
    let cos_sun = d.dot(sun);
    if cos_sun >= SUN_RADIUS_DEGREES.to_radians().cos() {
        return SUN;
    }
    let glow = cos_sun.max(0.0).powi(200) * 2.0 + cos_sun.max(0.0).powi(8) * 0.25;
    let horizon = [0.78, 0.84, 0.92];
    let c = if d.y >= 0.0 {
        let zenith = [0.12, 0.27, 0.70];
        let sky = mix(horizon, zenith, d.y.sqrt() * 1.15);
        // Clouds on a plane above the ground, thinning towards the horizon.
        let (px, pz) = (d.x / (d.y + 0.08), d.z / (d.y + 0.08));
        let density = fbm(71, [px * 1.5 + 20.0, pz * 1.5 + 20.0, 0.0], [0; 3], 4);
        let cover = ((density - 0.52) * 5.0).clamp(0.0, 1.0) * (d.y * 6.0).min(1.0);
        let cloud = [1.05, 1.05, 1.08].map(|v| v * (0.8 + 0.3 * density));
        mix(sky, cloud, cover)
    } else {
        // Fields on the ground plane one unit below, each its own shade of green or brown.
        let (px, pz) = (d.x / -d.y, d.z / -d.y);
        let (fx, fz) = ((px * 2.5).floor() as i64, (pz * 2.5).floor() as i64);
        let kind = lattice(5, fx, fz, 0);
        let field = mix([0.09, 0.16, 0.05], [0.22, 0.17, 0.09], kind);
        let grain = 0.8 + 0.4 * fbm(13, [px * 6.0, pz * 6.0, 0.0], [0; 3], 3);
        let ground = field.map(|v| v * grain);
        // The haze that hides the far ground.
        mix(horizon, ground, (-d.y * 12.0).min(1.0))
    };
    let tint = [1.0, 0.85, 0.6];
    [0, 1, 2].map(|i| c[i] + glow * tint[i])
}

/// The sky as the function that both `sky.hdr` and `sky_cubemap/` sample, without texels: the truth that
/// the two kinds of environment map are measured against (slower to look up than either image).
#[derive(Clone, Copy, Debug, Default)]
pub struct SkyFunction;

impl Environment for SkyFunction {
    fn get(&self, dir: Vector) -> Color {
        let [r, g, b] = sky_radiance(dir);
        Color::new(r, g, b)
    }
}

/// The equirectangular sky, `sky.hdr`: the radiance at the centre of each texel, averaged over 2 x 2
/// samples so the sun's edge and the horizon are smooth.
pub fn sky_equirect() -> Rgb32FImage {
    let (w, h) = SKY_SIZE;
    Rgb32FImage::from_fn(w, h, |x, y| {
        let mut sum = [0.0; 3];
        for (dx, dy) in [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)] {
            let d = equirect_direction((x as f32 + dx) / w as f32, (y as f32 + dy) / h as f32);
            let c = sky_radiance(d);
            sum = [0, 1, 2].map(|i| sum[i] + 0.25 * c[i]);
        }
        Rgb(sum)
    })
}

/// One face of `sky_cubemap/`, resampled from the equirectangular sky (drawn once and shared).
pub fn sky_face<const FACE: usize>() -> Rgb32FImage {
    static SKY: OnceLock<SphericalEnvironment> = OnceLock::new();
    let sky = SKY.get_or_init(|| {
        let img = sky_equirect();
        let pixels = img.pixels().map(|p| Color::new(p[0], p[1], p[2])).collect();
        SphericalEnvironment::new(Arc::new(Bitmap::from_pixels(img.width() as usize, img.height() as usize, pixels)))
    });
    let n = FACE_SIZE;
    Rgb32FImage::from_fn(n, n, |x, y| {
        let d = cube_face_direction(CubeFace::ALL[FACE], (x as f32 + 0.5) / n as f32, (y as f32 + 0.5) / n as f32);
        Rgb(sky.get(d).to_array())
    })
}
