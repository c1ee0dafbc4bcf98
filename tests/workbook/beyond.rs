//! Each step beyond the slides (src/lesson/beyond.rs) computes what the slide's version beside it computes:
//! the exact steps give the same hits, the filters and samplers the same means.
//! The steps that already have tests of their own against the slide's version: adaptive depth control
//! (layered_fresnel: within one level of `--exhaustive`), layer pruning (layered_fresnel: the slide's loop),
//! the mesh BVH (mesh: brute force), camera-relative coordinates (stress: scenes moved 1e6 away), and every
//! example against `--slide` (slide). A student's own types are tested here against the workbook's.

use crate::common::hidden::through_trait_objects;
use crate::common::{examples, parse, random_unit, root};
use lecture6::lesson::beyond::{Step, Steps};
use lecture6::lesson::bitmap::{Bitmap, Filter, Wrap};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::color::Color;
use lecture6::lesson::geometry::{Cube, Mesh, Plane, Sphere};
use lecture6::lesson::math::Vector;
use lecture6::lesson::math::floor;
use lecture6::lesson::node::Node;
use lecture6::lesson::photon_map::PhotonMap;
use lecture6::lesson::ray::Ray;
use lecture6::lesson::render::render;
use lecture6::lesson::rng::Rng;
use lecture6::lesson::sampling::{DiscSampler, DiscSamples, random_unit_disc_point};
use lecture6::lesson::scene::Scene;
use lecture6::lesson::shader::Lambert;
use std::sync::Arc;

/// Twenty nodes (more than the node tree's threshold): spheres, cubes, transformed teapots sharing one mesh,
/// and a plane.
fn crowded_scene() -> Scene {
    let mut scene = Scene::new(Camera::default());
    let teapot = Arc::new(Mesh::load(&root().join("textures/teapot_low.obj")).unwrap());
    let mut rng = Rng::for_keys(&[7]);
    for i in 0..18 {
        let at = (Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5) * 60.0;
        let shader = Lambert::new(Color::gray(0.5));
        scene.add(match i % 3 {
            0 => Node::new(Sphere::new(at, 2.0 + 4.0 * rng.next_f32()), shader),
            1 => Node::new(Cube::new(Vector::ZERO, 1.0), shader)
                .scale(Vector::new(3.0, 1.0, 2.0))
                .rotate(30.0 * i as f32, 10.0, 5.0)
                .translate(at),
            _ => Node::new(teapot.clone(), shader)
                .scale(Vector::splat(0.2))
                .rotate(17.0 * i as f32, 0.0, 0.0)
                .translate(at),
        });
    }
    scene.add(Node::new(Plane::new(-40.0, f32::INFINITY), Lambert::new(Color::WHITE)));
    scene.add(Node::new(Sphere::new(Vector::ZERO, 1.0), Lambert::new(Color::WHITE)));
    scene
}

/// The two-phase nearest hit through the node tree finds the node and the point that the slides' loop of
/// `Node::intersect` finds (the mesh's BVH against its triangles one by one included): on 99.9% of the rays
/// that hit, the same node, and the distance within 1e-4 relative everywhere but at triangle edges.
#[test]
fn the_node_tree_and_two_phase_hit_find_the_slides_closest_hit() {
    let scene = crowded_scene().prepared().into_owned();
    let mut slides = crowded_scene();
    slides.steps = Steps::SLIDES;
    let slides = slides.prepared().into_owned();
    let mut rng = Rng::for_keys(&[8]);
    let (mut hits, mut same) = (0, 0);
    for _ in 0..20_000 {
        let start = random_unit(&mut rng) * 80.0;
        let target = (Vector::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5) * 60.0;
        let ray = Ray::new(start, (target - start).normalize());
        let slide = slides.closest_hit(&ray).map(|(info, node)| (info, slides.node_name(node)));
        let default = scene.closest_hit(&ray).map(|(info, node)| (info, scene.node_name(node)));
        match (slide, default) {
            (None, None) => {}
            (Some((a, node_a)), Some((b, node_b))) => {
                hits += 1;
                let close = (a.distance - b.distance).abs() <= 1e-4 * a.distance;
                same += (node_a == node_b && close && (a.ip - b.ip).length() <= 1e-3 * a.distance) as u32;
            }
            (a, b) => panic!("{ray:?}: the slide's loop hits {}, the default {}", a.is_some(), b.is_some()),
        }
    }
    assert!(hits > 5_000, "too few rays hit: {hits}");
    assert!(same as f64 >= 0.999 * hits as f64, "{same} of {hits} hits agree");
}

/// Bilinear filtering (through `Bitmap::sample`) keeps the image's mean, as the slide's one texel per look-up
/// does: both averaged over a fine grid of u/v over a random image agree within 0.5%; and the nearest filter
/// reads exactly the slide's texel.
#[test]
fn bilinear_texels_keep_the_slides_mean_and_nearest_is_the_slides_texel() {
    let mut rng = Rng::for_keys(&[9]);
    let (w, h) = (13, 7);
    let pixels = (0..w * h).map(|_| Color::new(rng.next_f32(), rng.next_f32(), rng.next_f32())).collect();
    let bitmap = Bitmap::from_pixels(w, h, pixels);
    let wrap = (Wrap::Repeat, Wrap::Repeat);
    let (mut slide, mut bilinear) = (Color::BLACK, Color::BLACK);
    let n = 400;
    for i in 0..n {
        for j in 0..n {
            let (u, v) = ((i as f32 + 0.5) / n as f32 * 3.0 - 1.0, (j as f32 + 0.5) / n as f32 * 2.0 - 0.5);
            let (x, y) = (floor(u * w as f32) as i64, floor(v * h as f32) as i64);
            let texel = bitmap.get_pixel(wrap.0.texel(x, w), wrap.1.texel(y, h));
            assert_eq!(texel, bitmap.sample(u, v, Filter::Nearest, wrap), "nearest at ({u}, {v})");
            slide += texel;
            bilinear += bitmap.sample(u, v, Filter::Bilinear, wrap);
        }
    }
    for (a, b) in slide.to_array().into_iter().zip(bilinear.to_array()) {
        assert!((a - b).abs() <= 0.005 * a, "means {a} and {b}");
    }
}

