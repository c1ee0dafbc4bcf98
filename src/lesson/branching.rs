//! Bounded branching of the ray tree, for every shader alike (beyond the slides).
//!
//! A shader that averages N rays passes each of them its full weight ([`Ray::spawn`]'s `attenuation` is
//! what one ray's colour is multiplied by, not its 1/N share of the average: each ray estimates the whole).
//! Two such shaders facing each other then branch N^depth rays per camera ray: 16 rays and 10 bounces is
//! 10^12 rays, a render that never ends. Russian roulette on the weight cannot stop it (a white mirror's
//! rays keep a weight of 1), and a 1/N weight stops it by pruning the deep samples, which darkens the
//! picture the more rays the shader averages. This module puts a cap on every shader's rays in `raytrace`,
//! the workbook's glossy mirror's and a student's alike (the course's glossy mirror traces
//! [`crate::lesson::shader::SECONDARY_GLOSSY_SAMPLES`] per shading point below the first bounce; the cap
//! allows that down to [`SPLIT_DEPTH`] and one ray below it).
//!
//! The rule. Each shading point (the hit of one ray, or one layer of a `Layered` shader there) may pass its
//! rays, together, [`split_factor`] times its own ray's weight: without limit for a camera ray's hit, 2 times
//! down to [`SPLIT_DEPTH`], once below it. The first ray is always traced. A ray that would take the rays
//! of its shading point past that budget is not traced: `raytrace` returns the mean of the colours its
//! siblings brought back, and counts it in [`Counters::shared_rays`](crate::lesson::scene::Counters).
//!
//! Why it is unbiased. A shader averaging N rays that are independent and identically distributed (the
//! directions of a glossy cone, drawn alike) computes `(X_1 + ... + X_k + (N - k) * mean(X_1..X_k)) / N`
//! when only k are traced, which is `mean(X_1..X_k)`: the same expectation as the average of all N, with the
//! variance of k rays, so a student's N-ray glossy converges to the workbook's (`tests/workbook/branching.rs`
//! measures it).
//! The rays of a shading point that are *not* alike (a glass's reflection and refraction) are told apart by
//! their weights: they split the light, so their attenuations add up to at most one (R + T = 1) and they
//! never exceed the budget; an average's do, N times over. `Layered` shades each layer as a shading point
//! of its own, so a layer's rays never share another layer's colours. The limit of the rule: a shader whose
//! rays are not alike and together pass more than the budget (two full-weight rays that are then mixed
//! with factors of the shader's own) gets, for the later ones, the earlier ones' colours: biased. Passing
//! each ray the factor its colour is multiplied by (the contract) avoids it.
//!
//! What it costs. Nothing changes for the workbook's shaders down to [`SPLIT_DEPTH`], where every example's
//! rays end: each stays within its budget, so every default picture is the same bit for bit and
//! `--exhaustive` still traces every one of their rays. Below it a glossy mirror's second ray shares the
//! first one's colour, as a student's would. A student's
//! N-ray shader traces N rays at the camera ray's hit, 2 per shading point of a ray down to the split depth
//! and 1 below it: at most `N * 2^SPLIT_DEPTH` rays per camera ray at any depth (at depth `SPLIT_DEPTH + 1`
//! and below), a ray count linear in the depth limit.
//!
//! The budget of a branch. The rule bounds a shading point's rays by their weights, which bounds their
//! count only where weights do not shrink: the rays of a glass (R and T) or of a `Layered` shader's layers
//! (each shaded as a point of its own) fit their budgets however faint they get, and nothing else prunes
//! them when adaptive depth control is off (`--slide`, `--exhaustive`): two of them facing each other double
//! the rays at every level, 2^depth. So each ray the camera ray's hit traces (a branch of the ray tree) may
//! trace at most [`RAYS_PER_BRANCH`] rays in all, itself included, at any depth and in both readings; the
//! rays past it are not traced (black) and counted in
//! [`Counters::over_budget_rays`](crate::lesson::scene::Counters), which the end-of-run report names. No
//! example's branch comes near it (tests/workbook/branching.rs), so it changes no picture; it keeps a
//! scene of a program of one's own from rendering for days. The camera ray's hit itself may trace as many
//! rays as its shader likes (a glossy mirror's N), each a branch of its own.
//!
//! The energy check. A shading point also keeps what its shader had to make its colour of (`Income`): the
//! brightest colour, channel by channel, that one of its rays brought back, how many rays it traced, and
//! the light its light loops gathered ([`crate::lesson::light::light_loop`]: irradiance and highlights). A
//! shader that returns more than the brightest ray plus that light, in some channel, made light: a mean of
//! rays, a mirror's or a glass's weighted rays, a diffuse colour times the light, a Layered blend of these
//! never can. Only the hits whose shader traced two rays or more are weighed: the mistake it catches is the
//! naive sum of N rays (each at full weight, added up and not divided by N), and a shader of no rays (a
//! flat colour, one that glows) or of one (a mirror) is left alone. [`Problems::report`] names a node whose
//! shader gains on at least 1% of those hits.
//!
//! Nor does it cost the workbook's own nodes anything: where a node's shape and every shader of it are the
//! workbook's own (`Node::is_workbook`), the point needs no budget (those shaders stay within theirs)
//! and no check for rays that find their own surface (those shapes describe their hits exactly and those
//! shaders spawn their rays with [`Ray::spawn`]), so `raytrace` keeps no shading point for it: its rays
//! skip the bookkeeping, and only what they bring back NaN or infinite is noted (`Shading`).

