//! The end-of-run report (`lecture6::lesson::diagnostics`): a student's geometry that leaves its hit point
//! off the surface, or returns a NaN or unnormalised normal, and a shader that returns NaN, are named by
//! the line the render prints; the API page's own cylinder, done right, is not. (That the lines reach the
//! end of the run's output: `reflection_refraction::reflection_v01_*`, whose runaway the report explains.)

use lecture6::lesson::render::{RenderSettings, RenderStats, render};
use lecture6::prelude::*;

/// The API page's geometry (docs/homework-api.md, "Write a geometry"), the file docs/homework_geometry.rs.
#[path = "../../docs/homework_geometry.rs"]
mod homework_geometry;

use homework_geometry::Cylinder;

/// The cylinder with one mistake a student makes: its hit point as `ray.at(t)` (not put back on the
/// surface), its normal NaN, or its normal not normalised.
#[derive(Clone, Copy)]
enum Mistake {
    AtT,
    NanNormal,
    LongNormal,
}

struct Mistaken(Mistake);

impl Geometry for Mistaken {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        let info = Cylinder.intersect(ray, t_max)?;
        Some(match self.0 {
            Mistake::AtT => IntersectionInfo { ip: ray.at(info.distance), ..info },
            Mistake::NanNormal => IntersectionInfo { normal: Vector::ZERO.normalize(), ..info },
            Mistake::LongNormal => IntersectionInfo { normal: info.normal * 2.0, ..info },
        })
    }

    fn bounds(&self) -> Option<Aabb> {
        Cylinder.bounds()
    }
}

/// A mirror cylinder, stretched and turned, seen from far enough that `ray.at(t)` is off its surface by
/// more than the hit's error bound, beside a mirror ball; a striped sky.
fn scene(cylinder: impl Geometry + 'static, shader: impl Shader + 'static) -> Scene {
    let mut scene = Scene::new(Camera::look_at(Vector::new(0.0, 40.0, -300.0), Vector::ZERO, 12.0));
    scene.add(Node::new(cylinder, shader).named("pillar").scale(Vector::new(8.0, 20.0, 8.0)).rotate(20.0, 0.0, 30.0));
    scene.add(Node::new(Sphere::new(Vector::new(25.0, 0.0, 0.0), 8.0), Reflection::new(0.9)));
    scene.environment = Some(workbook::sky().unwrap());
    scene
}

fn rendered(scene: &Scene) -> RenderStats {
    let settings = RenderSettings { width: 160, height: 120, spp: 1, ..RenderSettings::default() };
    render(scene, &settings).unwrap().1
}

/// The one report line that contains `what`.
fn line<'a>(stats: &'a RenderStats, what: &str) -> &'a str {
    let lines: Vec<_> = stats.warnings.iter().filter(|l| l.contains(what)).collect();
    assert_eq!(lines.len(), 1, "one line about {what}: {:?}", stats.warnings);
    lines[0]
}

#[test]
fn the_pages_cylinder_renders_without_a_word() {
    let stats = rendered(&scene(Cylinder, Reflection::new(0.9)));
    assert!(stats.warnings.is_empty(), "{:?}", stats.warnings);
    assert!(stats.counters.rays_by_depth[1] > 1000, "the mirror cylinder reflects: {:?}", stats.counters);
}

#[test]
fn a_hit_point_left_at_ray_at_t_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::AtT), Reflection::new(0.9)));
    let line = line(&stats, "self-intersection");
    assert!(line.contains("pillar (Reflection)"), "{line}");
    assert!(!line.contains("Sphere"), "{line}");
}

#[test]
fn a_nan_normal_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::NanNormal), Reflection::new(0.9)));
    assert!(line(&stats, "not of unit length, or NaN").contains("pillar (Reflection)"), "{:?}", stats.warnings);
}

#[test]
fn a_normal_not_normalised_is_named() {
    let stats = rendered(&scene(Mistaken(Mistake::LongNormal), Lambert::new(Color::WHITE)));
    assert!(line(&stats, "not of unit length").contains("pillar (Lambert)"), "{:?}", stats.warnings);
}

/// A shader that returns NaN, as `0.0 / 0.0` in a student's formula would.
struct Broken;

impl Shader for Broken {
    fn shade(&self, _: &Ray, _: &IntersectionInfo, _: &mut TraceContext) -> Color {
        Color::gray(f32::NAN)
    }
}

#[test]
fn a_nan_colour_is_counted_and_named_where_it_was_made() {
    // The NaN is made by the pillar and seen in the mirror ball too: only the pillar made it.
    let stats = rendered(&scene(Cylinder, Broken));
    let line = line(&stats, "NaN or infinite");
    assert!(line.starts_with(&format!("{} sample(s)", stats.counters.non_finite_samples)), "{line}");
    assert!(line.contains("made by the shader of pillar (Broken)") && !line.contains("Sphere"), "{line}");
}
