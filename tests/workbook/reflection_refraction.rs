//! Reflection and refraction: Snell's law, total internal reflection, unit directions, a slab that gives
//! back the direction it was given, a perfect mirror that shows exactly its environment, and the depth
//! limit of v0.2 and the safety cap of v0.1.

use crate::common;

use common::examples::{reflect_v01, reflect_v02, refract as refract_scene};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::Color;
use lecture6::lesson::environment::{ConstantEnvironment, Environment};
use lecture6::lesson::geometry::{Cube, Sphere};
use lecture6::lesson::math::{OrthonormalBasis, Vector, reflect, refract};
use lecture6::lesson::node::Node;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Counters, RECURSION_SAFETY_CAP, Scene, TraceContext};
use lecture6::lesson::shader::{Reflection, Refraction};
use std::sync::Arc;

const GLASS: f32 = 1.5;

/// Unit normals in many directions, the same on every run.
fn normals() -> Vec<Vector> {
    let mut rng = Rng::for_keys(&[6, 1]);
    (0..40)
        .map(|_| {
            let z = 2.0 * rng.next_f32() - 1.0;
            let phi = 2.0 * std::f32::consts::PI * rng.next_f32();
            let r = (1.0 - z * z).sqrt();
            Vector::new(r * phi.cos(), r * phi.sin(), z)
        })
        .collect()
}

/// The unit direction that meets the surface with normal `n` at `angle` (radians) from the normal, coming
/// from the side `n` faces, turned by `azimuth` around `n`.
fn incoming(n: Vector, angle: f32, azimuth: f32) -> Vector {
    let basis = OrthonormalBasis::new(n);
    let s = angle.sin();
    basis.to_world(s * azimuth.cos(), s * azimuth.sin(), -angle.cos()).normalize()
}

/// sin of the angle between a unit direction and the normal's line.
fn sin_to(d: Vector, n: Vector) -> f32 {
    d.cross(n).length()
}

#[test]
fn refract_obeys_snells_law_with_unit_results() {
    for eta in [1.0 / 2.42, 1.0 / GLASS, 1.0 / 1.33, 1.0, 1.33, GLASS] {
        for n in normals() {
            for step in 0..90 {
                let angle = (step as f32 + 0.5).to_radians();
                let i = incoming(n, angle, step as f32 * 0.7);
                let sin_t = eta * sin_to(i, n);
                match refract(i, n, eta) {
                    Some(t) => {
                        assert!(sin_t <= 1.0, "eta {eta}, {angle} rad: refracted past the critical angle");
                        assert!((t.length() - 1.0).abs() < 1e-5, "not unit: {}", t.length());
                        assert!((sin_to(t, n) - sin_t).abs() < 1e-5, "eta {eta}, {angle} rad: Snell's law");
                        assert!(t.dot(n) < 0.0, "the refracted ray goes through the surface");
                        assert!(t.dot(i.cross(n)).abs() < 1e-5, "i, n and t lie in one plane");
                    }
                    None => assert!(sin_t > 1.0, "eta {eta}, {angle} rad: total internal reflection too early"),
                }
                let r = reflect(i, n);
                assert!((r.length() - 1.0).abs() < 1e-5, "reflected direction not unit: {}", r.length());
            }
        }
    }
}

#[test]
fn total_internal_reflection_starts_at_the_critical_angle() {
    // Leaving glass for air: the critical angle is asin(1 / 1.5).
    let critical = (1.0 / GLASS).asin();
    for n in normals() {
        let below = refract(incoming(n, critical - 1e-4, 0.3), n, GLASS).expect("just below the critical angle");
        assert!(below.dot(n).abs() < 0.03, "just below it, the ray leaves grazing the surface: {below}");
        assert!(refract(incoming(n, critical + 1e-4, 0.3), n, GLASS).is_none(), "just above it");
        // Entering the denser medium there is no critical angle.
        assert!(refract(incoming(n, 89.9f32.to_radians(), 0.3), n, 1.0 / GLASS).is_some());
    }
}

/// An environment that shows the direction it is looked at in: the colour is the direction.
struct DirectionEnvironment;

