//! Property tests: random rays, including degenerate ones, through every geometry and shader (and the caustic
//! photon map's estimate). Whatever the ray, nothing panics, every hit is finite and every colour finite and
//! non-negative.

use lecture6::Color;
use lecture6::lesson::bitmap::{Bitmap, Filter, Wrap};
use lecture6::lesson::camera::Camera;
use lecture6::lesson::environment::ConstantEnvironment;
use lecture6::lesson::geometry::{Cube, Geometry, Mesh, Plane, Prism, Sphere};
use lecture6::lesson::light::PointLight;
use lecture6::lesson::math::Vector;
use lecture6::lesson::node::Node;
use lecture6::lesson::photon_map::{PhotonMap, PhotonSettings};
use lecture6::lesson::ray::Ray;
use lecture6::lesson::rng::Rng;
use lecture6::lesson::scene::{Scene, TraceContext};
use lecture6::lesson::shader::{Lambert, Layered, Phong, Reflection, Refraction, Shader};
use lecture6::lesson::spectral::Ior;
use lecture6::lesson::texture::{CheckerTexture, Fresnel, FresnelMode};
use proptest::prelude::*;
use std::sync::{Arc, OnceLock};

/// Coordinates from tiny to huge, both signs, and exact zeros.
fn coordinate() -> impl Strategy<Value = f32> {
    prop_oneof![Just(0.0f32), -1e3f32..1e3, -1e6f32..1e6, -1e-3f32..1e-3]
}

fn vector() -> impl Strategy<Value = Vector> {
    (coordinate(), coordinate(), coordinate()).prop_map(|(x, y, z)| Vector::new(x, y, z))
}

/// Directions: random, axis-aligned, and almost parallel to an axis (grazing).
fn direction() -> impl Strategy<Value = Vector> {
    prop_oneof![
        vector(),
        (0usize..3, prop::bool::ANY).prop_map(|(axis, neg)| {
            let mut v = Vector::ZERO;
            v[axis] = if neg { -1.0 } else { 1.0 };
            v
        }),
        (0usize..3, -1e-30f32..1e-30).prop_map(|(axis, tiny)| {
            let mut v = Vector::splat(tiny);
            v[axis] = 1.0;
            v
        }),
    ]
    .prop_filter("a direction needs a length", |v| v.length_squared() > 0.0 && v.is_finite())
    .prop_map(|v| v.normalize())
}

fn geometries() -> Vec<Arc<dyn Geometry>> {
    vec![
        Arc::new(Plane::new(1.0, 100.0)),
        Arc::new(Plane::new(-3.0, f32::INFINITY)),
        Arc::new(Sphere::new(Vector::new(0.0, 30.0, -30.0), 27.0)),
        Arc::new(Sphere::new(Vector::new(1e5, 0.0, 0.0), 1e-3)),
        Arc::new(Cube::new(Vector::new(5.0, 5.0, 5.0), 5.0)),
        Arc::new(Prism::new(60.0, 2.0, 3.0)),
        Arc::new(tetrahedron()),
    ]
}

/// A closed triangle mesh (a tetrahedron with smooth normals), plus a degenerate triangle that is dropped.
fn tetrahedron() -> Mesh {
    let v = [(0.0, 30.0, 0.0), (-20.0, 0.0, -10.0), (20.0, 0.0, -10.0), (0.0, 0.0, 25.0), (1.0, 1.0, 1.0)]
        .map(|(x, y, z)| Vector::new(x, y, z));
    Mesh::new(&v, &[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], [4, 4, 0]]).expect("valid indices")
}

/// A scene with every shader: a Fresnel glass holding a second glass (nested dielectrics), a mirror box
/// touching the floor, a glossy sphere resting on it and an almost fully rough one (glossiness 0.02), a Phong sphere, a
/// checkered Lambert floor, a transformed (non-uniformly scaled) glass ellipsoid, and a turned prism of
/// dispersive flint glass.
fn all_shaders_scene() -> Scene {
    let mut scene = Scene::new(Camera::default());
    scene.environment = Some(Arc::new(ConstantEnvironment(Color::new(0.8, 0.9, 1.0))));
    scene.ambient = Color::gray(0.1);
    scene.max_depth = 8;
    scene.lights.push(PointLight::new(Vector::new(10.0, 40.0, -10.0), Color::WHITE, 2000.0));
    let mut glass = Layered::new();
    glass.add_layer(Arc::new(Refraction::new(1.5, 1.0)), Color::WHITE, None).add_layer(
        Arc::new(Reflection::new(1.0)),
        Color::WHITE,
        Some(Arc::new(Fresnel::new(1.5, FresnelMode::Exact))),
    );
    let glass: Arc<dyn Shader> = Arc::new(glass);
    let checker = CheckerTexture { color1: Color::gray(0.9), color2: Color::gray(0.2), scaling: 0.1 };
    scene
        .add(Node::new(Arc::new(Plane::new(0.0, 100.0)), Arc::new(Lambert::new(checker))))
        .add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 10.0, 20.0), 10.0)), glass.clone()))
        .add(Node::new(Arc::new(Sphere::new(Vector::new(0.0, 10.0, 20.0), 5.0)), Arc::new(Refraction::new(2.4, 0.9))))
        .add(Node::new(Arc::new(Cube::new(Vector::new(25.0, 5.0, 20.0), 5.0)), Arc::new(Reflection::new(0.9))))
        .add(Node::new(
            Arc::new(Sphere::new(Vector::new(25.0, 16.0, 20.0), 6.0)),
            Arc::new(Reflection::glossy(Color::gray(0.9), 0.7, 3).expect("valid glossiness")),
        ))
        .add(Node::new(
            Arc::new(Sphere::new(Vector::new(-25.0, 22.0, 20.0), 4.0)),
            Arc::new(Reflection::glossy(Color::gray(0.8), 0.02, 2).expect("valid glossiness")),
        ))
        .add(Node::new(
            Arc::new(Sphere::new(Vector::new(-25.0, 8.0, 20.0), 8.0)),
            Arc::new(Phong::new(Color::new(0.8, 0.2, 0.2), 0.5, 30.0)),
        ))
        .add(
            Node::new(Arc::new(Sphere::new(Vector::ZERO, 1.0)), glass)
                .scale(Vector::new(6.0, 2.0, 3.0))
                .rotate(30.0, 10.0, 5.0)
                .translate(Vector::new(0.0, 4.0, 0.0)),
        )
        .add(
            Node::new(Arc::new(Prism::new(60.0, 3.0, 4.0)), Arc::new(Refraction::with_ior(Ior::SF11, 1.0)))
                .rotate(20.0, 0.0, 0.0)
                .translate(Vector::new(-10.0, 4.0, -5.0)),
        );
    scene
}

