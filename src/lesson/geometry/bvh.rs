//! A bounding volume hierarchy over a mesh's triangles, built once when a [`Mesh`](super::Mesh) is loaded.
//! It is not on this lecture's slides; it is what lets a student's mesh of any size render in seconds.
//!
//! - Build: top-down, binned surface area heuristic (16 bins on each axis over the primitives' centroids);
//!   a node becomes a leaf when splitting it is not expected to be cheaper than testing its primitives.
//!   Primitives may be tested in groups ([`Bvh::build_in_groups`]: the mesh tests four triangles at once),
//!   and then the heuristic counts group tests: a leaf of 1 to 4 triangles costs one test.
//! - Layout: the binary tree is then collapsed into a 4-wide one (each node keeps the four largest nodes
//!   of the top of its binary subtree as children), which halves the depth a ray walks down. A node stores
//!   its up to four children's boxes plane by plane in 128 bytes aligned to 128 (the pair of cache lines
//!   the processor fetches together), so one memory access and one SIMD operation per plane test all
//!   four. Primitives are reordered so that each leaf owns a contiguous range, starting on a whole group
//!   and padded to whole groups.
//! - Traversal: all four children's boxes are tested at each node; the children hit are pushed sorted by
//!   their entry distance, the nearest visited first, and a pushed child is skipped when popped if a closer
//!   hit has been found meanwhile. The nodes of the children hit are requested from memory at once (a
//!   prefetch), so that on a large mesh their cache misses overlap. The slab test widens the exit distance
//!   by `1 + 2 gamma(3)` (pbrt-v4), so rounding never makes the box test miss a triangle that the
//!   (watertight) triangle test would hit.

use super::Aabb;
use crate::lesson::math::{Vector, gamma};
use glam::Vec4;
use std::mem::MaybeUninit;
use std::ops::Range;

/// Bins per axis of the binned SAH.
const BINS: usize = 16;
/// The deepest a tree may grow; the traversal stack holds three children for each level.
const MAX_DEPTH: usize = 64;
/// Cost of visiting a binary node, relative to one test of a group of primitives (one ray-triangle test,
/// or four at once for a mesh). 3 gives a 4-wide tree under half the size that 1 gives, so that the tree of
/// a 100,000-triangle mesh still fits the cache (docs/measurements.md, mesh benchmark).
const TRAVERSAL_COST: f32 = 3.0;
/// Leaves larger than this are split even when the heuristic would keep them.
const MAX_LEAF: usize = 8;

/// A node: its box, and either its children (`count == 0`: while building, the pair of nodes `first`;
/// once collapsed, the [`Quad`] `first`) or its primitives (`first .. first + count`). The indices ride
/// in the `w` lanes, so a node is two SIMD registers.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
struct Node {
    min_first: Vec4,
    max_count: Vec4,
}

impl Node {
    fn new(b: Aabb, first: usize, count: usize) -> Node {
        Node {
            min_first: b.min.extend(f32::from_bits(first as u32)),
            max_count: b.max.extend(f32::from_bits(count as u32)),
        }
    }
    fn first(&self) -> usize {
        self.min_first.w.to_bits() as usize
    }
    fn count(&self) -> usize {
        self.max_count.w.to_bits() as usize
    }
    fn aabb(&self) -> Aabb {
        Aabb::new(Vector::from_vec4(self.min_first), Vector::from_vec4(self.max_count))
    }

    /// Where the ray enters the box, if it meets it before `t_max`.
    #[inline(always)]
    fn entry(&self, start: Vector, inv_dir: Vector, t_max: f32) -> Option<f32> {
        let t0 = (Vector::from_vec4(self.min_first) - start) * inv_dir;
        let t1 = (Vector::from_vec4(self.max_count) - start) * inv_dir;
        let near = t0.min(t1).max_element().max(0.0);
        let far = t0.max(t1).min_element() * (1.0 + 2.0 * gamma(3));
        (near <= far && near < t_max).then_some(near)
    }
}

fn union(a: Aabb, b: Aabb) -> Aabb {
    Aabb::new(a.min.min(b.min), a.max.max(b.max))
}