impl Environment for DirectionEnvironment {
    fn get(&self, dir: Vector) -> Color {
        Color(dir)
    }
}

/// A glass slab 100 x 100 x 4 turned by `yaw`, in an environment that reports directions.
fn slab_scene(yaw: f32) -> Scene {
    let mut scene = Scene::new(Camera::default());
    scene.environment = Some(Arc::new(DirectionEnvironment));
    scene.max_depth = 10;
    scene.add(
        Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), Arc::new(Refraction::new(GLASS, 1.0)))
            .scale(Vector::new(50.0, 50.0, 2.0))
            .rotate(yaw, 0.0, 0.0)
            .translate(Vector::new(3.0, -2.0, 40.0)),
    );
    scene
}

#[test]
fn into_and_back_out_of_a_slab_restores_the_direction() {
    for yaw in [0.0, 25.0, -50.0] {
        let scene = slab_scene(yaw);
        // The outward normal of the face towards the camera.
        let n = lecture6::lesson::camera::rotation(yaw, 0.0, 0.0) * -Vector::Z;
        for step in 0..12 {
            let dir = incoming(n, (step as f32 * 5.0).to_radians(), step as f32);
            let ray = Ray::new(Vector::new(3.0, -2.0, 40.0) - 30.0 * dir, dir);
            let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[0]));
            let out = ctx.raytrace(&ray).0;
            assert!((out - dir).length() < 1e-5, "yaw {yaw}, step {step}: {dir} came out as {out}");
            // It went in (depth 1) and out (depth 2) and nothing more.
            assert_eq!(&ctx.counters.rays_by_depth[..4], &[1, 1, 1, 0], "yaw {yaw}, step {step}");
        }
    }
}

#[test]
fn total_internal_reflection_inside_the_slab_returns_black() {
    let scene = slab_scene(0.0);
    // From inside the glass, 60° from the face's normal: beyond the critical angle of 41.8°.
    let dir = Vector::new(60f32.to_radians().sin(), 0.0, 60f32.to_radians().cos());
    let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[0]));
    assert_eq!(ctx.raytrace(&Ray::new(Vector::new(3.0, -2.0, 40.0), dir)), Color::BLACK);
    // 30° escapes, unchanged in its plane and bent away from the normal by Snell's law.
    let dir = Vector::new(30f32.to_radians().sin(), 0.0, 30f32.to_radians().cos());
    let mut ctx = TraceContext::new(&scene, Rng::for_keys(&[0]));
    let out = ctx.raytrace(&Ray::new(Vector::new(3.0, -2.0, 40.0), dir)).0;
    assert!((out.x - GLASS * 0.5).abs() < 1e-5 && out.y.abs() < 1e-6, "{out}");
}

/// Renders a perfect mirror sphere (multiplier 1) of `radius` at `center`, seen from `camera`, in a constant
/// environment with `max_depth` 1: a reflected ray that hit the sphere again would return black.
fn mirror_sphere(camera: Vector, center: Vector, radius: f32) -> (Scene, Vec<Color>, Counters) {
    let sky = Color::new(0.2, 0.5, 0.9);
    let mut scene = Scene::new(Camera { position: camera, fov: 60.0, ..Camera::default() });
    scene.environment = Some(Arc::new(ConstantEnvironment(sky)));
    scene.max_depth = 1;
    scene.add(Node::new(Arc::new(Sphere::new(center, radius)), Arc::new(Reflection::new(1.0))));
    let settings = RenderSettings { width: 80, height: 60, ..RenderSettings::default() };
    let (frame, stats) = render(&scene, &settings).unwrap();
    (scene, frame.pixels, stats.counters)
}

