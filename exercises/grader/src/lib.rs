//! The grader of the lecture-6 exercises: not an exercise. The exercises' crate (`exercises/`) holds the
//! student's functions, the list of exercises handed out and the answers it gives the renderer; this crate
//! holds everything else the grading needs: each exercise's [`facts`], the [`grading`] in processes of their
//! own, the [`report`] a student reads, the [`draw`]ing of an example with the student's functions, the
//! [`hooks`] the renderer asks, and the types of the exercises' signatures. It is compiled once: the
//! exercises' crate and the programs that run it (`cargo test -p exercises`, its `draw` example) are thin, so
//! an edit of an exercise compiles those again, in seconds, and nothing of this.

#[macro_use]
#[path = "../../../tests/workbook/common/examples.rs"]
mod examples;
pub mod draw;
pub mod facts;
pub mod grading;
pub mod hooks;
pub mod report;

/// The course's `Vector`: three `f32`s (glam's SIMD-aligned `Vec3A`, the workbook's own vector type).
pub type Vector = glam::Vec3A;

/// A colour in linear light: `x` is red, `y` green, `z` blue (the workbook's `Color` holds the same three
/// numbers). Colours multiply channel by channel: `a * b`.
pub type Color = glam::Vec3A;

/// Mirror reflection of the incoming direction `i` about the normal `n` (slide "Reflect"):
/// `i + 2 * dot(-i, n) * n`. Given, not an exercise: the glossy cone uses it.
pub fn reflect(i: Vector, n: Vector) -> Vector {
    i + 2.0 * (-i).dot(n) * n
}

/// The six faces of a cube map, in the order the workbook numbers them (the cube map exercise returns one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    PosX,
    NegX,
    PosY,
    NegY,
    PosZ,
    NegZ,
}

/// A photon found near a shaded point, as the photon estimate exercise gets it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    /// The squared distance from the shaded point to where the photon landed.
    pub distance_squared: f32,
    /// The unit direction the photon travelled in when it landed.
    pub dir: Vector,
    /// The photon's power (flux), per channel.
    pub power: Color,
}

// The cone filter's constant (see the photon estimate exercise) is the workbook's own, read from its file.
include!("../../../src/lesson/photon_map/cone_filter_k.rs");