/// The stratified and joint disc samplers are unbiased, as the slide's random points are: over 64 sets of 64
/// points, the mean point is the centre (within 0.01) and the mean squared radius 1/2 (within 0.005), the
/// moments of a uniform disc, which the slide's random points meet too (within 0.02 and 0.01).
#[test]
fn stratified_and_joint_disc_points_have_the_slides_moments() {
    let moments = |point: &mut dyn FnMut(u32, &mut Rng) -> (f32, f32)| {
        let mut rng = Rng::for_keys(&[10]);
        let (mut x, mut y, mut r2, mut n) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        for i in 0..64 * 64 {
            let (px, py) = point(i, &mut rng);
            (x, y, r2, n) = (x + px as f64, y + py as f64, r2 + (px * px + py * py) as f64, n + 1.0);
        }
        (x / n, y / n, r2 / n)
    };
    let (x, y, r2) = moments(&mut |_, rng| random_unit_disc_point(rng));
    assert!(x.abs() < 0.02 && y.abs() < 0.02 && (r2 - 0.5).abs() < 0.01, "random: {x} {y} {r2}");
    for sampler in [DiscSampler::Stratified, DiscSampler::Joint] {
        let mut set = None;
        let (x, y, r2) = moments(&mut |i, rng| {
            if i % 64 == 0 {
                set = Some(DiscSamples::new(sampler, rng));
            }
            set.as_ref().unwrap().point(i % 64, rng)
        });
        assert!(x.abs() < 0.01 && y.abs() < 0.01 && (r2 - 0.5).abs() < 0.005, "{sampler:?}: {x} {y} {r2}");
    }
}

/// The photon grid with aimed emission and the slide's photons shot in all directions into a k-d tree carry
/// the same caustic power: on the photon_map example's scene the stored photons' powers add up to the same
/// flux within 3%, and the estimates at points of the floor under the glass agree within 10%.
#[test]
fn aimed_photons_in_a_grid_carry_the_slides_caustic() {
    let (scene, _) = parse::<examples::photon_map::Options>(&["--width", "64", "--height", "48"]).prepare().unwrap();
    let default = scene.photon_map.clone().expect("the example builds a photon map");
    let mut slides = scene.clone();
    slides.steps = scene.steps.without(Step::PhotonGrid);
    let slide = PhotonMap::build(&slides, 1).unwrap().expect("a slide photon map");
    let flux = |photons: &[lecture6::lesson::photon_map::StoredPhoton]| -> f64 {
        photons.iter().map(|p| p.power.to_array().iter().map(|&c| c as f64).sum::<f64>()).sum()
    };
    let (a, b) = (flux(default.photons()), flux(slide.photons()));
    assert!((a - b).abs() <= 0.03 * a, "caustic flux: {a} by default, {b} on the slide's map");
    let estimates = |map: &dyn Fn(Vector) -> Color| -> f64 {
        let brightest = default.photons().iter().map(|p| p.position).take(200);
        brightest.map(|p| map(p).to_array().iter().map(|&c| c as f64).sum::<f64>()).sum()
    };
    let up = Vector::Y;
    let (a, b) = (estimates(&|p| default.irradiance(p, up)), estimates(&|p| slide.irradiance(p, up)));
    assert!((a - b).abs() <= 0.10 * a, "estimates at the caustic: {a} by default, {b} on the slide's map");
}

/// A student's own types work as the workbook's do: every example renders the same picture bit for bit, and
/// traces the same rays, when each node's geometry and shader, and the environment, is hidden behind a type
/// of the test's own (called through its trait object, the case `Own` of its family, as a student's is).
#[test]
fn own_types_render_what_the_workbooks_types_render() {
    macro_rules! compare {
        ($($name:ident),*) => {$(
            let (scene, settings) =
                parse::<examples::$name::Options>(&["--width", "48", "--height", "36"]).prepare().unwrap();
            let (enum_frame, enum_stats) = render(&scene, &settings).unwrap();
            let (dyn_frame, dyn_stats) = render(&through_trait_objects(&scene), &settings).unwrap();
            let bits = |f: &lecture6::lesson::frame::Frame| -> Vec<u32> {
                f.pixels.iter().flat_map(|c| c.to_array()).map(f32::to_bits).collect()
            };
            assert!(bits(&enum_frame) == bits(&dyn_frame), "{}: the pictures differ", stringify!($name));
            assert_eq!(enum_stats.counters.rays_by_depth, dyn_stats.counters.rays_by_depth, "{}: the rays traced differ", stringify!($name));
        )*};
    }
    every_example!(compare);
}
