//! A course helper given a parameter outside its range by a student's shader at run time: the API page's
//! glossy mirror passing `GlossyCone::new` a glossiness of 1.5 or -0.2 is named in one line at the end of
//! the run, with the node, the shader, the helper, its range and the worst value, in both readings; its rays
//! landing on another of the student's nodes do not make that node named; the same mirror in range is not.

use crate::branching::homework_glossy::TintedGlossy;
use lecture6::lesson::beyond::Steps;
use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::prelude::*;

/// A ball of the student's glossy mirror with `glossiness` on a floor of the same mirror in range (a large
/// sphere), under the sky, rendered small in the reading `steps`.
fn rendered(glossiness: f32, steps: Steps) -> RenderStats {
    let glossy = |glossiness| TintedGlossy { tint: Color::new(0.9, 0.85, 0.8), glossiness, n: 4 };
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 10.0, -40.0), Vector::ZERO, 50.0));
    scene.add(Node::new(Sphere::new(Vector::ZERO, 10.0), glossy(glossiness)).named("ball"));
    scene.add(Node::new(Sphere::new(Vector::new(0.0, -1010.0, 0.0), 1000.0), glossy(0.9)).named("floor"));
    scene.environment = Some(sky().unwrap());
    scene.steps = steps;
    render(&scene, &RenderSettings { width: 80, height: 60, spp: 1, ..RenderSettings::default() }).unwrap().1
}

#[test]
fn a_glossiness_out_of_range_given_at_run_time_is_named_with_the_worst_value_in_both_readings() {
    for steps in [Steps::ALL, Steps::SLIDES] {
        for (glossiness, worst) in [(1.5, "the worst 1.5"), (-0.2, "the worst -0.2")] {
            let stats = rendered(glossiness, steps);
            assert_eq!(stats.warnings.len(), 1, "{steps:?}, {glossiness}: {:?}", stats.warnings);
            let line = &stats.warnings[0];
            assert!(line.contains("ball (TintedGlossy) (") && line.contains(worst), "{line}");
            assert!(line.contains("GlossyCone::new a glossiness outside its range, above 0 and at most 1"), "{line}");
            // The floor, which the ball's rays reach and whose own glossiness is in range, is not named.
            assert!(!line.contains("floor"), "{line}");
        }
        let right = rendered(0.9, steps);
        assert!(right.warnings.is_empty(), "{steps:?}: {:?}", right.warnings);
    }
}

/// The API page's glossy mirror with its glossiness read per hit, as from a texture: -0.5 on the left half of
/// the ball, which the rows of pixels meet first, 1.5 on the right, both 0.5 outside the range.
struct TwoSided;

impl Shader for TwoSided {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let glossiness = if info.ip.x < 0.0 { -0.5 } else { 1.5 };
        TintedGlossy { tint: Color::gray(0.9), glossiness, n: 2 }.shade(ray, info, ctx)
    }
}

#[test]
fn the_worst_value_is_the_same_whatever_the_thread_count() {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 10.0, -40.0), Vector::ZERO, 50.0));
    scene.add(Node::new(Sphere::new(Vector::ZERO, 10.0), TwoSided).named("ball"));
    scene.environment = Some(sky().unwrap());
    let warnings = |threads| {
        let settings = RenderSettings { width: 80, height: 60, spp: 1, threads: Some(threads), ..Default::default() };
        render(&scene, &settings).unwrap().1.warnings
    };
    let one = warnings(1);
    assert_eq!(one.len(), 1, "{one:?}");
    // Of two values as far outside the range, the larger is the worst, in whatever order they were met.
    assert!(one[0].contains("ball (TwoSided) (") && one[0].contains("the worst 1.5"), "{one:?}");
    for threads in [2, 3] {
        assert_eq!(warnings(threads), one, "{threads} threads");
    }
}
