//! The course's pinhole camera: a position, a yaw/pitch/roll orientation in degrees and a field of view.
//!
//! Conventions (the same as the course's C++ `Camera`, so its scenes carry over unchanged):
//! - With zero angles the camera looks along +Z, +Y is up and +X is to the right.
//! - The orientation is applied as roll (about Z), then pitch (about X; positive looks up), then yaw (about Y;
//!   positive turns to the left, towards -X).
//! - `fov` is the angle, in degrees, across the image's **diagonal** (the course measures it from the centre
//!   to a corner); `aspect` is width / height and is set from the image size when a frame begins.
//!
//! Deviation: [`FovAxis`] lets `fov` be measured across the height or the width instead (`--fov-axis`). With
//! the course's diagonal a wider picture shows less at the top and bottom (1920 x 1080 crops the top of the
//! fresnel sphere that 640 x 480 shows); with `vertical` the vertical extent stays whatever the aspect ratio
//! (ledger: `fov-axis`).

use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use glam::Mat3A;

/// The fields of view, in degrees, that a camera may be given from outside the code (a scene file's `fov`,
/// `--fov`): wider than a point and short of 180, where the image plane would be infinitely wide.
pub const FOV_LIMITS: std::ops::RangeInclusive<f64> = 0.0001..=179.0;

/// The pinhole camera: where it stands, where it looks (yaw, pitch, roll) and how much it sees (`fov`).
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// Where the camera stands, in world space.
    pub position: Vector,
    /// Degrees; positive turns left.
    pub yaw: f32,
    /// Degrees; positive looks up.
    pub pitch: f32,
    /// Degrees; positive tilts the picture clockwise.
    pub roll: f32,
    /// Degrees, across the diagonal of the image (or the axis `fov_axis` names).
    pub fov: f32,
    /// Which extent of the image `fov` spans: the course's diagonal unless a scene or `--fov-axis` says otherwise.
    pub fov_axis: FovAxis,
    /// Width / height.
    pub aspect: f32,
}

impl Default for Camera {
    fn default() -> Camera {
        Camera {
            position: Vector::ZERO,
            yaw: 0.0,
            pitch: 0.0,
            roll: 0.0,
            fov: 90.0,
            fov_axis: FovAxis::Diagonal,
            aspect: 4.0 / 3.0,
        }
    }
}

/// The extent of the image across which the camera's field of view is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum FovAxis {
    /// Corner to corner, as the course measures it: a change of aspect ratio changes both extents.
    #[default]
    Diagonal,
    /// Top to bottom: the vertical extent stays when the aspect ratio changes (most renderers' choice).
    Vertical,
    /// Left to right: the horizontal extent stays when the aspect ratio changes.
    Horizontal,
}

impl FovAxis {
    /// The length of this extent on an image plane `aspect` wide and 1 high.
    fn length(self, aspect: f32) -> f32 {
        match self {
            FovAxis::Diagonal => aspect.hypot(1.0),
            FovAxis::Vertical => 1.0,
            FovAxis::Horizontal => aspect,
        }
    }
}

/// The course's rotation: roll, then pitch, then yaw, with the course's signs.
pub fn rotation(yaw: f32, pitch: f32, roll: f32) -> Mat3A {
    Mat3A::from_rotation_y(-yaw.to_radians())
        * Mat3A::from_rotation_x(-pitch.to_radians())
        * Mat3A::from_rotation_z(-roll.to_radians())
}

/// A camera prepared for one frame of a given size (the course's `Camera::frameBegin`).
#[derive(Clone, Copy, Debug)]
pub struct CameraFrame {
    position: Vector,
    up_left: Vector,
    /// From the left edge to the right edge of the image plane.
    across: Vector,
    /// From the top edge to the bottom edge.
    down: Vector,
    width: f32,
    height: f32,
}

impl Camera {
    /// A camera at `from` looking at `to`, with the picture upright (no roll) and a field of view of `fov`
    /// degrees across the diagonal: the course's yaw and pitch computed from the direction, so that a scene
    /// is framed without trying angles. The direction must not be straight up or down.
    pub fn look_at(from: Vector, to: Vector, fov: f32) -> Camera {
        let d = (to - from).normalize();
        // With zero angles the camera looks along +Z; pitch lifts the view towards +Y, then a positive yaw
        // turns it towards -X (see `rotation`).
        let pitch = d.y.clamp(-1.0, 1.0).asin().to_degrees();
        let yaw = (-d.x).atan2(d.z).to_degrees();
        Camera { position: from, yaw, pitch, fov, ..Camera::default() }
    }

    /// The same camera with its field of view measured across `axis`, converted so that a picture of aspect
    /// ratio `aspect` (width / height) stays exactly as it was; other aspect ratios then keep that extent.
    /// `--fov-axis vertical` converts at the default 640 x 480, so that a scene framed there keeps its
    /// height at 1920 x 1080.
    pub fn with_fov_axis(self, axis: FovAxis, aspect: f32) -> Camera {
        let half = (self.fov.to_radians() * 0.5).tan() * axis.length(aspect) / self.fov_axis.length(aspect);
        Camera { fov: (half.atan() * 2.0).to_degrees(), fov_axis: axis, ..self }
    }

    /// Prepares the camera for a `width` x `height` image (sets `aspect`).
    pub fn frame(&self, width: u32, height: u32) -> CameraFrame {
        let aspect = width as f32 / height as f32;
        // On the unscaled image plane (from -aspect to aspect across, -1 to 1 up, at distance 1) the end of
        // the measured extent must lie fov/2 from the axis: the corner (-aspect, 1) for the diagonal.
        let scaling = (self.fov.to_radians() * 0.5).tan() / self.fov_axis.length(aspect);
        let (x, y) = (-aspect * scaling, scaling);
        let r = rotation(self.yaw, self.pitch, self.roll);
        let up_left = r * Vector::new(x, y, 1.0);
        let up_right = r * Vector::new(-x, y, 1.0);
        let down_left = r * Vector::new(x, -y, 1.0);
        CameraFrame {
            position: self.position,
            up_left,
            across: up_right - up_left,
            down: down_left - up_left,
            width: width as f32,
            height: height as f32,
        }
    }
}

impl CameraFrame {
    /// The camera ray through the image point (x, y), measured in pixels from the top-left corner
    /// (pixel (i, j) covers [i, i+1) x [j, j+1); its centre is (i + 0.5, j + 0.5)).
    pub fn get_screen_ray(&self, x: f32, y: f32) -> Ray {
        let through = self.up_left + self.across * (x / self.width) + self.down * (y / self.height);
        Ray::new(self.position, through.normalize())
    }
}
