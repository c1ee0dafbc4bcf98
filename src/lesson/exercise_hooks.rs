//! The renderer built for the graded exercises (feature `exercises`; the teacher's page is
//! docs/exercises.md). Each slide function an exercise covers starts with one line,
//! `exercise!(name(arguments));`. Built for the exercises, that line calls the function of the same name here,
//! which, when the exercise is handed out (`exercises::handed_out`), returns the student's answer from the
//! `exercises` crate: the slide function returns it, and its own code is not run. When the exercise is not
//! handed out it returns `None` and the workbook's own code runs. In the plain build the line is nothing at
//! all. The grader renders a picture [`drawing_around_blanks`], so that a blank does not stop the render at
//! the first `todo!()`: it names every exercise the picture needs in one run. A picture rendered
//! [`drawing_with_the_workbooks_own`] uses none of the student's functions, so the grader can set the two
//! side by side in one build.
//!
//! The exercises use glam's types only (they know nothing of the workbook), so these functions turn the
//! workbook's types into glam's and back; where the workbook does more than the slide's function around it
//! (the photon estimate's gamut), they do it too.

use crate::lesson::color::Color;
use crate::lesson::environment::CubeFace;
use crate::lesson::math::{OrthonormalBasis, Vector};
use crate::lesson::photon_map::StoredPhoton;
use crate::lesson::photon_map::arriving_light;
use crate::lesson::rng::Rng;
use exercises::handed_out;
pub use exercises::hooks::{Hook, answer, drawing_around_blanks, drawing_with_the_workbooks_own};
use glam::Affine3A;

/// [`Bitmap`](crate::lesson::bitmap::Bitmap)'s bilinear filter, with `texel(i, j)` the wrapped texel.
pub fn bilinear(x: f32, y: f32, texel: impl Fn(i64, i64) -> Color) -> Option<Color> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::BILINEAR, || Color(exercises::bilinear::bilinear(x, y, |i, j| texel(i, j).0)))
}

/// The inverse of a node's [`Transform`](crate::lesson::transform::Transform).
pub fn transform_inverse(t: Affine3A) -> Option<Affine3A> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::TRANSFORM_INVERSE, || exercises::transform_inverse::inverse(t))
}

/// [`cube_face_uv`](crate::lesson::environment::cube_face_uv); the exercise numbers the faces in the order of
/// [`CubeFace::ALL`].
pub fn cube_face_uv(dir: Vector) -> Option<(CubeFace, f32, f32)> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::CUBE_MAP, || {
        let (face, u, v) = exercises::cube_map::cube_face_uv(dir);
        (CubeFace::ALL[face as usize], u, v)
    })
}

/// [`faceforward`](crate::lesson::math::faceforward).
pub fn faceforward(n: Vector, i: Vector) -> Option<Vector> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::FACEFORWARD, || exercises::faceforward::faceforward(n, i))
}

/// [`refract`](crate::lesson::math::refract).
pub fn refract(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Option<Vector>> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::REFRACT, || exercises::refract::refract(i, n, eta1_over_eta2))
}

/// The weight of a layer of a [`Layered`](crate::lesson::shader::Layered) shader.
pub fn layer_weight(uncovered: Color, blend: Color) -> Option<Color> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::LAYERED_BLEND, || Color(exercises::layered_blend::layer_weight(uncovered.0, blend.0)))
}

/// [`fresnel`](crate::lesson::math::fresnel), Schlick's approximation.
pub fn fresnel(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::FRESNEL_SCHLICK, || exercises::fresnel_schlick::fresnel(i, n, eta1_over_eta2))
}

/// [`fresnel_exact`](crate::lesson::math::fresnel_exact).
pub fn fresnel_exact(i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::FRESNEL_EXACT, || exercises::fresnel_exact::fresnel_exact(i, n, eta1_over_eta2))
}

/// [`random_unit_disc_point`](crate::lesson::sampling::random_unit_disc_point), drawing from the pixel's
/// own random stream.
pub fn random_unit_disc_point(rng: &mut Rng) -> Option<(f32, f32)> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::GLOSSY_DISC, || exercises::glossy_disc::random_unit_disc_point(|| rng.next_f32()))
}

/// [`concentric_disc`](crate::lesson::sampling::concentric_disc).
pub fn concentric_disc(u: f32, v: f32) -> Option<(f32, f32)> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::GLOSSY_DISC, || exercises::glossy_disc::concentric_disc(u, v))
}

/// The tilt of a [`GlossyCone`](crate::lesson::shader::GlossyCone) (step 3 of the slide's algorithm).
pub fn glossy_scaling(glossiness: f32) -> Option<f32> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::GLOSSY_CONE, || exercises::glossy_cone::glossy_scaling(glossiness))
}

/// A [`GlossyCone`](crate::lesson::shader::GlossyCone)'s direction (steps 4-6), in the cone's basis (step 1).
pub fn glossy_direction(
    incoming: Vector,
    basis: &OrthonormalBasis,
    scaling: f32,
    disc_point: (f32, f32),
) -> Option<Option<Vector>> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::GLOSSY_CONE, || {
        exercises::glossy_cone::glossy_direction(
            incoming,
            basis.normal,
            basis.tangent,
            basis.bitangent,
            scaling,
            disc_point,
        )
    })
}

/// The photon map's estimate from the photons found, each with its squared distance, finished by
/// [`arriving_light`] as [`PhotonMap::irradiance`](crate::lesson::photon_map::PhotonMap::irradiance)
/// finishes its own.
pub fn irradiance_estimate<'a>(
    found: impl Iterator<Item = (f32, &'a StoredPhoton)>,
    radius_squared: f32,
    normal: Vector,
) -> Option<Color> {
    static HOOK: Hook = Hook::new();
    answer(&HOOK, handed_out::PHOTON_ESTIMATE, || {
        let photons: Vec<exercises::Photon> = found
            .map(|(distance_squared, p)| exercises::Photon { distance_squared, dir: p.dir, power: p.power.0 })
            .collect();
        arriving_light(Color(exercises::photon_estimate::irradiance_estimate(&photons, radius_squared, normal)))
    })
}
