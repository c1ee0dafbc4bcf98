//! # Graded exercises for lecture 6
//!
//! The slides' functions, for a student to write. Each module below is one exercise: the slide it comes
//! from, what the function must do (in the slide's words and formula), its signature, and `todo!()` where
//! the answer goes. Built for the exercises, the workbook's renderer calls these functions instead of its
//! own, so every picture it draws is drawn with the student's code:
//!
//! ```sh
//! cargo test -p exercises                                         # grade every exercise
//! cargo run --features exercises --example fresnel                # a picture drawn with your functions
//! ```
//!
//! The grader checks each exercise against facts (values the slide's formula gives, invariants such as
//! `|refract(i, n)| = 1`, conservation of energy) and then renders the workbook's example that uses it and
//! compares the picture with `expected/`. It prints, for every exercise, `passed`, `FAILED` with the first
//! wrong value, or `not yet written`. The teacher's page is docs/exercises.md.
//!
//! The exercises, in the order of the slides:
//!
//! | exercise | slide | function |
//! |---|---|---|
//! | [`bilinear`] | Bitmap текстури | the bitmap's bilinear filter |
//! | [`transform_inverse`] | Model трансформация | the inverse of the model transform, T^-1 |
//! | [`cube_map`] | Видове заден фон | the cube map's face and the point in it |
//! | [`faceforward`] | Ориентация на повърхнините | `faceforward` |
//! | [`refract`] | Refract | `refract`, with total internal reflection |
//! | [`layered_blend`] | Layered Shader | a layer's weight in the blend |
//! | [`fresnel_schlick`] | Fresnel | Schlick's approximation |
//! | [`fresnel_exact`] | Fresnel | the Fresnel equations Schlick approximates |
//! | [`glossy_disc`] | Симулиране на грапави отражения, step 2 | a point in the unit disc |
//! | [`glossy_cone`] | Симулиране на грапави отражения, steps 3-6 | a glossy reflection's direction |
//! | [`photon_estimate`] | Photon Mapping | the caustic light from the nearest photons |

// A blank exercise does not use its arguments yet.
#![allow(unused_variables, unused_mut)]

/// The course's `Vector`: three `f32`s (glam's SIMD-aligned `Vec3A`, the workbook's own vector type).
pub type Vector = glam::Vec3A;

/// A colour in linear light: `x` is red, `y` green, `z` blue (the workbook's `Color` holds the same three
/// numbers). Colours multiply channel by channel: `a * b`.
pub type Color = glam::Vec3A;

/// Mirror reflection of the incoming direction `i` about the normal `n` (slide "Reflect"):
/// `i + 2 * dot(-i, n) * n`. Given, not an exercise: [`glossy_cone`] uses it.
pub fn reflect(i: Vector, n: Vector) -> Vector {
    i + 2.0 * (-i).dot(n) * n
}

/// Which exercises are handed out. For an exercise set to `true`, the renderer built for the exercises uses
/// the function in this crate and the grader grades it; for one set to `false`, the renderer uses the
/// workbook's own function and the grader skips it. A teacher sets the list for a hand-out. A student may
/// set an exercise that is not written yet to `false` to see the pictures of the others: almost every
/// picture uses `faceforward`, the bilinear filter and the model transform.
pub mod handed_out {
    pub const BILINEAR: bool = true;
    pub const TRANSFORM_INVERSE: bool = true;
    pub const CUBE_MAP: bool = true;
    pub const FACEFORWARD: bool = true;
    pub const REFRACT: bool = true;
    pub const LAYERED_BLEND: bool = true;
    pub const FRESNEL_SCHLICK: bool = true;
    pub const FRESNEL_EXACT: bool = true;
    pub const GLOSSY_DISC: bool = true;
    pub const GLOSSY_CONE: bool = true;
    pub const PHOTON_ESTIMATE: bool = true;
}

// Each exercise is a file of its own; with the feature `solutions` its solution in src/solutions/ is
// compiled instead.
#[cfg_attr(feature = "solutions", path = "solutions/bilinear.rs")]
pub mod bilinear;
#[cfg_attr(feature = "solutions", path = "solutions/cube_map.rs")]
pub mod cube_map;
#[cfg_attr(feature = "solutions", path = "solutions/faceforward.rs")]
pub mod faceforward;
#[cfg_attr(feature = "solutions", path = "solutions/fresnel_exact.rs")]
pub mod fresnel_exact;
#[cfg_attr(feature = "solutions", path = "solutions/fresnel_schlick.rs")]
pub mod fresnel_schlick;
#[cfg_attr(feature = "solutions", path = "solutions/glossy_cone.rs")]
pub mod glossy_cone;
#[cfg_attr(feature = "solutions", path = "solutions/glossy_disc.rs")]
pub mod glossy_disc;
#[cfg_attr(feature = "solutions", path = "solutions/layered_blend.rs")]
pub mod layered_blend;
#[cfg_attr(feature = "solutions", path = "solutions/photon_estimate.rs")]
pub mod photon_estimate;
#[cfg_attr(feature = "solutions", path = "solutions/refract.rs")]
pub mod refract;
#[cfg_attr(feature = "solutions", path = "solutions/transform_inverse.rs")]
pub mod transform_inverse;

/// The six faces of a cube map, in the order the workbook numbers them ([`cube_map`] returns one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    PosX,
    NegX,
    PosY,
    NegY,
    PosZ,
    NegZ,
}

/// A photon found near a shaded point, as [`photon_estimate`] gets it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Photon {
    /// The squared distance from the shaded point to where the photon landed.
    pub distance_squared: f32,
    /// The unit direction the photon travelled in when it landed.
    pub dir: Vector,
    /// The photon's power (flux), per channel.
    pub power: Color,
}

/// The cone filter's constant k >= 1 (Jensen's 1.1): see [`photon_estimate`].
pub const CONE_FILTER_K: f32 = 1.1;
