//! `Node` (slide "Model трансформация"): a geometry, the shader that colours it, and the transform that
//! places it. Rays are intersected with nodes, not with bare geometry; a node takes its transform into
//! account (`Node::intersect` on the slide). Geometry and shaders can be shared through `Arc`, so two nodes can
//! show the same mesh with different transforms and shaders (instancing) without a copy.

use crate::lesson::geometry::bvh::Bvh;
use crate::lesson::geometry::{Aabb, Geometry, Hit, IntersectionInfo, Shape};
use crate::lesson::math::{Vector, gamma, max_abs};
use crate::lesson::ray::Ray;
use crate::lesson::shader::{IntoShader, Material};
use crate::lesson::transform::Transform;

pub use crate::lesson::geometry::IntoGeometry;

// The slide's Node::intersect first: the ray into the shape's own space, its hit there, the hit back in the world.
impl Node {
    /// The slide's `Node::intersect`: the ray goes to canonical space, meets the geometry there, and the hit
    /// comes back to world space.
    ///
    /// ```text
    /// function Node::intersect(ray, info)
    ///     t_ray = ray * T-1
    ///     geometry->intersect(t_ray, info)
    ///     info = info * T
    /// ```
    #[inline(always)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.checked_intersect(ray, t_max).map(|(info, _)| info)
    }

    /// [`Node::intersect`], and whether the geometry described the hit with a unit normal (see
    /// [`Node::checked_surface`]).
    #[inline(always)]
    pub(crate) fn checked_intersect(&self, ray: &Ray, t_max: f32) -> Option<(IntersectionInfo, bool)> {
        match &self.transform {
            None => self.geometry.intersect(ray, t_max).map(|info| (info, self.is_unit_normal(&info))),
            Some(t) => self.intersect_transformed(t, ray, t_max),
        }
    }

    /// [`Node::checked_intersect`] through the node's transform, out of the node loop as
    /// [`Node::hit_transformed`].
    #[inline(never)]
    fn intersect_transformed(&self, t: &Transform, ray: &Ray, t_max: f32) -> Option<(IntersectionInfo, bool)> {
        let info = self.geometry.intersect(&t.ray_to_canonical(ray), t_max)?;
        Some((t.info_to_world(&info), self.is_unit_normal(&info)))
    }
}

/// The slides' loop over the nodes (slide "Model трансформация"): `intersect(i, t_max)` of every node `i` in
/// turn, each searched up to the closest hit so far, so that a node added earlier keeps a tie. The closest
/// hit, its node's index, and whether its normal was of unit length.
#[inline(always)]
pub(crate) fn closest_of(
    count: usize,
    mut intersect: impl FnMut(usize, f32) -> Option<(IntersectionInfo, bool)>,
) -> Option<(IntersectionInfo, usize, bool)> {
    let mut closest = None;
    let mut t_max = f32::INFINITY;
    for i in 0..count {
        if let Some((info, unit_normal)) = intersect(i, t_max) {
            t_max = info.distance;
            closest = Some((info, i, unit_normal));
        }
    }
    closest
}

/// One object of the scene: a geometry in its canonical form, the shader that colours it and the transform
/// that places it in the world (slide "Model трансформация").
#[derive(Clone)]
pub struct Node {
    /// The shape, in its canonical form (a sphere, a cube, a mesh as loaded); nodes may share it (instancing).
    pub geometry: Shape,
    /// What colours the node's surface; can be shared with other nodes.
    pub shader: Material,
    /// `None` is the identity, and skips the two matrix products per ray.
    pub transform: Option<Transform>,
    /// What the ray tree (`--trace-pixel`) calls the node; `None` names it by its geometry and its position
    /// in the scene (see [`crate::lesson::scene::Scene::node_name`]).
    pub name: Option<String>,
}