use crate::lesson::color::Color;
use crate::lesson::geometry::IntersectionInfo;
use crate::lesson::helper_ranges;
use crate::lesson::math::{Vector, max_abs};
use crate::lesson::node::{Node, UNIT_NORMAL_TOLERANCE};
use crate::lesson::problems::{Gains, Problems, Source};
use crate::lesson::ray::{Ray, spawn_point};
use crate::lesson::scene::TraceContext;
use crate::lesson::shader::Shader;
use glam::Vec3A;
use std::collections::BTreeMap;

/// The deepest ray whose shading point may still pass its rays twice its own weight; a deeper one passes
/// at most its own. 4 is the course's default `maxTraceDepth`, so its scenes trace exactly the course's
/// rays.
pub const SPLIT_DEPTH: u32 = 4;

/// How many times its own weight a shading point of a ray at depth 1 to [`SPLIT_DEPTH`] may pass its rays
/// together: the 2 rays the course's glossy mirror traces there.
pub const SECONDARY_SPLIT: u32 = 2;

/// How many times its own weight the shading point of a ray at `depth` may pass to its rays, together.
#[inline(always)]
pub fn split_factor(depth: u32) -> f32 {
    const FACTORS: [f32; SPLIT_DEPTH as usize + 2] = {
        let mut factors = [SECONDARY_SPLIT as f32; SPLIT_DEPTH as usize + 2];
        factors[0] = f32::INFINITY;
        factors[SPLIT_DEPTH as usize + 1] = 1.0;
        factors
    };
    FACTORS[(depth as usize).min(SPLIT_DEPTH as usize + 1)]
}

/// The most rays one branch of the ray tree (a ray the camera ray's hit traces, and every ray below it) may
/// trace: 1024, four times what any example's branch traces in either reading at its own depth limit (the
/// largest, a glass at depth 10 with `--exhaustive`, traces between 64 and 256), and few enough that a scene
/// whose rays double at every level renders in seconds where it would take days.
pub const RAYS_PER_BRANCH: u32 = 1 << 10;

/// `sqrt(f32::EPSILON)`, 2^-11.5: the relative error of a hit point found by the textbook quadratic at its
/// worst, when cancellation takes half the digits.
const SQRT_EPSILON: f32 = 3.452_669_8e-4;

