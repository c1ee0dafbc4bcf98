//! The `Ray` of the lecture (slide "Adding reflection/refraction levels to Ray"): a start point, a unit
//! direction and the recursion `depth`. Two fields go beyond the slide and are used by later topics:
//! `weight`, how much this ray can still change its pixel (the product of the multipliers, blends and Fresnel
//! factors along its path, for adaptive ray-tree depth control), and `wavelength`, set for the passes of a
//! dispersive render.

use crate::lesson::geometry::intersection::IntersectionInfo;
use crate::lesson::math::{Vector, offset_ray_origin};

/// A ray: where it starts, where it goes and how deep in the ray tree it is.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    /// The point the ray starts from, in world space (in a geometry's canonical space while a node intersects it).
    pub start: Vector,
    /// Unit length for rays made by the camera and the shaders.
    pub dir: Vector,
    /// 0 for camera rays; each reflection or refraction adds 1.
    pub depth: u32,
    /// How much this ray contributes to its pixel: 1 for camera rays. A shader that averages N random
    /// samples gives each sample its full attenuation, not 1/N of it: each sample estimates the whole (the
    /// core bounds the branching of such an average: [`crate::lesson::branching`]).
    pub weight: f32,
    /// Wavelength in nanometres when the ray carries a single wavelength (dispersion), else `None`.
    pub wavelength: Option<f32>,
}

impl Ray {
    /// A camera ray (depth 0, full weight, white light).
    pub fn new(start: Vector, dir: Vector) -> Ray {
        Ray { start, dir, depth: 0, weight: 1.0, wavelength: None }
    }

    /// The point at parameter `t` along the ray.
    pub fn at(&self, t: f32) -> Vector {
        self.start + t * self.dir
    }

    /// A secondary ray spawned by a shader at the hit `info` (a reflection, a refraction, a glossy sample):
    /// going in the unit direction `dir`, one level deeper, carrying this ray's wavelength, its weight scaled
    /// by `attenuation`. **`attenuation` is the factor the shader multiplies this ray's colour by (a mirror's
    /// colour, its brightest channel; a glass's Fresnel factor), in full for each ray of an average of N,
    /// not 1/N of it**: rays too faint to change the picture are then not traced, and the core keeps an
    /// average's rays from multiplying ([`crate::lesson::branching`]; a 1/N share would prune the deep
    /// rays and darken the picture the more rays are averaged). It starts at the hit point
    /// moved off the surface, to the side `dir` goes to, by the hit's error bound. This replaces the slides'
    /// `info.ip + 1e-6 * n`, which fails for scenes much larger or smaller than the course's.
    #[inline(always)]
    pub fn spawn(&self, info: &IntersectionInfo, dir: Vector, attenuation: f32) -> Ray {
        Ray {
            start: spawn_point(info.ip, info.geometric_normal, info.error, dir),
            dir,
            depth: self.depth + 1,
            weight: self.weight * attenuation,
            wavelength: self.wavelength,
        }
    }
}

/// Where a ray leaving the surface point `p` (normal `n`, error bound `error`) in direction `dir` starts:
/// `p` moved off the surface, to the side `dir` goes to, by the error bound.
#[inline(always)]
pub fn spawn_point(p: Vector, n: Vector, error: f32, dir: Vector) -> Vector {
    offset_ray_origin(p, if dir.dot(n) >= 0.0 { n } else { -n }, error)
}
