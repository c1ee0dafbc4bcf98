//! The numeric edge cases of the geometry and the shaders, one by one: grazing rays on planes, rays along a
//! sphere's tangents, rays through a cube's edges and corners, refraction one ulp either side of the
//! critical angle, touching and nested dielectrics, slivers and zero-area triangles in an OBJ file, and
//! mesh hits for directions of any length.

use crate::common;

use lecture6::Color;
use lecture6::instruments::compare::{difference, heat_map};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::environment::ConstantEnvironment;
use lecture6::lesson::geometry::{Cube, Geometry, Mesh, Plane, Sphere};
use lecture6::lesson::light::PointLight;
use lecture6::lesson::math::{Vector, fresnel, fresnel_exact, refract};
use lecture6::lesson::node::Node;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::{RenderSettings, render};
use lecture6::lesson::scene::Scene;
use lecture6::lesson::shader::{Lambert, Layered, Reflection, Refraction, Shader};
use lecture6::lesson::texture::{CheckerTexture, Fresnel, FresnelMode};
use std::sync::Arc;

/// Every hit is in front of the ray, finite, and agrees with the any-hit test.
fn check_hit(g: &dyn Geometry, ray: &Ray) -> Option<f32> {
    let hit = g.intersect(ray, f32::INFINITY);
    assert_eq!(g.intersects(ray, f32::INFINITY), hit.is_some(), "closest and any hit disagree for {ray:?}");
    hit.map(|h| {
        assert!(h.distance > 0.0 && h.distance.is_finite(), "{ray:?}: {h:?}");
        assert!(
            h.ip.is_finite() && h.error.is_finite() && h.uv().0.is_finite() && h.uv().1.is_finite(),
            "{ray:?}: {h:?}"
        );
        assert!((h.normal.length() - 1.0).abs() < 1e-5, "{ray:?}: {h:?}");
        h.distance
    })
}

#[test]
fn grazing_rays_on_a_plane_hit_on_it_or_miss() {
    let plane = Plane::new(2.0, f32::INFINITY);
    // Directions from parallel to the plane up to one ulp, a denormal and the smallest normal f32 off it.
    let slopes = [0.0, f32::from_bits(1), f32::MIN_POSITIVE, 1e-30, 1e-20, 1e-7, f32::EPSILON];
    for height in [2.0f32, 2.0f32.next_up(), 2.0f32.next_down(), 3.0, 1.0, 1e6] {
        for slope in slopes {
            for sign in [1.0f32, -1.0] {
                let dir = Vector::new(1.0, sign * slope, 0.3).normalize();
                let ray = Ray::new(Vector::new(-5.0, height, 0.0), dir);
                let Some(t) = check_hit(&plane, &ray) else { continue };
                // A hit lies on the plane, in the direction of travel towards it.
                let hit = plane.intersect(&ray, f32::INFINITY).unwrap();
                assert_eq!(hit.ip.y, 2.0, "{ray:?}");
                assert!(
                    dir.y != 0.0 && (2.0 - height).signum() == dir.y.signum(),
                    "hit from the wrong side: {ray:?} at {t}"
                );
            }
        }
    }
    // A ray starting exactly on the plane never hits it again.
    for dir in [Vector::X, Vector::new(1.0, 1e-30, 0.0), Vector::new(1.0, -1e-3, 0.0).normalize()] {
        assert!(plane.intersect(&Ray::new(Vector::new(0.0, 2.0, 0.0), dir), f32::INFINITY).is_none(), "{dir}");
    }
}

