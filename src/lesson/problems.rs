//! What `raytrace` counts going wrong while it traces, by node (beyond the slides): the counts behind the
//! end-of-run report, which [`crate::lesson::diagnostics`] turns into its lines after the render.

use crate::lesson::helper_ranges::OutOfRange;
use std::collections::{BTreeMap, BTreeSet};

/// Where a NaN or infinite colour came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Source {
    /// The shader of the node with this index in `Scene::nodes`.
    Node(usize),
    /// The environment (or a node that is not in the scene's list).
    Environment,
}

/// What `raytrace` saw go wrong, counted by node (indices into `Scene::nodes`). Empty in a sound render.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Problems {
    /// Colours that came back NaN or infinite, by where they were first made.
    pub non_finite: BTreeMap<Source, u64>,
    /// Rays started off the surface (as `Ray::spawn` starts them) that hit the surface they left, right where
    /// they left it, by node: its hit point lies off the surface.
    pub self_hits: BTreeMap<usize, u64>,
    /// Rays a shader started on the hit point itself (not off the surface, as `Ray::spawn` does) that hit the
    /// surface they left, right where they left it, by node.
    pub unspawned_rays: BTreeMap<usize, u64>,
    /// The energy check, by node index (up to the last node weighed): the hits whose shader traced two rays
    /// or more, and those where it returned more than its brightest ray plus its light loop's light.
    pub energy_gains: Vec<Gains>,
    /// Hits whose normal, as the geometry returned it, is not of unit length (or is NaN), by node.
    pub bad_normals: BTreeMap<usize, u64>,
    /// Rays a shader traced in a direction not of unit length, by the node whose shader traced them.
    pub long_directions: BTreeMap<usize, u64>,
    /// Rays a shader traced with a depth below its own ray's (made with `Ray::new`, which starts at depth 0),
    /// by the node whose shader traced them: `raytrace` counts them at their real depth.
    pub restarted_depth: BTreeMap<Source, u64>,
    /// Calls of `GlossyCone::new` with a glossiness outside (0, 1], by the node whose shader made them
    /// ([`crate::lesson::helper_ranges`]).
    pub glossiness_out_of_range: BTreeMap<usize, OutOfRange>,
    /// The nodes whose shader gave rays of different wavelengths different colours though it says it does not
    /// depend on them (`diagnostics::undeclared_dispersion`, after the render).
    pub undeclared_dispersion: BTreeSet<usize>,
}

/// The energy check of one node ([`Problems::energy_gains`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Gains {
    /// Hits whose shader traced two rays or more.
    pub hits: u64,
    /// Those where it returned, in some channel, more than its brightest ray plus its light loop's light.
    pub gained: u64,
    /// The largest factor by which it did.
    pub largest: f32,
}

impl Problems {
    /// Adds `other`'s counts to these.
    pub fn add(&mut self, other: &Problems) {
        fn merge<K: Ord + Copy>(a: &mut BTreeMap<K, u64>, b: &BTreeMap<K, u64>) {
            if b.is_empty() {
                return;
            }
            for (k, n) in b {
                *a.entry(*k).or_default() += n;
            }
        }
        merge(&mut self.non_finite, &other.non_finite);
        merge(&mut self.self_hits, &other.self_hits);
        merge(&mut self.unspawned_rays, &other.unspawned_rays);
        if self.energy_gains.len() < other.energy_gains.len() {
            self.energy_gains.resize(other.energy_gains.len(), Gains::default());
        }
        for (mine, g) in self.energy_gains.iter_mut().zip(&other.energy_gains) {
            (mine.hits, mine.gained, mine.largest) =
                (mine.hits + g.hits, mine.gained + g.gained, mine.largest.max(g.largest));
        }
        merge(&mut self.bad_normals, &other.bad_normals);
        merge(&mut self.long_directions, &other.long_directions);
        merge(&mut self.restarted_depth, &other.restarted_depth);
        self.undeclared_dispersion.extend(&other.undeclared_dispersion);
        other.glossiness_out_of_range.iter().for_each(|(&i, &calls)| self.note_glossiness(i, calls));
    }

    /// Adds `calls` of `GlossyCone::new` with a glossiness out of range to node `i`'s.
    pub(crate) fn note_glossiness(&mut self, i: usize, calls: OutOfRange) {
        self.glossiness_out_of_range.entry(i).and_modify(|n| *n = n.merged(calls)).or_insert(calls);
    }

    /// Counts one more of `what` for `node`.
    pub(crate) fn count<K: Ord>(what: &mut BTreeMap<K, u64>, node: K) {
        *what.entry(node).or_default() += 1;
    }
}
