//! The scene prepared for tracing (beyond the slides): what the renderer works out once from a complete
//! scene instead of again for every ray, kept beside the scene's nodes by [`Scene::prepared`].
//!
//! - the BVH over the nodes ([`NodeTree`]), for scenes with more than a few of them;
//! - each node's shape and shader as the cases of an enum ([`crate::lesson::dispatch`]), so that the
//!   workbook's own types are called without a trait object.
//!
//! A preparation belongs to the nodes it was made from: `Preparation::describes` checks, in one pass over
//! the nodes, that the scene still holds exactly those (the same geometry and shader, by address, under the
//! same transform), so a scene changed after it was prepared is prepared again rather than traced wrongly.

use crate::lesson::color::Color;
use crate::lesson::dispatch::{Material, Shape};
use crate::lesson::geometry::{Hit, IntersectionInfo};
use crate::lesson::node::{Node, NodeHits, NodeTree, any_of, nearest_of};
use crate::lesson::ray::Ray;
use crate::lesson::scene::TraceContext;
use crate::lesson::transform::Transform;
use std::sync::Arc;

#[cfg(doc)]
use crate::lesson::{scene::Scene, shader::Shader};

/// What [`Scene::prepared`] works out once from the nodes.
pub(crate) struct Preparation {
    /// The BVH over the nodes, if there are enough of them for one to pay.
    pub(crate) node_tree: Option<NodeTree>,
    /// Each node's shape, in the order of the nodes.
    shapes: Vec<Shape>,
    /// Each node's shader, in the order of the nodes.
    materials: Vec<Material>,
    /// Whether each node's shader is dispersive ([`Shader::is_dispersive`]), asked once.
    dispersive: Vec<bool>,
    /// Whether each node is the workbook's own shape under the workbook's own shaders
    /// ([`Preparation::is_workbook_node`]).
    workbook: Vec<bool>,
    /// Which nodes it was made from.
    made_from: Vec<NodeIdentity>,
}

/// A node as a preparation knows it: the addresses of its geometry and shader (only compared, never
/// followed), and its transform.
#[derive(Debug, PartialEq)]
struct NodeIdentity {
    geometry: usize,
    shader: usize,
    transform: Option<Transform>,
}

impl NodeIdentity {
    fn of(node: &Node) -> NodeIdentity {
        NodeIdentity {
            geometry: Arc::as_ptr(&node.geometry) as *const () as usize,
            shader: Arc::as_ptr(&node.shader) as *const () as usize,
            transform: node.transform,
        }
    }
}

impl Preparation {
    /// Prepares `nodes` for tracing.
    pub(crate) fn new(nodes: &[Node]) -> Preparation {
        let shapes: Vec<Shape> = nodes.iter().map(Shape::of).collect();
        let materials: Vec<Material> = nodes.iter().map(|n| Material::of(&n.shader)).collect();
        Preparation {
            node_tree: NodeTree::build(nodes),
            workbook: shapes.iter().zip(&materials).map(|(s, m)| s.is_workbook() && m.is_workbook()).collect(),
            shapes,
            materials,
            dispersive: nodes.iter().map(|n| n.shader.is_dispersive()).collect(),
            made_from: nodes.iter().map(NodeIdentity::of).collect(),
        }
    }

    /// The nearest of `nodes` (the ones it was made from) hit by the ray: where, and the node's index.
    #[inline(always)]
    pub(crate) fn nearest_hit(&self, nodes: &[Node], ray: &Ray) -> Option<(Hit, usize)> {
        beyond!(StaticDispatch);
        let shapes = PreparedNodes { shapes: &self.shapes, nodes, ray };
        match &self.node_tree {
            Some(tree) => tree.nearest_of(&shapes, ray),
            None => nearest_of(&shapes, ray),
        }
    }

    /// The surface of node `i` at `hit` if it is one of the workbook's own shapes under the workbook's own
    /// shaders (a texture of a student's may colour it): its hits are described exactly, with unit normals,
    /// and its shaders spawn their rays with [`crate::lesson::ray::Ray::spawn`] within their budget, so
    /// `raytrace` shades it without the bookkeeping of [`crate::lesson::branching`]. `None` for any other
    /// node.
    #[inline(always)]
    pub(crate) fn workbook_surface(&self, i: usize, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        if !self.workbook[i] {
            return None;
        }
        self.shapes[i].workbook_surface(ray, hit)
    }

    /// Whether node `i`'s shader is dispersive.
    #[inline(always)]
    pub(crate) fn is_dispersive(&self, i: usize) -> bool {
        self.dispersive[i]
    }

    /// The surface of node `i` of `nodes` at `hit`, and whether its normal is of unit length.
    #[inline(always)]
    pub(crate) fn surface(&self, nodes: &[Node], i: usize, ray: &Ray, hit: &Hit) -> Option<(IntersectionInfo, bool)> {
        self.shapes[i].surface(&nodes[i], ray, hit)
    }

    /// Whether any of `nodes` is hit by the ray before `t_max`.
    #[inline(always)]
    pub(crate) fn intersects(&self, nodes: &[Node], ray: &Ray, t_max: f32) -> bool {
        beyond!(StaticDispatch);
        let shapes = PreparedNodes { shapes: &self.shapes, nodes, ray };
        match &self.node_tree {
            Some(tree) => tree.any_of(&shapes, ray, t_max),
            None => any_of(&shapes, t_max),
        }
    }

    /// The colour node `i`'s shader gives the hit.
    #[inline(always)]
    pub(crate) fn shade(&self, i: usize, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        beyond!(StaticDispatch);
        self.materials[i].shade(ray, info, ctx)
    }

    /// Whether this preparation was made from exactly `nodes`.
    pub(crate) fn describes(&self, nodes: &[Node]) -> bool {
        self.made_from.len() == nodes.len()
            && self.made_from.iter().zip(nodes).all(|(id, n)| *id == NodeIdentity::of(n))
    }
}

/// The prepared shapes of a scene's nodes, tested for one ray.
struct PreparedNodes<'a> {
    shapes: &'a [Shape],
    nodes: &'a [Node],
    ray: &'a Ray,
}

impl NodeHits for PreparedNodes<'_> {
    fn count(&self) -> usize {
        self.shapes.len()
    }
    #[inline(always)]
    fn hit(&self, i: usize, t_max: f32) -> Option<Hit> {
        self.shapes[i].hit(&self.nodes[i], self.ray, t_max)
    }
    #[inline(always)]
    fn intersects(&self, i: usize, t_max: f32) -> bool {
        self.shapes[i].intersects(&self.nodes[i], self.ray, t_max)
    }
}
