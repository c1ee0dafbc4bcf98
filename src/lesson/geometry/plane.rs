//! The course's `Plane`: the horizontal plane y = `y`, limited to |x|, |z| < `limit`, with u = x and v = z
//! (a bitmap's tile size or a checker's scaling turns these world units into texture repeats). Tilt or move
//! it with a node transform; its u/v stay attached to it.

use super::{Aabb, Geometry, Hit, IntersectionInfo, Shape};
use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use std::sync::Arc;

/// The course's horizontal plane y = `y`, with u = x and v = z; its normal is +Y (up) whichever side a ray comes from.
#[derive(Clone, Copy, Debug)]
pub struct Plane {
    /// The height of the plane.
    pub y: f32,
    /// Half the side of the square the plane is limited to; `f32::INFINITY` for an endless plane.
    pub limit: f32,
}

impl Plane {
    /// The plane y = `y`, limited to |x| and |z| below `limit` (`f32::INFINITY` for no limit).
    pub fn new(y: f32, limit: f32) -> Plane {
        Plane { y, limit }
    }
}

impl Geometry for Plane {
    #[inline(always)]
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.hit(ray, t_max).and_then(|hit| self.surface(ray, &hit))
    }

    /// The ray parameter and the hit's x and z (its u/v); the rest is known from them.
    #[inline(always)]
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        // A ray parallel to the plane (dir.y == 0) gives t = +-inf or NaN, and both fail this test.
        let t = (self.y - ray.start.y) / ray.dir.y;
        if !(t > 0.0 && t < t_max) {
            return None;
        }
        let ip = ray.at(t);
        if ip.x.abs() >= self.limit || ip.z.abs() >= self.limit {
            return None;
        }
        Some(Hit { distance: t, part: 0, coords: [ip.x, ip.z, 0.0] })
    }

    #[inline(always)]
    fn surface(&self, _ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        // The hit lies on the plane by definition: its y is the plane's, so only x and z carry rounding error.
        let [x, z, _] = hit.coords;
        Some(IntersectionInfo::new(Vector::new(x, self.y, z), Vector::Y, hit.distance, (x, z)))
    }

    /// The first phase alone: a shadow ray needs no surface.
    #[inline(always)]
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.hit(ray, t_max).is_some()
    }

    fn bounds(&self) -> Option<Aabb> {
        self.limit.is_finite().then(|| {
            Aabb::new(Vector::new(-self.limit, self.y, -self.limit), Vector::new(self.limit, self.y, self.limit))
        })
    }

    fn into_shape(self: Arc<Self>) -> Shape {
        Shape::Plane(*self)
    }
}
