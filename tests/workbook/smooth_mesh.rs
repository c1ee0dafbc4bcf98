//! A low-resolution mesh with smooth normals (a pot of 480 triangles, generated here, placed by a node's
//! transform as a course teapot is) under a mirror renders without a word in both readings: near its rim the
//! smooth normal lies on the other side of a triangle than the triangle's own normal, so a ray reflected
//! about it dips under that triangle and leaves the pot through the next one a few thousandths of a unit
//! further on, which is real geometry, not a self-hit. A ray a student's shader turns after starting it off
//! one of the workbook's shapes is still named, with the shader's fix.

use lecture6::lesson::beyond::Steps;
use lecture6::lesson::math::max_abs;
use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::lesson::shader::IntoShader;
use lecture6::prelude::*;
use std::f32::consts::{PI, TAU};
use std::sync::Arc;

/// A pot as a surface of revolution, 16 segments around and 16 rows up (480 triangles once the rows at the
/// two poles lose their empty halves), its smooth normals computed by `Mesh::new`: a round body, a narrow
/// neck and a rim flaring out under a low lid, whose edge is the sharp fold the mirror's rays meet.
fn pot() -> Arc<Mesh> {
    const AROUND: u32 = 16;
    const ROWS: u32 = 16;
    let radius = |s: f32| 0.9 + 0.6 * (1.25 * PI * s).sin() - 0.35 * (-(s - 0.85).powi(2) / 0.005).exp();
    let mut positions = Vec::new();
    for j in 0..=ROWS {
        let s = j as f32 / ROWS as f32;
        let r = if j == 0 || j == ROWS { 0.0 } else { radius(s) };
        for k in 0..AROUND {
            let a = k as f32 / AROUND as f32 * TAU;
            positions.push(Vector::new(r * a.cos(), 1.6 * s, r * a.sin()));
        }
    }
    let mut triangles = Vec::new();
    for j in 0..ROWS {
        for k in 0..AROUND {
            let (a, b) = (j * AROUND + k, j * AROUND + (k + 1) % AROUND);
            triangles.push([a, a + AROUND, b]);
            triangles.push([b, a + AROUND, b + AROUND]);
        }
    }
    let mesh = Mesh::new(&positions, &triangles).unwrap();
    assert_eq!(mesh.triangle_count(), 480);
    Arc::new(mesh)
}

/// The picture: 320x240, one sample at each pixel's centre, the size at which the rim shows the case often
/// enough to count (its 1280x960 count is about 16 times that of 320x240).
fn settings() -> RenderSettings {
    RenderSettings { width: 320, height: 240, spp: 1, ..RenderSettings::default() }
}

/// The pot, ten units tall, shaded by `shader`, seen from above its rim, under the sky, in the reading `steps`.
fn scene(shader: impl IntoShader, steps: Steps) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 25.0, -40.0), Vector::new(0.0, 15.0, -3.0), 15.0));
    scene.add(Node::new(pot(), shader).named("pot").scale(Vector::splat(10.0)));
    scene.environment = Some(sky().unwrap());
    scene.steps = steps;
    scene
}

/// A mirror as a student writes it on a copy of an example: reflected about the face-forwarded shading
/// normal, started with `ray.spawn`.
struct StudentMirror;

impl Shader for StudentMirror {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let dir = reflect(ray.dir, faceforward(info.normal, ray.dir));
        ctx.raytrace(&ray.spawn(info, dir, 0.9)) * 0.9
    }
}