/// How far from 1 the squared length of a normal may be for it to count as a unit normal: 2^-9, a length
/// within 0.1% of 1. A normal normalised in f32 is within a few 1e-7 of it, and one computed from a hit point
/// that a quadratic found with the textbook formula (which loses half the digits, `sqrt(EPSILON)`) within a
/// few 1e-4; a normal not normalised at all is off by its length.
pub(crate) const UNIT_NORMAL_TOLERANCE: f32 = 1.0 / 512.0;

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

    /// The first phase of [`Node::intersect`] ([`Geometry::hit`] in canonical space): where the ray meets
    /// the node, with the surface not yet described.
    #[inline(always)]
    pub fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        match &self.transform {
            None => self.geometry.hit(ray, t_max),
            Some(t) => self.hit_transformed(t, ray, t_max),
        }
    }

    /// [`Node::hit`] through the node's transform. Kept out of the node loop, so that a scene of
    /// untransformed nodes does not prepare every ray for a transform it never applies.
    #[inline(never)]
    fn hit_transformed(&self, t: &Transform, ray: &Ray, t_max: f32) -> Option<Hit> {
        self.geometry.hit(&t.ray_to_canonical(ray), t_max)
    }

    /// The second phase: the surface at a hit that [`Node::hit`] found for the same ray, in world space.
    #[inline]
    pub fn surface(&self, ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        self.checked_surface(ray, hit).map(|(info, _)| info)
    }

    /// [`Node::surface`], and whether the geometry described it with a unit normal: checked as the geometry
    /// returns it, before a transform normalises it (a NaN or unnormalised normal shades wrong, often
    /// without a NaN in the picture; `raytrace` counts it for the end-of-run report).
    #[inline(always)]
    pub(crate) fn checked_surface(&self, ray: &Ray, hit: &Hit) -> Option<(IntersectionInfo, bool)> {
        match &self.transform {
            None => self.geometry.surface(ray, hit).map(|info| (info, self.is_unit_normal(&info))),
            Some(t) => self
                .geometry
                .surface(&t.ray_to_canonical(ray), hit)
                .map(|info| (t.info_to_world(&info), self.is_unit_normal(&info))),
        }
    }

    /// Whether the node's geometry described its surface with a normal of unit length (within
    /// [`UNIT_NORMAL_TOLERANCE`]; false for a NaN normal): the workbook's sphere and plane do so by
    /// construction (a normalised offset from the centre, the plane's axis), so only another shape's is
    /// checked.
    #[inline(always)]
    fn is_unit_normal(&self, info: &IntersectionInfo) -> bool {
        self.geometry.is_exact() || (info.normal.length_squared() - 1.0).abs() <= UNIT_NORMAL_TOLERANCE
    }

    /// Whether the node is one of the workbook's own exact shapes, not transformed, under the workbook's own
    /// shaders ([`crate::lesson::shader::Material::is_workbook`]): its hits are described exactly and its
    /// shaders spawn their rays with [`Ray::spawn`] within their budget, so `raytrace` shades it without
    /// the bookkeeping of [`crate::lesson::branching`].
    #[inline(always)]
    pub(crate) fn is_workbook(&self) -> bool {
        self.transform.is_none() && self.geometry.is_exact() && self.shader.is_workbook()
    }

    /// Whether the ray hits this node before `t_max` (shadow rays).
    #[inline(always)]
    pub fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        match &self.transform {
            None => self.geometry.intersects(ray, t_max),
            Some(t) => self.intersects_transformed(t, ray, t_max),
        }
    }

    /// [`Node::intersects`] through the node's transform, out of the node loop as [`Node::hit_transformed`].
    #[inline(never)]
    fn intersects_transformed(&self, t: &Transform, ray: &Ray, t_max: f32) -> bool {
        self.geometry.intersects(&t.ray_to_canonical(ray), t_max)
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

/// A bounding volume hierarchy over a scene's nodes, by their world-space boxes (the top level above each
/// mesh's own BVH; the same builder and traversal). Not on the slides, which test every node for every ray:
/// with it a ray's cost grows about with the logarithm of the number of nodes instead of linearly. Nodes
/// without a box (an endless plane) are kept apart and tested one by one.
///
/// A scene of at most [`LINEAR_NODES`] nodes is not worth a tree: the loop is cheaper than walking one.
///
/// Ties keep the slides' order: when two nodes are hit at the same distance (within [`TIE`]), the one
/// added to the scene first wins, as in the loop over the nodes.
#[derive(Clone, Debug, Default)]
pub struct NodeTree {
    bvh: Bvh,
    /// The bounded nodes' indices, in the order the BVH's leaves refer to.
    bounded: Vec<u32>,
    /// The nodes without a (finite) box.
    unbounded: Vec<u32>,
}

/// Scenes with this many nodes or fewer are traced by the loop over the nodes, which tests them all faster
/// than a tree is walked (docs/beyond-the-slides.md has the measurement).
pub const LINEAR_NODES: usize = 8;

/// Two hits on different nodes whose distances differ by less than `TIE * (max_abs(ray start) + distance)`
/// are a tie, which the node added to the scene first wins, as in the course's loop (`<`, the first node in
/// file order keeps a tie). A hit's distance carries the rounding of the ray's move into its node's
/// canonical space, so two nodes with coincident faces (a window pane standing on its frame, both transformed)
/// meet a ray at distances a few float steps apart, and without the tolerance each pixel along the seam would
/// take whichever rounding happens to win: in the course's hw6/window, a bright line where the pane's bottom
/// face, seen from inside the glass, beats the frame's top face. γ(64) (32 float steps of the hit's scale)
/// settles 99.8% of the rays that meet those faces, measured over random rays at the seam (all but some that
/// graze the faces, whose distances differ much more); nodes meant to be apart are far farther apart.
pub const TIE: f32 = gamma(64);

/// How far apart two hits near `distance` may be and still be a tie ([`TIE`]), for a ray whose start's
/// largest coordinate is `start_scale`.
#[inline]
fn tie(start_scale: f32, distance: f32) -> f32 {
    TIE * (start_scale + distance)
}

/// The nearest hit found so far over the nodes a tree leads the ray to, which come in no particular order.
struct Closest {
    /// `max_abs(ray.start)`, the ray's part of the tie's scale: the same for every node, found once.
    start_scale: f32,
    t_max: f32,
    best: Option<(Hit, usize)>,
}

impl Closest {
    fn new(ray: &Ray) -> Closest {
        Closest { start_scale: max_abs(ray.start), t_max: f32::INFINITY, best: None }
    }

    /// Tests node `i` of `nodes`: a hit before the best so far wins, unless it is a tie ([`TIE`]); a tie
    /// goes to the node that comes earlier in the scene.
    #[inline]
    fn consider(&mut self, i: usize, nodes: &[Node], ray: &Ray) {
        let limit = match self.best {
            None => f32::INFINITY,
            Some((_, b)) if i < b => self.t_max + tie(self.start_scale, self.t_max),
            Some(_) => self.t_max - tie(self.start_scale, self.t_max),
        };
        if let Some(hit) = nodes[i].hit(ray, limit) {
            self.t_max = hit.distance;
            self.best = Some((hit, i));
        }
    }

    /// The farthest a node's box may start and still hold a hit that wins: the best distance, or a tie.
    #[inline]
    fn reach(&self) -> f32 {
        if self.best.is_some() { self.t_max + tie(self.start_scale, self.t_max) } else { self.t_max }
    }

    /// Where the winner was hit, and its index.
    fn finish(self) -> Option<(Hit, usize)> {
        self.best
    }
}

/// The nearest node hit by the ray, testing every node in turn (the slides' loop). In the scene's order a
/// later node wins only when it is closer by more than a tie ([`TIE`]), so ties go to the earlier node: after
/// each hit, the next nodes are searched up to that hit's distance less a tie.
#[inline]
pub fn nearest_hit_linear<'a>(nodes: &'a [Node], ray: &Ray) -> Option<(Hit, &'a Node)> {
    nearest_of(nodes, ray).map(|(hit, i)| (hit, &nodes[i]))
}

