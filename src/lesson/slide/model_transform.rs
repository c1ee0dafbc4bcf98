//! The model transform as the slides write it (slide "Model трансформация"): a node is intersected by
//! moving the ray into the geometry's canonical space with `T^-1`, intersecting there, and bringing the hit
//! back with `T`; the closest hit of a ray is found by testing every node in turn.
//!
//! ```text
//! function Node::intersect(ray, info)
//!     t_ray = ray * T-1
//!     geometry->intersect(t_ray, info)
//!     info = info * T
//! ```
//!
//! A mesh (the slides' teapot) is tested triangle by triangle, after one test against its bounding box, as
//! the course's program does at this lecture; every other shape by its own
//! [`Geometry::intersect`]. Which nodes are meshes is asked once, when the render starts
//! ([`slide_nodes`]), not by every ray at every node.

use crate::lesson::geometry::{Aabb, Geometry, IntersectionInfo, Mesh};
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::ray::Ray;
use std::any::Any;

/// A node of the scene as the slides' loop meets it: the node, and whether its geometry is a mesh (which is
/// tested triangle by triangle), asked once when the render starts rather than by every ray at every node.
#[derive(Clone, Copy)]
pub struct SlideNode<'a> {
    /// The scene's node.
    pub node: &'a Node,
    /// The node's geometry, if it is a mesh.
    mesh: Option<&'a Mesh>,
}

/// The scene's nodes as the slides' loop meets them, in the scene's order.
pub fn slide_nodes(nodes: &[Node]) -> Vec<SlideNode<'_>> {
    nodes.iter().map(|node| SlideNode { node, mesh: (&*node.geometry as &dyn Any).downcast_ref() }).collect()
}

/// The slide's `Node::intersect`: the closest hit of the ray on the node with ray parameter in (0, `t_max`).
pub fn intersect(node: &SlideNode, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
    match &node.node.transform {
        None => intersect_geometry(node, ray, t_max),
        Some(t) => {
            let t_ray = t.ray_to_canonical(ray);
            let info = intersect_geometry(node, &t_ray, t_max)?;
            Some(t.info_to_world(&info))
        }
    }
}

/// The closest node hit by the ray, and where: every node in turn, each searched up to the closest hit so
/// far (so a node added earlier keeps a tie).
pub fn closest_hit<'a>(nodes: &[SlideNode<'a>], ray: &Ray) -> Option<(IntersectionInfo, &'a Node)> {
    let mut closest = None;
    let mut t_max = f32::INFINITY;
    for node in nodes {
        if let Some(info) = intersect(node, ray, t_max) {
            t_max = info.distance;
            closest = Some((info, node.node));
        }
    }
    closest
}

/// The node's geometry's closest hit in its canonical space: a mesh's triangle by triangle, any other
/// shape's by its own [`Geometry::intersect`].
fn intersect_geometry(node: &SlideNode, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
    match node.mesh {
        Some(mesh) => intersect_mesh(mesh, ray, t_max),
        None => node.node.geometry.intersect(ray, t_max),
    }
}

/// A mesh's closest hit: its bounding box first, then every triangle.
fn intersect_mesh(mesh: &Mesh, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
    if !mesh.bounds().is_some_and(|b| hits_box(&b, ray, t_max)) {
        return None;
    }
    let mut closest = None;
    let mut t_max = t_max;
    for (slot, triangle) in mesh.slots() {
        if let Some((t, barycentric)) = intersect_triangle(ray, &triangle, t_max)
            && !mesh.culled(slot, ray.dir)
        {
            t_max = t;
            closest = Some((slot, t, barycentric));
        }
    }
    closest.map(|(slot, t, barycentric)| mesh.surface_at(slot, t, barycentric))
}

/// Whether the ray meets the box before `t_max` (the slab test).
fn hits_box(b: &Aabb, ray: &Ray, t_max: f32) -> bool {
    let inverse = Vector::ONE / ray.dir;
    let (t0, t1) = ((b.min - ray.start) * inverse, (b.max - ray.start) * inverse);
    let near = t0.min(t1).max_element().max(0.0);
    let far = t0.max(t1).min_element().min(t_max);
    near <= far
}

/// The ray's hit on a triangle (Möller and Trumbore): its parameter in (0, `t_max`) and the barycentric
/// coordinates of the hit point (the weights of the three corners).
fn intersect_triangle(ray: &Ray, [a, b, c]: &[Vector; 3], t_max: f32) -> Option<(f32, [f32; 3])> {
    let (ab, ac) = (*b - *a, *c - *a);
    let p = ray.dir.cross(ac);
    let det = ab.dot(p);
    if det == 0.0 {
        return None; // the ray runs in the triangle's plane
    }
    let to_start = ray.start - *a;
    let u = to_start.dot(p) / det;
    let q = to_start.cross(ab);
    let v = ray.dir.dot(q) / det;
    let t = ac.dot(q) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0 && t < t_max).then_some((t, [1.0 - u - v, u, v]))
}
