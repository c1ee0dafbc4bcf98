//! Geometry (lectures 2-3, and slide "Model трансформация"): the shapes rays can hit, each in its canonical
//! form: plane, sphere, cube, prism, triangle mesh (with its BVH). Placing a shape anywhere else is the job
//! of a [`Node`](crate::lesson::node::Node)'s transform.
//!
//! Every shape reports, with the hit, an absolute bound on the floating-point error of the hit point
//! (`IntersectionInfo::error`). Secondary rays start that far off the surface (see
//! [`Ray::spawn`](crate::lesson::ray::Ray::spawn)) instead of the slides' fixed `1e-6`, which is too small for a
//! scene at 1e6 and too large for one at 1e-4.

pub mod bvh;
mod cube;
pub mod intersection;
pub mod mesh;
mod one_by_one;
mod plane;
pub mod polygon;
mod prism;
mod shape;
mod sphere;
pub mod triangle4;

pub use cube::Cube;
pub use intersection::{IntersectionInfo, TexCoords, UvFunction};
pub use mesh::Mesh;
pub use plane::Plane;
pub use prism::Prism;
pub use shape::{IntoGeometry, Shape};
pub use sphere::Sphere;

use crate::lesson::math::Vector;
use crate::lesson::ray::Ray;
use std::any::Any;
use std::sync::Arc;

/// What the first, cheap phase of a closest-hit search found on a shape (see [`Geometry::hit`]): the ray
/// parameter, and what the shape needs to describe its surface there later: which part of it was hit (a
/// triangle, a face) and up to three coordinates on that part (barycentric coordinates).
///
/// The scene looks for the nearest hit over all its nodes with [`Geometry::hit`] and describes only the
/// winner's surface ([`Geometry::surface`]): the normal, u/v (spherical coordinates cost two inverse
/// trigonometric functions) and the error bound are computed once per ray instead of once per candidate
/// (pbrt's two-phase intersection). A `Hit` is kept small (20 bytes) because the search copies one for every
/// candidate that comes closer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter of the hit.
    pub distance: f32,
    /// Which part was hit: a mesh's triangle, the axis of a cube's face; 0 for a shape of one part.
    pub part: u32,
    /// What the shape keeps to describe the surface later: a triangle's barycentric coordinates, a plane's x
    /// and z; unused entries are 0.
    pub coords: [f32; 3],
}

impl Hit {
    /// A hit at ray parameter `distance`, on part 0, with no coordinates: all a shape needs when it finds
    /// its surface from the distance alone.
    pub fn at(distance: f32) -> Hit {
        Hit { distance, part: 0, coords: [0.0; 3] }
    }
}

/// A shape in its canonical form.
///
/// A new shape needs [`intersect`](Geometry::intersect) (its closest hit, described with
/// [`IntersectionInfo::new`]) and [`bounds`](Geometry::bounds) (or `None`); the other methods have correct
/// defaults, which call `intersect`: for the closest hit of a ray, once for the search and once more for
/// the surface of the winner. A shape whose surface description is expensive (or that wants to avoid the
/// second intersection) overrides [`hit`](Geometry::hit), to return just the ray parameter and what it needs
/// later, together with [`surface`](Geometry::surface), which finishes it.
pub trait Geometry: Any + Send + Sync + GeometryObject {
    /// The closest hit with ray parameter in (0, `t_max`), if any. The ray direction need not be unit
    /// (rays reach here through a node's inverse transform); `distance` is the ray parameter either way.
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo>;

    /// The first phase of a closest-hit search: where the ray meets the shape, the same hit as `intersect`,
    /// without its surface description (see [`Hit`]).
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        self.intersect(ray, t_max).map(|info| Hit::at(info.distance))
    }

    /// The second phase: the surface description of a hit that [`hit`](Geometry::hit) found for the same
    /// ray. `None` only if the shape cannot find the hit again.
    fn surface(&self, ray: &Ray, _hit: &Hit) -> Option<IntersectionInfo> {
        // The closest hit in (0, inf) is the closest one in (0, t_max) that `hit` found.
        self.intersect(ray, f32::INFINITY)
    }

    /// Whether anything is hit with ray parameter in (0, `t_max`) (shadow rays). Shapes with a cheaper
    /// any-hit test override it.
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        self.intersect(ray, t_max).is_some()
    }

    /// The shape's bounding box, or `None` for a shape too large to bound usefully.
    fn bounds(&self) -> Option<Aabb>;

    /// What the ray tree (`--trace-pixel`) calls this shape: its type's name.
    fn name(&self) -> &'static str {
        crate::lesson::type_label::<Self>()
    }

    /// The shape as a node stores it ([`Shape`]): for any shape but the workbook's own, the case that calls
    /// it through its trait object, [`Shape::Own`]. A new shape leaves it as it is.
    fn into_shape(self: Arc<Self>) -> Shape {
        Shape::Own(self.into_object())
    }
}

/// Any sized [`Geometry`] as a trait object: what [`Geometry::into_shape`] keeps of a shape that is not one
/// of the workbook's. Implemented for every shape; nothing to write.
pub trait GeometryObject {
    /// The shape behind a trait object.
    fn into_object(self: Arc<Self>) -> Arc<dyn Geometry>;
}

impl<G: Geometry> GeometryObject for G {
    fn into_object(self: Arc<Self>) -> Arc<dyn Geometry> {
        self
    }
}

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// The corner with the smallest x, y and z.
    pub min: Vector,
    /// The corner with the largest x, y and z.
    pub max: Vector,
}

impl Aabb {
    /// The box from corner `min` to corner `max`.
    pub fn new(min: Vector, max: Vector) -> Aabb {
        Aabb { min, max }
    }
    /// The point halfway between `min` and `max`.
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
