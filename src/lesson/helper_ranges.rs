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
//! nodes keep no shading point and pay nothing: the course's glossy mirror builds its cone without the check
//! (`GlossyCone::from_scene`), its glossiness being checked from the scene.
//!
//! Covered: [`GlossyCone::new`]'s glossiness. The other helpers a shader calls take no parameter with a range
//! of their own (`reflect` and `faceforward` take directions, `refract` any ratio of indices, with total
//! internal reflection as its answer).
//!
//! [`GlossyCone::new`]: crate::lesson::shader::GlossyCone::new

use std::cell::Cell;

/// A course helper that takes a parameter in a range.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Helper {
    /// `GlossyCone::new(incoming, n, glossiness)`: glossiness above 0 and at most 1 (slide "Грапави (glossy)
    /// отражения").
    GlossyCone,
}

impl Helper {
    /// What the report says of the helper: its call, its parameter and the range it takes.
    pub fn describe(self) -> &'static str {
        match self {
            Helper::GlossyCone => {
                "GlossyCone::new's glossiness, above 0 and at most 1 (outside it the cone, tan((1 - glossiness) * \
                 pi/2), is unbounded or turned inside out)"
            }
        }
    }

    /// How far `value` lies outside the helper's range: 0 at its edge, infinite for NaN.
    fn distance(self, value: f32) -> f32 {
        match self {
            Helper::GlossyCone if value.is_nan() => f32::INFINITY,
            Helper::GlossyCone => (-value).max(value - 1.0),
        }
    }
}

/// How often a helper was given a parameter outside its range, and the value furthest outside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutOfRange {
    /// The calls.
    pub calls: u64,
    /// The value furthest outside the range (NaN if one was NaN).
    pub worst: f32,
}

impl OutOfRange {
    /// These calls and `other`'s, for `helper`.
    pub(crate) fn merged(self, other: OutOfRange, helper: Helper) -> OutOfRange {
        let worst = if helper.distance(other.worst) > helper.distance(self.worst) { other.worst } else { self.worst };
        OutOfRange { calls: self.calls + other.calls, worst }
    }
}

thread_local! {
    /// Whether a helper noted a value since `raytrace` last moved the notes to a node: the one thing the
    /// trace reads at each hit of a student's node.
    static NOTED: Cell<bool> = const { Cell::new(false) };
    /// What was noted (one helper so far).
    static GLOSSY_CONE: Cell<Option<OutOfRange>> = const { Cell::new(None) };
}

/// `helper` was given `value`, outside its range: noted for the node whose shader called it.
#[cold]
#[inline(never)]
pub(crate) fn note(helper: Helper, value: f32) {
    let call = OutOfRange { calls: 1, worst: value };
    match helper {
        Helper::GlossyCone => GLOSSY_CONE.with(|c| c.set(Some(c.get().map_or(call, |n| n.merged(call, helper))))),
    }
    NOTED.with(|n| n.set(true));
}

/// Whether a helper noted a value since the last [`take`].
#[inline(always)]
pub(crate) fn noted() -> bool {
    NOTED.with(Cell::get)
}

/// What the helpers noted since the last call, cleared.
#[cold]
#[inline(never)]
pub(crate) fn take() -> Vec<(Helper, OutOfRange)> {
    NOTED.with(|n| n.set(false));
    GLOSSY_CONE.with(Cell::take).map(|n| (Helper::GlossyCone, n)).into_iter().collect()
}