const EMPTY: Aabb = Aabb { min: Vector::INFINITY, max: Vector::NEG_INFINITY };

/// Half the surface area of a box (the SAH only compares areas).
fn half_area(b: &Aabb) -> f32 {
    let d = b.max - b.min;
    d.x * d.y + d.y * d.z + d.z * d.x
}

/// Up to four children of a node, their boxes stored plane by plane (lane `i` is child `i`) so that one
/// SIMD operation per plane tests the ray against all four. An unused lane has an empty box (min +inf,
/// max -inf), which no ray enters.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(128))]
struct Quad {
    /// min x, max x, min y, max y, min z, max z.
    planes: [Vec4; 6],
    /// Per child, as in [`Node`]: a leaf's primitives, or (`count == 0`) the index of an interior child.
    first: [u32; 4],
    count: [u32; 4],
}

impl Quad {
    fn new(children: &[Node]) -> Quad {
        let mut quad = Quad {
            planes: [Vec4::INFINITY, Vec4::NEG_INFINITY].repeat(3).try_into().expect("six planes"),
            first: [0; 4],
            count: [0; 4],
        };
        for (i, child) in children.iter().enumerate() {
            let b = child.aabb();
            for k in 0..3 {
                quad.planes[2 * k][i] = b.min[k];
                quad.planes[2 * k + 1][i] = b.max[k];
            }
            quad.first[i] = child.first() as u32;
            quad.count[i] = child.count() as u32;
        }
        quad
    }
}

/// Moves the leaves' ranges apart so that each starts at a multiple of `group` and spans whole groups (the
/// leaves partition `order`, and keep their order); returns the primitive in each slot of the new order,
/// `None` where a leaf is padded.
fn pad_leaves(root: &mut Node, pairs: &mut [[Node; 2]], order: &[u32], group: usize) -> Vec<Option<u32>> {
    let mut leaves: Vec<&mut Node> =
        std::iter::once(root).chain(pairs.iter_mut().flatten()).filter(|node| node.count() > 0).collect();
    leaves.sort_by_key(|leaf| leaf.first());
    let mut slots = Vec::with_capacity(order.len());
    for leaf in leaves {
        let (first, count) = (leaf.first(), leaf.count());
        let padded = count.next_multiple_of(group);
        *leaf = Node::new(leaf.aabb(), slots.len(), padded);
        slots.extend(order[first..first + count].iter().map(|&p| Some(p)));
        slots.resize(slots.len() + padded - count, None);
    }
    slots
}

/// Collapses the binary subtree under the interior node `node` (whose children are the pair it names) into
/// 4-wide nodes appended to `quads`; returns the index of its top one. The children are found by opening,
/// while there are fewer than four, the interior child of largest surface area (the one rays enter most).
fn collapse(pairs: &[[Node; 2]], node: &Node, quads: &mut Vec<Quad>) -> u32 {
    let mut children = pairs[node.first()].to_vec();
    while children.len() < 4 {
        let largest = children
            .iter()
            .enumerate()
            .filter(|(_, c)| c.count() == 0)
            .max_by(|(_, a), (_, b)| half_area(&a.aabb()).total_cmp(&half_area(&b.aabb())));
        let Some((i, _)) = largest else { break };
        let opened = children.swap_remove(i);
        children.extend(pairs[opened.first()]);
    }
    let at = quads.len();
    quads.push(Quad::new(&children));
    for (i, child) in children.iter().enumerate() {
        if child.count() == 0 {
            quads[at].first[i] = collapse(pairs, child, quads);
        }
    }
    at as u32
}

/// A bounding volume hierarchy; see the module documentation.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    /// The root; when it is interior (`count == 0`), it is `quads[0]`.
    root: Option<Node>,
    quads: Vec<Quad>,
}

/// The chosen split of a node: primitives whose centroid falls in bins `..=bin` of `axis` go left.
struct Split {
    axis: usize,
    bin: usize,
    left: Aabb,
    right: Aabb,
}

