//! The studio of the slide "Хроматично пречупване" (chromatic dispersion), where the `dispersion` example
//! puts its prism: a dark room lit by one bright white slit and a ring of small lamps, so that the colours the
//! glass splits white light into show against it.

use crate::lesson::color::Color;
use crate::lesson::environment::Environment;
use crate::lesson::math::Vector;
use std::f32::consts::{PI, TAU};

/// The studio: dark, lit by one bright vertical slit (a narrow strip of the
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
    /// The elevation of the slit's top, radians above the horizon.
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
