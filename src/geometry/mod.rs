//! Geometry (lectures 2-3, and slide "Model трансформация"): the shapes rays can hit, each in its canonical
//! form: plane, sphere, cube, prism, triangle mesh (with its BVH). Placing a shape anywhere else is the job
//! of a [`Node`](crate::node::Node)'s transform.
//!
//! Every shape reports, with the hit, an absolute bound on the floating-point error of the hit point
//! (`IntersectionInfo::error`). Secondary rays start that far off the surface (see
//! [`Ray::spawn`](crate::ray::Ray::spawn)) instead of the slides' fixed `1e-6`, which is too small for a
//! scene at 1e6 and too large for one at 1e-4.

pub mod bvh;
mod cube;
pub mod mesh;
mod plane;
mod prism;
mod sphere;

pub use cube::Cube;
pub use mesh::Mesh;
pub use plane::Plane;
pub use prism::Prism;
pub use sphere::Sphere;

use crate::math::Vector;
use crate::ray::Ray;

/// What a ray hit (the course's `IntersectionInfo`).
#[derive(Clone, Copy, Debug)]
pub struct IntersectionInfo {
    /// The hit point.
    pub ip: Vector,
    /// The unit shading normal, pointing out of the object (not face-forwarded).
    pub normal: Vector,
    /// The unit normal of the surface itself (differs from `normal` on smoothly shaded meshes); used to
    /// offset secondary rays.
    pub geometric_normal: Vector,
    /// The ray parameter of the hit: its distance from the ray's start when the ray direction is unit.
    pub distance: f32,
    /// Texture coordinates.
    pub u: f32,
    pub v: f32,
    /// An absolute bound on the rounding error of `ip`, in each coordinate.
    pub error: f32,
}

/// A shape in its canonical form.
pub trait Geometry: Send + Sync {
    /// The closest hit with ray parameter in (0, `t_max`), if any. The ray direction need not be unit
    /// (rays reach here through a node's inverse transform); `distance` is the ray parameter either way.
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo>;

    /// Whether anything is hit with ray parameter in (0, `t_max`) (shadow rays). Shapes with a cheaper
    /// any-hit test override it.
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.intersect(ray, t_max).is_some()
    }

    /// The shape's bounding box, or `None` for a shape too large to bound usefully.
    fn bounds(&self) -> Option<Aabb>;

    /// What the ray tree (`--trace-pixel`) calls this shape: its type's name.
    fn name(&self) -> &'static str {
        crate::ray_tree::type_label::<Self>()
    }
}

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vector,
    pub max: Vector,
}

impl Aabb {
    pub fn new(min: Vector, max: Vector) -> Aabb {
        Aabb { min, max }
    }
    pub fn center(&self) -> Vector {
        (self.min + self.max) * 0.5
    }
    /// The eight corners.
    pub fn corners(&self) -> [Vector; 8] {
        std::array::from_fn(|i| {
            Vector::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }
    /// The smallest box holding all the points.
    pub fn from_points(points: impl IntoIterator<Item = Vector>) -> Aabb {
        points.into_iter().fold(Aabb::new(Vector::splat(f32::INFINITY), Vector::splat(f32::NEG_INFINITY)), |b, p| {
            Aabb::new(b.min.min(p), b.max.max(p))
        })
    }
}
