//! The scene made ready for tracing (beyond the slides): what the scene's `prepared` works out once from a
//! complete scene instead of again for every ray.
//!
//! - the BVH over the nodes ([`NodeTree`]), for scenes with more than a few of them, when they take that
//!   step ([`Step::NodeTree`]);
//! - the steps that belong to a value, resolved in the value: each mesh tested through its BVH or its
//!   triangles one by one ([`Step::MeshBvh`]). (The environment's images, read through their filter or one
//!   texel at a time under [`Step::TexelFilter`], are resolved the same way when a trace starts:
//!   [`crate::lesson::environment::Sky`].)
//!
//! Nothing else is copied: the nodes' shapes and shaders are the scene's own values. A preparation belongs
//! to the nodes it was made for: `Preparation::describes` checks that the scene still has the same steps
//! and nodes of the same bounds (all the node tree depends on), so a scene whose nodes moved after it was
//! prepared is prepared again rather than traced through a stale tree.

use crate::lesson::beyond::{Step, Steps};
use crate::lesson::geometry::Aabb;
use crate::lesson::node::{Node, NodeTree};

/// What the scene's `prepared` works out once from the nodes.
pub(crate) struct Preparation {
    /// The BVH over the nodes, if there are enough of them for one to pay and the scene takes that step.
    pub(crate) node_tree: Option<NodeTree>,
    /// The nodes' bounds it was made for.
    bounds: Vec<Option<Aabb>>,
    /// The steps it was made for.
    steps: Steps,
}

impl Preparation {
    /// Prepares `nodes` for tracing with `steps`: their meshes resolved for the step [`Step::MeshBvh`], and
    /// the tree over them.
    pub(crate) fn new(nodes: &mut [Node], steps: Steps) -> Preparation {
        for node in nodes.iter_mut() {
            node.geometry = node.geometry.with_mesh_bvh(steps.has(Step::MeshBvh));
        }
        Preparation {
            node_tree: if steps.has(Step::NodeTree) { NodeTree::build(nodes) } else { None },
            bounds: nodes.iter().map(Node::bounds).collect(),
            steps,
        }
    }

    /// Whether this preparation was made for `nodes` (the same bounds, in the same order) and `steps`.
    pub(crate) fn describes(&self, nodes: &[Node], steps: Steps) -> bool {
        self.steps == steps
            && self.bounds.len() == nodes.len()
            && self.bounds.iter().zip(nodes).all(|(b, n)| *b == n.bounds())
    }
}