#[test]
fn rays_along_sphere_tangents_hit_on_the_sphere_or_miss() {
    for (center, radius) in [(Vector::ZERO, 1.0f32), (Vector::new(1e5, -3.0, 7.0), 2.5), (Vector::splat(1e-3), 1e-4)] {
        let sphere = Sphere::new(center, radius);
        for k in 0..64 {
            let angle = k as f32 * 0.1;
            let (side, along) = (Vector::new(angle.cos(), angle.sin(), 0.0), Vector::Z);
            // Rays parallel to Z whose closest approach to the centre is the radius and its neighbours.
            for offset in [radius, radius.next_up(), radius.next_down(), radius * (1.0 - 1e-6), radius * (1.0 + 1e-6)] {
                let ray = Ray::new(center + side * offset - along * (10.0 * radius), along);
                if check_hit(&sphere, &ray).is_some() {
                    let ip = sphere.intersect(&ray, f32::INFINITY).unwrap().ip;
                    let r = (ip - center).length();
                    assert!(
                        (r - radius).abs() <= 1e-5 * (radius + center.abs().max_element()),
                        "{ray:?}: |ip - c| = {r}"
                    );
                }
            }
        }
        // A ray spawned at a hit along the tangent, or tilted a millionth into or out of the surface: the
        // spawn puts it on the side its direction goes to. Outside, it never finds the sphere again; inside
        // (the sphere is closed), it always finds it, leaving.
        for k in 0..64 {
            let a = k as f32 * 0.1;
            let dir = Vector::new(a.cos() * (a * 0.7).sin(), (a * 0.7).cos(), a.sin() * (a * 0.7).sin());
            let Some(hit) = sphere.intersect(&Ray::new(center - dir * (4.0 * radius), dir), f32::INFINITY) else {
                panic!("a ray at the centre missed");
            };
            let tangent = hit.normal.cross(Vector::new(dir.z, dir.x, dir.y)).normalize();
            for tilt in [0.0, 1e-6, -1e-6] {
                let along = (tangent + hit.normal * tilt).normalize();
                let ray = Ray::new(center, dir).spawn(&hit, along, 1.0);
                let inside = (ray.start - center).length() < radius;
                assert_eq!(inside, along.dot(hit.normal) < 0.0, "spawned on the wrong side: {ray:?}");
                match sphere.intersect(&ray, f32::INFINITY) {
                    Some(again) => assert!(inside && again.normal.dot(ray.dir) >= 0.0, "{ray:?} met {again:?}"),
                    None => assert!(!inside, "a ray inside the sphere missed it: {ray:?}"),
                }
                check_hit(&sphere, &ray);
            }
        }
    }
}

#[test]
fn rays_through_cube_edges_and_corners_never_slip_through() {
    let cube = Cube::new(Vector::new(1.0, -2.0, 3.0), 1.5);
    let (c, h) = (cube.center, cube.half_side);
    let mut targets = Vec::new();
    for x in [-1.0f32, 0.0, 1.0] {
        for y in [-1.0f32, 0.0, 1.0] {
            for z in [-1.0f32, 0.0, 1.0] {
                // Two or three non-zero coordinates: an edge's midpoint or a corner.
                if [x, y, z].iter().filter(|v| **v != 0.0).count() >= 2 {
                    targets.push(c + Vector::new(x, y, z) * h);
                }
            }
        }
    }
    let mut hits = 0;
    for target in targets {
        for k in 0..50 {
            // Rays from outside, from all around, aimed exactly at the edge point or corner.
            let a = k as f32 * 0.7;
            let from =
                target + Vector::new(a.cos() * (a * 0.3).sin(), (a * 0.3).cos(), a.sin() * (a * 0.3).sin()) * 20.0;
            if ((from - c).abs() - Vector::splat(h)).max_element() <= 0.0 {
                continue;
            }
            let ray = Ray::new(from, (target - from).normalize());
            let t = check_hit(&cube, &ray);
            // A ray aimed into the box's inside near the edge must hit; one that only touches it may miss.
            let inward = Ray::new(from, ((target * 0.999 + c * 0.001) - from).normalize());
            assert!(check_hit(&cube, &inward).is_some(), "slipped past the edge at {target}: {inward:?}");
            hits += t.is_some() as u32;
        }
    }
    assert!(hits > 0, "no ray aimed at an edge or a corner hit the cube");
}

/// The refraction shader's glass on both sides of the critical angle, one ulp apart.
#[test]
fn refraction_at_the_critical_angle_plus_and_minus_one_ulp() {
    let n = Vector::Y; // the normal faces the incoming ray, which leaves the glass going up
    for ior in [1.0001f32, 1.33, 1.5, 2.4, 4.0] {
        let eta = ior; // leaving the glass: eta1 / eta2 = ior
        let sin_c = 1.0 / ior;
        for sin in [sin_c.next_down(), sin_c, sin_c.next_up()] {
            let cos = (1.0 - sin * sin).sqrt();
            let i = Vector::new(sin, -cos, 0.0);
            let refracted = refract(i, n, eta);
            let (schlick, exact) = (fresnel(i, n, eta), fresnel_exact(i, n, eta));
            assert!((0.0..=1.0).contains(&schlick) && (0.0..=1.0).contains(&exact), "ior {ior}, sin {sin}");
            match refracted {
                Some(t) => {
                    assert!(t.is_finite(), "ior {ior}, sin {sin}: {t}");
                    assert!((t.length() - 1.0).abs() < 1e-4, "ior {ior}, sin {sin}: |t| = {}", t.length());
                    // The refracted ray leaves the glass: it goes to the far side of the surface or along it.
                    assert!(t.dot(n) <= 1e-3, "ior {ior}, sin {sin}: {t}");
                }
                // Total internal reflection: every Fresnel term sends all the light into the reflection.
                None => assert!(schlick == 1.0 && exact == 1.0, "ior {ior}, sin {sin}: {schlick} {exact}"),
            }
        }
        // Well below the critical angle light gets out; well above it does not.
        assert!(refract(Vector::new(0.5 * sin_c, -(1.0 - 0.25 * sin_c * sin_c).sqrt(), 0.0), n, eta).is_some());
        let s = sin_c + 0.5 * (1.0 - sin_c);
        assert!(refract(Vector::new(s, -(1.0 - s * s).sqrt(), 0.0), n, eta).is_none());
    }
}

