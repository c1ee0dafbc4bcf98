//! `Node` (slide "Model трансформация"): a geometry, the shader that colours it, and the transform that
//! places it. Rays are intersected with nodes, not with bare geometry; a node takes its transform into
//! account (`Node::intersect` on the slide). Geometry and shaders can be shared through `Arc`, so two nodes can
//! show the same mesh with different transforms and shaders (instancing) without a copy.

use crate::geometry::{Aabb, Geometry, IntersectionInfo};
use crate::math::Vector;
use crate::ray::Ray;
use crate::shader::{IntoShader, Shader};
use crate::transform::Transform;
use std::sync::Arc;

/// Anything that can be a node's geometry: a shape, or a shape shared with other nodes (`Arc<Mesh>`,
/// `Arc<dyn Geometry>`), which is how two nodes show one mesh without a copy (instancing).
pub trait IntoGeometry {
    fn into_geometry(self) -> Arc<dyn Geometry>;
}

impl<G: Geometry + 'static> IntoGeometry for G {
    fn into_geometry(self) -> Arc<dyn Geometry> {
        Arc::new(self)
    }
}

impl<G: Geometry + 'static> IntoGeometry for Arc<G> {
    fn into_geometry(self) -> Arc<dyn Geometry> {
        self
    }
}

impl IntoGeometry for Arc<dyn Geometry> {
    fn into_geometry(self) -> Arc<dyn Geometry> {
        self
    }
}

#[derive(Clone)]
pub struct Node {
    pub geometry: Arc<dyn Geometry>,
    pub shader: Arc<dyn Shader>,
    /// `None` is the identity, and skips the two matrix products per ray.
    pub transform: Option<Transform>,
    /// What the ray tree (`--trace-pixel`) calls the node; `None` names it by its geometry and its position
    /// in the scene (see [`crate::scene::Scene::node_name`]).
    pub name: Option<String>,
}

impl Node {
    /// A node showing `geometry` with `shader`, not yet transformed. Either may be shared with other nodes
    /// by passing an `Arc` of it (`Arc::new(mesh)`, then `mesh.clone()` for each node).
    pub fn new(geometry: impl IntoGeometry, shader: impl IntoShader) -> Node {
        Node { geometry: geometry.into_geometry(), shader: shader.into_shader(), transform: None, name: None }
    }

    /// Gives the node a name, for the ray tree (`--trace-pixel`).
    pub fn named(mut self, name: impl Into<String>) -> Node {
        self.name = Some(name.into());
        self
    }

    fn with_transform(mut self, f: impl FnOnce(Transform) -> Transform) -> Node {
        self.transform = Some(f(self.transform.unwrap_or_default()));
        self
    }
    /// Scales the node by (x, y, z) after its current transform.
    pub fn scale(self, s: Vector) -> Node {
        self.with_transform(|t| t.scale(s))
    }
    /// Rotates the node by yaw, pitch and roll (degrees) after its current transform.
    pub fn rotate(self, yaw: f32, pitch: f32, roll: f32) -> Node {
        self.with_transform(|t| t.rotate(yaw, pitch, roll))
    }
    /// Moves the node by `offset` after its current transform.
    pub fn translate(self, offset: Vector) -> Node {
        self.with_transform(|t| t.translate(offset))
    }

    /// The slide's `Node::intersect`: the ray goes to canonical space, meets the geometry there, and the hit
    /// comes back to world space.
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        match &self.transform {
            None => self.geometry.intersect(ray, t_max),
            Some(t) => self.geometry.intersect(&t.ray_to_canonical(ray), t_max).map(|info| t.info_to_world(&info)),
        }
    }

    /// Whether the ray hits this node before `t_max` (shadow rays).
    pub fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        match &self.transform {
            None => self.geometry.intersects(ray, t_max),
            Some(t) => self.geometry.intersects(&t.ray_to_canonical(ray), t_max),
        }
    }

    /// The node's bounding box in world space, if its geometry is bounded.
    pub fn bounds(&self) -> Option<Aabb> {
        let b = self.geometry.bounds()?;
        Some(match &self.transform {
            None => b,
            Some(t) => Aabb::from_points(b.corners().map(|c| t.point_to_world(c))),
        })
    }
}
