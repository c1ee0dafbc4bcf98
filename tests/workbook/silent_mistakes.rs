//! The mistakes a render used to pass without a word, named: a NaN or infinite light, refused by the scene's
//! check naming the light and its values; a direction not of unit length given to `ray.spawn` by a student's
//! shader, named with the fix in the end-of-run report; a course shader's parameter outside the range it
//! takes (a multiplier above 1, a blend outside 0 to 1, a glossiness outside (0, 1]), named by the command
//! line's run and by `render_and_report` after the report; and the NaN line's counts, which say what they
//! count. Each in one line naming the node and its shader, by default and with `--slide`; the same scenes
//! done right, and every example and the API page's homeworks, render without a word.

use crate::diagnostics::{Cylinder, line, rendered, scene};
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

/// A student's brushed mirror: the mirror direction tilted towards the normal, normalised or not before
/// `ray.spawn`.
struct Brushed {
    normalised: bool,
}

impl Shader for Brushed {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        let tilted = reflect(ray.dir, n) + 0.3 * n;
        let dir = if self.normalised { tilted.normalize() } else { tilted };
        ctx.raytrace(&ray.spawn(info, dir, 0.9)) * 0.9
    }
}

#[test]
fn a_direction_not_of_unit_length_given_to_spawn_is_named_with_the_fix() {
    let stats = rendered(&scene(Cylinder, Brushed { normalised: false }));
    let line = line(&stats, "not of unit length");
    assert!(line.contains("pillar (Brushed)") && !line.contains("Sphere"), "{line}");
    assert!(line.contains("normalise the direction before ray.spawn"), "{line}");
    assert_eq!(stats.warnings.len(), 1, "{:?}", stats.warnings);
}

#[test]
fn the_same_shader_normalising_its_direction_renders_without_a_word() {
    let stats = rendered(&scene(Cylinder, Brushed { normalised: true }));
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    assert!(stats.counters.rays_by_depth[1] > 1000, "the brushed pillar reflects: {:?}", stats.counters);
}

/// No false alarm: every example and the API page's homeworks, rendered at 80x60 with every node behind a
/// type the renderer does not know (so that every ray a shader traces has its direction checked, as a
/// student's shader's has), by default and with `--slide`, print no warning at all.
#[test]
fn every_example_and_the_pages_homeworks_render_without_a_word() {
    use crate::branching::homework_glossy;
    use crate::common::{examples, hidden::through_trait_objects, parse};
    use crate::homework::homework_scene;
    for reading in [&[][..], &["--slide"]] {
        let args = [&["--width", "80", "--height", "60", "--spp", "1"][..], reading].concat();
        let quiet = |what: &str, scene: &Scene, settings: &RenderSettings| {
            for scene in [scene.clone(), through_trait_objects(scene)] {
                let (_, stats) = render(&scene, settings).unwrap();
                assert!(stats.warnings.is_empty(), "{what}{reading:?}: {:?}", stats.warnings);
            }
        };
        macro_rules! quiet {
            ($($name:ident),*) => {$(
                let (scene, settings) = parse::<examples::$name::Options>(&args).prepare().unwrap();
                quiet(stringify!($name), &scene, &settings);
            )*};
        }
        every_example!(quiet);
        let (scene, settings) = parse::<homework_scene::Options>(&args).prepare().unwrap();
        quiet("homework_scene", &scene, &settings);
        let (scene, settings) = parse::<homework_glossy::Options>(&args).prepare().unwrap();
        quiet("homework_glossy", &scene, &settings);
    }
}