/// Glass on the slides' Fresnel material: refraction under a reflection layer blended by the Fresnel term.
fn glass(ior: f32) -> Arc<dyn Shader> {
    let mut glass = Layered::new();
    glass.add_layer(Arc::new(Refraction::new(ior, 1.0)), Color::WHITE, None).add_layer(
        Arc::new(Reflection::new(1.0)),
        Color::WHITE,
        Some(Arc::new(Fresnel::new(ior, FresnelMode::Exact))),
    );
    Arc::new(glass)
}

/// A glass ball resting on a glass slab, and a diamond ball inside a larger glass ball touching its wall
/// from inside; `gap` separates each pair by that fraction of the small ball's radius.
fn dielectrics(gap: f32) -> Scene {
    let mut scene = Scene::new(Camera { position: Vector::new(0.0, 6.0, -14.0), pitch: -18.0, ..Camera::default() });
    scene.environment = Some(Arc::new(ConstantEnvironment(Color::new(0.5, 0.6, 0.8))));
    scene.max_depth = 10;
    scene.lights.push(PointLight::new(Vector::new(-8.0, 20.0, -10.0), Color::WHITE, 600.0));
    let checker = CheckerTexture { color1: Color::gray(0.8), color2: Color::gray(0.1), scaling: 0.5 };
    scene.add(Node::new(Arc::new(Plane::new(-2.0, 50.0)), Arc::new(Lambert::new(checker))));
    // The slab's top face is y = 0 (its bottom stays clear of the floor: coplanar faces are a modelling
    // error no renderer resolves); the ball of radius 1.5 rests on it.
    scene.add(
        Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), glass(1.5))
            .scale(Vector::new(3.0, 0.75, 3.0))
            .translate(Vector::new(-3.0, -0.75, 0.0)),
    );
    scene.add(Node::new(Arc::new(Sphere::new(Vector::new(-3.0, 1.5 * (1.0 + gap), 0.0), 1.5)), glass(1.5)));
    // The outer ball, radius 2.5; the inner one, radius 1, touches its wall on the +X side.
    let outer = Vector::new(3.5, 1.0, 0.0);
    scene.add(Node::new(Arc::new(Sphere::new(outer, 2.5)), glass(1.5)));
    scene.add(Node::new(Arc::new(Sphere::new(outer + Vector::X * (1.5 - gap), 1.0)), glass(2.4)));
    scene
}

/// The touching picture and a heat map of its difference go to `target/edge-cases/` for a look.
#[test]
fn touching_and_nested_dielectrics_render_like_slightly_separated_ones() {
    let settings = RenderSettings { width: 160, height: 120, spp: 1, ..RenderSettings::default() };
    let frame = |gap| {
        let (frame, stats) = render(&dielectrics(gap), &settings).expect("render");
        assert_eq!(stats.counters.non_finite_samples, 0, "samples came back NaN or infinite");
        frame
    };
    let touching = frame(0.0);
    let separated = frame(1e-3);
    let d = difference(&touching.to_rgb8(), &separated.to_rgb8()).unwrap();
    let dir = common::root().join("target").join("edge-cases");
    std::fs::create_dir_all(&dir).unwrap();
    touching.to_rgb8().save(dir.join("touching.png")).unwrap();
    heat_map(&touching.to_rgb8(), &separated.to_rgb8()).unwrap().save(dir.join("touching-diff.png")).unwrap();
    eprintln!("touching against separated by 1e-3 of the radius: {d}");
    // A gap of a thousandth of the radius is below a pixel; acne or a leak at the contact would show as
    // speckles or a dark ring over many pixels.
    assert!(d.large_pixels * 200 <= d.pixels, "{d}");
    // Black acne: a glass pixel that is black where the separated scene is not.
    let black =
        touching.pixels.iter().zip(&separated.pixels).filter(|(a, b)| a.max_channel() == 0.0 && b.max_channel() > 0.0);
    assert_eq!(black.count(), 0, "black speckles where the dielectrics touch");
}