#[test]
fn a_perfect_mirror_sphere_shows_exactly_its_environment() {
    let sky = Color::new(0.2, 0.5, 0.9);
    for (camera, center, radius) in [
        (Vector::new(0.0, 0.0, -10.0), Vector::ZERO, 3.0),
        (Vector::new(1e5, -2e5, 3e5), Vector::new(1e5, -2e5, 3e5 + 40.0), 12.0),
        (Vector::new(0.0, 0.0, -1e-3), Vector::ZERO, 3e-4),
    ] {
        let (scene, pixels, counters) = mirror_sphere(camera, center, radius);
        let frame = scene.camera.frame(80, 60);
        let covered = (0..80 * 60)
            .filter(|i| {
                scene.closest_hit(&frame.get_screen_ray((i % 80) as f32 + 0.5, (i / 80) as f32 + 0.5)).is_some()
            })
            .count() as u64;
        assert!(covered > 400, "the sphere covers only {covered} pixels");
        assert!(pixels.iter().all(|&p| p == sky), "a pixel is not the environment colour (sphere at {center})");
        // One reflected ray per covered pixel, and none of them hit the sphere again.
        assert_eq!(&counters.rays_by_depth[..3], &[80 * 60, covered, 0], "sphere at {center}");
    }
}

fn counters<E: lecture6::app::cli::Example>(args: &[&str]) -> Counters {
    common::parse::<E>(args).render().unwrap().1.counters
}

// Odd image sizes put the centre pixel's ray exactly on the camera's axis, square-on to the mirrors.
const SMALL: [&str; 6] = ["--width", "65", "--height", "49", "--spp", "1"];

#[test]
fn reflection_v02_stops_at_max_ray_depth() {
    let c = counters::<reflect_v02::Options>(&SMALL);
    assert!(c.rays_by_depth[2] > 0 && c.rays_by_depth[3..].iter().all(|&n| n == 0), "{c:?}");
    let c = counters::<reflect_v02::Options>(&[&SMALL[..], &["--max-depth", "5"]].concat());
    assert!(c.rays_by_depth[5] > 0 && c.rays_by_depth[6..].iter().all(|&n| n == 0), "{c:?}");
    assert_eq!(c.capped_rays, 0);
}

#[test]
fn reflection_v01_survives_facing_mirrors_by_the_safety_cap() {
    let c = counters::<reflect_v01::Options>(&[&SMALL[..], &["--mirrors"]].concat());
    assert!(c.capped_rays > 0, "{c:?}");
    // The centre ray bounced all the way to the cap (the last counter holds depths 15 and more).
    assert!(c.rays_by_depth[15] >= (RECURSION_SAFETY_CAP - 14) as u64, "{c:?}");
    assert_eq!(counters::<reflect_v01::Options>(&SMALL).capped_rays, 0, "no runaway without the facing mirrors");

    let out =
        common::run_example("reflect_v01", &[&SMALL[..], &["--mirrors", "-o", "target/reflect/v01.png"]].concat());
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let explained: Vec<_> = stdout.lines().filter(|l| l.contains("safety cap")).collect();
    assert_eq!(explained.len(), 1, "{stdout}");
    assert!(explained[0].contains("MAX_RAY_DEPTH"), "{stdout}");
}

#[test]
fn the_examples_are_the_same_for_any_thread_count() {
    let one = common::render::<refract_scene::Options>(&["--width", "96", "--height", "72", "--threads", "1"]);
    let two = common::render::<refract_scene::Options>(&["--width", "96", "--height", "72", "--threads", "2"]);
    assert!(one == two, "refract changed with the thread count");
    let one = common::render::<reflect_v02::Options>(&["--width", "96", "--height", "72", "--threads", "1"]);
    let two = common::render::<reflect_v02::Options>(&["--width", "96", "--height", "72", "--threads", "2"]);
    assert!(one == two, "reflect_v02 changed with the thread count");
}

#[test]
fn impossible_ior_and_multiplier_are_rejected() {
    for (example, args, needle) in [
        ("refract", &["--ior=-1"][..], "ior -1"),
        ("refract", &["--ior", "NaN"][..], "ior NaN"),
        ("reflect_v01", &["--multiplier", "1.5"][..], "multiplier 1.5"),
        ("reflect_v02", &["--multiplier=-0.2"][..], "multiplier -0.2"),
    ] {
        let out = common::run_example(example, args);
        assert_eq!(out.status.code(), Some(2), "{example} {args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle) && err.trim_end().lines().count() == 1, "{example} {args:?}: {err}");
    }
}
