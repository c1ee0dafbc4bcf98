//! The interactive camera, as in the course's fly-through mode: keys move the camera along its own axes and
//! turn it, and dragging the mouse over the picture looks around. The camera stays the course's
//! [`Camera`] (position, yaw, pitch, roll, fov), so where the window ends up can be copied into a scene.

use crate::lesson::camera::{Camera, FovAxis, rotation};
use crate::lesson::math::Vector;

/// How the camera moves in one step: along its own axes (each in -1..=1, times the distance of the step)
/// and turns, in degrees.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Motion {
    /// Towards where the camera looks.
    pub forward: f32,
    /// Towards the picture's right edge.
    pub right: f32,
    /// Towards the picture's top edge.
    pub up: f32,
    /// Degrees to turn; positive turns left, as [`Camera::yaw`].
    pub yaw: f32,
    /// Degrees to tilt; positive looks up, as [`Camera::pitch`].
    pub pitch: f32,
    /// Degrees to roll, added to [`Camera::roll`].
    pub roll: f32,
}

impl Motion {
    /// True when the motion neither moves nor turns the camera.
    pub fn is_still(&self) -> bool {
        *self == Motion::default()
    }
}

/// The camera after `motion`, moving `distance` scene units per unit of motion. Pitch stops short of
/// straight up and down, where yaw would lose its meaning.
pub fn moved(camera: &Camera, motion: &Motion, distance: f32) -> Camera {
    let r = rotation(camera.yaw, camera.pitch, camera.roll);
    let step = r * Vector::new(motion.right, motion.up, motion.forward);
    Camera {
        position: camera.position + step * distance,
        yaw: (camera.yaw + motion.yaw + 180.0).rem_euclid(360.0) - 180.0,
        pitch: (camera.pitch + motion.pitch).clamp(-89.0, 89.0),
        roll: camera.roll + motion.roll,
        ..*camera
    }
}

/// The camera as the Rust that builds it, to paste into an example's scene.
pub fn as_code(camera: &Camera) -> String {
    let p = camera.position;
    let axis = match camera.fov_axis {
        FovAxis::Diagonal => String::new(),
        axis => format!("fov_axis: FovAxis::{axis:?}, "),
    };
    format!(
        "Camera {{ position: Vector::new({:.2}, {:.2}, {:.2}), yaw: {:.1}, pitch: {:.1}, roll: {:.1}, fov: {:.1}, \
         {axis}..Camera::default() }}",
        p.x, p.y, p.z, camera.yaw, camera.pitch, camera.roll, camera.fov
    )
}