/// The slack of the budget for rounding: a shader that splits its ray's weight `w` into `R * w` and
/// `(1 - R) * w` rounds `1 - R` and each product once, so their sum may exceed `w` by `2 * EPSILON * w`;
/// twice that is allowed, so that such a split is never taken for an average.
const ROUNDING: f32 = 1.0 + 4.0 * f32::EPSILON;

/// The least factor by which a shader's colour exceeds its brightest ray plus its light for the energy check
/// to count the hit: one 8-bit level at white, 1 + 1/255. Rounding makes a mean of equal colours exceed each
/// by a few units in the last place, which is far below it; a naive sum of N rays exceeds it by up to N.
const VISIBLE_GAIN: f32 = 1.0 + 1.0 / 255.0;

/// What `raytrace` keeps of the shaders running, innermost first: the shading point whose rays share a
/// budget, whether the innermost shader is the workbook's own, and whether a ray came back NaN or infinite.
#[derive(Clone, Copy)]
pub(crate) struct Shading<'a> {
    /// The innermost shading point whose rays are bounded: a student's shader's, a glossy mirror's, any
    /// shader's on a shape the renderer does not know.
    point: ShadingPoint<'a>,
    /// Whether the innermost running shader is the workbook's own on one of its shapes (or the camera):
    /// its rays skip the budget and the check for rays that find their own surface.
    pub(crate) workbook: bool,
    /// Whether a ray traced since the innermost shading point began came back NaN or infinite (then that
    /// point did not make the first such colour).
    pub(crate) non_finite_below: bool,
    /// The least depth a ray of the innermost shading point may have: one more than the ray it shades (0 for
    /// the camera's). A ray made with `Ray::new` (depth 0) is traced at this depth instead.
    pub(crate) least_depth: u32,
    /// How many rays the shader of the innermost shading point traced, or was given their siblings' mean
    /// colour, over all its layers (the energy check weighs it from two on).
    rays: u32,
}

/// The shading point of a shader that may branch past its budget: its rays ([`Siblings`]), what they and its
/// light loops brought ([`Income`]) and where it is ([`Origin`]).
#[derive(Clone, Copy)]
pub(crate) struct ShadingPoint<'a> {
    siblings: Siblings,
    income: Income,
    origin: Origin<'a>,
}

/// What the shader of a shading point had to make its colour of, over all its layers (the energy check).
#[derive(Clone, Copy, Default)]
struct Income {
    /// The brightest colour, channel by channel, that one of its rays brought back.
    brightest: Color,
    /// The light its light loops gathered.
    light: Color,
}

/// The rays of one shading point: what they may still weigh and what they brought back.
#[derive(Clone, Copy)]
pub(crate) struct Siblings {
    /// The colours the traced ones brought back, summed.
    sum: Color,
    /// What their weights may still add up to: the budget less the weights of every ray so far, those not
    /// traced included.
    remaining: f32,
    /// How many were traced.
    traced: u32,
}

/// Where a shading point is, for the end-of-run check of rays that hit the surface they left.
#[derive(Clone, Copy)]
struct Origin<'a> {
    /// The node hit; `None` for the camera.
    node: Option<&'a Node>,
    /// How close to the hit point a ray of this point must find its node again to be taken for one that
    /// found the surface it left (see [`ShadingPoint::finds_its_own_surface`]).
    near: f32,
    /// The surface's own normal at the hit.
    normal: Vector,
    /// The hit point, and its error bound (where [`Ray::spawn`] starts a ray).
    ip: Vector,
    error: f32,
}

impl Siblings {
    /// The rays of the shading point of a ray at `depth` with weight `weight`.
    #[inline(always)]
    fn new(depth: u32, weight: f32) -> Siblings {
        Siblings { sum: Color::BLACK, remaining: split_factor(depth) * ROUNDING * weight, traced: 0 }
    }
}