/// How many of the camera rays of `scene` (at the pixels' centres) the mirror reflects off the pot's first
/// node into another triangle of it, closer than the distance within which the report takes a hit for one
/// on the surface the ray left (`sqrt(EPSILON)` times the point's coordinates) and crossed the way the ray
/// left the first one, by their geometric normals: each of them was counted as a self-hit before a mesh's
/// faces were told apart.
fn rim_rays(scene: &Scene) -> usize {
    let s = settings();
    let camera = scene.camera.frame(s.width, s.height);
    let pot = &scene.nodes[0];
    let pixels = (0..s.height).flat_map(|y| (0..s.width).map(move |x| (x, y)));
    let second_hit = |(x, y): (u32, u32)| {
        let ray = camera.get_screen_ray(x as f32 + 0.5, y as f32 + 0.5);
        let first = pot.intersect(&ray, f32::INFINITY)?;
        let dir = reflect(ray.dir, faceforward(first.normal, ray.dir));
        let second = pot.intersect(&ray.spawn(&first, dir, 1.0), f32::INFINITY)?;
        Some((first, dir, second))
    };
    pixels
        .filter_map(second_hit)
        .filter(|(first, dir, second)| {
            second.distance <= f32::EPSILON.sqrt() * max_abs(first.ip).max(first.error)
                && second.geometric_normal != first.geometric_normal
                && dir.dot(first.geometric_normal) * dir.dot(second.geometric_normal) > 0.0
        })
        .count()
}

#[test]
fn the_rim_of_a_smooth_low_resolution_mesh_is_no_self_hit_in_either_reading() {
    // The case is there: rays that leave a triangle near the rim and cross the next one within the distance.
    let rim = rim_rays(&scene(StudentMirror, Steps::ALL));
    assert!(rim >= 20, "only {rim} mirror rays meet another triangle of the rim that close");
    for steps in [Steps::ALL, Steps::SLIDES] {
        let course = render(&scene(Reflection::new(0.9), steps), &settings()).unwrap().1;
        let student = render(&scene(StudentMirror, steps), &settings()).unwrap().1;
        for (who, stats) in [("the course's mirror", &course), ("a student's mirror", &student)] {
            assert!(stats.warnings.is_empty(), "{steps:?}, {who}: {:?}", stats.warnings);
        }
    }
}

/// A student's glass that starts its refracted ray where the reflected one starts (off the surface on the
/// outside) and turns it inwards: it finds the surface again at once.
struct TurnedAfterSpawn;

impl Shader for TurnedAfterSpawn {
    fn shade(&self, ray: &Ray, info: &IntersectionInfo, ctx: &mut TraceContext) -> Color {
        let n = faceforward(info.normal, ray.dir);
        let reflected = ray.spawn(info, reflect(ray.dir, n), 0.5);
        let refracted = Ray { dir: ray.dir, ..reflected };
        (ctx.raytrace(&reflected) + ctx.raytrace(&refracted)) * 0.5
    }
}

/// The report's one line on rays that found their own surface, in both readings (the same in each).
fn self_hit_line(shape: impl Fn() -> Node) -> String {
    let lines = [Steps::ALL, Steps::SLIDES].map(|steps| {
        let mut scene = scene(Lambert::new(Color::WHITE), steps);
        scene.nodes[0] = shape();
        let stats: RenderStats = render(&scene, &settings()).unwrap().1;
        let lines: Vec<&String> = stats.warnings.iter().filter(|l| l.contains("self-intersection")).collect();
        assert_eq!(lines.len(), 1, "{steps:?}: {:?}", stats.warnings);
        lines[0].chars().filter(|c| !c.is_ascii_digit()).collect::<String>()
    });
    assert_eq!(lines[0], lines[1], "the two readings' lines differ");
    lines[0].clone()
}

#[test]
fn a_ray_turned_after_it_was_started_off_a_workbook_shape_is_the_shaders_mistake() {
    let mesh = || Node::new(pot(), TurnedAfterSpawn).named("pot").scale(Vector::splat(10.0));
    let ball = || Node::new(Sphere::new(Vector::new(0.0, 8.0, 0.0), 8.0), TurnedAfterSpawn).named("ball");
    for (name, line) in [("pot", self_hit_line(mesh)), ("ball", self_hit_line(ball))] {
        assert!(line.contains(&format!("{name} (TurnedAfterSpawn)")), "{line}");
        // The workbook's shape puts its hit point on its surface: the fix is the shader's.
        assert!(line.contains("ray.spawn") && !line.contains("with_error"), "{line}");
    }
}
