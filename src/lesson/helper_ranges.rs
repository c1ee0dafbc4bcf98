//! A course helper's parameter outside the range it takes, given at run time by a student's shader (beyond
//! the slides): the end-of-run report's line on it.
//!
//! The course's shaders' parameters are fixed when the scene is built and are checked from the scene after
//! the render (`crate::app::parameter_ranges`). A student's shader may instead pass a helper a value it
//! computes at each hit (a glossiness read from a texture): [`GlossyCone::new`] with a glossiness outside
//! (0, 1] makes a cone that is unbounded or turned inside out, and nothing fails. The helper has no context
//! to count it in (its signature is the course's), so it notes the value in a counter of its thread
//! (`note`), and `raytrace` moves what is noted to the node whose shader called the helper: when that
//! shader's ray reaches a hit, and when that shader returns (`TraceContext::shade_hit`). The workbook's own
//! nodes keep no shading point and pay nothing: the course's glossy mirror builds its cone without the note
//! (`GlossyCone::from_scene`), its glossiness being checked from the scene.
//!
//! Covered: [`GlossyCone::new`]'s glossiness. The other helpers a shader calls take no parameter with a range
//! of their own (`reflect` and `faceforward` take directions, `refract` any ratio of indices, with total
//! internal reflection as its answer).
//!
//! [`GlossyCone::new`]: crate::lesson::shader::GlossyCone::new

use std::cell::Cell;

/// How often `GlossyCone::new` was given a glossiness outside (0, 1], and the value furthest outside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutOfRange {
    /// The calls.
    pub calls: u64,
    /// The value furthest from the range's middle, 1/2 (NaN if one was NaN); of two as far, the larger, so
    /// that the report is the same in whatever order the threads' counts are added.
    pub worst: f32,
}

impl OutOfRange {
    /// These calls and `other`'s.
    pub(crate) fn merged(self, other: OutOfRange) -> OutOfRange {
        let key = |v: f32| (v - 0.5).abs();
        let further = key(other.worst).total_cmp(&key(self.worst)).then(other.worst.total_cmp(&self.worst));
        OutOfRange { calls: self.calls + other.calls, worst: if further.is_gt() { other.worst } else { self.worst } }
    }
}

thread_local! {
    /// What was noted since `raytrace` last moved it to a node.
    static NOTED: Cell<Option<OutOfRange>> = const { Cell::new(None) };
}

/// `GlossyCone::new` was given `glossiness`, outside (0, 1]: noted for the node whose shader called it.
#[cold]
#[inline(never)]
pub(crate) fn note(glossiness: f32) {
    let call = OutOfRange { calls: 1, worst: glossiness };
    NOTED.with(|n| n.set(Some(n.get().map_or(call, |noted| noted.merged(call)))));
}

/// Whether anything was noted since the last [`take`]: the one thing the trace reads at a hit of a
/// student's node (read, not taken, on that path).
#[inline(always)]
pub(crate) fn noted() -> bool {
    NOTED.with(|n| n.get().is_some())
}

/// What was noted since the last call, cleared.
#[cold]
#[inline(never)]
pub(crate) fn take() -> Option<OutOfRange> {
    NOTED.with(Cell::take)
}
