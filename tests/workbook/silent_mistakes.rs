//! The mistakes a render used to pass without a word, named: a NaN or infinite light, refused by the scene's
//! check naming the light and its values; a direction not of unit length given to `ray.spawn` by a student's
//! shader, named with the fix in the end-of-run report; a course shader's parameter outside the range it
//! takes (a multiplier above 1, a blend outside 0 to 1, a glossiness outside (0, 1]), named by the command
//! line's run and by `render_and_report` after the report; and the NaN line's counts, which say what they
//! count. Each in one line naming the node and its shader, by default and with `--slide`; the same scenes
//! done right, and every example and the API page's homeworks, render without a word.

use lecture6::lesson::beyond::Steps;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::prelude::*;

/// The homework's settings for the light check: small, one sample.
fn small() -> RenderSettings {
    RenderSettings { width: 80, height: 60, spp: 1, ..RenderSettings::default() }
}

/// The error of rendering the fresnel example (as its `main` builds it) with `light` added, in the reading
/// `steps`: the scene's check refuses a NaN or infinite light before a ray is traced, naming it by its
/// index in the scene's lights.
fn refused(light: PointLight, steps: Steps) -> String {
    use crate::common::{examples::fresnel, parse};
    let (mut scene, _) = parse::<fresnel::Options>(&[]).prepare().unwrap();
    scene.steps = steps;
    scene.lights.push(light);
    let index = scene.lights.len() - 1;
    let error = render(&scene, &small()).expect_err("a NaN or infinite light is refused").to_string();
    assert!(error.starts_with(&format!("invalid light {index} (a point light at ")), "{error}");
    assert!(error.ends_with("): its position, colour and intensity must be finite"), "{error}");
    assert!(!error.contains('\n'), "one line: {error}");
    error
}

#[test]
fn a_nan_or_infinite_light_is_refused_naming_the_light_and_the_value() {
    let at = Vector::new(0.0, 100.0, -50.0);
    for steps in [Steps::default(), Steps::SLIDES] {
        let error = refused(PointLight::new(at, Color::WHITE, f32::NAN), steps);
        assert!(error.contains("at [0, 100, -50], colour [1, 1, 1], intensity NaN)"), "{error}");
        let error = refused(PointLight::new(Vector::new(0.0, f32::INFINITY, 0.0), Color::WHITE, 1000.0), steps);
        assert!(error.contains("at [0, inf, 0], colour [1, 1, 1], intensity 1000)"), "{error}");
        let error = refused(PointLight::new(at, Color::new(1.0, f32::NAN, 1.0), 1000.0), steps);
        assert!(error.contains("colour [1, NaN, 1], intensity 1000)"), "{error}");
    }
    // A finite light, however bright or dark, is the scene's business.
    let (mut scene, _) = crate::common::parse::<crate::common::examples::fresnel::Options>(&[]).prepare().unwrap();
    scene.lights.push(PointLight::new(at, Color::WHITE, 0.0));
    assert!(render(&scene, &small()).is_ok());
}
