//! The student's functions handed to the workbook's renderer: not an exercise. The renderer, built for the
//! exercises, asks its [`Answers`] at the start of each slide function an exercise covers; these answer with
//! the function of this crate when the exercise is handed out ([`handed_out`]), through its
//! [`Hook`] (which the grader uses to draw around blanks), and turn the workbook's types into glam's and back.
//! [`register`] hands them over; the grader and `cargo run -p exercises --example draw` do so when they start.

use crate::handed_out;
use exercise_grader::hooks::{Hook, answer};
use glam::Affine3A;
use lecture6::lesson::color::Color;
use lecture6::lesson::environment::CubeFace;
use lecture6::lesson::exercise_hooks::{Answers, answer_with};
use lecture6::lesson::math::{OrthonormalBasis, Vector};
use lecture6::lesson::photon_map::{StoredPhoton, arriving_light};
use lecture6::lesson::rng::Rng;

/// The student's functions, as the renderer asks for them.
struct Students;

/// Draws every picture of this program with the student's functions from now on (once; again changes
/// nothing).
pub fn register() {
    answer_with(&Students);
}

impl Answers for Students {
    fn bilinear(&self, x: f32, y: f32, texel: &dyn Fn(i64, i64) -> Color) -> Option<Color> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::BILINEAR, || Color(crate::bilinear::bilinear(x, y, |i, j| texel(i, j).0)))
    }

    fn transform_inverse(&self, t: Affine3A) -> Option<Affine3A> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::TRANSFORM_INVERSE, || crate::transform_inverse::inverse(t))
    }

    /// The exercise numbers the faces in the order of [`CubeFace::ALL`].
    fn cube_face_uv(&self, dir: Vector) -> Option<(CubeFace, f32, f32)> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::CUBE_MAP, || {
            let (face, u, v) = crate::cube_map::cube_face_uv(dir);
            (CubeFace::ALL[face as usize], u, v)
        })
    }

    fn faceforward(&self, n: Vector, i: Vector) -> Option<Vector> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::FACEFORWARD, || crate::faceforward::faceforward(n, i))
    }

    fn refract(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<Option<Vector>> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::REFRACT, || crate::refract::refract(i, n, eta1_over_eta2))
    }

    fn layer_weight(&self, uncovered: Color, blend: Color) -> Option<Color> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::LAYERED_BLEND, || Color(crate::layered_blend::layer_weight(uncovered.0, blend.0)))
    }

    fn fresnel(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::FRESNEL_SCHLICK, || crate::fresnel_schlick::fresnel(i, n, eta1_over_eta2))
    }

    fn fresnel_exact(&self, i: Vector, n: Vector, eta1_over_eta2: f32) -> Option<f32> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::FRESNEL_EXACT, || crate::fresnel_exact::fresnel_exact(i, n, eta1_over_eta2))
    }

    /// Draws from the pixel's own random stream.
    fn random_unit_disc_point(&self, rng: &mut Rng) -> Option<(f32, f32)> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::GLOSSY_DISC, || crate::glossy_disc::random_unit_disc_point(|| rng.next_f32()))
    }

    fn concentric_disc(&self, u: f32, v: f32) -> Option<(f32, f32)> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::GLOSSY_DISC, || crate::glossy_disc::concentric_disc(u, v))
    }

    fn glossy_scaling(&self, glossiness: f32) -> Option<f32> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::GLOSSY_CONE, || crate::glossy_cone::glossy_scaling(glossiness))
    }

    fn glossy_direction(
        &self,
        incoming: Vector,
        basis: &OrthonormalBasis,
        scaling: f32,
        disc_point: (f32, f32),
    ) -> Option<Option<Vector>> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::GLOSSY_CONE, || {
            crate::glossy_cone::glossy_direction(
                incoming,
                basis.normal,
                basis.tangent,
                basis.bitangent,
                scaling,
                disc_point,
            )
        })
    }

    fn irradiance_estimate(
        &self,
        found: &mut dyn Iterator<Item = (f32, &StoredPhoton)>,
        radius_squared: f32,
        normal: Vector,
    ) -> Option<Color> {
        static HOOK: Hook = Hook::new();
        answer(&HOOK, handed_out::PHOTON_ESTIMATE, || {
            let photons: Vec<crate::Photon> = found
                .map(|(distance_squared, p)| crate::Photon { distance_squared, dir: p.dir, power: p.power.0 })
                .collect();
            arriving_light(Color(crate::photon_estimate::irradiance_estimate(&photons, radius_squared, normal)))
        })
    }
}