impl<'a> Shading<'a> {
    /// The camera's: its rays are never shared and start from no surface.
    pub(crate) fn camera() -> Shading<'a> {
        Shading {
            point: ShadingPoint {
                siblings: Siblings::new(0, 1.0),
                income: Income::default(),
                origin: Origin { node: None, near: 0.0, normal: Vector::ZERO, ip: Vector::ZERO, error: 0.0 },
            },
            workbook: true,
            non_finite_below: false,
            least_depth: 0,
            rays: 0,
        }
    }

    /// A ray of the innermost shader with weight `weight` is about to be traced: `None` if it is to be, or
    /// the mean of its traced siblings' colours if it is over its shading point's budget.
    #[inline(always)]
    pub(crate) fn share(&mut self, weight: f32) -> Option<Color> {
        if self.workbook {
            return None;
        }
        let s = &mut self.point.siblings;
        s.remaining -= weight;
        if s.traced == 0 || s.remaining >= 0.0 {
            return None;
        }
        self.rays += 1;
        Some(s.sum / s.traced as f32)
    }

    /// A ray of the innermost shader was traced and brought back `color`.
    #[inline(always)]
    pub(crate) fn traced(&mut self, color: Color) {
        if !self.workbook {
            let s = &mut self.point.siblings;
            s.traced += 1;
            s.sum += color;
            let income = &mut self.point.income;
            income.brightest = Color(income.brightest.0.max(color.0));
            self.rays += 1;
        }
        if !color.is_finite() {
            self.non_finite_below = true;
        }
    }

    /// A light loop of the innermost shader gathered `light` (its irradiance and highlights).
    #[inline(always)]
    pub(crate) fn lit(&mut self, light: Color) {
        if !self.workbook {
            self.point.income.light += light;
        }
    }

    /// The node of the innermost shading point, if it is a hit's (not the camera's, and not one of the
    /// workbook's own nodes, which keep no shading point).
    pub(crate) fn node(&self) -> Option<&'a Node> {
        if self.workbook { None } else { self.point.origin.node }
    }

    /// One layer of the innermost shading point, seen by `ray`, begins: its rays get a budget of their own
    /// and share no colour with the rays of the layers before it (a `Layered` shader traces no rays of its
    /// own, so the point's own are not kept for after the layer).
    #[inline(always)]
    pub(crate) fn begin_layer(&mut self, ray: &Ray) {
        if !self.workbook {
            self.point.siblings = Siblings::new(ray.depth, ray.weight);
        }
    }
}

impl<'a> ShadingPoint<'a> {
    /// The hit `info` on `node` of `ray`.
    #[inline(always)]
    fn new(node: &'a Node, ray: &Ray, info: &IntersectionInfo) -> ShadingPoint<'a> {
        ShadingPoint {
            siblings: Siblings::new(ray.depth, ray.weight),
            income: Income::default(),
            origin: Origin {
                node: Some(node),
                near: SQRT_EPSILON * max_abs(info.ip).max(info.error),
                normal: info.geometric_normal,
                ip: info.ip,
                error: info.error,
            },
        }
    }

    /// Whether a ray of this point, `ray`, that hit `node` at `hit` found the surface it left again: the same
    /// node, closer to the point it left than the rounding error of a hit point computed by the textbook
    /// quadratic, which loses half the digits to cancellation (`sqrt(EPSILON)` times the point's
    /// coordinates), and the same surface there. A ray correctly started off the surface
    /// ([`crate::lesson::ray::Ray::spawn`]) leaves it by at least the hit's error bound, so only a hit point
    /// off the surface by more than its error bound (a geometry returning `ray.at(t)` unrefined), or a ray
    /// a shader started elsewhere, lands here.
    ///
    /// The same surface: on a shape of flat faces (a mesh,
    /// [`Shape::has_flat_faces`](crate::lesson::geometry::Shape::has_flat_faces)) the same face, told by its
    /// geometric normal, which a ray started off it to the side it goes to can never meet again; another
    /// triangle of the mesh met that close is real geometry (a ray reflected about a smooth shading normal
    /// that dips under a low-resolution mesh's face near its edge and leaves through the next triangle) and
    /// is shaded. On any other shape, a hit crossed the way the ray left the surface (from the side opposite
    /// to the one it went to: it started under the surface). A true second hit of such a shape is crossed the
    /// other way (a ray leaving a closed shape near an edge, after a short chord through it, leaves through
    /// another face; a concave surface is met again from the side the ray went to). A mesh needs its own
    /// rule because its geometric normals are turned to the side of its smooth shading normals, which on a
    /// sharp rim lie on opposite sides of two neighbouring triangles: the crossing test then takes a ray
    /// leaving one triangle and the solid through the next for one that never left.
    #[inline(always)]
    fn finds_its_own_surface(&self, node: &Node, ray: &Ray, hit: &IntersectionInfo) -> bool {
        let origin = &self.origin;
        origin.node.is_some_and(|n| std::ptr::eq(n, node))
            && hit.distance <= origin.near
            && match node.geometry.has_flat_faces() {
                true => hit.geometric_normal == origin.normal || hit.geometric_normal == -origin.normal,
                false => ray.dir.dot(origin.normal) * ray.dir.dot(hit.geometric_normal) > 0.0,
            }
    }
}

impl Origin<'_> {
    /// Whether `ray` starts nearer the surface than [`Ray::spawn`] starts a ray in its direction (at the hit
    /// point itself: `Ray::new(info.ip, dir)`): then a ray that finds the surface again is the shader's
    /// mistake, not the geometry's.
    fn starts_on_the_surface(&self, ray: &Ray) -> bool {
        let spawned = spawn_point(self.ip, self.normal, self.error, ray.dir);
        (ray.start - self.ip).dot(self.normal).abs() < (spawned - self.ip).dot(self.normal).abs()
    }
}

