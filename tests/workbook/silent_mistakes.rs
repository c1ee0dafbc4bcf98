//! The mistakes a render used to pass without a word, named: a NaN or infinite light, refused by the scene's
//! check naming the light and its values; a direction not of unit length given to `ray.spawn` by a student's
//! shader, named with the fix in the end-of-run report; a course shader's parameter outside the range it
//! takes (a multiplier above 1, a blend outside 0 to 1, a glossiness outside (0, 1]), named by the command
//! line's run and by `render_and_report` after the report; and the NaN line's counts, which say what they
//! count. Each in one line naming the node and its shader, by default and with `--slide`; the same scenes
//! done right, and every example and the API page's homeworks, render without a word.

use crate::diagnostics::{Broken, Cylinder, Mistake, Mistaken, line, rendered, scene};
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

#[test]
fn a_direction_made_from_a_normal_not_of_unit_length_is_left_to_the_normals_line() {
    // The course's mirror reflects about the geometry's normal as it comes: a normal twice too long makes a
    // direction that is not of unit length either, which is the normal's fault, not the mirror's.
    // Untransformed and seen from near: a transform would normalise the normal on its way to the world.
    let mut scene = scene(Mistaken(Mistake::LongNormal), Reflection::new(0.9));
    scene.nodes[0].transform = None;
    scene.camera = Camera::look_at(Vector::new(0.0, 4.0, -30.0), Vector::ZERO, 12.0);
    let stats = rendered(&scene);
    assert!(stats.counters.problems.long_directions.contains_key(&0), "{:?}", stats.counters.problems);
    assert!(line(&stats, "a geometry returned a normal").contains("pillar (Reflection)"));
    assert_eq!(stats.warnings.len(), 1, "the normal's line only: {:?}", stats.warnings);
}

/// The pillar's scene with the mirror ball's shader replaced by `shader`, named "ball".
fn ball(shader: impl IntoShader) -> Scene {
    let mut scene = scene(Cylinder, Lambert::new(Color::gray(0.5)));
    scene.nodes[1] = Node::new(Sphere::new(Vector::new(25.0, 0.0, 0.0), 8.0), shader).named("ball");
    scene.lights.push(PointLight::new(Vector::new(0.0, 100.0, -100.0), Color::WHITE, 20000.0));
    scene
}

/// The ball's shader in the cases of [`Ball`]: out of range (0 to 3), then in range (4 to 7).
fn ball_shader(case: usize) -> Material {
    let layered = |blend: Color| {
        let mut layered = Layered::new();
        layered.add_layer(Lambert::new(Color::gray(0.5)), Color::WHITE, None).add_layer(
            Reflection::new(0.9),
            blend,
            None,
        );
        layered.into_shader()
    };
    let glossy = |glossiness: f32| {
        let mut glossy = Reflection::glossy(Color::gray(0.9), 0.9, 4).unwrap();
        glossy.glossiness = glossiness;
        glossy.into_shader()
    };
    match case {
        0 => fresnel_glass(1.5, FresnelMode::Schlick, 9.0).into_shader(),
        1 => Reflection::new(1.2).into_shader(),
        2 => layered(Color::new(0.2, 1.5, 0.2)),
        3 => glossy(1.3),
        4 => fresnel_glass(1.5, FresnelMode::Schlick, 1.0).into_shader(),
        5 => layered(Color::new(0.0, 1.0, 0.5)),
        6 => glossy(1.0),
        _ => Refraction::new(1.5, 0.0).into_shader(),
    }
}

/// A homework of the pillar and the ball, the ball's shader picked by `--case` ([`ball_shader`]).
#[derive(clap::Args, Clone, Debug)]
struct Ball {
    #[arg(long)]
    case: usize,
}

impl Example for Ball {
    const DEFAULT_SPP: u32 = 1;
    fn scene(&self) -> Result<Scene> {
        Ok(ball(ball_shader(self.case)))
    }
}

/// The end-of-run report of the homework [`Ball`] in `case`, as the example's run prints it (`Cli::render`)
/// and as a homework's test gets it (`render_and_report`), the same by default and with `--slide`.
fn reported(case: usize) -> Vec<String> {
    let case = case.to_string();
    let args = ["--width", "160", "--height", "120", "--case", &case];
    let warnings = render_and_report::<Ball>(&args).unwrap().1;
    for args in [&args[..], &[&args[..], &["--slide"]].concat()] {
        let (_, stats) = crate::common::parse::<Ball>(args).render().unwrap();
        assert_eq!(stats.warnings, warnings, "{args:?}");
        assert_eq!(render_and_report::<Ball>(args).unwrap().1, warnings, "{args:?}");
    }
    warnings
}

