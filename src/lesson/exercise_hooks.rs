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
use glam::Affine3A;
use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// One function a slide function hands over to an exercise: whether the student's is still a blank, found
/// so while the renderer draws around blanks ([`drawing_around_blanks`]).
pub struct Hook {
    /// The student's function panicked with `todo!()`: the workbook's own is used from then on, when the
    /// renderer draws around blanks.
    blank: AtomicBool,
    /// The blank was met during the current [`drawing_around_blanks`].
    met: AtomicBool,
    /// The text of its `todo!()`, once met.
    text: Mutex<String>,
}

impl Hook {
    /// A hook whose function has not been found blank.
    pub const fn new() -> Hook {
        Hook { blank: AtomicBool::new(false), met: AtomicBool::new(false), text: Mutex::new(String::new()) }
    }
}

impl Default for Hook {
    fn default() -> Hook {
        Hook::new()
    }
}

/// Whether the renderer draws around blanks now (see [`drawing_around_blanks`]).
static AROUND_BLANKS: AtomicBool = AtomicBool::new(false);

/// Whether every hook answers with the workbook's own function now (see [`drawing_with_the_workbooks_own`]).
static WORKBOOKS_OWN: AtomicBool = AtomicBool::new(false);

/// The hooks met blank during the current [`drawing_around_blanks`].
static MET: Mutex<Vec<&'static Hook>> = Mutex::new(Vec::new());

/// The student's answer `student()` for an exercise handed out (`handed_out`), `None` for one that is not.
/// Normally a blank's `todo!()` panics out of the render; within [`drawing_around_blanks`] it is caught,
/// remembered, and answered with the workbook's own function (`None`) from then on, so that the render
/// goes on and meets every other blank it needs.
pub fn answer<T>(hook: &'static Hook, handed_out: bool, student: impl FnOnce() -> T) -> Option<T> {
    if !handed_out || WORKBOOKS_OWN.load(Relaxed) {
        return None;
    }
    if !AROUND_BLANKS.load(Relaxed) {
        return Some(student());
    }
    if hook.blank.load(Relaxed) {
        note_met(hook);
        return None;
    }
    match catch_unwind(AssertUnwindSafe(student)) {
        Ok(answer) => Some(answer),
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            let Some(text) = message.strip_prefix("not yet implemented") else { resume_unwind(payload) };
            *hook.text.lock().unwrap_or_else(|e| e.into_inner()) = text.strip_prefix(": ").unwrap_or(text).to_string();
            hook.blank.store(true, Relaxed);
            note_met(hook);
            None
        }
    }
}

/// Remembers that `hook` was met blank in this drawing (once).
fn note_met(hook: &'static Hook) {
    if !hook.met.swap(true, Relaxed) {
        MET.lock().unwrap_or_else(|e| e.into_inner()).push(hook);
    }
}

/// Runs `draw` (a render) with every blank it meets answered by the workbook's own function, and returns
/// what it returned with the texts of the `todo!()`s of the blanks it met (`"cube_map"`,
/// `"glossy_disc: concentric_disc"`), in the order met: the grader names every exercise a picture needs in
/// one run. One drawing at a time.
pub fn drawing_around_blanks<T>(draw: impl FnOnce() -> T) -> (T, Vec<String>) {
    let result = while_set(&AROUND_BLANKS, draw);
    let met = std::mem::take(&mut *MET.lock().unwrap_or_else(|e| e.into_inner()));
    let texts = met
        .iter()
        .map(|hook| {
            hook.met.store(false, Relaxed);
            hook.text.lock().unwrap_or_else(|e| e.into_inner()).clone()
        })
        .collect();
    (result, texts)
}

/// Runs `draw` (a render) with the workbook's own function for every exercise, handed out or not, and
/// returns what it returned: the picture the workbook draws without the student's functions, to compare
/// theirs with. One drawing at a time.
pub fn drawing_with_the_workbooks_own<T>(draw: impl FnOnce() -> T) -> T {
    while_set(&WORKBOOKS_OWN, draw)
}

/// Runs `f` with `flag` set, and clears it afterwards, also when `f` panics.
fn while_set<T>(flag: &'static AtomicBool, f: impl FnOnce() -> T) -> T {
    struct Clear(&'static AtomicBool);
    impl Drop for Clear {
        fn drop(&mut self) {
            self.0.store(false, Relaxed);
        }
    }
    flag.store(true, Relaxed);
    let _clear = Clear(flag);
    f()
}

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
