//! [`Shape`]: a node's geometry, stored once, as the node's own value. The course calls a node's geometry
//! through its interface (a virtual call in its C++, [`Geometry`] here); the workbook keeps the shapes it
//! ships as the cases of an enum, so a ray meets a sphere or a plane without a call through a pointer, and
//! any other shape (a cube, a prism, a student's own) as one more case, [`Shape::Own`], called through its
//! trait object: a new shape works the moment it compiles.
//!
//! A shape becomes its case by its own [`Geometry::into_shape`], which the workbook's shapes override and
//! every other shape inherits: nothing asks a value's type. This is the one place that lists the cases.

use super::{Aabb, Geometry, Hit, IntersectionInfo, Mesh, Plane, Sphere};
use crate::lesson::ray::Ray;
use std::sync::Arc;

/// A node's geometry: one of the workbook's shapes, or any other through its trait object.
#[derive(Clone)]
pub enum Shape {
    /// A sphere.
    Sphere(Sphere),
    /// A horizontal plane.
    Plane(Plane),
    /// A triangle mesh (shared between nodes: instancing). `bvh` is false when the scene leaves out the step
    /// [`Step::MeshBvh`](crate::lesson::beyond::Step::MeshBvh): its triangles are then tested one by one, as
    /// on the slide ([`Mesh::hit_one_by_one`]).
    Mesh {
        /// The mesh.
        mesh: Arc<Mesh>,
        /// Whether its BVH is used.
        bvh: bool,
    },
    /// Any other shape, through its trait object.
    Own(Arc<dyn Geometry>),
}

impl Shape {
    /// Whether the shape describes its hits exactly, with unit normals: the workbook's sphere and plane (a
    /// mesh is checked as any other shape is).
    #[inline(always)]
    pub fn is_exact(&self) -> bool {
        matches!(self, Shape::Sphere(_) | Shape::Plane(_))
    }

    /// Whether the shape is made of flat faces that a hit tells apart by its geometric normal: a mesh's
    /// triangles, each of whose normals is computed from its three corners alone, so two hits on one
    /// triangle have the same geometric normal bit for bit (up to its sign, turned to the shading normal's
    /// side), and two with different ones are on different triangles.
    #[inline(always)]
    pub(crate) fn has_flat_faces(&self) -> bool {
        matches!(self, Shape::Mesh { .. })
    }

    /// Whether the shape is one of the workbook's that the enum lists (sphere, plane, mesh): each puts its
    /// hit point on its surface within the error bound it gives it, so a ray started off that point by
    /// [`Ray::spawn`](crate::lesson::ray::Ray::spawn) never finds the surface again where it left it.
    pub(crate) fn bounds_its_hit_points(&self) -> bool {
        !matches!(self, Shape::Own(_))
    }

    /// The same shape as a scene with `bvh` for its meshes traces it.
    pub(crate) fn with_mesh_bvh(&self, bvh: bool) -> Shape {
        match self {
            Shape::Mesh { mesh, .. } => Shape::Mesh { mesh: mesh.clone(), bvh },
            other => other.clone(),
        }
    }
}

impl Geometry for Shape {
    #[inline(always)]
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        match self {
            Shape::Sphere(sphere) => sphere.intersect(ray, t_max),
            Shape::Plane(plane) => plane.intersect(ray, t_max),
            Shape::Mesh { mesh, bvh: true } => mesh.intersect(ray, t_max),
            Shape::Mesh { mesh, bvh: false } => mesh.hit_one_by_one(ray, t_max).and_then(|hit| mesh.surface(ray, &hit)),
            Shape::Own(geometry) => geometry.intersect(ray, t_max),
        }
    }

    #[inline(always)]
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        match self {
            Shape::Sphere(sphere) => sphere.hit(ray, t_max),
            Shape::Plane(plane) => plane.hit(ray, t_max),
            Shape::Mesh { mesh, bvh: true } => mesh.hit(ray, t_max),
            Shape::Mesh { mesh, bvh: false } => mesh.hit_one_by_one(ray, t_max),
            Shape::Own(geometry) => geometry.hit(ray, t_max),
        }
    }

    #[inline(always)]
    fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        match self {
            Shape::Sphere(sphere) => sphere.surface(ray, hit),
            Shape::Plane(plane) => plane.surface(ray, hit),
            Shape::Mesh { mesh, .. } => mesh.surface(ray, hit),
            Shape::Own(geometry) => geometry.surface(ray, hit),
        }
    }

    #[inline(always)]
    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        match self {
            Shape::Sphere(sphere) => sphere.intersects(ray, t_max),
            Shape::Plane(plane) => plane.intersects(ray, t_max),
            Shape::Mesh { mesh, bvh: true } => mesh.intersects(ray, t_max),
            Shape::Mesh { mesh, bvh: false } => mesh.hit_one_by_one(ray, t_max).is_some(),
            Shape::Own(geometry) => geometry.intersects(ray, t_max),
        }
    }

    fn bounds(&self) -> Option<Aabb> {
        match self {
            Shape::Sphere(sphere) => sphere.bounds(),
            Shape::Plane(plane) => plane.bounds(),
            Shape::Mesh { mesh, .. } => mesh.bounds(),
            Shape::Own(geometry) => geometry.bounds(),
        }
    }

    fn name(&self) -> &'static str {
        match self {
            Shape::Sphere(sphere) => sphere.name(),
            Shape::Plane(plane) => plane.name(),
            Shape::Mesh { mesh, .. } => mesh.name(),
            Shape::Own(geometry) => geometry.name(),
        }
    }

    fn into_shape(self: Arc<Self>) -> Shape {
        Arc::unwrap_or_clone(self)
    }
}

/// Anything that can be a node's geometry: a shape, a shape shared with other nodes (`Arc<Mesh>`,
/// `Arc<dyn Geometry>`), which is how two nodes show one mesh without a copy (instancing), or a node's
/// [`Shape`].
pub trait IntoGeometry {
    /// The geometry as a node stores it.
    fn into_geometry(self) -> Shape;
}

impl<G: Geometry> IntoGeometry for G {
    fn into_geometry(self) -> Shape {
        Arc::new(self).into_shape()
    }
}

impl<G: Geometry> IntoGeometry for Arc<G> {
    fn into_geometry(self) -> Shape {
        self.into_shape()
    }
}

impl IntoGeometry for Arc<dyn Geometry> {
    fn into_geometry(self) -> Shape {
        self.into_shape()
    }
}