impl Bvh {
    /// Builds the hierarchy over primitives given by their boxes. Returns it with the order in which the
    /// primitives must be stored: leaf ranges index that order.
    pub fn build(boxes: &[Aabb]) -> (Bvh, Vec<u32>) {
        let (bvh, slots) = Bvh::build_in_groups(boxes, 1);
        // Groups of one need no padding: every slot holds a primitive.
        (bvh, slots.into_iter().flatten().collect())
    }

    /// Builds the hierarchy as [`Bvh::build`] does, with every leaf's range starting at a multiple of
    /// `group` and spanning whole groups, so that a leaf's primitives can be stored `group` to a SIMD
    /// test (the mesh's [`Triangle4`](super::triangle4::Triangle4)). Returns it with the primitive in each
    /// slot of that order, `None` in the slots that pad a leaf to whole groups.
    pub fn build_in_groups(boxes: &[Aabb], group: usize) -> (Bvh, Vec<Option<u32>>) {
        let mut order: Vec<u32> = (0..boxes.len() as u32).collect();
        if boxes.is_empty() {
            return (Bvh::default(), Vec::new());
        }
        let centroids: Vec<Vector> = boxes.iter().map(Aabb::center).collect();
        let mut root = Node::new(boxes.iter().copied().fold(EMPTY, union), 0, boxes.len());
        let mut pairs: Vec<[Node; 2]> = Vec::with_capacity(boxes.len());
        // Work items: a node (None for the root, else a pair and a side) and its depth.
        let mut work: Vec<(Option<(usize, usize)>, usize)> = vec![(None, 0)];
        while let Some((at, depth)) = work.pop() {
            let node = match at {
                None => root,
                Some((pair, side)) => pairs[pair][side],
            };
            let (first, count) = (node.first(), node.count());
            let prims = &mut order[first..first + count];
            if count <= 1 || depth + 1 >= MAX_DEPTH {
                continue;
            }
            let Some((split, bounds)) = best_split(prims, boxes, &centroids, &node.aabb(), group) else { continue };
            // Partition in place: the left part first.
            let scale = BINS as f32 / (bounds.max[split.axis] - bounds.min[split.axis]);
            let bin = |p: u32| bin_of(centroids[p as usize][split.axis], bounds.min[split.axis], scale);
            let mut mid = 0;
            for i in 0..prims.len() {
                if bin(prims[i]) <= split.bin {
                    prims.swap(i, mid);
                    mid += 1;
                }
            }
            if mid == 0 || mid == count {
                continue;
            }
            let children = pairs.len();
            pairs.push([Node::new(split.left, first, mid), Node::new(split.right, first + mid, count - mid)]);
            let interior = Node::new(node.aabb(), children, 0);
            match at {
                None => root = interior,
                Some((pair, side)) => pairs[pair][side] = interior,
            }
            work.push((Some((children, 0)), depth + 1));
            work.push((Some((children, 1)), depth + 1));
        }
        let slots = pad_leaves(&mut root, &mut pairs, &order, group);
        let mut quads = Vec::with_capacity(pairs.len() / 2 + 1);
        if root.count() == 0 {
            collapse(&pairs, &root, &mut quads);
            root = Node::new(root.aabb(), 0, 0);
        }
        (Bvh { root: Some(root), quads }, slots)
    }

    /// The box around everything, or `None` when there is nothing.
    pub fn bounds(&self) -> Option<Aabb> {
        self.root.as_ref().map(Node::aabb)
    }