/// [`nearest_hit_linear`] over `nodes`, tested for `ray`: where the nearest is hit, and its index.
#[inline(always)]
pub(crate) fn nearest_of(nodes: &[Node], ray: &Ray) -> Option<(Hit, usize)> {
    let start_scale = max_abs(ray.start);
    let mut nearest = None;
    let mut limit = f32::INFINITY;
    for (i, node) in nodes.iter().enumerate() {
        if let Some(found) = node.hit(ray, limit) {
            limit = found.distance - tie(start_scale, found.distance);
            nearest = Some((found, i));
        }
    }
    nearest
}

/// Whether any of `nodes` is hit by `ray` before `t_max`, testing them in turn.
#[inline(always)]
pub(crate) fn any_of(nodes: &[Node], ray: &Ray, t_max: f32) -> bool {
    for node in nodes {
        if node.intersects(ray, t_max) {
            return true;
        }
    }
    false
}

impl NodeTree {
    /// The tree over `nodes`, or `None` when there are too few for a tree to pay ([`LINEAR_NODES`]).
    pub fn build(nodes: &[Node]) -> Option<NodeTree> {
        if nodes.len() <= LINEAR_NODES {
            return None;
        }
        let mut boxes = Vec::new();
        let mut bounded = Vec::new();
        let mut unbounded = Vec::new();
        for (i, node) in nodes.iter().enumerate() {
            match node.bounds().filter(|b| b.min.is_finite() && b.max.is_finite()) {
                Some(b) => {
                    boxes.push(b);
                    bounded.push(i as u32);
                }
                None => unbounded.push(i as u32),
            }
        }
        let (bvh, order) = Bvh::build(&boxes);
        let bounded = order.iter().map(|&k| bounded[k as usize]).collect();
        Some(NodeTree { bvh, bounded, unbounded })
    }