impl<'a> TraceContext<'a> {
    /// Whether a ray at `depth`, about to be traced, is within its branch's budget ([`RAYS_PER_BRANCH`]),
    /// counting it: a camera ray (depth 0) belongs to no branch, and a ray of the camera ray's hit (depth 1)
    /// begins one.
    #[inline(always)]
    pub(crate) fn within_branch_budget(&mut self, depth: u32) -> bool {
        self.branch_rays = if depth <= 1 { depth } else { self.branch_rays.saturating_add(1) };
        self.branch_rays <= RAYS_PER_BRANCH
    }

    /// The colour the shader of `node` gives the hit `info` of `ray`, shaded as a shading point of its own
    /// (its rays bounded by its budget), and what went wrong there counted for the end-of-run report: a
    /// normal that was not of unit length as the geometry returned it (`unit_normal` false), a ray that
    /// found the surface it left (black, not followed), a NaN or infinite colour made here. A node of the
    /// workbook's own shape and shaders is shaded by [`TraceContext::shade_workbook_hit`] instead.
    #[inline(always)]
    pub(crate) fn shade_hit(&mut self, i: usize, ray: &Ray, info: &IntersectionInfo, unit_normal: bool) -> Color {
        let scene = self.scene;
        let node = &scene.nodes[i];
        // A helper given a parameter out of its range by the shader whose ray this is (none at the camera).
        if helper_ranges::noted() {
            self.note_helper(self.shading.point.origin.node);
        }
        if !unit_normal {
            self.note(i, |p| &mut p.bad_normals);
        }
        if !self.shading.workbook && self.shading.point.finds_its_own_surface(node, ray, info) {
            // Not followed: shaded, it would leave the same surface from the same point again, down to the
            // depth limit (a shader's ray started without an offset). Black shows the mistake, and the
            // end-of-run report names it: the shader's, if the ray started on the hit point, else the geometry's.
            match self.shading.point.origin.starts_on_the_surface(ray) {
                true => self.note(i, |p| &mut p.unspawned_rays),
                false => self.note(i, |p| &mut p.self_hits),
            }
            return Color::BLACK;
        }
        let outer = std::mem::replace(
            &mut self.shading,
            Shading {
                point: ShadingPoint::new(node, ray, info),
                workbook: false,
                non_finite_below: false,
                least_depth: ray.depth + 1,
                rays: 0,
            },
        );
        let color = node.shader.shade(ray, info, self);
        if helper_ranges::noted() {
            self.note_helper(Some(node));
        }
        self.note_non_finite(i, color);
        if self.shading.rays >= 2 && color.is_finite() {
            self.weigh_energy(i, color);
        }
        self.shading = outer;
        color
    }

