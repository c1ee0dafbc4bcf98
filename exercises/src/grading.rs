//! The exercises as the grader grades them: each one's switch, its facts checked on the function of this
//! crate, and the example whose picture checks it. Not an exercise.

use exercise_grader::facts;
use exercise_grader::grading::Exercise;

/// The workbook's exercises, in the order of the slides, checked with the functions of this crate.
pub fn workbook() -> Vec<Exercise> {
    use crate::*;
    let switch = |handed_out: bool, name: &str| (handed_out, listed(TAKEN_OUT, name));
    vec![
        Exercise::new(
            "bilinear",
            switch(handed_out::BILINEAR, "bilinear"),
            || facts::bilinear(&|x, y, texel| bilinear::bilinear(x, y, texel)),
            "bitmap_textures",
        ),
        Exercise::new(
            "transform_inverse",
            switch(handed_out::TRANSFORM_INVERSE, "transform_inverse"),
            || facts::transform_inverse(&transform_inverse::inverse),
            "model_transform",
        ),
        Exercise::new(
            "cube_map",
            switch(handed_out::CUBE_MAP, "cube_map"),
            || facts::cube_map(&cube_map::cube_face_uv),
            "fresnel",
        ),
        Exercise::new(
            "faceforward",
            switch(handed_out::FACEFORWARD, "faceforward"),
            || facts::faceforward(&faceforward::faceforward),
            "reflect_v02",
        ),
        Exercise::new(
            "refract",
            switch(handed_out::REFRACT, "refract"),
            || facts::refract(&refract::refract),
            "refract",
        ),
        Exercise::new(
            "layered_blend",
            switch(handed_out::LAYERED_BLEND, "layered_blend"),
            || facts::layered_blend(&layered_blend::layer_weight),
            "layered",
        ),
        Exercise::new(
            "fresnel_schlick",
            switch(handed_out::FRESNEL_SCHLICK, "fresnel_schlick"),
            || facts::fresnel_schlick(&fresnel_schlick::fresnel),
            "fresnel",
        ),
        Exercise::new(
            "fresnel_exact",
            switch(handed_out::FRESNEL_EXACT, "fresnel_exact"),
            || facts::fresnel_exact(&fresnel_exact::fresnel_exact),
            "layered",
        ),
        Exercise::new(
            "glossy_disc",
            switch(handed_out::GLOSSY_DISC, "glossy_disc"),
            || facts::glossy_disc(&|random| glossy_disc::random_unit_disc_point(random), &glossy_disc::concentric_disc),
            "glossy",
        ),
        Exercise::new(
            "glossy_cone",
            switch(handed_out::GLOSSY_CONE, "glossy_cone"),
            || facts::glossy_cone(&glossy_cone::glossy_scaling, &glossy_cone::glossy_direction),
            "glossy",
        ),
        Exercise::new(
            "photon_estimate",
            switch(handed_out::PHOTON_ESTIMATE, "photon_estimate"),
            || facts::photon_estimate(&photon_estimate::irradiance_estimate),
            "photon_map",
        ),
    ]
}
