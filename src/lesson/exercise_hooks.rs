//! The renderer built for the graded exercises (feature `exercises`; the teacher's page is
//! docs/exercises.md). Each slide function an exercise covers starts with one line,
//! `exercise!(name(arguments));`. Built for the exercises, that line asks the method of the same name of the
//! [`Answers`] the program registered ([`answer_with`]): an answer is returned by the slide function, and its
//! own code is not run; `None` (no answers registered, or the exercise not handed out) runs the workbook's
//! own code. In the plain build the line is nothing at all.
//!
//! The library does not depend on the students' crate: the grader (`cargo test -p exercises`) registers the
//! student's functions when it starts (`exercises/src/answers.rs`), so an edit of an exercise compiles that
//! crate and the grader again, never the renderer.

use crate::lesson::color::Color;
use crate::lesson::environment::CubeFace;
use crate::lesson::math::{OrthonormalBasis, Vector};
use crate::lesson::photon_map::StoredPhoton;
use crate::lesson::rng::Rng;
use glam::Affine3A;
use std::sync::OnceLock;

/// A student's version of each slide function an exercise covers, each `None` to use the workbook's own.
pub trait Answers: Sync {
    /// [`Bitmap`](crate::lesson::bitmap::Bitmap)'s bilinear filter, with `texel(i, j)` the wrapped texel.
    fn bilinear(&self, x: f32, y: f32, texel: &dyn Fn(i64, i64) -> Color) -> Option<Color>;
    /// The inverse of a node's [`Transform`](crate::lesson::transform::Transform).
    fn transform_inverse(&self, t: Affine3A) -> Option<Affine3A>;
    /// [`cube_face_uv`](crate::lesson::environment::cube_face_uv).
    fn cube_face_uv(&self, dir: Vector) -> Option<(CubeFace, f32, f32)>;
    /// [`faceforward`](crate::lesson::math::faceforward).
    fn faceforward(&self, n: Vector, i: Vector) -> Option<Vector>;
    /// [`refract`](crate::lesson::math::refract).
    fn refract(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Option<Vector>>;
    /// The weight of a layer of a [`Layered`](crate::lesson::shader::Layered) shader.
    fn layer_weight(&self, uncovered: Color, blend: Color) -> Option<Color>;
    /// [`fresnel`](crate::lesson::math::fresnel), Schlick's approximation.
    fn fresnel(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32>;
    /// [`fresnel_exact`](crate::lesson::math::fresnel_exact).
    fn fresnel_exact(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32>;
    /// [`random_unit_disc_point`](crate::lesson::sampling::random_unit_disc_point), drawing from the pixel's
    /// own random stream.
    fn random_unit_disc_point(&self, rng: &mut Rng) -> Option<(f32, f32)>;
    /// [`concentric_disc`](crate::lesson::sampling::concentric_disc).
    fn concentric_disc(&self, u: f32, v: f32) -> Option<(f32, f32)>;
    /// The tilt of a [`GlossyCone`](crate::lesson::shader::GlossyCone) (step 3 of the slide's algorithm).
    fn glossy_scaling(&self, glossiness: f32) -> Option<f32>;
    /// A [`GlossyCone`](crate::lesson::shader::GlossyCone)'s direction (steps 4-6), in the cone's basis
    /// (step 1).
    fn glossy_direction(
        &self,
        incoming: Vector,
        basis: &OrthonormalBasis,
        scaling: f32,
        disc_point: (f32, f32),
    ) -> Option<Option<Vector>>;
    /// The photon map's estimate from the photons found, each with its squared distance, finished by
    /// [`arriving_light`](crate::lesson::photon_map::arriving_light) as
    /// [`PhotonMap::irradiance`](crate::lesson::photon_map::PhotonMap::irradiance) finishes its own.
    fn irradiance_estimate(
        &self,
        found: &mut dyn Iterator<Item = (f32, &StoredPhoton)>,
        radius_squared: f32,
        normal: Vector,
    ) -> Option<Color>;
}

/// The answers the program registered, if any.
static ANSWERS: OnceLock<&'static dyn Answers> = OnceLock::new();

/// Draws every picture of this program with `answers` from now on. The first registration holds: a second
/// returns `false` and changes nothing.
pub fn answer_with(answers: &'static dyn Answers) -> bool {
    ANSWERS.set(answers).is_ok()
}

/// The registered answers, if any: what `exercise!(hook(arguments))` asks (`answers()?.hook(arguments)`).
pub fn answers() -> Option<&'static dyn Answers> {
    ANSWERS.get().copied()
}
