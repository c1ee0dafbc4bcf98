//! The course's `Plane`: the horizontal plane y = `y`, limited to |x|, |z| < `limit`, with u = x and v = z
//! (a texture's `scaling` turns these world units into texture repeats). Tilt or move it with a node
//! transform; its u/v stay attached to it.

use super::{Aabb, Geometry, IntersectionInfo};
use crate::math::{Vector, gamma, max_abs};
use crate::ray::Ray;

#[derive(Clone, Copy, Debug)]
pub struct Plane {
    pub y: f32,
    /// Half the side of the square the plane is limited to; `f32::INFINITY` for an endless plane.
    pub limit: f32,
}

impl Plane {
    pub fn new(y: f32, limit: f32) -> Plane {
        Plane { y, limit }
    }
}

impl Geometry for Plane {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        // A ray parallel to the plane (dir.y == 0) gives t = +-inf or NaN, and both fail this test.
        let t = (self.y - ray.start.y) / ray.dir.y;
        if !(t > 0.0 && t < t_max) {
            return None;
        }
        let mut ip = ray.at(t);
        if ip.x.abs() >= self.limit || ip.z.abs() >= self.limit {
            return None;
        }
        // The hit lies on the plane by definition: snap y, so only x and z carry rounding error.
        ip.y = self.y;
        let normal = Vector::Y;
        Some(IntersectionInfo {
            ip,
            normal,
            geometric_normal: normal,
            distance: t,
            u: ip.x,
            v: ip.z,
            error: gamma(3) * max_abs(ip),
        })
    }

    fn bounds(&self) -> Option<Aabb> {
        self.limit.is_finite().then(|| {
            Aabb::new(Vector::new(-self.limit, self.y, -self.limit), Vector::new(self.limit, self.y, self.limit))
        })
    }
}
