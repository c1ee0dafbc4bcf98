//! The scene prepared for tracing (beyond the slides): what the renderer works out once from a complete
//! scene instead of again for every ray, kept beside the scene's nodes by [`Scene::prepared`].
//!
//! - the BVH over the nodes ([`NodeTree`]), for scenes with more than a few of them, when they take that step
//!   ([`Step::NodeTree`]);
//! - each node's shape and shader as the cases of an enum ([`crate::lesson::dispatch`], the one place that
//!   lists the workbook's own types), so that they are called without a trait object, as the scene's steps
//!   say.
//!
//! A preparation belongs to the nodes it was made from: `Preparation::describes` checks, in one pass over
//! the nodes, that the scene still holds exactly those (the same geometry and shader, by address, under the
//! same transform) and the same steps, so a scene changed after it was prepared is prepared again rather than
//! traced wrongly.

use crate::lesson::beyond::{Step, Steps};
use crate::lesson::color::Color;
use crate::lesson::dispatch::{Material, Shape, Sky};
use crate::lesson::environment::Environment;
use crate::lesson::geometry::{Hit, IntersectionInfo};
use crate::lesson::math::Vector;
use crate::lesson::node::{Node, NodeHits, NodeTree, any_of, closest_of, nearest_of};
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
    /// Each node as the renderer traces it, in the order of the nodes.
    nodes: Vec<PreparedNode>,
    /// What rays that hit nothing see.
    sky: Sky,
    /// Which nodes it was made from.
    made_from: Vec<NodeIdentity>,
    /// Which environment it was made from (its address, only compared, never followed).
    made_with: Option<usize>,
    /// Which steps it was made for.
    steps: Steps,
}

/// One node as the renderer traces it.
struct PreparedNode {
    /// Its shape.
    shape: Shape,
    /// Its shader.
    material: Material,
    /// Whether its shader is dispersive ([`Shader::is_dispersive`]), asked once.
    dispersive: bool,
    /// Whether it is the workbook's own shape under the workbook's own shaders
    /// ([`Preparation::workbook_surface`]).
    workbook: bool,
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
    /// Prepares `nodes` and `environment` for tracing with `steps`.
    pub(crate) fn new(nodes: &[Node], environment: &Option<Arc<dyn Environment>>, steps: Steps) -> Preparation {
        let prepare = |node: &Node| {
            let (shape, material) = (Shape::of(node, steps), Material::of(&node.shader, steps));
            let workbook = shape.is_workbook() && material.is_workbook();
            PreparedNode { shape, material, dispersive: node.shader.is_dispersive(), workbook }
        };
        Preparation {
            node_tree: if steps.has(Step::NodeTree) { NodeTree::build(nodes) } else { None },
            nodes: nodes.iter().map(prepare).collect(),
            sky: Sky::of(environment, steps),
            made_from: nodes.iter().map(NodeIdentity::of).collect(),
            made_with: environment_identity(environment),
            steps,
        }
    }

    /// What a ray that hits nothing sees in the direction `dir`.
    #[inline(always)]
    pub(crate) fn sky(&self, dir: Vector) -> Color {
        self.sky.get(dir)
    }

    /// The nearest of the nodes hit by the ray: where, and the node's index.
    #[inline(always)]
    pub(crate) fn nearest_hit(&self, ray: &Ray) -> Option<(Hit, usize)> {
        let nodes = PreparedNodes { nodes: &self.nodes, ray };
        match &self.node_tree {
            Some(tree) => tree.nearest_of(&nodes, ray),
            None => nearest_of(&nodes, ray),
        }
    }

    /// The surface of node `i` at `hit` if it is one of the workbook's own shapes under the workbook's own
    /// shaders (a texture of a student's may colour it): its hits are described exactly, with unit normals,
    /// and its shaders spawn their rays with [`crate::lesson::ray::Ray::spawn`] within their budget, so
    /// `raytrace` shades it without the bookkeeping of [`crate::lesson::branching`]. `None` for any other
    /// node.
    #[inline(always)]
    pub(crate) fn workbook_surface(&self, i: usize, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        let node = &self.nodes[i];
        if !node.workbook {
            return None;
        }
        node.shape.workbook_surface(ray, hit)
    }

    /// Whether node `i` is the workbook's own shape under the workbook's own shaders (see
    /// [`Preparation::workbook_surface`]).
    #[inline(always)]
    pub(crate) fn is_workbook(&self, i: usize) -> bool {
        self.nodes[i].workbook
    }

    /// The slide's loop over the nodes, each intersected in full: the closest hit, its node's index, and
    /// whether its normal was of unit length ([`crate::lesson::scene::Scene::closest_by_loop`]).
    #[inline(always)]
    pub(crate) fn closest_by_loop(&self, ray: &Ray) -> Option<(IntersectionInfo, usize, bool)> {
        closest_of(self.nodes.len(), |i, t_max| self.nodes[i].shape.intersect(ray, t_max))
    }

    /// Whether any node is hit before `t_max`, each intersected in full in turn (the slide's shadow ray).
    pub(crate) fn any_by_loop(&self, ray: &Ray, t_max: f32) -> bool {
        self.nodes.iter().any(|node| node.shape.intersect(ray, t_max).is_some())
    }

    /// Whether node `i`'s shader is dispersive.
    #[inline(always)]
    pub(crate) fn is_dispersive(&self, i: usize) -> bool {
        self.nodes[i].dispersive
    }

    /// The surface of node `i` at `hit`, and whether its normal is of unit length.
    #[inline(always)]
    pub(crate) fn surface(&self, i: usize, ray: &Ray, hit: &Hit) -> Option<(IntersectionInfo, bool)> {
        self.nodes[i].shape.surface(ray, hit)
    }

    /// Whether any of the nodes is hit by the ray before `t_max`.
    #[inline(always)]
    pub(crate) fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        let nodes = PreparedNodes { nodes: &self.nodes, ray };
        match &self.node_tree {
            Some(tree) => tree.any_of(&nodes, ray, t_max),
            None => any_of(&nodes, t_max),
        }
    }

    /// The colour node `i`'s shader gives the hit.
    #[inline(always)]
    pub(crate) fn shade(&self, i: usize, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        self.nodes[i].material.shade(ray, info, ctx)
    }

    /// Whether this preparation was made from exactly `nodes` and `environment`, for `steps`.
    pub(crate) fn describes(&self, nodes: &[Node], environment: &Option<Arc<dyn Environment>>, steps: Steps) -> bool {
        self.steps == steps
            && self.made_from.len() == nodes.len()
            && self.made_from.iter().zip(nodes).all(|(id, n)| *id == NodeIdentity::of(n))
            && self.made_with == environment_identity(environment)
    }
}

/// An environment as a preparation knows it: its address, only compared, never followed.
fn environment_identity(environment: &Option<Arc<dyn Environment>>) -> Option<usize> {
    environment.as_ref().map(|e| Arc::as_ptr(e) as *const () as usize)
}

/// The prepared nodes of a scene, tested for one ray.
struct PreparedNodes<'a> {
    nodes: &'a [PreparedNode],
    ray: &'a Ray,
}

impl NodeHits for PreparedNodes<'_> {
    fn count(&self) -> usize {
        self.nodes.len()
    }
    #[inline(always)]
    fn hit(&self, i: usize, t_max: f32) -> Option<Hit> {
        self.nodes[i].shape.hit(self.ray, t_max)
    }
    #[inline(always)]
    fn intersects(&self, i: usize, t_max: f32) -> bool {
        self.nodes[i].shape.intersects(self.ray, t_max)
    }
}
