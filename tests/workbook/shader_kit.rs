//! The test kit for a shader of one's own (`lecture6::instruments::test_kit`, in the prelude): one hit
//! shaded without a render, where the caller puts it; and its three checks, which pass a correct glossy
//! shader of a student's and fail each of its deliberate mistakes (an undivided sum of N rays, a NaN from
//! dividing by the rays kept when none was, an energy-gaining multiplier). `render_and_report` returns the
//! end-of-run report where `render_for_test` fails on it.

use crate::common;
use lecture6::prelude::*;

/// What a [`Brushed`] shader gets wrong, if anything.
#[derive(Clone, Copy, PartialEq)]
enum Mistake {
    None,
    /// The N rays added up and not divided by N.
    UndividedSum,
    /// The sum divided by the rays kept, also when none was: 0 / 0.
    UnguardedMean,
}

/// A brushed metal as a student writes it: `rays` reflections, each jittered within `roughness` of the
/// mirror direction, those under the surface dropped, the rest averaged and tinted.
struct Brushed {
    tint: Color,
    roughness: f32,
    rays: u32,
    mistake: Mistake,
}

impl Brushed {
    fn new(tint: Color, roughness: f32) -> Brushed {
        Brushed { tint, roughness, rays: 8, mistake: Mistake::None }
    }
}

impl Shader for Brushed {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        let mirror = reflect(ray.dir, n);
        let (mut sum, mut kept) = (Color::BLACK, 0);
        for _ in 0..self.rays {
            let mut jitter = || 2.0 * ctx.rng.next_f32() - 1.0;
            let dir = (mirror + self.roughness * Vector::new(jitter(), jitter(), jitter())).normalize();
            if dir.dot(n) <= 0.0 {
                continue;
            }
            sum += ctx.raytrace(&ray.spawn(info, dir, self.tint.max_channel()));
            kept += 1;
        }
        match self.mistake {
            Mistake::UndividedSum => sum * self.tint,
            Mistake::UnguardedMean => sum * self.tint / kept as f32,
            Mistake::None if kept == 0 => Color::BLACK,
            Mistake::None => sum * self.tint / kept as f32,
        }
    }
}

fn near(a: Vector, b: Vector) -> bool {
    // Within the rounding of a hit found 1 unit from its ray's start, at points up to 100 units out.
    (a - b).length() <= 100.0 * 1e-5
}

#[test]
fn a_hit_is_where_it_was_asked_for_on_a_plane_and_on_a_sphere() {
    let normals = [Vector::Y, -Vector::Y, Vector::Z, Vector::new(0.3, -0.5, 0.8).normalize()];
    for normal in normals {
        let sideways = normal.cross(Vector::new(0.6, 0.7, 0.2)).normalize();
        let incoming = (0.5 * sideways - normal).normalize();
        let point = Vector::new(30.0, -12.0, 7.5);
        let hit = OneHit::on_plane_at(point, normal, incoming, (2.0, -3.0)).info();
        assert!(near(hit.ip, point) && near(hit.normal, normal), "plane {normal}: {hit:?}");
        let (u, v) = hit.uv();
        assert!((u - 2.0).abs() < 1e-3 && (v + 3.0).abs() < 1e-3, "plane {normal}: u/v {u}, {v}");
        let hit = OneHit::on_sphere(point - 2.0 * normal, 2.0, normal, incoming).info();
        assert!(near(hit.ip, point) && near(hit.normal, normal), "sphere {normal}: {hit:?}");
    }
    // A white Lambert lit by a lamp straight above at 10 units, of intensity 100: 100 / 10^2 = 1.
    let lamp = PointLight::new(Vector::new(0.0, 10.0, 0.0), Color::WHITE, 100.0);
    let lit = OneHit::on_plane(Vector::ZERO, Vector::Y, -Vector::Y).with_light(lamp).shade(Lambert::new(Color::WHITE));
    assert!((lit.max_channel() - 1.0).abs() < test_kit::ONE_LEVEL, "{lit:?}");
}

#[test]
fn the_checks_pass_a_correct_shader() {
    let tint = Color::new(0.9, 0.7, 0.4);
    check_furnace(Brushed::new(Color::WHITE, 0.3), 16).unwrap();
    check_furnace(Brushed::new(tint, 0.3), 16).unwrap();
    check_mirror_limit(Brushed::new(tint, 0.0), Reflection::mirror(tint)).unwrap();
    check_finite(Brushed { rays: 1, ..Brushed::new(tint, 1.0) }, 200).unwrap();
    // The course's own shaders pass as well: a glass, a glossy mirror.
    check_furnace(fresnel_glass(1.5, FresnelMode::Schlick, 1.0), 4).unwrap();
    check_furnace(Reflection::glossy(Color::WHITE, 0.8, 16).unwrap(), 4).unwrap();
}

#[test]
fn each_check_fails_the_mistake_it_is_for() {
    let tint = Color::new(0.9, 0.7, 0.4);
    // The undivided sum of 8 rays returns up to 8 times what arrived, and at roughness 0 8 mirrors' worth.
    let sum = || Brushed { mistake: Mistake::UndividedSum, ..Brushed::new(tint, 0.3) };
    let failed = check_furnace(sum(), 16).unwrap_err().to_string();
    assert!(failed.starts_with("Brushed returned") && failed.contains("times the light that arrived"), "{failed}");
    let at_zero = Brushed { roughness: 0.0, ..sum() };
    let failed = check_mirror_limit(at_zero, Reflection::mirror(tint)).unwrap_err().to_string();
    assert!(failed.contains("where the mirror Reflection returns"), "{failed}");
    // A multiplier above 1 gains energy though the mean is right; its own mirror is no reference for it.
    let failed = check_furnace(Brushed::new(Color::gray(1.5), 0.3), 16).unwrap_err().to_string();
    assert!(failed.contains("1.50 times the light that arrived"), "{failed}");
    // The mean over the rays kept, when the one ray of a rough metal went under the surface: 0 / 0.
    let unguarded = Brushed { rays: 1, mistake: Mistake::UnguardedMean, ..Brushed::new(tint, 1.0) };
    let failed = check_finite(unguarded, 200).unwrap_err().to_string();
    assert!(failed.contains("returned (NaN, NaN, NaN) at random hit"), "{failed}");
}

#[test]
fn render_and_report_returns_the_report_where_render_for_test_fails() {
    // The first reflection slide's facing mirrors without a depth limit: the centre ray of an odd-sized
    // picture meets them square-on and bounces to the safety cap.
    let args = ["--width", "17", "--height", "13", "--spp", "1", "--mirrors"];
    let (frame, warnings) = render_and_report::<common::examples::reflect_v01::Options>(&args).unwrap();
    assert_eq!((frame.width, frame.height), (17, 13));
    assert!(warnings.iter().any(|w| w.contains("safety cap")), "{warnings:?}");
    let failed = std::panic::catch_unwind(|| render_for_test::<common::examples::reflect_v01::Options>(&args));
    assert!(failed.is_err(), "render_for_test passed a render whose report warns");
    let refused = render_and_report::<common::examples::reflect_v01::Options>(&["--width", "0"]).unwrap_err();
    assert!(refused.contains("--width"), "{refused}");
}