    /// Walks the tree front to back along the ray, calling `leaf(range, t_max)` for each leaf whose box the
    /// ray meets before `t_max`. `leaf` may lower `t_max` (closest hit) or return `true` to stop (any hit).
    #[inline]
    pub fn traverse(
        &self,
        start: Vector,
        dir: Vector,
        mut t_max: f32,
        mut leaf: impl FnMut(Range<usize>, &mut f32) -> bool,
    ) {
        let Some(root) = &self.root else { return };
        let inv_dir = dir.recip();
        if root.entry(start, inv_dir, t_max).is_none() {
            return;
        }
        let (o, inv) =
            ([start.x, start.y, start.z].map(Vec4::splat), [inv_dir.x, inv_dir.y, inv_dir.z].map(Vec4::splat));
        // Per axis, the plane the ray meets first (the min plane, or the max plane where the direction is
        // negative) and the one it leaves by.
        let negative = [inv_dir.x < 0.0, inv_dir.y < 0.0, inv_dir.z < 0.0].map(usize::from);
        let entry_plane = [0, 1, 2].map(|k| 2 * k + negative[k]);
        let exit_plane = [0, 1, 2].map(|k| 2 * k + 1 - negative[k]);
        let grow = Vec4::splat(1.0 + 2.0 * gamma(3));
        let mut stack = Stack::new();
        let (mut first, mut count) = (root.first() as u32, root.count() as u32);
        loop {
            if count > 0 {
                if leaf(first as usize..(first + count) as usize, &mut t_max) {
                    return;
                }
            } else {
                let quad = &self.quads[first as usize];
                let slab = |plane: [usize; 3], k: usize| (quad.planes[plane[k]] - o[k]) * inv[k];
                // Lane i: where the ray enters and leaves child i's box.
                let near = slab(entry_plane, 0).max(slab(entry_plane, 1)).max(slab(entry_plane, 2)).max(Vec4::ZERO);
                let far = slab(exit_plane, 0).min(slab(exit_plane, 1)).min(slab(exit_plane, 2)) * grow;
                let mut hit = (near.cmple(far) & near.cmplt(Vec4::splat(t_max))).bitmask();
                if hit.is_power_of_two() {
                    // One child hit (the commonest case): no ordering needed.
                    let i = hit.trailing_zeros() as usize;
                    (first, count) = (quad.first[i], quad.count[i]);
                    continue;
                }
                if hit != 0 {
                    // The children hit, nearest first: visit the nearest, push the others farthest first.
                    let mut children = [(0, 0, 0.0); 4];
                    let mut n = 0;
                    while hit != 0 {
                        let i = hit.trailing_zeros() as usize;
                        hit &= hit - 1;
                        let entry = (quad.first[i], quad.count[i], near[i]);
                        if entry.1 == 0 {
                            self.prefetch(entry.0);
                        }
                        let mut j = n;
                        while j > 0 && children[j - 1].2 > entry.2 {
                            children[j] = children[j - 1];
                            j -= 1;
                        }
                        children[j] = entry;
                        n += 1;
                    }
                    children[1..n].iter().rev().for_each(|&c| stack.push(c));
                    (first, count, _) = children[0];
                    continue;
                }
            }
            // Pop the next node that may still hold something closer than the best hit so far.
            loop {
                let Some((f, c, t_entry)) = stack.pop() else { return };
                if t_entry < t_max {
                    (first, count) = (f, c);
                    break;
                }
            }
        }
    }

    /// Asks the processor to start loading 4-wide node `quad` into the cache, without waiting for it: a
    /// hint that changes no result. On a large mesh a node's box test waits for its memory; issuing the
    /// loads of all the children hit at once overlaps those waits.
    #[inline(always)]
    fn prefetch(&self, quad: u32) {
        let lines = &self.quads[quad as usize].planes;
        cache::prefetch(&lines[0]);
        cache::prefetch(&lines[4]);
    }

    /// The number of nodes, leaves included (for the benchmark's report).
    pub fn node_count(&self) -> usize {
        let children: usize =
            self.quads.iter().map(|q| q.planes[0].cmple(q.planes[1]).bitmask().count_ones() as usize).sum();
        self.root.map_or(0, |_| 1 + children)
    }
}

/// A node still to visit: its `first` and `count` (as in [`Node`]) and where the ray enters its box.
type Entry = (u32, u32, f32);

/// The traversal stack. Each level of the tree pushes at most three children, and the 4-wide tree is no
/// deeper than the binary one it was collapsed from.
struct Stack {
    entries: [MaybeUninit<Entry>; 3 * MAX_DEPTH],
    len: usize,
}

