//! The course's `Sphere`: a centre and a radius, with u/v from spherical coordinates
//! (u = longitude / 2 pi, measured from -X through +Z; v = 0 at the top, 1 at the bottom), as in the course.
//! Scale it with a node transform to get an ellipsoid.

use super::{Aabb, Geometry, Hit, IntersectionInfo, Shape, TexCoords};
use crate::lesson::math::{Vector, gamma, max_abs};
use crate::lesson::ray::Ray;
use std::f32::consts::{FRAC_1_PI, PI};
use std::sync::Arc;

/// The course's sphere, with u/v from longitude and latitude; its normals point out of it. A node's transform
/// scales it into an ellipsoid.
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    /// The centre of the sphere.
    pub center: Vector,
    /// The radius.
    pub radius: f32,
}

impl Sphere {
    /// The sphere around `center` with the given radius.
    pub fn new(center: Vector, radius: f32) -> Sphere {
        Sphere { center, radius }
    }

    /// The two ray parameters where the ray meets the sphere, smaller first; `None` when the ray's line
    /// misses the sphere, or when the ray starts outside it and points away from its centre (both
    /// parameters would be negative: the sphere is behind the ray).
    ///
    /// The discriminant is computed as r^2 - |f|^2 with f the offset from the centre to the ray's closest
    /// point (pbrt-v4, section 6.8.4), and the roots by the cancellation-free form, so that rays starting
    /// far away or right on the surface still get accurate parameters.
    #[inline(always)]
    fn roots(&self, ray: &Ray) -> Option<(f32, f32)> {
        let oc = ray.start - self.center;
        let b = oc.dot(ray.dir);
        let c = oc.length_squared() - self.radius * self.radius;
        // Outside (c > 0) and going away (b > 0): no square root or division needed to know that the sphere
        // is behind the ray (Ericson, "Real-Time Collision Detection", 5.3.2). Rays that leave the sphere's
        // surface outwards, a reflection off it or a refraction out of it, stop here.
        if c > 0.0 && b > 0.0 {
            return None;
        }
        let a = ray.dir.length_squared();
        let f = oc - (b / a) * ray.dir;
        // Most rays miss: decide that from squared lengths, before any square root or division.
        if f.length_squared() > self.radius * self.radius {
            return None;
        }
        let disc = a * (self.radius - f.length()) * (self.radius + f.length());
        // `disc` is NaN for a degenerate ray: treat that as a miss too.
        if disc.is_nan() || disc < 0.0 {
            return None;
        }
        let q = -(b + disc.sqrt().copysign(b));
        let (t0, t1) = (q / a, c / q);
        Some(if t0 <= t1 { (t0, t1) } else { (t1, t0) })
    }
}

impl Sphere {
    /// The surface at the hit at ray parameter `t`.
    #[inline(always)]
    fn info(&self, ray: &Ray, t: f32) -> IntersectionInfo {
        // Re-project the hit onto the sphere: the error is then that of the projection, not of t.
        let d = ray.at(t) - self.center;
        // A sphere smaller than the spacing of floats where it stands can round the hit onto its centre:
        // then the side facing the ray is the only sensible normal.
        let normal = d.try_normalize().unwrap_or_else(|| -ray.dir.normalize());
        let ip = self.center + normal * self.radius;
        IntersectionInfo::new(ip, normal, t, (0.0, 0.0))
            .with_error(gamma(5) * (max_abs(self.center) + self.radius))
            .with_tex_coords(TexCoords::deferred(normal.to_array(), spherical_uv))
    }
}

/// The course's u/v of the point with unit normal `[x, y, z]` on a sphere: longitude and latitude, computed
/// only when a shader reads them (two inverse trigonometric functions, which glass and mirrors never need).
fn spherical_uv([x, y, z]: [f32; 3]) -> (f32, f32) {
    let u = (PI + z.atan2(x)) * (0.5 * FRAC_1_PI);
    let v = 1.0 - (0.5 * PI + y.clamp(-1.0, 1.0).asin()) * FRAC_1_PI;
    (u, v)
}

impl Geometry for Sphere {
    #[inline(always)]
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.hit(ray, t_max).map(|hit| self.info(ray, hit.distance))
    }

    /// Only the ray parameter: the normal waits for the winner, and its u/v for a shader that reads them.
    #[inline(always)]
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let (t0, t1) = self.roots(ray)?;
        let t = if t0 > 0.0 { t0 } else { t1 };
        (t > 0.0 && t < t_max).then_some(Hit::at(t))
    }

    #[inline(always)]
    fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        Some(self.info(ray, hit.distance))
    }

    #[inline(always)]
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.roots(ray).is_some_and(|(t0, t1)| (t0 > 0.0 && t0 < t_max) || (t1 > 0.0 && t1 < t_max))
    }

    fn bounds(&self) -> Option<Aabb> {
        Some(Aabb::new(self.center - self.radius, self.center + self.radius))
    }

    fn into_shape(self: Arc<Self>) -> Shape {
        Shape::Sphere(*self)
    }
}