    /// The energy check of node `i`'s hit, whose shader traced two rays or more and gave `color` (finite):
    /// counted, and counted as a gain if some channel exceeds the brightest ray plus the light by
    /// [`VISIBLE_GAIN`]. A channel that received nothing is left out: light the shader makes of its own (a
    /// glow) is no gain of its rays. Kept out of `shade_hit`.
    #[inline(never)]
    fn weigh_energy(&mut self, i: usize, color: Color) {
        let income = self.shading.point.income;
        let bound = (income.brightest + income.light).0;
        let gain = Vec3A::select(bound.cmpgt(Vec3A::ZERO), color.0 / bound, Vec3A::ZERO).max_element();
        // By node index, not in a map: a lookup per weighed hit was 1% of the glossy example's instructions.
        let nodes = &mut self.counters.problems.energy_gains;
        if nodes.len() <= i {
            nodes.resize(i + 1, Gains::default());
        }
        let gains = &mut nodes[i];
        gains.hits += 1;
        if gain > VISIBLE_GAIN {
            gains.gained += 1;
            gains.largest = gains.largest.max(gain);
        }
    }

    /// The shader of node `i` gave `color`: a NaN or infinite colour is counted against the node if no ray
    /// it traced brought one back.
    #[inline(always)]
    pub(crate) fn note_non_finite(&mut self, i: usize, color: Color) {
        if !color.is_finite() && !self.shading.non_finite_below {
            Problems::count(&mut self.counters.problems.non_finite, Source::Node(i));
        }
    }

    /// Counts `dir`, the direction of a ray the innermost shader traces, against its node if it is not of
    /// unit length (the camera's rays, and those of the workbook's own shaders on its own shapes, are made
    /// so). Its squared length may be off by four times a normal's ([`UNIT_NORMAL_TOLERANCE`]): a direction
    /// made of unit vectors by a few f32 operations (a reflection, a refraction, a normalisation) is within
    /// a few `EPSILON` of 1, and the reflection `i - 2 (i.n) n` of a unit direction about a normal of squared
    /// length `1 + d` has squared length `1 + 4 (i.n)^2 d`, so a normal the normal check lets pass never makes
    /// a direction this check names; a direction a shader did not normalise is off by what it left out. A NaN
    /// direction is left to the NaN check (a NaN normal makes one in the course's own mirror), and the report
    /// leaves out the directions of a node whose normals the normal check names (they are made from them).
    #[inline(always)]
    pub(crate) fn check_direction(&mut self, dir: Vector) {
        if !self.shading.workbook && (dir.length_squared() - 1.0).abs() > 4.0 * UNIT_NORMAL_TOLERANCE {
            let node = self.shading.node().and_then(|node| self.scene.nodes.iter().position(|n| std::ptr::eq(n, node)));
            node.into_iter().for_each(|i| self.note(i, |p| &mut p.long_directions));
        }
    }

    /// Counts the calls of a course helper given a parameter out of its range that its thread noted against
    /// `node`, or drops them for `None` (noted outside a render's shaders: a photon's).
    #[cold]
    #[inline(never)]
    fn note_helper(&mut self, node: Option<&Node>) {
        let i = node.and_then(|node| self.scene.nodes.iter().position(|n| std::ptr::eq(n, node)));
        let calls = helper_ranges::take().zip(i);
        calls.into_iter().for_each(|(calls, i)| self.counters.problems.note_glossiness(i, calls));
    }

    /// Counts one more problem of the kind `what` picks for `node` (kept out of `raytrace`'s code: it is
    /// the rare path).
    #[inline(never)]
    fn note(&mut self, i: usize, what: impl FnOnce(&mut Problems) -> &mut BTreeMap<usize, u64>) {
        Problems::count(what(&mut self.counters.problems), i);
    }
}