impl Stack {
    /// An empty stack. Its entries are left uninitialised: zeroing its 2.3 KB for every ray would cost more
    /// than most of the rays' traversals (docs/measurements.md, mesh benchmark).
    #[inline(always)]
    fn new() -> Stack {
        Stack { entries: [const { MaybeUninit::uninit() }; 3 * MAX_DEPTH], len: 0 }
    }

    #[inline(always)]
    fn push(&mut self, entry: Entry) {
        self.entries[self.len].write(entry);
        self.len += 1;
    }

    #[inline(always)]
    #[allow(unsafe_code)] // Sound: see the SAFETY comment.
    fn pop(&mut self) -> Option<Entry> {
        self.len = self.len.checked_sub(1)?;
        // SAFETY: entries `..len` (before the decrement) were all written by `push`, which is the only way
        // `len` grows.
        Some(unsafe { self.entries[self.len].assume_init() })
    }
}

fn bin_of(c: f32, min: f32, scale: f32) -> usize {
    (((c - min) * scale) as usize).min(BINS - 1)
}

/// The cheapest binned SAH split of a node with box `node_box`, with the centroid bounds it was binned in;
/// `None` when keeping the node as a leaf is cheaper (and it is small enough) or the centroids coincide.
/// Primitives are tested `group` at a time: n of them cost `ceil(n / group)` tests.
fn best_split(
    prims: &[u32],
    boxes: &[Aabb],
    centroids: &[Vector],
    node_box: &Aabb,
    group: usize,
) -> Option<(Split, Aabb)> {
    let tests = |n: usize| n.div_ceil(group) as f32;
    let cb = Aabb::from_points(prims.iter().map(|&p| centroids[p as usize]));
    let mut best: Option<(f32, Split)> = None;
    let extent = cb.max - cb.min;
    let scale = Vector::splat(BINS as f32) / extent;
    // One pass bins every primitive on all three axes.
    let mut all_bins = [[(EMPTY, 0usize); BINS]; 3];
    for &p in prims {
        let offset = (centroids[p as usize] - cb.min) * scale;
        for (axis, bins) in all_bins.iter_mut().enumerate() {
            let b = &mut bins[(offset[axis] as usize).min(BINS - 1)];
            b.0 = union(b.0, boxes[p as usize]);
            b.1 += 1;
        }
    }
    for (axis, bins) in all_bins.iter().enumerate() {
        // Centroids are finite, so the extent is a number; zero when they all lie in one plane.
        if extent[axis] <= 0.0 {
            continue;
        }
        // Sweep from the right: the box and count of bins i.. for every i.
        let mut right = [(EMPTY, 0usize); BINS];
        let mut acc = (EMPTY, 0);
        for i in (1..BINS).rev() {
            acc = (union(acc.0, bins[i].0), acc.1 + bins[i].1);
            right[i] = acc;
        }
        let mut left = (EMPTY, 0);
        for i in 0..BINS - 1 {
            left = (union(left.0, bins[i].0), left.1 + bins[i].1);
            let r = right[i + 1];
            if left.1 == 0 || r.1 == 0 {
                continue;
            }
            let cost = half_area(&left.0) * tests(left.1) + half_area(&r.0) * tests(r.1);
            if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                best = Some((cost, Split { axis, bin: i, left: left.0, right: r.0 }));
            }
        }
    }
    let (cost, split) = best?;
    let area = half_area(node_box);
    let split_cost = TRAVERSAL_COST + cost / area;
    (split_cost < tests(prims.len()) || prims.len() > MAX_LEAF).then_some((split, cb))
}

/// The cache hint, on the targets that have one (SSE's `prefetcht0` on x86_64; elsewhere nothing).
mod cache {
    /// Starts loading the cache line holding `value` into every level of the cache.
    #[inline(always)]
    #[allow(unsafe_code)] // Sound: see the SAFETY comment.
    pub fn prefetch<T>(value: &T) {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
            // SAFETY: a prefetch only hints the cache: it reads nothing the program sees and cannot fault.
            unsafe { _mm_prefetch::<_MM_HINT_T0>((value as *const T).cast()) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        let _ = value;
    }
}
