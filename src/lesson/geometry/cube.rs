//! The course's `Cube`: axis-aligned, given by its centre and half the side. u/v run from 0 to 1 across each
//! face (for the X faces u follows Z and v follows Y; for Y faces u = X, v = Z; for Z faces u = X, v = Y).
//! Scale and rotate it with a node transform to get any box.

use super::{Aabb, Geometry, Hit, IntersectionInfo};
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;

/// The course's axis-aligned cube (lectures 2-3); its normals point out of it. A node's transform makes any
/// box of it.
#[derive(Clone, Copy, Debug)]
pub struct Cube {
    /// The centre of the cube.
    pub center: Vector,
    /// Half the length of a side: the distance from the centre to each face.
    pub half_side: f32,
}

impl Cube {
    /// The cube around `center` whose faces are `half_side` from it.
    pub fn new(center: Vector, half_side: f32) -> Cube {
        Cube { center, half_side }
    }

    /// Slab test: the entry and exit parameters and the axes of the entry and exit faces.
    fn slabs(&self, ray: &Ray) -> Option<(f32, usize, f32, usize)> {
        let inv = ray.dir.recip();
        let lo = (self.center - self.half_side - ray.start) * inv;
        let hi = (self.center + self.half_side - ray.start) * inv;
        let (near, far) = (lo.min(hi), lo.max(hi));
        let mut entry = (f32::NEG_INFINITY, 0);
        let mut exit = (f32::INFINITY, 0);
        for axis in 0..3 {
            // NaN (a ray in the plane of a face, 0 * inf) imposes no limit.
            if near[axis] > entry.0 {
                entry = (near[axis], axis);
            }
            if far[axis] < exit.0 {
                exit = (far[axis], axis);
            }
        }
        (entry.0 <= exit.0).then_some((entry.0, entry.1, exit.0, exit.1))
    }
}

impl Cube {
    /// The surface at the hit at ray parameter `t` on a face perpendicular to `axis`.
    fn info(&self, ray: &Ray, t: f32, axis: usize) -> IntersectionInfo {
        let mut ip = ray.at(t);
        let local = ip - self.center;
        let sign = if local[axis] >= 0.0 { 1.0 } else { -1.0 };
        // Snap the hit onto the face it lies on.
        ip[axis] = self.center[axis] + sign * self.half_side;
        let mut normal = Vector::ZERO;
        normal[axis] = sign;
        let (a, b) = match axis {
            0 => (2, 1),
            1 => (0, 2),
            _ => (0, 1),
        };
        let side = 2.0 * self.half_side;
        let uv = |k: usize| ((local[k] + self.half_side) / side).clamp(0.0, 1.0);
        IntersectionInfo::new(ip, normal, t, (uv(a), uv(b)))
    }
}

impl Geometry for Cube {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.hit(ray, t_max).and_then(|hit| self.surface(ray, &hit))
    }

    /// The ray parameter and the axis of the face hit; the point, normal and u/v wait for the winner.
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (t_in, axis_in, t_out, axis_out) = self.slabs(ray)?;
        let (t, axis) = if t_in > 0.0 { (t_in, axis_in) } else { (t_out, axis_out) };
        (t > 0.0 && t < t_max).then_some(Hit { part: axis as u32, ..Hit::at(t) })
    }

    fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        Some(self.info(ray, hit.distance, hit.part as usize))
    }

    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.slabs(ray).is_some_and(|(t_in, _, t_out, _)| {
            let t = if t_in > 0.0 { t_in } else { t_out };
            t > 0.0 && t < t_max
        })
    }

    fn bounds(&self) -> Option<Aabb> {
        Some(Aabb::new(self.center - self.half_side, self.center + self.half_side))
    }
}
