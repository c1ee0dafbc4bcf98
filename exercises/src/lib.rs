//! # Graded exercises for lecture 6
//!
//! The slides' functions, for a student to write. Each module below is one exercise: the slide it comes
//! from, what the function must do (in the slide's words and formula), its signature, and `todo!()` where
//! the answer goes. The grader hands these functions to the workbook's renderer, built for the exercises,
//! which calls them instead of its own, so every picture it draws is drawn with the student's code:
//!
//! ```sh
//! cargo test --release -p exercises                          # grade every exercise
//! cargo run --release -p exercises --example draw -- fresnel # a picture drawn with your functions
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

// The types of the exercises' signatures, and `reflect`, are the grader's: it checks values of them.
pub use exercise_grader::{CONE_FILTER_K, Color, Face, Photon, Vector, reflect};

/// The exercises handed out, by name: **the one switch of a hand-out**. For an exercise listed, the renderer
/// built for the exercises uses the function in this crate and the grader grades it; for one left out, the
/// renderer uses the workbook's own function and the grader skips it. A teacher handing out two exercises
/// lists those two (`&["refract", "fresnel_schlick"]`); a student may leave out an exercise not written yet
/// to see the pictures of the others (almost every picture uses `faceforward`, the bilinear filter and the
/// model transform). A name that is not one of [`EXERCISES`] stops the build.
pub const HANDED_OUT: &[&str] = EXERCISES;

/// The exercises whose workbook's own function is not in this copy of the workbook: a students' copy made
/// by the hand-out command takes out the workbook's own version of each exercise it hands out, so leaving
/// one of these out of [`HANDED_OUT`] leaves its `todo!()` in the renderer. None in the teacher's workbook.
pub const TAKEN_OUT: &[&str] = &[];

/// Every exercise, in the order of the slides.
pub const EXERCISES: &[&str] = &[
    "bilinear",
    "transform_inverse",
    "cube_map",
    "faceforward",
    "refract",
    "layered_blend",
    "fresnel_schlick",
    "fresnel_exact",
    "glossy_disc",
    "glossy_cone",
    "photon_estimate",
];

/// Whether `name` is in `list` (usable in constants).
pub const fn listed(list: &[&str], name: &str) -> bool {
    let mut i = 0;
    while i < list.len() {
        if list[i].len() == name.len() {
            let (a, b) = (list[i].as_bytes(), name.as_bytes());
            let mut j = 0;
            while j < a.len() && a[j] == b[j] {
                j += 1;
            }
            if j == a.len() {
                return true;
            }
        }
        i += 1;
    }
    false
}

// A misspelt name in HANDED_OUT would hand out nothing without a word: it stops the build instead.
const _: () = {
    let mut i = 0;
    while i < HANDED_OUT.len() {
        assert!(listed(EXERCISES, HANDED_OUT[i]), "HANDED_OUT names an exercise that does not exist");
        i += 1;
    }
    let mut i = 0;
    while i < TAKEN_OUT.len() {
        assert!(listed(EXERCISES, TAKEN_OUT[i]), "TAKEN_OUT names an exercise that does not exist");
        i += 1;
    }
};

pub mod answers;
pub mod grading;

/// Each exercise's switch, as the renderer and the grader read it: whether it is in [`HANDED_OUT`].
pub mod handed_out {
    use super::{HANDED_OUT, listed};
    pub const BILINEAR: bool = listed(HANDED_OUT, "bilinear");
    pub const TRANSFORM_INVERSE: bool = listed(HANDED_OUT, "transform_inverse");
    pub const CUBE_MAP: bool = listed(HANDED_OUT, "cube_map");
    pub const FACEFORWARD: bool = listed(HANDED_OUT, "faceforward");
    pub const REFRACT: bool = listed(HANDED_OUT, "refract");
    pub const LAYERED_BLEND: bool = listed(HANDED_OUT, "layered_blend");
    pub const FRESNEL_SCHLICK: bool = listed(HANDED_OUT, "fresnel_schlick");
    pub const FRESNEL_EXACT: bool = listed(HANDED_OUT, "fresnel_exact");
    pub const GLOSSY_DISC: bool = listed(HANDED_OUT, "glossy_disc");
    pub const GLOSSY_CONE: bool = listed(HANDED_OUT, "glossy_cone");
    pub const PHOTON_ESTIMATE: bool = listed(HANDED_OUT, "photon_estimate");
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