/// The one line of `warnings` that contains `what`.
fn only_line<'a>(warnings: &'a [String], what: &str) -> &'a str {
    assert_eq!(warnings.len(), 1, "one line about {what}: {warnings:?}");
    assert!(warnings[0].contains(what), "{warnings:?}");
    &warnings[0]
}

#[test]
fn a_glass_passing_nine_times_the_light_is_named_with_its_multipliers() {
    // The teacher's class: a copy of fresnel whose glass passes 9 times the light.
    let warnings = reported(0);
    let line = only_line(&warnings, "multiplier is outside 0 to 1");
    let named = "ball (Layered): layer 0's Refraction multiplier 9, layer 1's Reflection multiplier (9, 9, 9)";
    assert!(line.ends_with(named), "{line}");
}

#[test]
fn a_mirror_above_one_a_blend_above_one_and_a_glossiness_above_one_are_named() {
    let line = only_line(&reported(1), "multiplier is outside 0 to 1").to_string();
    assert!(line.ends_with("ball (Reflection): its Reflection multiplier (1.2, 1.2, 1.2)"), "{line}");
    let line = only_line(&reported(2), "blend is outside 0 to 1").to_string();
    assert!(line.ends_with("ball (Layered): layer 1's blend (0.2, 1.5, 0.2)"), "{line}");
    let line = only_line(&reported(3), "glossiness is outside its range").to_string();
    assert!(line.ends_with("ball (Reflection): its Reflection glossiness 1.3"), "{line}");
}

#[test]
fn course_shaders_in_range_render_without_a_word() {
    for case in 4..8 {
        assert_eq!(reported(case), Vec::<String>::new(), "case {case}: {}", ball_shader(case).name());
    }
}

/// A student's correct glossy-like shader: the mean of four mirror rays.
struct MeanOfFour;

impl Shader for MeanOfFour {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let dir = reflect(ray.dir, faceforward(info.normal, ray.dir));
        let mut sum = Color::BLACK;
        for _ in 0..4 {
            sum += ctx.raytrace(&ray.spawn(info, dir, 0.9));
        }
        sum / 4.0 * 0.9
    }
}

#[test]
fn the_nan_lines_counts_say_what_they_count() {
    // The pillar makes NaN; the ball's four rays each carry one of them into the same sample, so the counts
    // beside the pillar add up to more samples than came back NaN, and the line says why.
    let mut scene = ball(MeanOfFour);
    scene.nodes[0].shader = Broken.into_shader();
    let stats = rendered(&scene);
    let line = line(&stats, "NaN or infinite");
    let counted: u64 = stats.counters.problems.non_finite.values().sum();
    assert!(counted > stats.counters.non_finite_samples, "{counted} {:?}", stats.counters);
    assert!(line.starts_with(&format!("{} sample(s)", stats.counters.non_finite_samples)), "{line}");
    assert!(line.contains("made by the shader of pillar (Broken)"), "{line}");
    assert!(
        line.ends_with(
            "each count is of the NaN or infinite colours that source made, and one sample can carry several of them"
        ),
        "{line}"
    );
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

/// No false alarm at the sizes a student renders: the API page's homeworks at 640x480 and 1280x960, one
/// sample per pixel, by default and with `--slide`, print no warning at all (the self-hit check's rim cases
/// and the energy check's grazing ones come with more pixels; `tests/workbook/smooth_mesh.rs` has the
/// low-resolution smooth mesh).
#[test]
fn the_pages_homeworks_render_without_a_word_at_full_size() {
    use crate::branching::homework_glossy;
    use crate::common::parse;
    use crate::homework::homework_scene;
    for reading in [&[][..], &["--slide"]] {
        for (width, height) in [("640", "480"), ("1280", "960")] {
            let args = [&["--width", width, "--height", height, "--spp", "1"][..], reading].concat();
            let scene = parse::<homework_scene::Options>(&args).prepare().unwrap();
            let glossy = parse::<homework_glossy::Options>(&args).prepare().unwrap();
            for (what, (scene, settings)) in [("homework_scene", scene), ("homework_glossy", glossy)] {
                let (_, stats) = render(&scene, &settings).unwrap();
                assert!(stats.warnings.is_empty(), "{what} {args:?}: {:?}", stats.warnings);
            }
        }
    }
}