    /// The nearest of `nodes` (the ones the tree was built over) hit by the ray, and where.
    pub fn nearest_hit<'a>(&self, nodes: &'a [Node], ray: &Ray) -> Option<(Hit, &'a Node)> {
        self.nearest_of(nodes, ray).map(|(hit, i)| (hit, &nodes[i]))
    }

    /// [`NodeTree::nearest_hit`] over `nodes`, tested for `ray`: where the nearest is hit, and its index.
    /// Kept out of line: the loop over a few nodes, inlined into `raytrace`, stays small.
    #[inline(never)]
    pub(crate) fn nearest_of(&self, nodes: &[Node], ray: &Ray) -> Option<(Hit, usize)> {
        beyond!(NodeTree);
        let mut closest = Closest::new(ray);
        for &i in &self.unbounded {
            closest.consider(i as usize, nodes, ray);
        }
        self.bvh.traverse(ray.start, ray.dir, closest.reach(), |range, t_max| {
            for &i in &self.bounded[range] {
                closest.consider(i as usize, nodes, ray);
            }
            *t_max = closest.reach();
            false
        });
        closest.finish()
    }

    /// Whether any of `nodes` is hit before `t_max` (shadow rays).
    /// Kept out of line, as the search for the nearest hit.
    #[inline(never)]
    pub fn intersects(&self, nodes: &[Node], ray: &Ray, t_max: f32) -> bool {
        beyond!(NodeTree);
        if self.unbounded.iter().any(|&i| nodes[i as usize].intersects(ray, t_max)) {
            return true;
        }
        let mut hit = false;
        self.bvh.traverse(ray.start, ray.dir, t_max, |range, t_max| {
            hit = self.bounded[range].iter().any(|&i| nodes[i as usize].intersects(ray, *t_max));
            hit
        });
        hit
    }
}