/// The all-shaders scene with a caustic photon map (built once; its glass and mirrors are the casters), so
/// that the photon estimate in Lambert and Phong is shaded too.
fn scene_with_caustics() -> &'static Scene {
    static SCENE: OnceLock<Scene> = OnceLock::new();
    SCENE.get_or_init(|| {
        let mut scene = all_shaders_scene();
        scene.photons = PhotonSettings { count: 20_000, k: 20, max_radius: None, show: false };
        let map = PhotonMap::build(&scene, 7).expect("photon map").expect("the scene has caustic casters");
        scene.photon_map = Some(Arc::new(map));
        scene
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    #[test]
    fn every_hit_is_finite(start in vector(), dir in direction()) {
        let ray = Ray::new(start, dir);
        for g in geometries() {
            if let Some(hit) = g.intersect(&ray, f32::INFINITY) {
                prop_assert!(hit.distance > 0.0 && hit.distance.is_finite());
                prop_assert!(hit.ip.is_finite() && hit.uv().0.is_finite() && hit.uv().1.is_finite());
                prop_assert!(hit.error.is_finite() && hit.error >= 0.0);
                prop_assert!((hit.normal.length() - 1.0).abs() < 1e-4, "normal {}", hit.normal);
            }
            // The any-hit test agrees with the closest-hit test.
            prop_assert_eq!(g.intersects(&ray, f32::INFINITY), g.intersect(&ray, f32::INFINITY).is_some());
        }
    }

    #[test]
    fn every_colour_is_finite_and_non_negative(
        start in vector(),
        dir in direction(),
        seed in any::<u64>(),
        wavelength in prop::option::of(400.0f32..700.0),
    ) {
        let scene = scene_with_caustics();
        let mut ctx = TraceContext::new(scene, Rng::for_keys(&[seed]));
        let c = ctx.raytrace(&Ray { wavelength, ..Ray::new(start, dir) });
        prop_assert!(c.is_finite() && c.0.min_element() >= 0.0, "{c:?}");
    }

    /// The bilinear look-up, whose usual case reads the four texels as two pairs without wrapping each
    /// index, gives what it gives inside a larger image with the wrapping written out (the image's texels laid
    /// out as the wrap mode repeats them, four tiles each way), for any (u, v) and every wrap mode, inside the
    /// image, across its edges and tiles away. The test holds no filter of its own: a students' copy, where
    /// the filter is an exercise, holds no answer.
    #[test]
    fn bilinear_sampling_wraps_as_the_image_with_its_wrapping_written_out(
        u in -3.0f32..3.0,
        v in -3.0f32..3.0,
        wrap_u in prop::sample::select(vec![Wrap::Repeat, Wrap::Mirror, Wrap::Clamp]),
        wrap_v in prop::sample::select(vec![Wrap::Repeat, Wrap::Mirror, Wrap::Clamp]),
    ) {
        let (w, h) = (5usize, 3usize);
        let texel = |i: usize, j: usize| Color::new(i as f32, j as f32, (i * 7 + j * 3) as f32 * 0.01);
        let bitmap = Bitmap::from_pixels(w, h, (0..h).flat_map(|j| (0..w).map(move |i| texel(i, j))).collect());
        let wrapped = |k: i64, n: usize, wrap: Wrap| {
            let n = n as i64;
            (match wrap {
                Wrap::Repeat => k.rem_euclid(n),
                Wrap::Clamp => k.clamp(0, n - 1),
                Wrap::Mirror => {
                    let m = k.rem_euclid(2 * n);
                    if m < n { m } else { 2 * n - 1 - m }
                }
            }) as usize
        };
        let (margin_w, margin_h) = (4 * w, 4 * h);
        let (big_w, big_h) = (w + 2 * margin_w, h + 2 * margin_h);
        let written_out = (0..big_h)
            .flat_map(|j| {
                (0..big_w).map(move |i| {
                    let (i, j) = (i as i64 - margin_w as i64, j as i64 - margin_h as i64);
                    texel(wrapped(i, w, wrap_u), wrapped(j, h, wrap_v))
                })
            })
            .collect();
        let big = Bitmap::from_pixels(big_w, big_h, written_out);
        let (big_u, big_v) =
            ((u * w as f32 + margin_w as f32) / big_w as f32, (v * h as f32 + margin_h as f32) / big_h as f32);
        let expected = big.sample(big_u, big_v, Filter::Bilinear, (Wrap::Clamp, Wrap::Clamp));
        let got = bitmap.sample(u, v, Filter::Bilinear, (wrap_u, wrap_v));
        prop_assert!((got.0 - expected.0).abs().max_element() < 1e-4, "{got:?} against {expected:?}");
    }
}