#[test]
fn slivers_and_zero_area_triangles_in_an_obj_stay_finite() {
    // One good triangle; a zero-area one (collinear points); one with a repeated vertex; a sliver whose
    // height is a denormal; a needle a million times longer than wide; a triangle far from the origin.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 0.5 1e-40 0\nv 1e6 0 1\nv 1e6 1e-6 1\nv 0 0 1\n\
                v 1e6 1e6 1e6\nv 1e6 1.0001e6 1e6\nv 1.0001e6 1e6 1e6\n\
                f 1 2 3\nf 1 2 4\nf 1 1 3\nf 1 2 5\nf 8 6 7\nf 9 10 11\n";
    let path = common::temp_file("edge-cases", "slivers.obj", text);
    let mesh = Mesh::load(&path).unwrap();
    assert!(mesh.triangle_count() >= 3, "the good triangle, the needle and the far one stay");
    for k in 0..400 {
        let a = k as f32 * 0.37;
        let start = Vector::new(0.3 + a.sin(), 0.2 + (a * 1.3).cos(), -2.0);
        for dir in [Vector::Z, (Vector::new(0.4, 0.3, 0.5) - start).normalize(), Vector::new(a.cos(), 0.0, a.sin())] {
            check_hit(&mesh, &Ray::new(start, dir));
        }
    }
    // The same file placed in the model_transform scene renders without NaN (through the example's path).
    let frame = common::render::<common::examples::model_transform::Options>(&[
        "--mesh",
        path.to_str().unwrap(),
        "--width",
        "64",
        "--height",
        "48",
        "--spp",
        "1",
    ]);
    // `common::render` checks that no sample came back NaN or infinite.
    assert!(frame.pixels.iter().any(|c| c.max_channel() > 0.0), "the mesh scene renders black");
}

/// A node's transform hands its geometry rays whose direction is not of unit length (1/s for a node scaled
/// by s). The watertight triangle test once inflated its error bounds with that length until it rejected
/// every hit of a teapot scaled by 1e4; the hit must not depend on the direction's length.
#[test]
fn a_mesh_hit_does_not_depend_on_the_length_of_the_direction() {
    let mesh = Mesh::load(&lecture6::app::workbook::texture_path("teapot.obj")).unwrap();
    let mut hits = 0;
    for k in 0..200 {
        let a = k as f32 * 0.31;
        let start = Vector::new(8.0 * a.cos(), 1.5 + 3.0 * (a * 0.7).sin(), 8.0 * a.sin());
        let target = Vector::new(0.5 * (a * 1.3).sin(), 1.5 + (a * 0.9).cos(), 0.5 * (a * 1.7).cos());
        let dir = (target - start).normalize();
        let unit = mesh.intersect(&Ray::new(start, dir), f32::INFINITY).map(|h| h.distance);
        for length in [1e-6f32, 1e-4, 1e-2, 1e2, 1e4, 1e6] {
            let scaled = mesh.intersect(&Ray::new(start, dir * length), f32::INFINITY).map(|h| h.distance * length);
            match (unit, scaled) {
                (Some(t), Some(u)) => assert!((t - u).abs() <= 1e-4 * t, "length {length}: {t} against {u}"),
                (None, None) => {}
                _ => panic!("length {length}: {unit:?} against {scaled:?} from {start} towards {target}"),
            }
        }
        hits += unit.is_some() as u32;
    }
    assert!(hits > 100, "only {hits} of 200 rays aimed at the teapot hit it");
}

/// The same for every canonical shape: the plane, the sphere, the cube and the prism hit the same point for
/// directions of length 1e-6 to 1e6.
#[test]
fn every_shape_hits_the_same_point_whatever_the_length_of_the_direction() {
    use lecture6::lesson::geometry::Prism;
    let shapes: [(&str, Box<dyn Geometry>); 4] = [
        ("plane", Box::new(Plane::new(0.0, 3.0))),
        ("sphere", Box::new(Sphere::new(Vector::ZERO, 1.0))),
        ("cube", Box::new(Cube::new(Vector::ZERO, 1.0))),
        ("prism", Box::new(Prism::new(60.0, 1.0, 1.0))),
    ];
    for (name, shape) in &shapes {
        let mut hits = 0;
        for k in 0..300 {
            let a = k as f32 * 0.37;
            let start = Vector::new(4.0 * a.cos(), 3.0 * (a * 0.6).sin() + 0.5, 4.0 * a.sin());
            let target = Vector::new(0.8 * (a * 1.3).sin(), 0.8 * (a * 0.9).cos(), 0.8 * (a * 1.7).cos());
            let dir = (target - start).normalize();
            let unit = shape.intersect(&Ray::new(start, dir), f32::INFINITY).map(|h| (h.distance, h.ip));
            for length in [1e-6f32, 1e-3, 1e3, 1e6] {
                let scaled = shape.intersect(&Ray::new(start, dir * length), f32::INFINITY);
                match (unit, scaled) {
                    (Some((_, p)), Some(h)) => {
                        assert!((h.ip - p).length() <= 1e-4, "{name}, length {length}: {} against {p}", h.ip)
                    }
                    (None, None) => {}
                    _ => panic!("{name}, length {length}: {unit:?} against {scaled:?}"),
                }
            }
            hits += unit.is_some() as u32;
        }
        assert!(hits > 50, "{name}: only {hits} of 300 rays hit");
    }
}
